//! The grid of the histograms in a family's frame (`cos theta` or, for a
//! lossy family, `theta`, against `phi`) and midpoint-rule integrals of a
//! family's density over it.

use std::f64::consts::PI;

use glam::Vec3;
use pathtracer::math::Frame;

use crate::families::Family;

/// The radial grid coordinate of `w` and its `phi`: `cos theta` (rings of
/// equal solid angle), or for a lossy family `theta` itself, computed from
/// the local `x, y` so that it stays accurate near the pole. Rings uniform
/// in `theta` resolve a narrow lobe near its centre: the lobe of a grazing,
/// smooth conductor is a thin streak through the mirror direction, which
/// the innermost rings of equal solid angle (uniform in `theta^2`) blur.
pub fn radial(family: &Family, w: Vec3) -> (f64, f64) {
    if !family.lossy {
        return polar(&family.frame, w);
    }
    let l = family.frame.to_local(w).as_dvec3();
    let phi = l.y.atan2(l.x).rem_euclid(2.0 * PI);
    (l.x.hypot(l.y).atan2(l.z), phi)
}

/// The range of the radial grid coordinate, `[cos_min, 1]` or
/// `[0, acos(cos_min)]`.
pub fn radial_range(family: &Family) -> (f64, f64) {
    if family.lossy {
        (0.0, family.cos_min.clamp(-1.0, 1.0).acos())
    } else {
        (family.cos_min, 1.0)
    }
}

/// Midpoint-rule integral of `family.pdf` over `[r0, r1] x [p0, p1]` in
/// the family's radial coordinate and `phi`, `n x m` points.
pub fn integrate_radial(family: &Family, r: (f64, f64), p: (f64, f64), n: usize, m: usize) -> f64 {
    if !family.lossy {
        return integrate(family, r, p, n, m);
    }
    integrate_angle(family, r, p, n, m).0
}

/// Midpoint-rule integral over `[t0, t1] x [p0, p1]` in `(theta, phi)`,
/// and the number of points where the density is 0.
pub fn integrate_angle(
    family: &Family,
    r: (f64, f64),
    p: (f64, f64),
    n: usize,
    m: usize,
) -> (f64, usize) {
    // d omega = sin(theta) d theta d phi.
    let ((t0, t1), (p0, p1)) = (r, p);
    let (dt, dp) = ((t1 - t0) / n as f64, (p1 - p0) / m as f64);
    let mut sum = 0.0;
    let mut zeros = 0;
    for i in 0..n {
        let t = t0 + (i as f64 + 0.5) * dt;
        let (st, ct) = t.sin_cos();
        for j in 0..m {
            let (sp, cp) = (p0 + (j as f64 + 0.5) * dp).sin_cos();
            let w = family
                .frame
                .to_world(Vec3::new((st * cp) as f32, (st * sp) as f32, ct as f32));
            let pdf = (family.pdf)(w);
            zeros += usize::from(pdf == 0.0);
            sum += pdf * st;
        }
    }
    (sum * dt * dp, zeros)
}

/// `cos theta` and `phi` in `[0, 2 pi)` of `w` in `frame`.
fn polar(frame: &Frame, w: Vec3) -> (f64, f64) {
    let l = frame.to_local(w).normalize();
    let phi = (l.y as f64).atan2(l.x as f64).rem_euclid(2.0 * PI);
    ((l.z as f64).clamp(-1.0, 1.0), phi)
}

/// The world direction of `(cos theta, phi)` in `frame`.
fn direction(frame: &Frame, cos_theta: f64, phi: f64) -> Vec3 {
    let s = (1.0 - cos_theta * cos_theta).max(0.0).sqrt();
    frame.to_world(Vec3::new(
        (s * phi.cos()) as f32,
        (s * phi.sin()) as f32,
        cos_theta as f32,
    ))
}

/// Midpoint-rule integral of `family.pdf` over `[c0, c1] x [p0, p1]` in
/// `(cos theta, phi)` with `n x m` points.
pub fn integrate(
    family: &Family,
    (c0, c1): (f64, f64),
    (p0, p1): (f64, f64),
    n: usize,
    m: usize,
) -> f64 {
    let (dc, dp) = ((c1 - c0) / n as f64, (p1 - p0) / m as f64);
    let mut sum = 0.0;
    for i in 0..n {
        let c = c0 + (i as f64 + 0.5) * dc;
        for j in 0..m {
            let p = p0 + (j as f64 + 0.5) * dp;
            sum += (family.pdf)(direction(&family.frame, c, p));
        }
    }
    sum * dc * dp
}
