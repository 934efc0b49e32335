//! The rough conductor's unit tests.

use super::*;

/// Gold's `eta` and `k` at red, green and blue.
const GOLD: (Rgb, Rgb) = (Rgb::new(0.143, 0.375, 1.442), Rgb::new(3.983, 2.386, 1.603));

/// The starter's model differs from the physical one by its `Lambda`
/// and by where it takes the Fresnel term: `f_starter / f_physical =
/// F(wi.z) / F(wo.h) x (1 + Lo + Li) / (1 + Lo' + Li')`, with `D` the
/// same; checked on gold at three pairs of directions.
#[test]
fn the_starters_model_swaps_lambda_and_the_fresnel_angle() {
    let (eta, k) = GOLD;
    let physical = Conductor::new(0.4, eta, k, MicrofacetSampling::HalfVector);
    let starter = physical.with_model(MicrofacetModel::Starter);
    let b = physical.distribution;
    for (wo, wi) in [
        (Vec3::new(0.3, 0.1, 0.9), Vec3::new(-0.5, 0.2, 0.8)),
        (Vec3::new(0.9, 0.0, 0.2), Vec3::new(-0.8, 0.1, 0.3)),
        (Vec3::new(0.0, 0.6, 0.7), Vec3::new(0.1, -0.7, 0.6)),
    ] {
        let (wo, wi) = (wo.normalize(), wi.normalize());
        let h = (wo + wi).normalize();
        let g = |l: f64, m: f64| 1.0 / (1.0 + l + m);
        let g_ratio = g(b.starter_lambda(wo), b.starter_lambda(wi))
            / g(f64::from(b.lambda(wo)), f64::from(b.lambda(wi)));
        let expected = fresnel::conductor(wi.z, eta, k) / fresnel::conductor(wo.dot(h), eta, k)
            * g_ratio as f32;
        let got = starter.f(wo, wi) / physical.f(wo, wi);
        assert!(
            (got - expected).abs().max_element() < 1e-4,
            "{got} vs {expected}"
        );
        // The sampler is the same: so is the density.
        assert_eq!(starter.pdf(wo, wi), physical.pdf(wo, wi));
    }
}

fn gold(sampling: MicrofacetSampling) -> Conductor {
    Conductor::new(0.3, GOLD.0, GOLD.1, sampling)
}

/// `wo` at the stretched slope `alpha tan(theta_o) = slope`, at an
/// azimuth where `x` and `y` both count (`x^2 + y^2` made `x^2 - y^2`
/// or `x^2 y^2` moves the slope far from the boundary).
fn at_slope(alpha: f32, slope: f32, azimuth: f32) -> Vec3 {
    let tan = slope / alpha;
    Vec3::new(tan * azimuth.cos(), tan * azimuth.sin(), 1.0).normalize()
}

// The rule of `Auto` (its doc, and docs/07): the half vector below the
// stretched slope AUTO_SLOPE = 0.1, the visible normals above, taken
// 2 % either side of the boundary at three roughnesses whose `alpha^2`
// is far from `2 alpha` and from 1. Fails with each arithmetic mutant of
// the comparison, `<` made `==` or `>`, the guard `!=` made `==`, or
// the strategy made `Default::default()` (which is `Auto`); the
// density, taken where the two strategies' densities differ, checks that
// `pdf` follows the strategy chosen.
// (`<` made `<=` differs only where the two products are equal in f64.)
#[test]
fn auto_draws_the_half_vector_below_the_stretched_slope_and_visible_normals_above() {
    use MicrofacetSampling::{HalfVector, VisibleNormals};
    let slope = AUTO_SLOPE as f32;
    for alpha in [0.05, 0.3, 0.8] {
        let auto = Conductor {
            distribution: Beckmann::new(alpha),
            ..gold(MicrofacetSampling::Auto)
        };
        for azimuth in [0.4_f32, 2.2] {
            for (s, expected) in [
                (0.0, HalfVector),
                (0.98 * slope, HalfVector),
                (1.02 * slope, VisibleNormals),
                (20.0 * slope, VisibleNormals),
            ] {
                let wo = at_slope(alpha, s, azimuth);
                let what = format!("alpha {alpha}, slope {s}, azimuth {azimuth}");
                assert_eq!(auto.strategy(wo), expected, "{what}");
                let with = |sampling| Conductor { sampling, ..auto };
                // `wo` reflected about a normal a slope `alpha` off the
                // pole, tilted towards `wo` (so that `wi` stays above the
                // surface): in the lobe, where `D` is far from 0 and the
                // two densities differ (but at normal incidence, where
                // they are the same function).
                let (toward, across) =
                    (Vec2::from_angle(azimuth), Vec2::from_angle(azimuth).perp());
                let tilt = alpha * (0.8 * toward + 0.5 * across);
                let h = Vec3::new(tilt.x, tilt.y, 1.0).normalize();
                let wi = 2.0 * wo.dot(h) * h - wo;
                let pdf = auto.pdf(wo, wi);
                assert!(pdf > 0.0, "{what}");
                assert_eq!(pdf, with(expected).pdf(wo, wi), "{what}");
                let (half, visible) = (
                    with(HalfVector).pdf(wo, wi),
                    with(VisibleNormals).pdf(wo, wi),
                );
                assert!(
                    s == 0.0 || (half - visible).abs() > 1e-3 * half,
                    "{what}: {half} {visible}"
                );
            }
        }
    }
}

