//! Warps from the unit square to directions, each with its pdf (per steradian).
//!
//! - Uniform sphere: `z = 1 - 2 u1`, `phi = 2 pi u2`, pdf `1 / (4 pi)`.
//! - Uniform hemisphere (around +Z): `z = u1`, `phi = 2 pi u2`, pdf `1 / (2 pi)`.
//!
//! Both follow from inverting the CDF of `z`, which is uniform on the
//! sphere by Archimedes' hat-box theorem (pbrt-v4, section A.5).

use glam::{Vec2, Vec3};
use std::f32::consts::PI;

fn from_z_phi(z: f32, phi: f32) -> Vec3 {
    let r = (1.0 - z * z).max(0.0).sqrt();
    Vec3::new(r * phi.cos(), r * phi.sin(), z)
}

/// A direction uniform on the unit sphere, from `u` in `[0, 1)^2`.
pub fn sample_uniform_sphere(u: Vec2) -> Vec3 {
    from_z_phi(1.0 - 2.0 * u.x, 2.0 * PI * u.y)
}

/// Density of [`sample_uniform_sphere`]: `1 / (4 pi)` per steradian.
pub fn uniform_sphere_pdf() -> f32 {
    1.0 / (4.0 * PI)
}

/// A direction uniform on the hemisphere `z >= 0`, from `u` in `[0, 1)^2`.
pub fn sample_uniform_hemisphere(u: Vec2) -> Vec3 {
    from_z_phi(u.x, 2.0 * PI * u.y)
}

/// Density of [`sample_uniform_hemisphere`]: `1 / (2 pi)` per steradian for `w.z >= 0`.
pub fn uniform_hemisphere_pdf(w: Vec3) -> f32 {
    if w.z >= 0.0 {
        1.0 / (2.0 * PI)
    } else {
        0.0
    }
}
