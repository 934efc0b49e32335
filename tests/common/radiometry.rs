//! Closed forms of radiometry for the estimator tests.

use glam::DVec3;

/// Irradiance at `x` (unit normal `n`) from a polygon of uniform radiance
/// `radiance` entirely above the horizon of `x`: Lambert's formula
///
/// ```text
/// E = L / 2 * | sum_i gamma_i n . (r_i x r_{i+1}) / |r_i x r_{i+1}| |
/// ```
///
/// with `r_i` the unit vectors from `x` to the vertices and `gamma_i` the
/// angle between `r_i` and `r_{i+1}` (Lambert 1760; see Arvo 1995,
/// "Applications of irradiance tensors to the simulation of non-Lambertian
/// phenomena", eq. 9).
pub fn polygon_irradiance(x: DVec3, n: DVec3, corners: &[DVec3], radiance: f64) -> f64 {
    let r: Vec<DVec3> = corners.iter().map(|&c| (c - x).normalize()).collect();
    let sum: f64 = (0..r.len())
        .map(|i| {
            let (a, b) = (r[i], r[(i + 1) % r.len()]);
            a.dot(b).clamp(-1.0, 1.0).acos() * n.dot(a.cross(b).normalize())
        })
        .sum();
    radiance / 2.0 * sum.abs()
}
