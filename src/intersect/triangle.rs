//! Watertight ray-triangle intersection (Woop, Benthin and Wald,
//! "Watertight Ray/Triangle Intersection", JCGT 2(1), 2013; pbrt-v4,
//! section 6.5.3).
//!
//! Translate the vertices so the ray starts at the origin, permute the axes
//! so the ray's largest direction component is z, and shear so the ray
//! becomes the +z axis: `x' = x + S_x z`, `y' = y + S_y z` with
//! `S_x = -d_x / d_z`, `S_y = -d_y / d_z`. The ray now passes through the
//! 2D origin, and the 2D edge functions of the sheared vertices
//!
//! ```text
//! e0 = x1 y2 - y1 x2,   e1 = x2 y0 - y2 x0,   e2 = x0 y1 - y0 x1
//! ```
//!
//! are (twice) the signed areas of the triangles the origin forms with
//! each edge. The ray meets the triangle when all three have the same sign
//! (zero counts as either); the barycentrics are `e_i / (e0 + e1 + e2)` and
//! `t` is the same combination of the vertices' z, scaled by `1 / d_z`.
//!
//! Why watertight: two triangles sharing an edge share its two vertices
//! bit for bit, so they compute the same sheared coordinates and the same
//! edge function with opposite sign (`fl(a - b) = -fl(b - a)`). A ray
//! through the edge therefore lies inside, or on, at least one of them,
//! whatever the rounding; a value of exactly zero is recomputed in double
//! precision so its sign is right. (An earlier Möller-Trumbore version
//! widened the barycentric tests by a fixed 1e-6; rays slipped through
//! shared vertices of small or distant triangles, found by the property
//! test `fan_spokes_are_watertight`.)
//!
//! Hits closer than the rounding error of `t` are rejected (pbrt-v4,
//! section 6.8.4): there the sign of `t` is unknown, and a ray spawned from
//! the triangle ([`crate::intersect::Hit::spawn_ray`], origin pushed off the
//! surface by the hit point's error bound) could hit its own triangle.

use glam::Vec3;

use super::Ray;
use crate::math::float::gamma;

/// A triangle stored for intersection: its three vertices, exactly as in
/// the mesh (watertightness needs shared vertices bit for bit).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleShape {
    pub p0: Vec3,
    pub p1: Vec3,
    pub p2: Vec3,
}

/// Where a ray meets a triangle: distance and the barycentrics of `p1`, `p2`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleHit {
    pub t: f32,
    pub u: f32,
    pub v: f32,
}

/// Index of the largest component of `v`.
#[inline(always)]
pub(crate) fn max_axis(v: Vec3) -> usize {
    if v.x > v.y {
        if v.x > v.z {
            0
        } else {
            2
        }
    } else if v.y > v.z {
        1
    } else {
        2
    }
}

/// `a b - c d` in `f32`; recomputed in `f64` when the `f32` result is
/// exactly zero, so a ray through an edge or vertex gets the right sign.
#[inline(always)]
pub(crate) fn edge_function(a: f32, b: f32, c: f32, d: f32) -> f32 {
    let e = a * b - c * d;
    if e == 0.0 {
        (f64::from(a) * f64::from(b) - f64::from(c) * f64::from(d)) as f32
    } else {
        e
    }
}

impl TriangleShape {
    pub fn new(p0: Vec3, p1: Vec3, p2: Vec3) -> Self {
        TriangleShape { p0, p1, p2 }
    }

    /// The watertight test; `None` for a miss, a ray in the triangle's
    /// plane, a zero-area triangle or non-finite input.
    #[inline(always)]
    pub fn intersect(&self, ray: &Ray, t_max: f32) -> Option<TriangleHit> {
        // Translate to the ray origin, permute so that z is the largest axis.
        let kz = max_axis(ray.dir.abs());
        let kx = (kz + 1) % 3;
        let ky = (kx + 1) % 3;
        let permute = |v: Vec3| Vec3::new(v[kx], v[ky], v[kz]);
        let d = permute(ray.dir);
        let mut p0 = permute(self.p0 - ray.origin);
        let mut p1 = permute(self.p1 - ray.origin);
        let mut p2 = permute(self.p2 - ray.origin);
        // Shear so the ray is the +z axis (z is scaled later, only for hits).
        let (sx, sy, sz) = (-d.x / d.z, -d.y / d.z, 1.0 / d.z);
        for p in [&mut p0, &mut p1, &mut p2] {
            p.x += sx * p.z;
            p.y += sy * p.z;
        }
        // Edge functions: all of one sign (or zero) inside.
        let e0 = edge_function(p1.x, p2.y, p1.y, p2.x);
        let e1 = edge_function(p2.x, p0.y, p2.y, p0.x);
        let e2 = edge_function(p0.x, p1.y, p0.y, p1.x);
        if (e0 < 0.0 || e1 < 0.0 || e2 < 0.0) && (e0 > 0.0 || e1 > 0.0 || e2 > 0.0) {
            return None;
        }
        let det = e0 + e1 + e2;
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        // Scaled distance, compared with the interval before dividing.
        let (z0, z1, z2) = (p0.z * sz, p1.z * sz, p2.z * sz);
        let t_scaled = e0 * z0 + e1 * z1 + e2 * z2;
        let inv_det = 1.0 / det;
        let t = t_scaled * inv_det;
        if !(t >= ray.t_min && t <= t_max) {
            return None;
        }
        // Reject t within its rounding error of zero (pbrt-v4, eq. 6.32-6.37).
        let max_z = Vec3::new(z0, z1, z2).abs().max_element();
        let max_x = Vec3::new(p0.x, p1.x, p2.x).abs().max_element();
        let max_y = Vec3::new(p0.y, p1.y, p2.y).abs().max_element();
        let delta_z = gamma(3) * max_z;
        let delta_x = gamma(5) * (max_x + max_z);
        let delta_y = gamma(5) * (max_y + max_z);
        let delta_e = 2.0 * (gamma(2) * max_x * max_y + delta_y * max_x + delta_x * max_y);
        let max_e = Vec3::new(e0, e1, e2).abs().max_element();
        let delta_t =
            3.0 * (gamma(3) * max_e * max_z + delta_e * max_z + delta_z * max_e) * inv_det.abs();
        if t <= delta_t {
            return None;
        }
        let u = (e1 * inv_det).clamp(0.0, 1.0);
        let v = (e2 * inv_det).clamp(0.0, 1.0 - u);
        Some(TriangleHit { t, u, v })
    }
}
