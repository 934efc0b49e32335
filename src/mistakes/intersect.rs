//! Parts 1 and 2 as a student writes them: `Triangle::intersect`,
//! `Sphere::intersect`, `BBox::intersect` and the recursive
//! `BVHAccel::intersect` / `has_intersection` of the starter, over the
//! project's tree, with the catalogue's intersection mistakes at the lines
//! a student gets wrong. The course's renderer uses [`StudentBvh`] in place
//! of the project's BVH only when one of these mistakes is chosen
//! ([`StudentBvh::is_needed`]).
//!
//! The starter's routines share one mutable ray: a primitive hit with
//! `min_t <= t <= max_t` overwrites the hit record and sets
//! `r.max_t = t`, so later tests only accept nearer hits and the record
//! ends as the nearest. Traversal visits a node when its box meets the
//! ray within `[min_t, max_t]` (the slab test: per axis
//! `t = (p - o) / d` for both planes; enter at the largest near distance,
//! leave at the smallest far one), and both children of every node it
//! visits:
//!
//! ```text
//! intersect(node):  if !node.bb.intersect(r, r.min_t, r.max_t): return false
//!                   leaf: hit = false; for p in node: hit |= p.intersect(r, isect); return hit
//!                   hit1 = intersect(node.l); hit2 = intersect(node.r); return hit1 || hit2
//! ```
//!
//! The triangle test is Möller and Trumbore's (as the handout's), the
//! sphere's the quadratic `|o + t d - c|^2 = r^2` with roots
//! `t = (-b -+ sqrt(b^2 - 4 a c)) / 2a`, and the shading normal of a
//! triangle the barycentric blend `(1 - b1 - b2) n0 + b1 n1 + b2 n2`.

use glam::Vec3;

use super::{Mistake, Mistakes};
use crate::bvh::{build::build_from, BuildOptions, Bvh, Link};
use crate::intersect::{Aabb, Hit, Intersector, PrimitiveHit, Primitives, Ray, Shape, ShapeHit};

/// The hit record: the primitive's id and where the ray meets it.
type Record = (u32, ShapeHit);

/// A student's BVH over a scene's primitives, with `mistakes`.
pub struct StudentBvh<'a> {
    primitives: &'a Primitives,
    bvh: Bvh,
    mistakes: Mistakes,
}

impl<'a> StudentBvh<'a> {
    /// Whether `mistakes` holds one of parts 1 and 2's intersection
    /// mistakes, which only this intersector makes.
    pub fn is_needed(mistakes: Mistakes) -> bool {
        use Mistake::*;
        mistakes.iter().any(|m| {
            matches!(
                m,
                TriangleChainedComparison
                    | SphereFarRoot
                    | BarycentricsPermuted
                    | BoxMissesRaysFromInside
                    | TraversalReturnsFirstHit
                    | MaxTNotShrunk
            )
        })
    }

    /// The tree over `primitives` (the project's build: a student's split
    /// rule changes speed, not hits), traversed as a student does.
    pub fn new(primitives: &'a Primitives, mistakes: Mistakes) -> Self {
        let bvh = build_from(
            primitives.shapes.iter().map(Shape::bounds),
            &BuildOptions::default(),
        );
        StudentBvh {
            primitives,
            bvh,
            mistakes,
        }
    }

    /// `BBox::intersect(r, t0, t1)`.
    fn box_hit(&self, bounds: &Aabb, ray: &Ray) -> bool {
        let to_min = (bounds.min - ray.origin) / ray.dir;
        let to_max = (bounds.max - ray.origin) / ray.dir;
        let near = to_min.min(to_max).max_element();
        let far = to_min.max(to_max).min_element();
        if self.mistakes.has(Mistake::BoxMissesRaysFromInside) {
            // Asks for the ray to enter the box within [t0, t1]: a ray
            // that starts inside enters at a negative distance.
            return near >= ray.t_min && near <= far.min(ray.t_max);
        }
        near.max(ray.t_min) <= far.min(ray.t_max)
    }

    /// Whether `t` passes the primitive's range test against `ray`.
    fn in_range(&self, t: f32, ray: &Ray) -> bool {
        if self.mistakes.has(Mistake::TriangleChainedComparison) {
            // C++'s `r.min_t <= t <= r.max_t` is `(r.min_t <= t) <= r.max_t`:
            // a bool, 0 or 1, against max_t.
            let first = if ray.t_min <= t { 1.0 } else { 0.0 };
            return first <= ray.t_max;
        }
        ray.t_min <= t && t <= ray.t_max
    }

