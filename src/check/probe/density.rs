//! [`warp`]'s chi-square test for a density known only
//! pointwise, over the whole sphere of directions: the upper hemisphere
//! cut into warp's cells (equal widths in `cos(theta)` and in `phi`),
//! each cell's probability integrated numerically by the midpoint rule on
//! [`SUB`] x [`SUB`] sub-cells of equal `cos(theta)` and `phi`
//! (`d omega = d cos(theta) d phi`), plus one cell for every direction
//! below the surface, whose probability is the rest, `1 - sum` of the
//! others (a sampler may send some directions below the surface, as the
//! microfacet's half-vector sampler does).

use std::f64::consts::PI;

use glam::DVec3;

use super::warp::{self, Histogram, COS_CELLS, PHI_CELLS};

/// Sub-cells per cell along `cos(theta)` and along `phi`.
pub const SUB: usize = 8;

/// The direction of `cos(theta) = u` and azimuth `phi`.
fn direction(u: f64, phi: f64) -> DVec3 {
    let s = (1.0 - u * u).max(0.0).sqrt();
    DVec3::new(s * phi.cos(), s * phi.sin(), u)
}

/// The probability of each of warp's cells under `pdf` (per steradian),
/// `cos(theta)` cells outer, then that of the rest of the sphere.
pub fn cell_masses(pdf: impl Fn(DVec3) -> f64) -> Vec<f64> {
    let (du, dphi) = (1.0 / COS_CELLS as f64, 2.0 * PI / PHI_CELLS as f64);
    let (su, sphi) = (du / SUB as f64, dphi / SUB as f64);
    let mut masses: Vec<f64> = (0..COS_CELLS * PHI_CELLS)
        .map(|k| {
            let (u0, phi0) = ((k / PHI_CELLS) as f64 * du, (k % PHI_CELLS) as f64 * dphi);
            let mut sum = 0.0;
            for a in 0..SUB {
                for b in 0..SUB {
                    let u = u0 + (a as f64 + 0.5) * su;
                    let phi = phi0 + (b as f64 + 0.5) * sphi;
                    sum += pdf(direction(u, phi));
                }
            }
            sum * su * sphi
        })
        .collect();
    let upper: f64 = masses.iter().sum();
    masses.push((1.0 - upper).max(0.0));
    masses
}

/// The histogram of `dirs` against `masses` ([`cell_masses`]): warp's
/// cells for the directions with `z > 0`, the last cell for the others.
pub fn histogram(dirs: &[DVec3], masses: &[f64]) -> Histogram {
    let upper: Vec<DVec3> = dirs.iter().copied().filter(|d| d.z > 0.0).collect();
    let mut observed = warp::histogram(&upper, |_, _, _| 0.0).observed;
    observed.push((dirs.len() - upper.len()) as f64);
    let n = dirs.len() as f64;
    Histogram {
        observed,
        expected: masses.iter().map(|m| n * m).collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_pcg::Pcg64;

    /// The numerical masses of the cosine density match warp's closed
    /// form, and leave nothing below; uniform directions over the sphere
    /// pass against the uniform density (half of them below) and fail
    /// against the cosine one.
    #[test]
    fn numerical_masses_match_the_closed_forms() {
        let cos = cell_masses(|d| d.z.max(0.0) / PI);
        let closed = warp::histogram(&[DVec3::Z], warp::cosine(1.0 / PI)).expected;
        for (a, b) in cos.iter().zip(&closed) {
            assert!((a - b).abs() < 1e-6, "{a} {b}");
        }
        assert!(cos[COS_CELLS * PHI_CELLS].abs() < 1e-9);
        let mut rng = Pcg64::seed_from_u64(7);
        let dirs: Vec<DVec3> = (0..20_000)
            .map(|_| {
                let (u, phi): (f64, f64) = (rng.gen_range(-1.0..1.0), rng.gen_range(0.0..2.0 * PI));
                direction(u, phi)
            })
            .collect();
        let uniform = cell_masses(|_| 1.0 / (4.0 * PI));
        assert!((uniform[COS_CELLS * PHI_CELLS] - 0.5).abs() < 1e-9);
        assert!(warp::chi_square(&histogram(&dirs, &uniform), 1e-5).2);
        assert!(!warp::chi_square(&histogram(&dirs, &cos), 1e-5).2);
    }
}
