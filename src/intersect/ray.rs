//! Rays: `r(t) = o + t d` over the interval `[t_min, t_max]`.

use glam::Vec3;

/// A ray with a unit-length direction and a parametric interval.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// Origin, world space.
    pub origin: Vec3,
    /// Direction, unit length (callers normalise; intersection routines
    /// rely on it only for spheres and report `t` in scene units).
    pub dir: Vec3,
    /// Start of the valid interval, scene units.
    pub t_min: f32,
    /// End of the valid interval, scene units (may be infinite).
    pub t_max: f32,
}

impl Ray {
    /// A ray over `[0, inf)`. `dir` must be unit length.
    pub fn new(origin: Vec3, dir: Vec3) -> Self {
        Ray {
            origin,
            dir,
            t_min: 0.0,
            t_max: f32::INFINITY,
        }
    }

    /// The point `o + t d`.
    pub fn at(&self, t: f32) -> Vec3 {
        self.origin + t * self.dir
    }
}
