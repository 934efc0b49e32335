//! Leaf contents: triangles packed four to a [`TrianglePack`], and the
//! watertight ray-triangle test ([`crate::intersect::triangle`], Woop,
//! Benthin and Wald 2013) run on the four lanes at once.
//!
//! A pack stores its triangles as a structure of arrays: `corners[j][a]`
//! is a `Vec4` whose lane `i` is coordinate `a` of corner `j` of
//! triangle `i`, exactly the mesh's values (watertightness needs shared
//! vertices bit for bit). 9 x 16 bytes of corners and 4 ids: 160 bytes,
//! 40 per triangle, the size of a [`crate::intersect::Shape`].
//!
//! What depends on the ray alone is computed once per ray in
//! [`RayShear`]: the axis permutation (the largest direction component
//! becomes z), the shear `S_x = -d_x / d_z`, `S_y = -d_y / d_z`,
//! `S_z = 1 / d_z`, and the origin. Each lane then runs the scalar test's
//! steps with the same `f32` operations in the same order (IEEE arithmetic
//! is the same in a SIMD lane), so every lane's result equals the scalar
//! test's to the bit; a unit test checks this on random and grazing rays:
//!
//! ```text
//! (x_j, y_j, z_j) = permute(p_j - o),  x_j += S_x z_j,  y_j += S_y z_j
//! e0 = x1 y2 - y1 x2,  e1 = x2 y0 - y2 x0,  e2 = x0 y1 - y0 x1
//! reject if some e_k < 0 and some e_k > 0, or det = e0 + e1 + e2 is 0 or not finite
//! t = (e0 S_z z0 + e1 S_z z1 + e2 S_z z2) / det,  reject unless t_min <= t <= t_max
//! reject if t <= delta_t (pbrt-v4, eq. 6.32-6.37: t within its rounding error of 0)
//! ```
//!
//! An edge function that is exactly zero is recomputed in `f64` for that
//! lane, as the scalar test does. Most packs are missed by every lane at
//! the sign test; the code returns there, before the division and the
//! error bound.
//!
//! Unused lanes (a leaf of 1 to 3 triangles, or a sphere's lane) hold NaN
//! corners: their edge functions and `det` are NaN, which the finiteness
//! test rejects. A sphere's lane carries its id with [`SPHERE`] set and is
//! tested by the scalar code.

use glam::{BVec4A, Vec3, Vec4};

use super::WIDTH;
use crate::intersect::triangle::{edge_function, max_axis, TriangleHit, TriangleShape};
use crate::intersect::{Ray, Shape};
use crate::math::float::gamma;

/// Id of an unused lane.
pub const PAD: u32 = u32::MAX;
/// Set in a lane's id when the lane holds a sphere, not a triangle.
pub const SPHERE: u32 = 1 << 31;

/// Up to four primitives, triangles in SIMD lanes.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(16))]
pub struct TrianglePack {
    /// `corners[j][a]`, lane `i`: coordinate `a` of corner `j` of triangle `i`.
    pub corners: [[Vec4; 3]; 3],
    /// Primitive id per lane; [`PAD`] for an unused lane, [`SPHERE`] set
    /// for a sphere.
    pub ids: [u32; WIDTH],
}

/// A ray prepared for the lane-wise watertight test (see the module docs).
#[derive(Clone, Copy, Debug)]
pub struct RayShear {
    /// Source axes of the permuted x, y, z.
    pub(super) k: [usize; 3],
    /// Ray origin, permuted, splatted.
    pub(super) origin: [Vec4; 3],
    /// `S_x, S_y, S_z`, splatted.
    pub(super) shear: [Vec4; 3],
    pub(super) t_min: f32,
}

impl RayShear {
    pub fn new(ray: &Ray) -> Self {
        let kz = max_axis(ray.dir.abs());
        let kx = (kz + 1) % 3;
        let ky = (kx + 1) % 3;
        let d = Vec3::new(ray.dir[kx], ray.dir[ky], ray.dir[kz]);
        let shear = [-d.x / d.z, -d.y / d.z, 1.0 / d.z];
        RayShear {
            k: [kx, ky, kz],
            origin: [kx, ky, kz].map(|k| Vec4::splat(ray.origin[k])),
            shear: shear.map(Vec4::splat),
            t_min: ray.t_min,
        }
    }
}

impl TrianglePack {
    /// Packs up to four `(id, shape)` pairs; ids must be below [`SPHERE`].
    pub fn new(lanes: &[(u32, Shape)]) -> Self {
        assert!(lanes.len() <= WIDTH, "at most {WIDTH} lanes");
        let mut corners = [[[f32::NAN; WIDTH]; 3]; 3];
        let mut ids = [PAD; WIDTH];
        for (i, &(id, shape)) in lanes.iter().enumerate() {
            assert!(id < SPHERE, "primitive id {id} too large for a pack");
            match shape {
                Shape::Triangle(t) => {
                    for (j, p) in [t.p0, t.p1, t.p2].into_iter().enumerate() {
                        for a in 0..3 {
                            corners[j][a][i] = p[a];
                        }
                    }
                    ids[i] = id;
                }
                Shape::Sphere(_) => ids[i] = id | SPHERE,
            }
        }
        TrianglePack {
            corners: corners.map(|c| c.map(Vec4::from_array)),
            ids,
        }
    }

    /// Number of lanes in use.
    pub fn occupied(&self) -> usize {
        self.ids.iter().filter(|&&id| id != PAD).count()
    }

    /// Lane `i`'s primitive id, whether it is a sphere, or `None` if unused.
    #[inline(always)]
    pub fn lane(&self, i: usize) -> Option<(u32, bool)> {
        let id = self.ids[i];
        (id != PAD).then_some((id & !SPHERE, id & SPHERE != 0))
    }

