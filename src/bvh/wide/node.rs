//! A wide node and the slab test of one ray against its eight child boxes.
//!
//! Layout: `planes[a]` holds the eight children's minima along axis `a`
//! as two groups of four lanes (group `g`, lane `i` is child `4 g + i`),
//! `planes[3 + a]` their maxima; then the eight links. 6 x 32 + 8 x 8 =
//! 256 bytes, four cache lines. The two groups are tested one after the
//! other with the same 4-lane code; they do not depend on each other, so
//! the processor overlaps their arithmetic. Where the processor has AVX,
//! [`super::avx`] tests all eight in one register instead, with the same
//! result ([`NodeTest`] chooses).
//!
//! The slab test (Kay and Kajiya 1986, as in [`crate::intersect::Aabb`]),
//! with the near and far planes chosen once per ray by the sign of the
//! direction, so no min/max is needed per axis:
//!
//! ```text
//! r_a    = 1 / d_a,  r'_a = r_a F,  F = 1 + 8u    (u = 2^-24, the unit roundoff)
//! near_a = (planes[near(a)] - o_a) r_a     near(a) = a if d_a >= +0, else 3 + a
//! far_a  = (planes[far(a)]  - o_a) r'_a    far(a)  = the other one
//! enter  = max(max(near_x, near_y), max(near_z, t_min))
//! exit   = min(min(far_x, far_y), min(far_z, t_max))
//! hit    <=> enter <= exit
//! ```
//!
//! The factor `F` keeps the test conservative under rounding (the idea
//! of pbrt-v4, section 6.8.2, with a bound of its own): a computed near
//! distance carries three roundings (the difference, the reciprocal, the
//! product), so it is at most `(1 + u)^3` times the exact one; a far
//! distance carries four (`F` is folded into the reciprocal once per
//! ray, rounded), so it is at least `(1 - u)^4 F` times the exact one.
//! With `F = 1 + 8u` (exact in `f32`), `(1 - u)^4 F > (1 + u)^3`, so a box
//! the exact ray enters is entered by the computed one too, whichever
//! axes give its entry and exit (barring underflow). pbrt multiplies each
//! far distance by `1 + 2 gamma(3)`, about `1 + 6u`, at every box, which
//! covers the same four roundings only to first order. Folding the factor
//! into the reciprocal takes a multiplication off the path from a node's
//! load to its mask, the path one ray's traversal waits on; so do the
//! pairwise maxima and minima, two levels instead of a chain of three. No
//! operand is NaN (a zero direction component's NaN is replaced first,
//! below), so their order changes no comparison (at most the sign of a
//! zero entry distance). Together: primary rays +7 % on the benchmark
//! (`docs/maintainers/wide-bvh.md`, round 10). The hits do not change: the
//! test only decides which boxes are opened, and a box holding a hit
//! within `[t_min, t_max]` is opened either way.
//!
//! An unused slot has the empty box (`min = +inf`, `max = -inf`): with
//! planes ordered by the direction's sign its near distance is `+inf` and
//! its far one `-inf` on every axis, so no ray enters it.
//!
//! A ray that does not move along an axis (`d_a = ±0`, `1/d_a = ±inf`)
//! and starts exactly on a plane gets `0 · inf = NaN` there. It lies in
//! that slab, so a NaN near distance becomes `-inf` and a NaN far one
//! `+inf`. Only rays with a zero direction component can meet this, and
//! only they pay for the check. (Tried instead: `1/d = ±f32::MAX` for a
//! zero component, which avoids the NaN, but a ray starting exactly on a
//! box's far plane then gets a far distance of 0 instead of +inf and
//! misses the box: the unit test below caught it.)

use glam::{Vec3, Vec4};

use super::leaf::{RayShear, TrianglePack};
use super::{WideLink, ARITY};
use crate::intersect::triangle::TriangleHit;
use crate::intersect::Aabb;

/// `F = 1 + 8u`, the far distances' factor (see the module doc).
pub const FAR_FACTOR: f32 = 1.0 + 4.0 * f32::EPSILON;

