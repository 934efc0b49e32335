//! The course's ray-triangle test: Möller and Trumbore, "Fast, Minimum
//! Storage Ray/Triangle Intersection", JGT 2(1), 1997.
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
//! A hit needs `det != 0` (the ray is not parallel to the plane; a zero-area
//! triangle also has `det = 0`), `u >= 0`, `v >= 0`, `u + v <= 1` and `t`
//! inside the ray's interval. Cost: two cross and four dot products and one
//! division.
//!
//! It is exact in real arithmetic but not watertight in floating point: two
//! triangles sharing an edge compute the edge's zero barycentric from
//! different expressions, each rounded its own way, and a ray through the
//! edge can be "outside" both. `part1-raygen` uses it, as the course's
//! part 1 does; the BVH and the lighting parts use the watertight test of
//! [`super::triangle`], which agrees with this one everywhere else
//! (`tests/moller_trumbore.rs` checks both, and shows rays slipping through
//! a mesh with this one). [`super::TriangleTest`] selects between them.

use super::triangle::{TriangleHit, TriangleShape};
use super::Ray;

/// Möller-Trumbore; `None` for a miss, a ray parallel to the plane or a
/// zero-area triangle.
#[doc(alias = "intersect")]
pub fn moller_trumbore(triangle: &TriangleShape, ray: &Ray, t_max: f32) -> Option<TriangleHit> {
    let e1 = triangle.p1 - triangle.p0;
    let e2 = triangle.p2 - triangle.p0;
    let p = ray.dir.cross(e2);
    let det = e1.dot(p);
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let inv_det = 1.0 / det;
    let s = ray.origin - triangle.p0;
    let u = s.dot(p) * inv_det;
    if !(0.0..=1.0).contains(&u) {
        return None;
    }
    let q = s.cross(e1);
    let v = ray.dir.dot(q) * inv_det;
    if v < 0.0 || u + v > 1.0 {
        return None;
    }
    let t = e2.dot(q) * inv_det;
    (t >= ray.t_min && t <= t_max).then_some(TriangleHit { t, u, v })
}
