//! Statistical tests of every direction sampler against its density.
//!
//! A table of sampler families ([`families`]) goes through the same
//! checks (design.md, "Testing"):
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
//! Seeds are fixed. The whole table is one test of significance
//! [`ALPHA`] = 1e-4, split evenly among the families (Bonferroni), so a
//! correct sampler fails it less than once in 10^4 seeds.
//! [`the_checks_reject_wrong_densities`] shows each check can fail: a pdf
//! off by a factor 1.1, the course's area-light pdf with `r` instead of
//! `r^2`, a cosine sampler checked against the uniform pdf. Checked once
//! by hand on the library too: a hemisphere warp with `z = sqrt(u1)` and an
//! area-light sample shifted by 5 % of a side both fail the chi-square test
//! (p = 0).

mod common;

use std::f64::consts::PI;

use common::{chi_square, rect_corners, rect_light, ALPHA};
use glam::{Vec2, Vec3};
use pathtracer::lights::{Light as SampledLight, LightConvention, LightPdf};
use pathtracer::materials::Diffuse;
use pathtracer::math::rng::{next_2d, sampler};
use pathtracer::math::warp::{
    cosine_hemisphere_pdf, sample_cosine_hemisphere, sample_uniform_hemisphere,
    sample_uniform_sphere, uniform_hemisphere_pdf, uniform_sphere_pdf,
};
use pathtracer::math::Frame;
use pathtracer::scene::Light;