/// An interior node of the wide BVH: its children's boxes, plane by plane,
/// and the links to them.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(64))]
pub struct WideNode {
    /// `[min x, min y, min z, max x, max y, max z]`; group `g`, lane `i`
    /// is child `4 g + i`.
    pub planes: [[Vec4; GROUPS]; 6],
    pub children: [WideLink; ARITY],
}

/// Groups of four lanes in a node: [`ARITY`] / 4.
pub const GROUPS: usize = ARITY / 4;

/// A ray prepared for box tests: origin and inverse direction splatted
/// across the lanes, and which plane of each axis is entered first.
#[derive(Clone, Copy, Debug)]
pub struct RayBoxes {
    pub(super) origin: [Vec4; 3],
    pub(super) inv_dir: [Vec4; 3],
    pub(super) inv_dir_far: [Vec4; 3],
    pub(super) near: [usize; 3],
    pub(super) far: [usize; 3],
    pub(super) has_zero_direction: bool,
    pub t_min: f32,
}

impl RayBoxes {
    /// `dir` need not be normalised; a component may be ±0.
    pub fn new(origin: Vec3, dir: Vec3, t_min: f32) -> Self {
        Self::from_inverse(origin, Vec3::ONE / dir, t_min)
    }

    /// The same from the direction's inverse `1 / dir` (which keeps the
    /// direction's signs, zeros included: `1 / -0 = -inf`).
    #[inline(always)]
    pub fn from_inverse(origin: Vec3, inv: Vec3, t_min: f32) -> Self {
        let near = [0, 1, 2].map(|a| if inv[a].is_sign_negative() { 3 + a } else { a });
        // Infinite where `inv` is, and where `inv` is within the factor
        // of `f32::MAX` (a component just above 2^-128: its reciprocal is
        // finite, `F` times it is not); both get the NaN check.
        let inv_far = inv * FAR_FACTOR;
        RayBoxes {
            origin: [origin.x, origin.y, origin.z].map(Vec4::splat),
            inv_dir: [inv.x, inv.y, inv.z].map(Vec4::splat),
            inv_dir_far: [inv_far.x, inv_far.y, inv_far.z].map(Vec4::splat),
            near,
            far: near.map(|p| (p + 3) % 6),
            has_zero_direction: !inv_far.is_finite(),
            t_min,
        }
    }
}

impl WideNode {
    /// A node over up to [`ARITY`] children; missing slots are left empty.
    pub fn new(children: &[(Aabb, WideLink)]) -> Self {
        assert!(children.len() <= ARITY, "at most {ARITY} children");
        let mut boxes = [Aabb::EMPTY; ARITY];
        let mut links = [WideLink::EMPTY; ARITY];
        for (i, &(b, l)) in children.iter().enumerate() {
            boxes[i] = b;
            links[i] = l;
        }
        let lanes = |f: &dyn Fn(&Aabb) -> f32| {
            std::array::from_fn(|g| Vec4::from_array(std::array::from_fn(|i| f(&boxes[4 * g + i]))))
        };
        WideNode {
            planes: [
                lanes(&|b| b.min.x),
                lanes(&|b| b.min.y),
                lanes(&|b| b.min.z),
                lanes(&|b| b.max.x),
                lanes(&|b| b.max.y),
                lanes(&|b| b.max.z),
            ],
            children: links,
        }
    }

    /// The box of child `i`.
    pub fn child_bounds(&self, i: usize) -> Aabb {
        let p = self.planes.map(|v| v[i / 4].to_array()[i % 4]);
        Aabb {
            min: Vec3::new(p[0], p[1], p[2]),
            max: Vec3::new(p[3], p[4], p[5]),
        }
    }