#[test]
fn an_explicit_sampling_strategy_is_kept_whatever_the_slope() {
    for sampling in [
        MicrofacetSampling::CosineHemisphere,
        MicrofacetSampling::HalfVector,
        MicrofacetSampling::VisibleNormals,
    ] {
        for slope in [0.0, 2.0] {
            let wo = at_slope(0.3, slope, 0.4);
            assert_eq!(gold(sampling).strategy(wo), sampling, "slope {slope}");
        }
    }
}

// A direction below (or in) the surface gets neither value nor density,
// whichever of the two it is. Fails with `half_terms`' `||` made `&&`
// (then one direction below is let through, and the visible normals give
// the direction in the surface a positive density).
#[test]
fn a_direction_below_the_surface_has_no_value_and_no_density() {
    let above = Vec3::new(0.3, 0.1, 0.9).normalize();
    for below in [
        Vec3::new(-0.2, 0.1, -0.9).normalize(),
        Vec3::new(-0.6, 0.8, 0.0),
    ] {
        for sampling in [
            MicrofacetSampling::HalfVector,
            MicrofacetSampling::VisibleNormals,
            MicrofacetSampling::Auto,
        ] {
            let conductor = gold(sampling);
            for (wo, wi) in [(above, below), (below, above)] {
                assert_eq!(conductor.eval(wo, wi), (Rgb::ZERO, 0.0), "{wo} {wi}");
                assert_eq!(conductor.f(wo, wi), Rgb::ZERO, "{wo} {wi}");
                assert_eq!(conductor.pdf(wo, wi), 0.0, "{wo} {wi}");
            }
        }
    }
}

// Every strategy's sample is the pair its `f` and `pdf` describe, above
// the surface, and most draws are kept. Fails with `sample_cosine`
// made `None` (the cosine baseline keeps nothing), or with a sample
// weighed by another pair than the one it returns.
#[test]
fn each_strategy_samples_what_its_f_and_pdf_describe() {
    let wo = Vec3::new(0.4, -0.2, 0.9).normalize();
    for sampling in [
        MicrofacetSampling::CosineHemisphere,
        MicrofacetSampling::HalfVector,
        MicrofacetSampling::VisibleNormals,
        MicrofacetSampling::Auto,
    ] {
        let conductor = gold(sampling);
        let mut kept = 0;
        for i in 0..16 {
            for j in 0..16 {
                let u = Vec2::new((i as f32 + 0.5) / 16.0, (j as f32 + 0.5) / 16.0);
                let Some(sample) = conductor.sample(wo, u) else {
                    continue;
                };
                kept += 1;
                let wi = sample.wi;
                assert!(wi.z > 0.0 && !sample.transmission, "{sampling:?} {wi}");
                assert_eq!(sample.f, conductor.f(wo, wi), "{sampling:?} {wi}");
                assert_eq!(sample.pdf(), conductor.pdf(wo, wi), "{sampling:?} {wi}");
            }
        }
        assert!(kept >= 200, "{sampling:?} kept {kept} of 256 draws");
    }
}
