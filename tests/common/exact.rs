//! Exact references for the intersection tests: the `t` of a ray against a
//! triangle's plane or a sphere, computed in `f64` from the same `f32`
//! inputs, and bounds on the rounding error of the `f32` routines.
//!
//! Each bound is derived in a comment from the operations it covers, with
//! `u = 2^-24` the unit roundoff and `gamma(n) = n u / (1 - n u)`.

use glam::{DVec3, Vec3};
use pathtracer::intersect::Ray;
use pathtracer::math::float::gamma;

use super::geometry::plane_normal;

/// `gamma(n)` in double precision.
pub fn g(n: i32) -> f64 {
    f64::from(gamma(n))
}

/// The exact `t` at which the `f32` ray meets the plane of the `f32`
/// triangle, in double precision.
pub fn plane_t(tri: &[Vec3; 3], ray: &Ray) -> f64 {
    let n = plane_normal(tri);
    (tri[0].as_dvec3() - ray.origin.as_dvec3()).dot(n) / ray.dir.as_dvec3().dot(n)
}

/// Bound on the absolute error of the watertight test's `t` against the
/// exact plane crossing, recomputed in double precision from the sheared
/// vertices (pbrt-v4, section 6.8.4, eqs. 6.32-6.37): with `X`, `Y`, `Z` the
/// largest sheared coordinates and `E` the largest edge function, the
/// sheared x and y are off by `gamma(5) (X + Z)` and `gamma(5) (Y + Z)`,
/// z by `gamma(3) Z`, each edge function by
/// `2 (gamma(2) X Y + dy X + dx Y)`, and `t = sum e_i z_i / sum e_i` by
/// `3 (gamma(3) E Z + de Z + dz E) / |det|`; doubled here as a margin for
/// the terms of second order.
pub fn watertight_t_error(tri: &[Vec3; 3], ray: &Ray) -> f64 {
    let d = ray.dir.as_dvec3();
    let kz = if d.x.abs() > d.y.abs() && d.x.abs() > d.z.abs() {
        0
    } else if d.y.abs() > d.z.abs() {
        1
    } else {
        2
    };
    let (kx, ky) = ((kz + 1) % 3, (kz + 2) % 3);
    let sheared: Vec<DVec3> = tri
        .iter()
        .map(|p| {
            let q = p.as_dvec3() - ray.origin.as_dvec3();
            let z = q[kz] / d[kz];
            DVec3::new(q[kx] - d[kx] * z, q[ky] - d[ky] * z, z)
        })
        .collect();
    let max = |f: fn(&DVec3) -> f64| sheared.iter().map(|p| f(p).abs()).fold(0.0, f64::max);
    let (mx, my, mz) = (max(|p| p.x), max(|p| p.y), max(|p| p.z));
    let [a, b, c] = [sheared[0], sheared[1], sheared[2]];
    let e = [
        b.x * c.y - b.y * c.x,
        c.x * a.y - c.y * a.x,
        a.x * b.y - a.y * b.x,
    ];
    let det = e.iter().sum::<f64>().abs();
    let me = e.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let (dx, dy, dz) = (g(5) * (mx + mz), g(5) * (my + mz), g(3) * mz);
    let de = 2.0 * (g(2) * mx * my + dy * mx + dx * my);
    2.0 * 3.0 * (g(3) * me * mz + de * mz + dz * me) / det
}

/// Bound on the absolute error of the sphere routine's root `t` for a ray
/// with `f = o - c`, `q = -b - sign(b) sqrt(disc)` (exact values).
///
/// `f` is rounded (`u`), `b = f.d` (`gamma(3) |f|`),
/// `disc = r^2 - |f - b d|^2` and `c = f.f - r^2` each carry at most
/// `gamma(8) (|f|^2 + r^2)`, which reaches `sqrt(disc)` divided by
/// `2 sqrt(disc)`, `q` unamplified (no cancellation in `q`), and
/// `t0 = c / q` divided by `|q|`. Doubling for second-order terms and the
/// final division gives the `gamma(16)` terms below, plus `gamma(16) t`
/// for the relative error of `|d| = 1` and of the quotient.
pub fn sphere_t_tolerance(ray: &Ray, center: Vec3, radius: f32, t: f64) -> f64 {
    let f = ray.origin.as_dvec3() - center.as_dvec3();
    let d = ray.dir.as_dvec3();
    let r = f64::from(radius);
    let b = f.dot(d);
    let disc = r * r - (f - b * d).length_squared();
    let root = disc.abs().sqrt();
    let q = (-b - root.copysign(b)).abs();
    let scale = f.length_squared() + r * r;
    g(16) * (scale / q + scale / root + t.abs())
}

/// The roots of the exact quadratic for the `f32` ray, in double precision.
pub fn sphere_roots(ray: &Ray, center: Vec3, radius: f32) -> Option<(f64, f64)> {
    let f = ray.origin.as_dvec3() - center.as_dvec3();
    let d = ray.dir.as_dvec3();
    let r = f64::from(radius);
    let b = f.dot(d) / d.length_squared();
    let c = (f.length_squared() - r * r) / d.length_squared();
    let disc = b * b - c;
    (disc >= 0.0).then(|| (-b - disc.sqrt(), -b + disc.sqrt()))
}