    /// The primitive's `intersect`: the hit, if it is accepted.
    fn primitive_hit(&self, shape: &Shape, ray: &Ray) -> Option<ShapeHit> {
        match shape {
            Shape::Triangle(tri) => {
                let (t, u, v) = moller_trumbore_any_t(tri.p0, tri.p1, tri.p2, ray)?;
                self.in_range(t, ray).then_some(ShapeHit { t, u, v })
            }
            Shape::Sphere(s) => {
                let (t1, t2) = sphere_roots(s.center, s.radius, ray)?;
                let order = if self.mistakes.has(Mistake::SphereFarRoot) {
                    [t2, t1]
                } else {
                    [t1, t2]
                };
                let t = order.into_iter().find(|&t| self.in_range(t, ray))?;
                Some(ShapeHit { t, u: 0.0, v: 0.0 })
            }
        }
    }

    /// `BVHAccel::intersect(r, isect, node)`.
    fn visit(&self, link: Link, bounds: &Aabb, ray: &mut Ray, best: &mut Option<Record>) -> bool {
        if !self.box_hit(bounds, ray) {
            return false;
        }
        if link.is_leaf() {
            let mut hit = false;
            for slot in link.slots() {
                let id = self.bvh.order[slot as usize];
                let shape = &self.primitives.shapes[id as usize];
                if let Some(h) = self.primitive_hit(shape, ray) {
                    if !self.mistakes.has(Mistake::MaxTNotShrunk) {
                        ray.t_max = h.t;
                    }
                    *best = Some((id, h));
                    hit = true;
                }
            }
            return hit;
        }
        let node = &self.bvh.nodes[link.first as usize];
        let [left, right] = node.children;
        let hit_left = self.visit(left, &node.child_bounds(0), ray, best);
        if hit_left && self.mistakes.has(Mistake::TraversalReturnsFirstHit) {
            // `return intersect(l) || intersect(r)`: the right child is
            // never visited once the left one has a hit.
            return true;
        }
        let hit_right = self.visit(right, &node.child_bounds(1), ray, best);
        hit_left || hit_right
    }

    /// `BVHAccel::has_intersection(r, node)`.
    fn any(&self, link: Link, bounds: &Aabb, ray: &Ray) -> bool {
        if !self.box_hit(bounds, ray) {
            return false;
        }
        if link.is_leaf() {
            return link.slots().any(|slot| {
                let id = self.bvh.order[slot as usize];
                self.primitive_hit(&self.primitives.shapes[id as usize], ray)
                    .is_some()
            });
        }
        let node = &self.bvh.nodes[link.first as usize];
        let [left, right] = node.children;
        self.any(left, &node.child_bounds(0), ray) || self.any(right, &node.child_bounds(1), ray)
    }
}

impl Intersector for StudentBvh<'_> {
    fn primitives(&self) -> &Primitives {
        self.primitives
    }

    fn nearest(&self, ray: &Ray) -> Option<PrimitiveHit> {
        let root = self.bvh.root?;
        let mut student_ray = students_ray(ray);
        let mut best = None;
        self.visit(root, &self.bvh.bounds, &mut student_ray, &mut best);
        // The record holds the last hit accepted.
        let (id, hit) = best?;
        let shape = self.primitives.shapes[id as usize];
        Some(PrimitiveHit { id, shape, hit })
    }

    fn intersect(&self, ray: &Ray) -> Option<Hit> {
        let PrimitiveHit { id, shape, hit } = self.nearest(ray)?;
        let mut record = self.primitives.finish_hit(id, &shape, ray, hit);
        if self.mistakes.has(Mistake::BarycentricsPermuted) {
            if let Some([n0, n1, n2]) = self.primitives.vertex_normals(id) {
                // b1 n0 + b2 n1 + (1 - b1 - b2) n2: each weight on the
                // wrong vertex.
                let w = 1.0 - hit.u - hit.v;
                record.n = (hit.u * n0 + hit.v * n1 + w * n2).normalize_or(record.ng);
            }
        }
        Some(record)
    }

    fn occluded(&self, ray: &Ray) -> bool {
        let ray = students_ray(ray);
        self.bvh
            .root
            .is_some_and(|root| self.any(root, &self.bvh.bounds, &ray))
    }
}

