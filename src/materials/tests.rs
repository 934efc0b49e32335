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
