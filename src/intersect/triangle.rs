//! Ray-triangle intersection by Möller and Trumbore (1997).
//!
//! Write the hit point in barycentric form, `o + t d = (1-u-v) p0 + u p1 + v p2`,
//! with edges `e1 = p1 - p0`, `e2 = p2 - p0` and `s = o - p0`. Cramer's rule
//! on `[-d, e1, e2] (t, u, v)^T = s` gives, with `P = d x e2`, `Q = s x e1`
//! and `det = e1 . P`:
//!
//! ```text
//! t = (e2 . Q) / det,   u = (s . P) / det,   v = (d . Q) / det
//! ```
//!
//! A hit needs `det != 0` (the ray is not parallel to the plane),
//! `u >= 0`, `v >= 0`, `u + v <= 1` and `t` inside the ray's interval.
//!
//! Shared edges: the barycentric tests are widened by [`EDGE_TOLERANCE`]
//! so that rounding cannot let a ray slip between two triangles that share
//! an edge; the returned barycentrics are then clamped back into the
//! triangle. (A fully watertight alternative is Woop, Benthin and Wald,
//! "Watertight Ray/Triangle Intersection", JCGT 2013.)
//!
//! Hits closer than the rounding error of `t` are rejected ([`t_error`]):
//! there the sign of `t` is unknown. Without this, a ray spawned from the
//! triangle (origin pushed off the surface by the hit point's error bound,
//! [`crate::intersect::Hit::spawn_ray`]) can compute a tiny positive `t`
//! although its true `t` is negative, and hit its own triangle (found by
//! the property test `spawned_rays_leave_a_triangle`; pbrt-v4 makes the
//! same check, section 6.8.4).

use glam::Vec3;

use super::Ray;
use crate::math::float::gamma;

/// How far outside `[0, 1]` a barycentric coordinate may fall and still
/// count as a hit.
pub const EDGE_TOLERANCE: f32 = 1e-6;

/// A triangle stored for intersection: one vertex and two edges.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleShape {
    pub p0: Vec3,
    pub e1: Vec3,
    pub e2: Vec3,
}

/// Where a ray meets a triangle: distance and the barycentrics of `p1`, `p2`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleHit {
    pub t: f32,
    pub u: f32,
    pub v: f32,
}

impl TriangleShape {
    pub fn new(p0: Vec3, p1: Vec3, p2: Vec3) -> Self {
        TriangleShape {
            p0,
            e1: p1 - p0,
            e2: p2 - p0,
        }
    }

    /// Möller-Trumbore; `None` for a miss, a parallel ray or a zero-area
    /// triangle (whose `det` is zero).
    #[inline(always)]
    pub fn intersect(&self, ray: &Ray, t_max: f32) -> Option<TriangleHit> {
        let p = ray.dir.cross(self.e2);
        let det = self.e1.dot(p);
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        let inv_det = 1.0 / det;
        let s = ray.origin - self.p0;
        let u = s.dot(p) * inv_det;
        if !(-EDGE_TOLERANCE..=1.0 + EDGE_TOLERANCE).contains(&u) {
            return None;
        }
        let q = s.cross(self.e1);
        let v = ray.dir.dot(q) * inv_det;
        if v < -EDGE_TOLERANCE || u + v > 1.0 + EDGE_TOLERANCE {
            return None;
        }
        let t = self.e2.dot(q) * inv_det;
        if !(t >= ray.t_min && t <= t_max) || t <= t_error(self, ray, s, det, t) {
            return None;
        }
        // Clamp the widened barycentrics back into the triangle.
        let u = u.clamp(0.0, 1.0);
        let v = v.clamp(0.0, 1.0 - u);
        Some(TriangleHit { t, u, v })
    }
}

/// Bound on the absolute rounding error of Möller-Trumbore's
/// `t = (e2 . (s x e1)) / (e1 . (d x e2))` against the exact plane
/// crossing of the ray with the triangle's `f32` vertices.
///
/// A triple product `a . (b x c)` in floating point is off by at most
/// `gamma(5) |a| . (|b| x' |c|)` (absolute values per component, `x'` the
/// cross product with its two terms added): `gamma(2)` for the cross
/// product, `gamma(3)` for the dot. `e1`, `e2` and `s` are rounded
/// differences, one more `u` per factor: `gamma(8)` for the numerator
/// (three factors), `gamma(7)` for `det` (two; `d` is taken as given).
/// To first order `|err t| <= (err_num + |t| err_det) / |det| + u |t|`;
/// the factor 2 covers second-order terms and the rounding of the bound.
/// Only evaluated for hits inside the ray's interval, so it stays off the
/// hot path of misses.
#[inline]
fn t_error(tri: &TriangleShape, ray: &Ray, s: Vec3, det: f32, t: f32) -> f32 {
    let cross_abs = |b: Vec3, c: Vec3| {
        Vec3::new(
            b.y * c.z + b.z * c.y,
            b.z * c.x + b.x * c.z,
            b.x * c.y + b.y * c.x,
        )
    };
    let (e1, e2) = (tri.e1.abs(), tri.e2.abs());
    let num_err = gamma(8) * e2.dot(cross_abs(s.abs(), e1));
    let det_err = gamma(7) * e1.dot(cross_abs(ray.dir.abs(), e2));
    2.0 * ((num_err + t.abs() * det_err) / det.abs() + gamma(1) * t.abs())
}
