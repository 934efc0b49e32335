//! Warps from the unit square to directions, each with its pdf (per steradian).
//!
//! - Uniform sphere: `z = 1 - 2 u1`, `phi = 2 pi u2`, pdf `1 / (4 pi)`.
//! - Uniform hemisphere (around +Z): `z = u1`, `phi = 2 pi u2`, pdf `1 / (2 pi)`.
//! - Cosine hemisphere (around +Z): a uniform point on the unit disk
//!   (concentric map) lifted by `z = sqrt(1 - x^2 - y^2)`, pdf `cos(theta) / pi`
//!   (Malley's method; pbrt-v4, section A.5.3).
//!
//! - Uniform cone (around +Z, half-angle `theta_max`): `1 - cos(theta) =
//!   u1 (1 - cos(theta_max))`, `phi = 2 pi u2`, pdf `1 / (2 pi (1 - cos(theta_max)))`
//!   (pbrt-v4, section A.5.4). The cone is given by `1 - cos(theta_max)`,
//!   so a narrow cone keeps its precision (`1 - cos` of a small angle
//!   cancels in `f32`).
//!
//! - Uniform triangle: barycentrics `(1 - s, s (1 - u2), s u2)` with
//!   `s = sqrt(u1)` (pbrt-v4, section 6.5.4; the square root undoes the
//!   triangle's width growing linearly away from the first corner), density
//!   `1 / A` per unit area of a triangle of area `A`.
//!
//! The first two follow from inverting the CDF of `z`, which is uniform on the
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

/// A point uniform on the unit disk by Shirley and Chiu's concentric map
/// ("A Low Distortion Map Between Disk and Square", 1997), from `u` in
/// `[0, 1)^2`; density `1 / pi` per unit area.
pub fn sample_uniform_disk_concentric(u: Vec2) -> Vec2 {
    let offset = 2.0 * u - Vec2::ONE;
    if offset == Vec2::ZERO {
        return Vec2::ZERO;
    }
    let (r, theta) = if offset.x.abs() > offset.y.abs() {
        (
            offset.x,
            std::f32::consts::FRAC_PI_4 * (offset.y / offset.x),
        )
    } else {
        (
            offset.y,
            std::f32::consts::FRAC_PI_2 - std::f32::consts::FRAC_PI_4 * (offset.x / offset.y),
        )
    };
    r * Vec2::new(theta.cos(), theta.sin())
}

/// A direction on the hemisphere `z >= 0` with density `cos(theta) / pi`,
/// by Malley's method: a uniform point on the disk lifted to the hemisphere.
pub fn sample_cosine_hemisphere(u: Vec2) -> Vec3 {
    let d = sample_uniform_disk_concentric(u);
    let z = (1.0 - d.length_squared()).max(0.0).sqrt();
    Vec3::new(d.x, d.y, z)
}

/// Density of [`sample_cosine_hemisphere`]: `cos(theta) / pi` per
/// steradian for `w.z > 0`, else 0.
pub fn cosine_hemisphere_pdf(w: Vec3) -> f32 {
    if w.z > 0.0 {
        w.z / PI
    } else {
        0.0
    }
}

/// A direction uniform in the cone around +Z of half-angle `theta_max`,
/// given as `one_minus_cos_max = 1 - cos(theta_max)` in `(0, 2]`, from
/// `u` in `[0, 1)^2`.
pub fn sample_uniform_cone(u: Vec2, one_minus_cos_max: f32) -> Vec3 {
    let one_minus_cos = u.x * one_minus_cos_max;
    // sin^2 = 1 - cos^2 = (1 - cos)(1 + cos), without cancelling.
    let sin = (one_minus_cos * (2.0 - one_minus_cos)).max(0.0).sqrt();
    let phi = 2.0 * PI * u.y;
    Vec3::new(sin * phi.cos(), sin * phi.sin(), 1.0 - one_minus_cos)
}

/// Density of [`sample_uniform_cone`] inside its cone:
/// `1 / (2 pi (1 - cos(theta_max)))` per steradian (the caller tests
/// whether a direction is inside).
pub fn uniform_cone_pdf(one_minus_cos_max: f32) -> f32 {
    1.0 / (2.0 * PI * one_minus_cos_max)
}

/// Barycentric coordinates of a point uniform on a triangle, from `u` in
/// `[0, 1)^2`: the point is `b.x p0 + b.y p1 + b.z p2`, with density
/// [`uniform_triangle_pdf`] per unit area.
pub fn sample_uniform_triangle(u: Vec2) -> Vec3 {
    let s = u.x.sqrt();
    Vec3::new(1.0 - s, s * (1.0 - u.y), s * u.y)
}

/// Density of [`sample_uniform_triangle`] per unit area on a triangle of area `area`.
pub fn uniform_triangle_pdf(area: f32) -> f32 {
    1.0 / area
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Shirley and Chiu's map is continuous: points of the square just
    /// either side of a diagonal `|x| = |y|` land next to each other on
    /// the disk, so a stratified sampler's neighbouring strata stay
    /// neighbours. Mirroring one wedge (`pi/2 + pi/4 x/y` for `pi/2 -
    /// pi/4 x/y`) keeps the density uniform, so no density test sees it,
    /// but it tears the disk along the diagonals by `sqrt(2)` times the
    /// radius: checked by hand, this test fails on it.
    #[test]
    fn the_concentric_map_is_continuous_across_its_diagonals() {
        let eps = 1e-4f32;
        let to_square = |offset: Vec2| (offset + Vec2::ONE) * 0.5;
        for k in 1..40 {
            let t = k as f32 / 40.0;
            for sign in [
                Vec2::new(1.0, 1.0),
                Vec2::new(1.0, -1.0),
                -Vec2::ONE,
                Vec2::new(-1.0, 1.0),
            ] {
                let wide = sample_uniform_disk_concentric(to_square(sign * Vec2::new(t + eps, t)));
                let tall = sample_uniform_disk_concentric(to_square(sign * Vec2::new(t, t + eps)));
                assert!(
                    (wide - tall).length() < 10.0 * eps,
                    "the map tears at {:?}: {wide} and {tall}",
                    sign * t
                );
            }
        }
    }
}
