//! The chi-square test of sampled directions against a density, after
//! Nori's `warptest` (Jakob, Nori educational renderer, 2012-): the upper
//! hemisphere cut into cells of equal width in `cos(theta)` and in `phi`,
//! each cell's expected count `N` times the density integrated over it,
//! cells expected below 5 pooled into one, and Pearson's statistic
//! `sum (observed - expected)^2 / expected` held to the chi-square
//! quantile of `cells - 1` degrees of freedom at `1 - alpha`.
//!
//! The densities here integrate in closed form over a cell
//! `[u0, u1] x [phi0, phi1]` (with `u = cos(theta)`, `d omega = du dphi`):
//! a constant `c` gives `c (u1 - u0)(phi1 - phi0)`, and `k cos(theta)`
//! gives `k (u1^2 - u0^2) / 2 (phi1 - phi0)`.

use std::f64::consts::PI;

use glam::DVec3;

use crate::check::stats::chi_square_quantile;

/// Cells in `cos(theta)` and in `phi`.
pub const COS_CELLS: usize = 10;
pub const PHI_CELLS: usize = 20;

/// Observed and expected counts per cell, `cos(theta)` cells outer.
#[derive(Debug, Clone)]
pub struct Histogram {
    pub observed: Vec<f64>,
    pub expected: Vec<f64>,
}

/// The cell of a direction of the upper hemisphere.
fn cell(d: DVec3) -> usize {
    let u = ((d.z.clamp(0.0, 1.0) * COS_CELLS as f64) as usize).min(COS_CELLS - 1);
    let phi = d.y.atan2(d.x).rem_euclid(2.0 * PI);
    let p = ((phi / (2.0 * PI) * PHI_CELLS as f64) as usize).min(PHI_CELLS - 1);
    u * PHI_CELLS + p
}

/// The histogram of `dirs` (all in the upper hemisphere) against the
/// density whose integral over a cell is `mass(u0, u1, dphi)`.
pub fn histogram(dirs: &[DVec3], mass: impl Fn(f64, f64, f64) -> f64) -> Histogram {
    let mut observed = vec![0.0; COS_CELLS * PHI_CELLS];
    for d in dirs {
        observed[cell(*d)] += 1.0;
    }
    let dphi = 2.0 * PI / PHI_CELLS as f64;
    let n = dirs.len() as f64;
    let expected = (0..COS_CELLS * PHI_CELLS)
        .map(|k| {
            let u0 = (k / PHI_CELLS) as f64 / COS_CELLS as f64;
            n * mass(u0, u0 + 1.0 / COS_CELLS as f64, dphi)
        })
        .collect();
    Histogram { observed, expected }
}

/// A constant density `c`'s integral over a cell.
pub fn constant(c: f64) -> impl Fn(f64, f64, f64) -> f64 {
    move |u0, u1, dphi| c * (u1 - u0) * dphi
}

/// The density `k cos(theta)`'s integral over a cell.
pub fn cosine(k: f64) -> impl Fn(f64, f64, f64) -> f64 {
    move |u0, u1, dphi| k * (u1 * u1 - u0 * u0) / 2.0 * dphi
}

/// Pearson's statistic with cells expected below 5 pooled, its degrees
/// of freedom, and whether it stays under the quantile at `1 - alpha`.
pub fn chi_square(h: &Histogram, alpha: f64) -> (f64, usize, bool) {
    let (mut pooled_o, mut pooled_e) = (0.0, 0.0);
    let (mut stat, mut cells) = (0.0, 0usize);
    for (o, e) in h.observed.iter().zip(&h.expected) {
        if *e < 5.0 {
            pooled_o += o;
            pooled_e += e;
        } else {
            stat += (o - e) * (o - e) / e;
            cells += 1;
        }
    }
    if pooled_e > 0.0 {
        stat += (pooled_o - pooled_e) * (pooled_o - pooled_e) / pooled_e.max(1e-12);
        cells += 1;
    }
    let dof = cells.saturating_sub(1).max(1);
    (stat, dof, stat <= chi_square_quantile(dof as f64, alpha))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_pcg::Pcg64;

    /// Cosine-weighted directions (Malley's method) pass against the
    /// cosine density and fail against the uniform one; the masses of
    /// both densities sum to 1 over the hemisphere.
    #[test]
    fn the_test_tells_cosine_from_uniform() {
        let mut rng = Pcg64::seed_from_u64(1);
        let dirs: Vec<DVec3> = (0..20_000)
            .map(|_| {
                let (r, phi) = (rng.gen::<f64>().sqrt(), 2.0 * PI * rng.gen::<f64>());
                DVec3::new(r * phi.cos(), r * phi.sin(), (1.0 - r * r).sqrt())
            })
            .collect();
        let cos = histogram(&dirs, cosine(1.0 / PI));
        let total: f64 = cos.expected.iter().sum();
        assert!((total - 20_000.0).abs() < 1e-6);
        assert!(chi_square(&cos, 1e-5).2);
        let uniform = histogram(&dirs, constant(1.0 / (2.0 * PI)));
        assert!((uniform.expected.iter().sum::<f64>() - 20_000.0).abs() < 1e-6);
        assert!(!chi_square(&uniform, 1e-5).2);
    }
}
