//! Ray-sphere intersection, solved without catastrophic cancellation.
//!
//! With `f = o - c` and unit `d`, `|o + t d - c|^2 = r^2` is
//! `t^2 + 2 (f.d) t + (f.f - r^2) = 0`. The usual discriminant
//! `(f.d)^2 - (f.f - r^2)` cancels badly when the sphere is small and far
//! away; the same quantity is `r^2 - |f - (f.d) d|^2`, which does not
//! (Haines et al., "Precision Improvements for Ray/Sphere Intersection",
//! Ray Tracing Gems, 2019, eq. 7.5). The roots are then
//! `q = -(f.d) - sign(f.d) sqrt(disc)` and `c / q` with `c = f.f - r^2`,
//! again without subtracting nearly equal numbers (Press et al.,
//! Numerical Recipes, section 5.6).

use glam::Vec3;

use super::Ray;

/// A sphere stored for intersection.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SphereShape {
    pub center: Vec3,
    pub radius: f32,
}

impl SphereShape {
    /// The nearest root in `[ray.t_min, t_max]`; a ray starting inside the
    /// sphere finds the far root.
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_max: f32) -> Option<f32> {
        let f = ray.origin - self.center;
        let b = f.dot(ray.dir);
        let r2 = self.radius * self.radius;
        let perp = f - b * ray.dir;
        let disc = r2 - perp.length_squared();
        // Also rejects a NaN discriminant (a ray with NaN components).
        if disc.is_nan() || disc < 0.0 {
            return None;
        }
        let c = f.length_squared() - r2;
        let q = -b - disc.sqrt().copysign(b);
        let (mut t0, mut t1) = if q == 0.0 { (0.0, 0.0) } else { (c / q, q) };
        if t0 > t1 {
            std::mem::swap(&mut t0, &mut t1);
        }
        // Only finite roots: with huge coordinates a root can overflow to
        // +-inf, which an interval with an infinite end would accept, and
        // the hit point o + t d would then be NaN.
        [t0, t1]
            .into_iter()
            .find(|t| t.is_finite() && *t >= ray.t_min && *t <= t_max)
    }
}

/// The surface point of the sphere nearest `p`: `c + r (p - c) / |p - c|`.
/// Re-projecting a computed hit point this way bounds its error by
/// `gamma(5) |p - c|` (pbrt-v4, section 6.8.5).
pub fn reproject(center: Vec3, radius: f32, p: Vec3) -> Vec3 {
    let local = p - center;
    let len = local.length();
    if len > 0.0 {
        center + local * (radius / len)
    } else {
        p
    }
}
