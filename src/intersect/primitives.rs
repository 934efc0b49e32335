//! Every shape of a scene, packed for intersection.
//!
//! Primitive ids: triangles `0..T` in mesh order, then spheres `T..T+S`.
//! The hot loop only needs [`Shape`] (a triangle's three corners, or a
//! sphere's centre and radius); the rest of the hit record (point, normals,
//! error bound) is computed once, for the closest hit, by
//! [`Primitives::finish_hit`].

use glam::Vec3;

use crate::math::float::{gamma, unit_cross};
use crate::scene::{MaterialId, Scene, Sphere};

use super::moller_trumbore::moller_trumbore;
use super::sphere::{reproject, SphereShape};
use super::triangle::TriangleShape;
use super::{Aabb, Hit, Ray};

/// A shape stored for intersection.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shape {
    Triangle(TriangleShape),
    Sphere(SphereShape),
}

/// Where a ray meets a shape: `t`, and barycentrics `(u, v)` for triangles.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShapeHit {
    pub t: f32,
    pub u: f32,
    pub v: f32,
}

impl From<super::triangle::TriangleHit> for ShapeHit {
    fn from(h: super::triangle::TriangleHit) -> Self {
        ShapeHit {
            t: h.t,
            u: h.u,
            v: h.v,
        }
    }
}

/// Which ray-triangle test to use.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum TriangleTest {
    /// Woop, Benthin and Wald's watertight test ([`super::triangle`]): no
    /// ray slips between triangles that share an edge. The default.
    #[default]
    Watertight,
    /// Möller and Trumbore's test ([`super::moller_trumbore`]), the
    /// course's: exact in real numbers, but rays can slip through shared
    /// edges and vertices.
    MollerTrumbore,
}

impl Shape {
    /// The ray's hit with this shape with `t` in `[ray.t_min, t_max]`
    /// (triangles by the watertight test).
    #[inline(always)]
    pub fn intersect(&self, ray: &Ray, t_max: f32) -> Option<ShapeHit> {
        self.intersect_with(ray, t_max, TriangleTest::Watertight)
    }

    /// [`Shape::intersect`] with the given triangle test.
    #[inline(always)]
    pub fn intersect_with(&self, ray: &Ray, t_max: f32, test: TriangleTest) -> Option<ShapeHit> {
        match self {
            Shape::Triangle(tri) => {
                let hit = match test {
                    TriangleTest::Watertight => tri.intersect(ray, t_max),
                    TriangleTest::MollerTrumbore => moller_trumbore(tri, ray, t_max),
                };
                hit.map(ShapeHit::from)
            }
            Shape::Sphere(s) => s
                .intersect(ray, t_max)
                .map(|t| ShapeHit { t, u: 0.0, v: 0.0 }),
        }
    }

    /// The shape's bounding box.
    pub fn bounds(&self) -> Aabb {
        match self {
            Shape::Triangle(t) => Aabb::from_points([t.p0, t.p1, t.p2]),
            Shape::Sphere(s) => Aabb {
                min: s.center - Vec3::splat(s.radius),
                max: s.center + Vec3::splat(s.radius),
            },
        }
    }
}

/// What shading needs of a triangle beyond its shape, in one record so a
/// hit costs one memory access for it: the three vertex normals and the
/// material.
#[derive(Clone, Copy, Debug, PartialEq)]
struct TriangleShading {
    normals: [Vec3; 3],
    material: MaterialId,
}

/// The scene's shapes plus what it takes to finish a hit record.
#[derive(Clone, Debug, Default)]
pub struct Primitives {
    /// One shape per primitive id.
    pub shapes: Vec<Shape>,
    /// The ray-triangle test intersectors over these shapes use.
    pub triangle_test: TriangleTest,
    /// Per triangle id.
    triangle_shading: Vec<TriangleShading>,
    spheres: Vec<Sphere>,
}

impl Primitives {
    /// Packs a scene's triangles and spheres.
    pub fn from_scene(scene: &Scene) -> Self {
        let mesh = &scene.mesh;
        let triangles = mesh.triangles.iter().map(|&[a, b, c]| {
            Shape::Triangle(TriangleShape::new(
                mesh.positions[a as usize],
                mesh.positions[b as usize],
                mesh.positions[c as usize],
            ))
        });
        let spheres = scene.spheres.iter().map(|s| {
            Shape::Sphere(SphereShape {
                center: s.center,
                radius: s.radius,
            })
        });
        // Read once per hit, at scattered ids: huge pages spare the TLB
        // misses (`math::huge_pages`).
        let mut triangle_shading = Vec::with_capacity(mesh.triangles.len());
        crate::math::huge_pages::advise(&triangle_shading);
        triangle_shading.extend(mesh.triangles.iter().zip(&mesh.materials).map(
            |(corners, &material)| TriangleShading {
                normals: corners.map(|v| mesh.normals[v as usize]),
                material,
            },
        ));
        Primitives {
            shapes: triangles.chain(spheres).collect(),
            triangle_test: TriangleTest::default(),
            triangle_shading,
            spheres: scene.spheres.clone(),
        }
    }

    pub fn len(&self) -> usize {
        self.shapes.len()
    }