    /// Lane `i`'s triangle, exactly as stored.
    pub fn triangle(&self, i: usize) -> TriangleShape {
        let [p0, p1, p2] = self
            .corners
            .map(|c| Vec3::new(c[0].to_array()[i], c[1].to_array()[i], c[2].to_array()[i]));
        TriangleShape { p0, p1, p2 }
    }

    /// The nearest lane hit within `[t_min, t_max]` by the watertight test,
    /// and its hit; `None` if no lane is hit.
    #[inline(always)]
    pub fn intersect(&self, ray: &RayShear, t_max: f32) -> Option<(usize, TriangleHit)> {
        let [kx, ky, kz] = ray.k;
        let [sx, sy, sz] = ray.shear;
        // Translate to the ray origin, permute, shear (z is scaled later).
        let sheared = |c: &[Vec4; 3]| {
            let z = c[kz] - ray.origin[2];
            let x = (c[kx] - ray.origin[0]) + sx * z;
            let y = (c[ky] - ray.origin[1]) + sy * z;
            (x, y, z)
        };
        let (x0, y0, z0) = sheared(&self.corners[0]);
        let (x1, y1, z1) = sheared(&self.corners[1]);
        let (x2, y2, z2) = sheared(&self.corners[2]);
        // Edge functions: all of one sign (or zero) inside.
        let mut e0 = x1 * y2 - y1 * x2;
        let mut e1 = x2 * y0 - y2 * x0;
        let mut e2 = x0 * y1 - y0 * x1;
        if (e0.cmpeq(Vec4::ZERO) | e1.cmpeq(Vec4::ZERO) | e2.cmpeq(Vec4::ZERO)).any() {
            e0 = recompute_zeros(e0, [x1, y2, y1, x2]);
            e1 = recompute_zeros(e1, [x2, y0, y2, x0]);
            e2 = recompute_zeros(e2, [x0, y1, y0, x1]);
        }
        let negative = e0.cmplt(Vec4::ZERO) | e1.cmplt(Vec4::ZERO) | e2.cmplt(Vec4::ZERO);
        let positive = e0.cmpgt(Vec4::ZERO) | e1.cmpgt(Vec4::ZERO) | e2.cmpgt(Vec4::ZERO);
        let det = e0 + e1 + e2;
        let finite = det.abs().cmplt(Vec4::INFINITY);
        let mut hit = !(negative & positive) & det.cmpne(Vec4::ZERO) & finite;
        if !hit.any() {
            return None;
        }
        // Scaled distance; interval test.
        let (z0, z1, z2) = (z0 * sz, z1 * sz, z2 * sz);
        let t_scaled = e0 * z0 + e1 * z1 + e2 * z2;
        let inv_det = Vec4::ONE / det;
        let t = t_scaled * inv_det;
        hit &= t.cmpge(Vec4::splat(ray.t_min)) & t.cmple(Vec4::splat(t_max));
        if !hit.any() {
            return None;
        }
        hit &= t.cmpgt(distance_error(
            [x0, x1, x2],
            [y0, y1, y2],
            [z0, z1, z2],
            [e0, e1, e2],
            inv_det,
        ));
        let lane = nearest_lane(hit, t)?;
        let (t, e1, e2, inv_det) = (t[lane], e1[lane], e2[lane], inv_det[lane]);
        let u = (e1 * inv_det).clamp(0.0, 1.0);
        let v = (e2 * inv_det).clamp(0.0, 1.0 - u);
        Some((lane, TriangleHit { t, u, v }))
    }
}

/// The bound `delta_t` on the rounding error of `t` (pbrt-v4, eq.
/// 6.32-6.37), lane-wise, in the scalar test's order of operations.
#[inline(always)]
fn distance_error(x: [Vec4; 3], y: [Vec4; 3], z: [Vec4; 3], e: [Vec4; 3], inv_det: Vec4) -> Vec4 {
    let max_abs = |v: [Vec4; 3]| v[0].abs().max(v[1].abs()).max(v[2].abs());
    let (max_x, max_y, max_z, max_e) = (max_abs(x), max_abs(y), max_abs(z), max_abs(e));
    let delta_z = gamma(3) * max_z;
    let delta_x = gamma(5) * (max_x + max_z);
    let delta_y = gamma(5) * (max_y + max_z);
    let delta_e = 2.0 * (gamma(2) * max_x * max_y + delta_y * max_x + delta_x * max_y);
    3.0 * (gamma(3) * max_e * max_z + delta_e * max_z + delta_z * max_e) * inv_det.abs()
}

/// The lane of smallest `t` among those set in `hit`.
#[inline(always)]
fn nearest_lane(hit: BVec4A, t: Vec4) -> Option<usize> {
    let mask = hit.bitmask();
    if mask == 0 {
        return None;
    }
    if mask.is_power_of_two() {
        return Some(mask.trailing_zeros() as usize);
    }
    let t = Vec4::select(hit, t, Vec4::INFINITY);
    let nearest = t.cmpeq(Vec4::splat(t.min_element())).bitmask() & mask;
    Some(nearest.trailing_zeros() as usize)
}

/// `e` with each lane that is exactly zero recomputed from its operands
/// `a b - c d` in `f64` ([`edge_function`]), as the scalar test does.
#[cold]
#[inline(never)]
pub(super) fn recompute_zeros(e: Vec4, [a, b, c, d]: [Vec4; 4]) -> Vec4 {
    let [e, a, b, c, d] = [e, a, b, c, d].map(|v| v.to_array());
    Vec4::from_array(std::array::from_fn(|i| {
        if e[i] == 0.0 {
            edge_function(a[i], b[i], c[i], d[i])
        } else {
            e[i]
        }
    }))
}
