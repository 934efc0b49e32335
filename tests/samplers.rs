//! Statistical tests of every direction sampler against its density.
//!
//! A table of sampler families ([`families`]) goes through the same
//! checks, each a sampler must pass to be unbiased with the density it
//! reports:
//!
//! 1. the density integrates to 1 over its domain (midpoint quadrature on a
//!    fine `(cos theta, phi)` grid, where `d omega = d cos(theta) d phi`);
//! 2. the density a sample reports equals the density function at the
//!    sampled direction;
//! 3. Pearson's chi-square goodness of fit: the histogram of sampled
//!    directions on a `(cos theta, phi)` grid in the family's frame against
//!    the expected counts `N * integral of pdf over the cell` (quadrature on
//!    a sub-grid), cells with expected count under 5 pooled. The expected
//!    counts are *not* renormalised, so a density off by a constant factor
//!    fails too.
//!
//! Lossy families (the microfacet conductor, which discards a direction
//! reflected below the surface) have a sub-density: its integral over the
//! sphere is the probability that a draw is kept, not 1. For them check 1
//! compares the integral over the whole sphere with the fraction of draws
//! kept (a z-test), and check 3 adds one cell for everything off the grid,
//! discarded draws included, whose expected count is `N` minus the grid's
//! (so lost draws are counted against the density too). Their grid is a
//! cap around the mirror direction whose radius scales with the roughness
//! (`4 alpha`), so that even the narrow lobe of `alpha = 0.01` spreads
//! over all its rings (about 2 % of the draws of a narrow lobe fall
//! outside the cap, in the extra cell).
//!
//! Seeds are fixed. The whole table is one test of significance
//! [`ALPHA`] = 1e-4, split evenly among the families (Bonferroni), so a
//! correct sampler fails it less than once in 10^4 seeds.
//! [`the_checks_reject_wrong_densities`] shows each check can fail: a pdf
//! off by a factor 1.1, the course's area-light pdf with `r` instead of
//! `r^2`, a cosine sampler checked against the uniform pdf. Checked once
//! by hand on the library too: a hemisphere warp with `z = sqrt(u1)` and an
//! area-light sample shifted by 5 % of a side both fail the chi-square test
//! (p = 0).

//!
//! The table of families is in `samplers/families.rs` (the distributions'
//! and environment maps' in `samplers/environment_families.rs`), the grid and its
//! quadrature in `samplers/quadrature.rs`.

mod common;
#[path = "samplers/environment_families.rs"]
mod environment_families;
#[path = "samplers/families.rs"]
mod families;
#[path = "samplers/quadrature.rs"]
mod quadrature;

use std::f64::consts::PI;

use common::{chi_square, rect_light, ALPHA};
use families::{families, Family};
use glam::Vec3;
use pathtracer::lights::{Light as SampledLight, LightConvention};
use pathtracer::math::rng::{next_2d, sampler};
use pathtracer::math::warp::uniform_hemisphere_pdf;
use pathtracer::scene::Light;
use quadrature::{integrate, integrate_angle, integrate_radial, radial, radial_range};

/// [`integrate_radial`] of a lossy family over one cell of the histogram:
/// on `SUB` squared points, or on `4 SUB` squared for a cell the horizon
/// crosses (where the density drops to 0, some points are 0 and some are
/// not): the midpoint rule's error there, proportional to the point
/// spacing, would otherwise show in the chi-square statistic of a
/// grazing lobe cut by the horizon.
fn integrate_cell(family: &Family, r: (f64, f64), p: (f64, f64)) -> f64 {
    if !family.lossy {
        return integrate(family, r, p, SUB, SUB);
    }
    let (value, zeros) = integrate_angle(family, r, p, SUB, SUB);
    if zeros > 0 && zeros < SUB * SUB {
        integrate_angle(family, r, p, 4 * SUB, 4 * SUB).0
    } else {
        value
    }
}

/// Histogram grid: cells in `cos theta` and in `phi`, sub-grid points per
/// cell side for the expected counts, and samples per family.
const COS_CELLS: usize = 16;
const PHI_CELLS: usize = 32;
const SUB: usize = 32;
const SAMPLES: u64 = 400_000;