/// The starter's `EPS_F`, the `min_t` of rays that leave a surface.
const EPS_F: f32 = 1e-5;

/// `ray` as a student's code has it: starting no nearer than `EPS_F`. The
/// project's rays leave a surface at `t_min = 0` from an origin pushed off
/// it by its error bound, which the watertight test needs; Möller and
/// Trumbore's test can meet the surface again at `t = 0` from there.
fn students_ray(ray: &Ray) -> Ray {
    Ray {
        t_min: ray.t_min.max(EPS_F),
        ..*ray
    }
}

/// Möller and Trumbore's test without the range check: `(t, b1, b2)` where
/// the ray's line crosses the triangle, at any `t`.
fn moller_trumbore_any_t(p0: Vec3, p1: Vec3, p2: Vec3, ray: &Ray) -> Option<(f32, f32, f32)> {
    let (e1, e2, s) = (p1 - p0, p2 - p0, ray.origin - p0);
    let s1 = ray.dir.cross(e2);
    let s2 = s.cross(e1);
    let det = s1.dot(e1);
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let t = s2.dot(e2) / det;
    let b1 = s1.dot(s) / det;
    let b2 = s2.dot(ray.dir) / det;
    (b1 >= 0.0 && b2 >= 0.0 && b1 + b2 <= 1.0).then_some((t, b1, b2))
}

/// The roots `t1 <= t2` of `|o + t d - c|^2 = r^2`, if real.
fn sphere_roots(center: Vec3, radius: f32, ray: &Ray) -> Option<(f32, f32)> {
    let oc = ray.origin - center;
    let a = ray.dir.dot(ray.dir);
    let b = 2.0 * oc.dot(ray.dir);
    let c = oc.dot(oc) - radius * radius;
    let disc = b * b - 4.0 * a * c;
    if disc.is_nan() || disc < 0.0 {
        return None;
    }
    let root = disc.sqrt();
    Some(((-b - root) / (2.0 * a), (-b + root) / (2.0 * a)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::intersect::{LinearScan, TriangleTest};
    use crate::scene::builtin;

    /// Rays from in front of the Cornell box and from inside it, towards
    /// points spread through the box.
    fn rays() -> Vec<Ray> {
        let origins = [
            Vec3::new(0.1234, 0.8123, 3.0),
            Vec3::new(-0.2137, 1.0123, 0.4871),
        ];
        let mut rays = Vec::new();
        for origin in origins {
            for i in 0..20 {
                for j in 0..15 {
                    for k in 0..10 {
                        let (x, y, z) = (i as f32 / 19.0, j as f32 / 14.0, k as f32 / 9.0);
                        // Inside the walls: the student's slab test has no
                        // room for rounding, and a ray through a box's
                        // edge may miss it.
                        let target = Vec3::new(1.9 * x - 0.95, 1.4 * y + 0.05, 1.9 * z - 0.95);
                        rays.push(Ray::new(origin, (target - origin).normalize()));
                    }
                }
            }
        }
        rays
    }

    /// Without a mistake, the student's BVH finds what testing every
    /// primitive with Möller and Trumbore's test finds.
    #[test]
    fn without_a_mistake_it_finds_the_nearest_hit() {
        let mut primitives = Primitives::from_scene(&builtin::mesh_balls_box());
        primitives.triangle_test = TriangleTest::MollerTrumbore;
        let student = StudentBvh::new(&primitives, Mistakes::NONE);
        let linear = LinearScan::new(&primitives);
        for ray in rays() {
            let (a, b) = (student.nearest(&ray), linear.nearest(&ray));
            // The same t (a ray through a shared edge may name either
            // triangle).
            let (ta, tb) = (a.map(|h| h.hit.t), b.map(|h| h.hit.t));
            let same = match (ta, tb) {
                (Some(ta), Some(tb)) => (ta - tb).abs() <= 1e-5 * tb,
                (ta, tb) => ta == tb,
            };
            assert!(same, "{ray:?}: {ta:?} against {tb:?}");
            assert_eq!(student.occluded(&ray), linear.occluded(&ray), "{ray:?}");
        }
    }
}
