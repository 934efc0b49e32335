//! Unit tests of what every material shares: the sample record.

use glam::Vec3;

use super::*;

/// A reflection sample exists only with a density that is positive and
/// finite: with 0 the estimator would divide by it, with infinity it
/// would weigh nothing, and a negative one is no density. Checked by
/// hand: `pdf > 0 && pdf.is_finite()` with `&&` made `||` or `>` made
/// `>=` fails here (found by the mutation run of `materials`).
#[test]
fn a_reflection_sample_needs_a_positive_finite_density() {
    let (f, wi) = (Rgb::new(0.2, 0.4, 0.6), Vec3::new(0.0, 0.6, 0.8));
    for pdf in [0.0, -0.0, -1.0, f32::INFINITY, f32::NAN] {
        assert!(BsdfSample::reflection(f, wi, pdf).is_none(), "pdf {pdf}");
    }
    let sample = BsdfSample::reflection(f, wi, 0.5).expect("a density of 0.5");
    assert_eq!((sample.f, sample.wi, sample.pdf()), (f, wi, 0.5));
    assert!(!sample.transmission && !sample.is_delta());
    assert_eq!(sample.eta, 1.0);
}

/// A sample's weight is `f |cos theta_i| / pdf`, and zero where the density
/// is not positive and finite (a record made by hand can hold any density;
/// a delta lobe's probability is its density here). Checked by hand: the
/// guard's `&&` made `||` or `>` made `>=` fails here.
#[test]
fn a_sample_weighs_f_cos_over_pdf_and_nothing_without_a_density() {
    let (f, wi) = (Rgb::new(0.2, 0.4, 0.6), Vec3::new(0.0, 0.6, -0.8));
    let sample = |density| BsdfSample {
        f,
        wi,
        density,
        transmission: true,
        eta: 1.5,
    };
    for (density, expected) in [(Density::SolidAngle(0.5), 1.6), (Density::Delta(0.25), 3.2)] {
        let weight = sample(density).weight();
        assert!(
            (weight - f * expected).abs().max_element() < 1e-6,
            "{weight:?}"
        );
    }
    for pdf in [0.0, -1.0, f32::INFINITY, f32::NAN] {
        for density in [Density::SolidAngle(pdf), Density::Delta(pdf)] {
            assert_eq!(sample(density).weight(), Rgb::ZERO, "{density:?}");
        }
    }
}