/// The chi-square test of `family` with `SAMPLES` draws from stream
/// `stream`: the p-value, plus draws the sampler refused and draws off the
/// grid (both must be 0), unless the family is lossy: those draws then
/// fill one more cell.
fn goodness_of_fit(family: &Family, stream: u64) -> (common::ChiSquare, u64) {
    let (c0, c1) = radial_range(family);
    let dc = (c1 - c0) / COS_CELLS as f64;
    let dp = 2.0 * PI / PHI_CELLS as f64;
    let mut observed = vec![0u64; COS_CELLS * PHI_CELLS];
    let mut refused = 0;
    let mut off_grid = 0;
    let mut rng = sampler(0x5A3D_1E55, stream);
    for _ in 0..SAMPLES {
        let Some((w, _)) = (family.sample)(next_2d(&mut rng)) else {
            refused += 1;
            continue;
        };
        let (c, p) = radial(family, w);
        if c < c0 || c > c1 {
            off_grid += 1;
            continue;
        }
        let i = (((c - c0) / dc) as usize).min(COS_CELLS - 1);
        let j = ((p / dp) as usize).min(PHI_CELLS - 1);
        observed[i * PHI_CELLS + j] += 1;
    }
    let mut expected = Vec::with_capacity(observed.len());
    for i in 0..COS_CELLS {
        let ci = c0 + i as f64 * dc;
        for j in 0..PHI_CELLS {
            let pj = j as f64 * dp;
            let cell = integrate_cell(family, (ci, ci + dc), (pj, pj + dp));
            expected.push(SAMPLES as f64 * cell);
        }
    }
    if !family.lossy {
        return (chi_square(&observed, &expected), refused + off_grid);
    }
    let on_grid: f64 = expected.iter().sum();
    observed.push(refused + off_grid);
    expected.push((SAMPLES as f64 - on_grid).max(0.0));
    (chi_square(&observed, &expected), 0)
}

/// The integral of a lossy family's density over the whole sphere: its
/// cap finely, then rings of doubling angular radius out to the south pole.
fn integrate_sphere(family: &Family) -> f64 {
    let (_, cap) = radial_range(family);
    let mut total = integrate_radial(family, (0.0, cap), (0.0, 2.0 * PI), 400, 400);
    let mut theta = cap;
    while theta < PI {
        let next = (2.0 * theta).min(PI);
        total += integrate_radial(family, (theta, next), (0.0, 2.0 * PI), 100, 400);
        theta = next;
    }
    total
}

/// The fraction of `n` draws from stream `stream` the sampler keeps, with
/// its binomial standard error.
fn kept_fraction(family: &Family, n: u64, stream: u64) -> (f64, f64) {
    let mut rng = sampler(0x0C0B_BEE5, stream);
    let kept = (0..n)
        .filter(|_| (family.sample)(next_2d(&mut rng)).is_some())
        .count() as f64
        / n as f64;
    (kept, (kept * (1.0 - kept) / n as f64).sqrt())
}

/// The lossy family's density integrates to its kept fraction: `Ok` with
/// both, or `Err` with a message.
fn check_lossy_mass(family: &Family, stream: u64, alpha: f64) -> Result<(f64, f64), String> {
    let total = integrate_sphere(family);
    let (kept, se) = kept_fraction(family, 100_000, stream);
    // Quadrature error of the midpoint rule across the horizon's cut: 2e-3.
    let limit = common::z_two_sided(alpha) * se + 2e-3;
    if (total - kept).abs() <= limit {
        Ok((total, kept))
    } else {
        Err(format!(
            "{}: the pdf integrates to {total} over the sphere, but {kept} of the draws are kept              (limit {limit:.2e})",
            family.name
        ))
    }
}

#[test]
fn every_density_integrates_to_one() {
    let families = families();
    let lossy = families.iter().filter(|f| f.lossy).count();
    for (stream, family) in families.iter().enumerate() {
        if family.lossy {
            let (total, kept) = check_lossy_mass(family, stream as u64, ALPHA / lossy as f64)
                .unwrap_or_else(|e| panic!("{e}"));
            eprintln!("{}: integral {total:.5}, kept {kept:.5}", family.name);
            continue;
        }
        // Where the density lives, finely; below cos_min, coarsely (it must be 0).
        let inside = integrate(family, (family.cos_min, 1.0), (0.0, 2.0 * PI), 1500, 1500);
        let outside = if family.cos_min > -1.0 {
            integrate(family, (-1.0, family.cos_min), (0.0, 2.0 * PI), 200, 400)
        } else {
            0.0
        };
        // Quadrature error: ~1e-6 for smooth densities, ~1e-3 along the
        // edge of an area light; a factor 1.1 is far outside.
        assert!(
            (inside - 1.0).abs() < 3e-3 && outside == 0.0,
            "{}: the pdf integrates to {inside} where it lives and {outside} elsewhere",
            family.name
        );
    }
}

