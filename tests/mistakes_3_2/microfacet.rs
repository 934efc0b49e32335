//! Part 6's rough-metal mistakes ([`pathtracer::mistakes::materials::MICROFACET_MISTAKES`]):
//! their factors on the copper balls of the materials box and of part 6's
//! check (Beckmann alpha 0.15 and 0.4).

use super::*;
use pathtracer::check::scenes::microfacet_box;

const COPPER_BALL: Vec3 = Vec3::new(0.15, 0.22, -0.55);

/// Part 6's microfacet mistakes on the materials box's copper ball:
/// `microfacet-no-4` makes its direct light (`-m 1`, light sampled, `f`
/// alone) exactly 4 times as bright; `microfacet-pdf-no-jacobian` leaves
/// that unchanged and darkens what the ball reflects (its second bounce
/// alone, `-m 2 -o 0`, sampled by `sample_f`) by `4 wo.h`: measured 0.35
/// here (`wo.h`, the cosine between the view and the half vector, is 0.6
/// or more on most of the ball).
#[test]
fn microfacet_mistakes_change_the_copper_ball() {
    let view = CourseView::of(builtin::materials_box());
    let copper = view.pixels_seeing(|p| (p - COPPER_BALL).length() < 0.23);
    assert!(copper.len() > 20, "{}", copper.len());
    let alpha = ALPHA / 3.0;
    let direct =
        |m: &[Mistake], seed| view.mean_over(&starter_tracer(m, L, 1, 1, true), 256, &copper, seed);
    let right = direct(&[], 560);
    let four = direct(&[Mistake::MicrofacetNoFour], 561);
    assert_ratio("microfacet-no-4", four, right, 4.0, alpha);
    let jacobian = direct(&[Mistake::MicrofacetPdfNoJacobian], 562);
    assert_ratio(
        "microfacet-pdf-no-jacobian, -m 1",
        jacobian,
        right,
        1.0,
        alpha,
    );
    let second = |m: &[Mistake], seed| {
        view.mean_over(&starter_tracer(m, L, 1, 2, false), 256, &copper, seed)
    };
    let right = second(&[], 563);
    let wrong = second(&[Mistake::MicrofacetPdfNoJacobian], 564);
    assert_ratio_in(
        "microfacet-pdf-no-jacobian, -m 2 -o 0",
        wrong,
        right,
        0.25..0.6,
        alpha,
    );
}

/// `microfacet-d-no-cos4` multiplies `f` by `cos^4(theta_h)`; where `D`
/// puts its half vectors (`tan^2(theta_h) = alpha^2 E`, `E` exponential
/// of mean 1) its mean is `E[(1 + alpha^2 E)^-2]`, 0.958 at alpha 0.15 and
/// 0.777 at 0.4: the light-sampled highlights of part 6's check's rough
/// ball darken by about a fifth, its sharp ball's by a few per cent, and
/// nothing brightens.
/// The same samples with and without the mistake (it changes no
/// sampling), so the ratio's noise is small. Measured 0.959 and 0.788
/// (standard errors 0.0013 and 0.0018). The right `D` fails both ranges;
/// a `cos^2` for the `cos^4` fails both too, at 0.979 and 0.883 (by hand,
/// in `microfacet_f_factor`).
#[test]
fn microfacet_d_without_cos4_darkens_the_rough_ball_most() {
    let view = CourseView::of(microfacet_box());
    let [sharp, rough] = builtin::BALL_CENTRES
        .map(|c| view.pixels_seeing(|p| (p - c).length() < builtin::BALL_RADIUS + 0.01));
    assert!(sharp.len() > 40 && rough.len() > 40);
    let right = starter_tracer(&[], L, 1, 1, true);
    let wrong = starter_tracer(&[Mistake::MicrofacetDNoCos4], L, 1, 1, true);
    let cases = [(&sharp, 0.93..0.975, 570), (&rough, 0.7..0.85, 572)];
    for (pixels, range, seed) in cases {
        let ratio = view.paired_ratio(&right, &wrong, 64, pixels, seed);
        assert_ratio_safely_in("microfacet-d-no-cos4", ratio, range, ALPHA / 2.0);
    }
}