    /// Which children the ray meets within `[ray.t_min, t_max]` (bit `i`
    /// for child `i`) and the entry distance into each (valid for those).
    /// The groups of four are independent, so their arithmetic overlaps.
    #[inline(always)]
    pub fn hit(&self, ray: &RayBoxes, t_max: f32) -> (u32, [f32; ARITY]) {
        let mut mask = 0;
        let mut entries = [0.0; ARITY];
        for g in 0..GROUPS {
            let axis = |a: usize| {
                let o = ray.origin[a];
                let mut near = (self.planes[ray.near[a]][g] - o) * ray.inv_dir[a];
                let mut far = (self.planes[ray.far[a]][g] - o) * ray.inv_dir_far[a];
                if ray.has_zero_direction {
                    near = Vec4::select(near.is_nan_mask(), Vec4::NEG_INFINITY, near);
                    far = Vec4::select(far.is_nan_mask(), Vec4::INFINITY, far);
                }
                (near, far)
            };
            let (near_x, far_x) = axis(0);
            let (near_y, far_y) = axis(1);
            let (near_z, far_z) = axis(2);
            let enter = near_x.max(near_y).max(near_z.max(Vec4::splat(ray.t_min)));
            let exit = far_x.min(far_y).min(far_z.min(Vec4::splat(t_max)));
            mask |= enter.cmple(exit).bitmask() << (4 * g);
            entries[4 * g..4 * g + 4].copy_from_slice(&enter.to_array());
        }
        (mask, entries)
    }
}

/// How a traversal tests a ray against a node's eight boxes: the same
/// slab test, compiled for the instructions the processor has (see
/// [`super::avx`]). Every implementation returns the same bits.
pub trait NodeTest {
    fn hit(node: &WideNode, ray: &RayBoxes, t_max: f32) -> (u32, [f32; ARITY]);

    /// The nearest triangle lane hit within `[ray.t_min, t_max]` among
    /// `packs` (a leaf's, consecutive): its pack's offset in `packs`, its
    /// lane and its hit. This default tests the packs one after the
    /// other, each with `t_max` lowered to the hit found so far.
    #[inline(always)]
    fn packs_hit(
        packs: &[TrianglePack],
        ray: &RayShear,
        mut t_max: f32,
    ) -> Option<(usize, usize, TriangleHit)> {
        let mut best = None;
        for (offset, pack) in packs.iter().enumerate() {
            if let Some((lane, hit)) = pack.intersect(ray, t_max) {
                t_max = hit.t;
                best = Some((offset, lane, hit));
            }
        }
        best
    }
}

/// The two groups of four lanes with SSE2 (NEON on ARM): every processor.
pub struct Sse;

impl NodeTest for Sse {
    #[inline(always)]
    fn hit(node: &WideNode, ray: &RayBoxes, t_max: f32) -> (u32, [f32; ARITY]) {
        node.hit(ray, t_max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_node_is_four_cache_lines() {
        assert_eq!(std::mem::size_of::<WideNode>(), 256);
        assert_eq!(std::mem::align_of::<WideNode>(), 64);
    }

    /// Four boxes along x; rays from the left, the right, along a face
    /// (zero direction components of both signs), and one missing all.
    #[test]
    fn slab_test_agrees_with_the_box_test() {
        let boxes: Vec<Aabb> = (0..3)
            .map(|i| {
                let x = 2.0 * i as f32;
                Aabb::from_points([Vec3::new(x, 0.0, 0.0), Vec3::new(x + 1.0, 1.0, 1.0)])
            })
            .collect();
        let children: Vec<(Aabb, WideLink)> =
            boxes.iter().map(|&b| (b, WideLink::default())).collect();
        let node = WideNode::new(&children);
        let origins = [
            Vec3::new(-1.0, 0.5, 0.5),
            Vec3::new(9.0, 0.5, 0.5),
            Vec3::new(-1.0, 1.0, 0.0),
            Vec3::new(-1.0, 2.0, 0.5),
        ];
        for origin in origins {
            for dir in [Vec3::X, -Vec3::X, Vec3::new(1.0, -0.0, 0.0)] {
                let ray = RayBoxes::new(origin, dir, 0.0);
                let (mask, enter) = node.hit(&ray, f32::INFINITY);
                assert_eq!(mask & !7, 0, "empty slots are never entered");
                for (i, b) in boxes.iter().enumerate() {
                    let expected =
                        b.hit_distance(origin.into(), (Vec3::ONE / dir).into(), 0.0, f32::INFINITY);
                    let found = (mask >> i & 1 != 0).then(|| enter[i]);
                    assert_eq!(found, expected, "box {i} from {origin} along {dir}");
                }
            }
        }
    }
}