    pub fn is_empty(&self) -> bool {
        self.shapes.is_empty()
    }

    /// Whether any primitive is a sphere.
    pub fn has_spheres(&self) -> bool {
        !self.spheres.is_empty()
    }

    /// Bounding box of every primitive.
    pub fn bounds(&self) -> Aabb {
        self.shapes
            .iter()
            .fold(Aabb::EMPTY, |b, s| b.union(s.bounds()))
    }

    /// Hints that [`Primitives::finish_hit`] will soon read primitive
    /// `id`'s shading record (a cache miss in a large scene otherwise).
    #[inline(always)]
    pub fn prefetch_shading(&self, id: u32) {
        crate::math::prefetch::prefetch_lines(
            self.triangle_shading.as_ptr().wrapping_add(id as usize),
            1,
        );
    }

    /// The vertex normals of triangle `id` (`None` for a sphere).
    pub fn vertex_normals(&self, id: u32) -> Option<[Vec3; 3]> {
        self.triangle_shading.get(id as usize).map(|s| s.normals)
    }

    /// The full hit record for primitive `id`, whose shape is `shape`, hit
    /// by `ray` at `hit`.
    pub fn finish_hit(&self, id: u32, shape: &Shape, ray: &Ray, hit: ShapeHit) -> Hit {
        let index = id as usize;
        if let Shape::Triangle(TriangleShape { p0, p1, p2 }) = *shape {
            let shading = &self.triangle_shading[index];
            let w = 1.0 - hit.u - hit.v;
            // Point from barycentrics; error bound from pbrt-v4 eq. 6.49.
            let p = w * p0 + hit.u * p1 + hit.v * p2;
            let p_error = gamma(7) * ((w * p0).abs() + (hit.u * p1).abs() + (hit.v * p2).abs());
            let ng = unit_cross(p1 - p0, p2 - p0).unwrap_or(-ray.dir);
            let [n0, n1, n2] = shading.normals;
            let n = (w * n0 + hit.u * n1 + hit.v * n2).normalize_or(ng);
            Hit {
                t: hit.t,
                p,
                p_error,
                n,
                ng,
                material: shading.material,
                primitive: id,
            }
        } else {
            let sphere = &self.spheres[index - self.triangle_shading.len()];
            let p = reproject(sphere.center, sphere.radius, ray.at(hit.t));
            let local = p - sphere.center;
            let p_error = gamma(5) * local.abs() + gamma(1) * p.abs();
            let ng = (local / sphere.radius).normalize_or(-ray.dir);
            Hit {
                t: hit.t,
                p,
                p_error,
                n: ng,
                ng,
                material: sphere.material,
                primitive: id,
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::intersect::{Intersector, LinearScan};
    use crate::scene::builtin;

    /// What a scene's primitives report about themselves: one per triangle
    /// and sphere, whether any is a sphere (which picks the BVH's build
    /// options, so only the build's speed would show a wrong answer), and
    /// the box around them all. Each of these functions made to return a
    /// constant or a default fails here (found by the mutation run of
    /// `intersect`; each checked by hand).
    #[test]
    fn primitives_count_themselves_know_their_spheres_and_bound_them_all() {
        let scene = builtin::cornell_box();
        let primitives = Primitives::from_scene(&scene);
        let (triangles, spheres) = (scene.mesh.triangles.len(), scene.spheres.len());
        assert!(triangles > 1 && spheres > 1);
        assert_eq!(primitives.len(), triangles + spheres);
        assert!(!primitives.is_empty() && primitives.has_spheres());
        let mut expected = Aabb::from_points(scene.mesh.positions.iter().copied());
        for s in &scene.spheres {
            let r = Vec3::splat(s.radius);
            expected = expected.union(Aabb::from_points([s.center - r, s.center + r]));
        }
        assert_eq!(primitives.bounds(), expected);
        assert!(!expected.is_empty());

        let mesh_only = Primitives::from_scene(&builtin::bumpy_sphere(8, 4));
        assert!(!mesh_only.is_empty() && !mesh_only.has_spheres());
        let none = Primitives::default();
        assert!(none.is_empty() && !none.has_spheres());
        assert_eq!(none.len(), 0);
        assert!(none.bounds().is_empty());
    }

    /// A sphere so small beside its distance (radius `1e-20` seen from 1)
    /// that the hit point rounds onto its centre has no outward direction
    /// there; its normal then faces back along the ray, the side the ray
    /// came from. Checked by hand: the fallback `-ray.dir` made `ray.dir`
    /// fails here.
    #[test]
    fn a_sphere_too_small_for_an_outward_direction_faces_the_ray() {
        let scene = Scene {
            spheres: vec![Sphere {
                center: Vec3::ZERO,
                radius: 1e-20,
                material: 0,
            }],
            ..Scene::default()
        };
        let primitives = Primitives::from_scene(&scene);
        let ray = Ray::new(Vec3::new(0.0, 0.0, 1.0), -Vec3::Z);
        let hit = LinearScan::new(&primitives)
            .intersect(&ray)
            .expect("aimed at it");
        assert_eq!(hit.p, Vec3::ZERO);
        assert_eq!((hit.ng, hit.n), (Vec3::Z, Vec3::Z));
    }
}