#[test]
fn sampled_densities_equal_the_density_function() {
    for family in families() {
        let mut rng = sampler(17, 0);
        for _ in 0..10_000 {
            let Some((w, reported)) = (family.sample)(next_2d(&mut rng)) else {
                continue;
            };
            let evaluated = (family.pdf)(w);
            assert!(
                (reported - evaluated).abs() <= 1e-3 * evaluated.max(reported),
                "{}: sample reports pdf {reported} at {w}, pdf() says {evaluated}",
                family.name
            );
        }
    }
}

#[test]
fn every_sampler_matches_its_density_chi_square() {
    let families = families();
    let alpha = ALPHA / families.len() as f64;
    for (stream, family) in families.iter().enumerate() {
        let (test, lost) = goodness_of_fit(family, stream as u64);
        eprintln!(
            "{}: chi-square {:.1}, {} dof, p = {:.3e}",
            family.name, test.statistic, test.degrees_of_freedom, test.p_value
        );
        assert!(
            lost == 0 && test.p_value > alpha,
            "{}: chi-square {:.1} with {} degrees of freedom, p = {:.3e} (alpha {alpha:.1e}); \
             {lost} samples refused or off the grid",
            family.name,
            test.statistic,
            test.degrees_of_freedom,
            test.p_value,
        );
    }
}

/// The checks above have power: deliberately wrong densities fail them.
#[test]
fn the_checks_reject_wrong_densities() {
    let mut wrong = Vec::new();
    // Of the conductor families, those of alpha 0.1 (both strategies, every
    // angle) stand for the rest, to keep the run short.
    let sample_of_families = families()
        .into_iter()
        .filter(|f| !f.lossy || f.name.contains("alpha 0.1,"));
    for family in sample_of_families {
        let Family {
            name,
            sample,
            pdf,
            frame,
            cos_min,
            lossy,
        } = family;
        if name.starts_with("area light, far") {
            // The course's quirk: r / (A cos) instead of r^2 / (A cos).
            let light = rect_light(
                1.0,
                Vec3::new(0.7, 2.0, -0.4),
                Vec3::new(-0.5, -1.0, 0.6),
                0.6,
                0.8,
            );
            let p = Vec3::new(0.1, 0.0, 0.2);
            wrong.push(Family {
                name: "area light with the pdf's r^2 replaced by r".into(),
                sample,
                pdf: Box::new(move |w| {
                    let sampled = SampledLight::from_scene(&light, LightConvention::Physical);
                    let t = sampled.pdf_li(p, w, None) as f64;
                    // pdf = r^2 / (A cos): divide by r once.
                    let r = match light {
                        Light::Area {
                            center, direction, ..
                        } => (direction.dot(center - p) / direction.dot(w)) as f64,
                        _ => 1.0,
                    };
                    if t > 0.0 {
                        t / r
                    } else {
                        0.0
                    }
                }),
                frame,
                cos_min,
                lossy,
            });
        } else if name == "cosine hemisphere" {
            wrong.push(Family {
                name: "cosine samples against the uniform pdf".into(),
                sample,
                pdf: Box::new(|w| uniform_hemisphere_pdf(w) as f64),
                frame,
                cos_min,
                lossy,
            });
        } else {
            wrong.push(Family {
                name: format!("{name} with its pdf times 1.1"),
                sample,
                pdf: Box::new(move |w| 1.1 * pdf(w)),
                frame,
                cos_min,
                lossy,
            });
        }
    }
    let alpha = ALPHA / wrong.len() as f64;
    for (stream, family) in wrong.iter().enumerate() {
        let (test, _) = goodness_of_fit(family, 100 + stream as u64);
        eprintln!("{}: p = {:.3e}", family.name, test.p_value);
        assert!(
            test.p_value < alpha,
            "{}: the chi-square test should reject it, p = {:.3e}",
            family.name,
            test.p_value
        );
        if family.lossy {
            assert!(
                check_lossy_mass(family, 100 + stream as u64, alpha).is_err(),
                "{}: the mass check should reject it",
                family.name
            );
            continue;
        }
        let total = integrate(family, (family.cos_min, 1.0), (0.0, 2.0 * PI), 600, 600);
        if !family.name.starts_with("cosine samples") {
            assert!(
                (total - 1.0).abs() > 3e-2,
                "{}: integrates to {total}",
                family.name
            );
        }
    }
}