/// A sampler of unit directions with its density per steradian.
struct Family {
    name: String,
    /// A direction (world space) and the density the sampler reports for
    /// it, or `None` when the sampler gives nothing.
    sample: Box<dyn Fn(Vec2) -> Option<(Vec3, f64)>>,
    /// The density function, per steradian.
    pdf: Box<dyn Fn(Vec3) -> f64>,
    /// Frame of the histogram grid (its +Z is the grid's pole).
    frame: Frame,
    /// The density vanishes for `cos theta < cos_min` in that frame, so the
    /// grid covers `[cos_min, 1] x [0, 2 pi)`.
    cos_min: f64,
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
fn integrate(
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

/// The family of `Light::sample_li` / `Light::pdf_li` for `light` seen from `p`.
/// The grid's pole points at the light's centre (area light) or up (sky),
/// and `cos_min` bounds the light's extent (for a rectangle the largest
/// angle from the pole is at a corner, as the region within a cone is
/// convex on the light's plane).
fn light_family(name: &str, light: Light, p: Vec3) -> Family {
    let sampled = SampledLight::from_scene(&light, LightConvention::Physical);
    let queried = sampled.clone();
    let (frame, cos_min) = match light {
        Light::Area { center, .. } => {
            let axis = (center - p).normalize();
            let cos_min = rect_corners(&light)
                .iter()
                .map(|&q| (q - p).normalize().dot(axis) as f64)
                .fold(1.0, f64::min);
            (Frame::from_z(axis), (cos_min - 1e-3).max(-1.0))
        }
        _ => (Frame::from_z(Vec3::Y), 0.0),
    };
    Family {
        name: name.into(),
        sample: Box::new(move |u| {
            let s = sampled.sample_li(p, 0.5, u)?;
            match s.pdf {
                LightPdf::SolidAngle(pdf) => Some((s.wi, pdf as f64)),
                LightPdf::Delta => None,
            }
        }),
        pdf: Box::new(move |w| queried.pdf_li(p, w, None) as f64),
        frame,
        cos_min,
    }
}

/// A warp of the unit square to directions around +Z with its density,
/// which vanishes below `cos_min`.
fn warp_family(name: &str, sample: fn(Vec2) -> Vec3, pdf: fn(Vec3) -> f32, cos_min: f64) -> Family {
    Family {
        name: name.into(),
        sample: Box::new(move |u| {
            let w = sample(u);
            Some((w, pdf(w) as f64))
        }),
        pdf: Box::new(move |w| pdf(w) as f64),
        frame: Frame::from_z(Vec3::Z),
        cos_min,
    }
}

/// Every direction sampler of the library.
fn families() -> Vec<Family> {
    let diffuse = Diffuse {
        albedo: Vec3::splat(0.7),
    };
    let wo = Vec3::new(0.3, -0.2, 0.9).normalize();
    vec![
        warp_family(
            "uniform hemisphere",
            sample_uniform_hemisphere,
            uniform_hemisphere_pdf,
            0.0,
        ),
        warp_family(
            "cosine hemisphere",
            sample_cosine_hemisphere,
            cosine_hemisphere_pdf,
            0.0,
        ),
        warp_family(
            "uniform sphere",
            sample_uniform_sphere,
            |_| uniform_sphere_pdf(),
            -1.0,
        ),
        Family {
            name: "diffuse BSDF".into(),
            sample: Box::new(move |u| {
                let s = diffuse.sample(wo, u)?;
                Some((s.wi, s.pdf() as f64))
            }),
            pdf: Box::new(move |w| diffuse.pdf(wo, w) as f64),
            frame: Frame::from_z(Vec3::Z),
            cos_min: 0.0,
        },
        light_family(
            "area light, far and oblique",
            rect_light(
                1.0,
                Vec3::new(0.7, 2.0, -0.4),
                Vec3::new(-0.5, -1.0, 0.6),
                0.6,
                0.8,
            ),
            Vec3::new(0.1, 0.0, 0.2),
        ),
        light_family(
            "area light, near and large",
            rect_light(1.0, Vec3::new(0.2, 0.4, 0.1), -Vec3::Y, 1.5, 1.0),
            Vec3::ZERO,
        ),
        light_family(
            "ambient sky",
            Light::Ambient {
                radiance: Vec3::ONE,
            },
            Vec3::new(3.0, -1.0, 2.0),
        ),
    ]
}

/// Histogram grid: cells in `cos theta` and in `phi`, sub-grid points per
/// cell side for the expected counts, and samples per family.
const COS_CELLS: usize = 16;
const PHI_CELLS: usize = 32;
const SUB: usize = 32;
const SAMPLES: u64 = 400_000;

/// The chi-square test of `family` with `SAMPLES` draws from stream
/// `stream`: the p-value, plus draws the sampler refused and draws off the
/// grid (both must be 0).
fn goodness_of_fit(family: &Family, stream: u64) -> (common::ChiSquare, u64) {
    let c0 = family.cos_min;
    let dc = (1.0 - c0) / COS_CELLS as f64;
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
        let (c, p) = polar(&family.frame, w);
        if c < c0 {
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
            expected
                .push(SAMPLES as f64 * integrate(family, (ci, ci + dc), (pj, pj + dp), SUB, SUB));
        }
    }
    (chi_square(&observed, &expected), refused + off_grid)
}

#[test]
fn every_density_integrates_to_one() {
    for family in families() {
        // Where the density lives, finely; below cos_min, coarsely (it must be 0).
        let inside = integrate(&family, (family.cos_min, 1.0), (0.0, 2.0 * PI), 1500, 1500);
        let outside = if family.cos_min > -1.0 {
            integrate(&family, (-1.0, family.cos_min), (0.0, 2.0 * PI), 200, 400)
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
    for family in families() {
        let Family {
            name,
            sample,
            pdf,
            frame,
            cos_min,
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
            });
        } else if name == "cosine hemisphere" {
            wrong.push(Family {
                name: "cosine samples against the uniform pdf".into(),
                sample,
                pdf: Box::new(|w| uniform_hemisphere_pdf(w) as f64),
                frame,
                cos_min,
            });
        } else {
            wrong.push(Family {
                name: format!("{name} with its pdf times 1.1"),
                sample,
                pdf: Box::new(move |w| 1.1 * pdf(w)),
                frame,
                cos_min,
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
