//! The Beckmann distribution's unit tests.

use super::*;

/// Midpoint quadrature of `g(w)` over the upper hemisphere in
/// `(theta, phi)` with `d omega = sin(theta) d theta d phi`, the `theta`
/// points packed towards the pole when `alpha` is small.
fn hemisphere_integral(theta_max: f64, n: usize, g: impl Fn(Vec3) -> f64) -> f64 {
    let (dt, dp) = (theta_max / n as f64, 2.0 * PI / n as f64);
    let mut sum = 0.0;
    for i in 0..n {
        let t = (i as f64 + 0.5) * dt;
        for j in 0..n {
            let p = (j as f64 + 0.5) * dp;
            let w = Vec3::new(
                (t.sin() * p.cos()) as f32,
                (t.sin() * p.sin()) as f32,
                t.cos() as f32,
            );
            sum += g(w) * t.sin();
        }
    }
    sum * dt * dp
}

fn theta_max(alpha: f32) -> f64 {
    (f64::from(alpha) * 12.0).atan().min(PI / 2.0)
}

#[test]
fn lambda_skipped_past_six_is_below_f32_precision_of_one_plus_lambda() {
    for alpha in [0.01f32, 0.025, 0.1, 0.25] {
        for a in [6.0001f64, 6.5, 8.0, 20.0] {
            // A direction with cot(theta) = a alpha.
            let tan = 1.0 / (a * f64::from(alpha));
            let w = Vec3::new(tan as f32, 0.0, 1.0).normalize();
            let b = Beckmann::new(alpha);
            let exact = 0.5 * ((-a * a).exp() / (a * SQRT_PI) - libm::erfc(a));
            assert!(exact < 1e-18, "alpha {alpha}, a {a}: {exact}");
            assert_eq!(1.0f32 + exact as f32, 1.0);
            assert!(b.lambda(w) < 1e-18);
        }
    }
}

#[test]
fn d_is_normalised_by_projected_area() {
    for alpha in [0.01f32, 0.1, 0.5, 1.0] {
        let b = Beckmann::new(alpha);
        let total = hemisphere_integral(theta_max(alpha), 800, |h| {
            f64::from(b.d(h)) * f64::from(h.z)
        });
        assert!((total - 1.0).abs() < 1e-3, "alpha {alpha}: {total}");
    }
}

/// Heitz 2014, eq. 9 with eq. 17: the visible projected area of the
/// microfacets is the macro surface's, `w.z`, times `G1(w)`, i.e.
/// `integral max(0, w.h) D(h) dh = w.z (1 + Lambda(w))`. A wrong
/// `Lambda` (or the handout's `G1` mistyped) fails this.
#[test]
fn lambda_matches_the_visible_projected_area() {
    for alpha in [0.05f32, 0.3, 1.0] {
        let b = Beckmann::new(alpha);
        for cos in [1.0f32, 0.7, 0.3, 0.05] {
            let w = Vec3::new((1.0 - cos * cos).sqrt(), 0.0, cos);
            let visible = hemisphere_integral(theta_max(alpha), 1200, |h| {
                f64::from(w.dot(h).max(0.0)) * f64::from(b.d(h))
            });
            let expected = f64::from(cos) * (1.0 + f64::from(b.lambda(w)));
            assert!(
                (visible - expected).abs() < 2e-3 * expected,
                "alpha {alpha}, cos {cos}: {visible} vs {expected}"
            );
            let pdf_total =
                hemisphere_integral(theta_max(alpha), 600, |h| f64::from(b.pdf_visible(w, h)));
            assert!((pdf_total - 1.0).abs() < 3e-3, "{alpha} {cos}: {pdf_total}");
        }
    }
}

#[test]
fn lambda_limits() {
    let b = Beckmann::new(0.5);
    assert_eq!(b.lambda(Vec3::Z), 0.0);
    assert!(b.lambda(Vec3::new(1.0, 0.0, 1e-6)) > 1e4);
    assert_eq!(b.lambda(Vec3::new(1.0, 0.0, 0.0)), f32::INFINITY);
    assert_eq!(b.g1(Vec3::new(1.0, 0.0, 0.0)), 0.0);
    // Monotone: more masking towards grazing.
    let mut last = 0.0;
    for i in (1..=100).rev() {
        let c = i as f32 / 100.0;
        let l = b.lambda(Vec3::new((1.0 - c * c).sqrt(), 0.0, c));
        assert!(l >= last, "{c}");
        last = l;
    }
}

#[test]
fn visible_slopes_follow_their_cdf() {
    // The sampled x is the inverse of the normalised C at u.x.
    for theta in [0.0f64, 0.5, 1.2, 1.5, std::f64::consts::FRAC_PI_2 - 1e-4] {
        let (c, s) = (theta.cos(), theta.sin());
        let cdf = |x: f64| c * (1.0 + libm::erf(x)) + s * (-x * x).exp() / SQRT_PI;
        let top = if s > 0.0 { (c / s).min(6.0) } else { 6.0 };
        for k in 1..100 {
            let u = k as f32 / 100.0;
            let (x, _) = sample_unit_slopes(c, s, Vec2::new(u, 0.5));
            assert!(x <= top + 1e-12);
            // Only cot(theta) counts: `sample_visible` passes the
            // stretched direction's (z, r) without normalising.
            let (scaled, _) = sample_unit_slopes(0.3 * c, 0.3 * s, Vec2::new(u, 0.5));
            assert!((scaled - x).abs() < 1e-7, "theta {theta}, u {u}");
            let got = cdf(x) / cdf(top);
            assert!(
                (got - f64::from(u)).abs() <= SLOPE_TOLERANCE * f64::from(u),
                "theta {theta}, u {u}: {got}"
            );
        }
    }
}

// `D` of a half vector not normalised (`wo + wi`) is `D` of its
// direction. Fails with `cos^2 = h.z^2 / |h|^2` made `h.z^2 |h|^2` (which
// no caller with a unit `h` sees).
#[test]
fn d_depends_on_the_direction_of_h_only() {
    let b = Beckmann::new(0.3);
    for h in [Vec3::Z, Vec3::new(0.2, -0.1, 0.9), Vec3::new(0.5, 0.4, 0.6)] {
        let unit = b.d(h.normalize());
        for scale in [0.25, 3.0] {
            let d = b.d(h.normalize() * scale);
            assert!(
                (d - unit).abs() <= 1e-6 * unit,
                "{h} x {scale}: {d} vs {unit}"
            );
        }
    }
}

// Heitz 2014 (section 6): the height-correlated `G` counts a microfacet
// masked and shadowed at once once, so it lies between the separable
// product `G1(wo) G1(wi)` and the smaller of the two `G1`, strictly when
// both directions are masked in part, and it is `G1` of the other
// direction when one is the normal. Fails with any operator of `g` swapped
// or its value made a constant.
#[test]
fn the_height_correlated_g_lies_between_the_separable_product_and_each_g1() {
    let b = Beckmann::new(0.5);
    let grazing = [
        Vec3::new(0.8, 0.0, 0.6),
        Vec3::new(-0.6, 0.6, 0.3).normalize(),
        Vec3::new(0.1, -0.95, 0.2).normalize(),
    ];
    for wo in grazing {
        assert_eq!(b.g(wo, Vec3::Z), b.g1(wo), "{wo}");
        assert_eq!(b.g(Vec3::Z, wo), b.g1(wo), "{wo}");
        for wi in grazing {
            let (g, go, gi) = (b.g(wo, wi), b.g1(wo), b.g1(wi));
            assert!(go < 1.0 && gi < 1.0, "{wo} {wi}: both in part masked");
            assert!(go * gi < g && g < go.min(gi), "{wo} {wi}: {g}");
            assert_eq!(g, b.g(wi, wo), "{wo} {wi}");
        }
    }
    assert_eq!(b.g(Vec3::Z, Vec3::Z), 1.0);
}

// `pdf_h` is the density of `sample_h`: the probability it puts on the
// cap `theta <= theta_h` of the normal drawn at `u.x` is `u.x`, and the
// azimuth is `2 pi u.y`. Fails with `pdf_h` made a constant or its `*`
// made `+` or `/` (nothing in the renderer calls it: the conductor
// computes `D cos` itself; the starter's `sample_f` has it).
#[test]
fn pdf_h_is_the_density_of_sample_h() {
    for alpha in [0.1f32, 0.6] {
        let b = Beckmann::new(alpha);
        for u in [0.1f32, 0.5, 0.9] {
            let h = b.sample_h(Vec2::new(u, 0.3));
            let theta = f64::from(h.z).acos();
            let cap = hemisphere_integral(theta, 600, |m| f64::from(b.pdf_h(m)));
            assert!(
                (cap - f64::from(u)).abs() < 1e-3,
                "alpha {alpha}, u {u}: {cap}"
            );
            let phi = f64::from(h.y).atan2(f64::from(h.x));
            assert!((phi - 0.6 * PI).abs() < 1e-5, "alpha {alpha}, u {u}: {phi}");
        }
    }
}

// Newton's method from the normal-incidence estimate converges fast: over
// `theta` from 0 to grazing and `u` across (0, 1), 4.4 steps on average
// and at most 14 (measured; both bounds leave a margin). The answer is
// held by `visible_slopes_follow_their_cdf`; this holds the speed, which
// no answer shows, as the bisection bracket rescues any slower search.
// Fails with the derivative made wrong (`/ sqrt(pi)` made `* sqrt(pi)`:
// mean 46), the start made wrong (`2 u - 1` made `2 + u - 1`: mean 6.0),
// the step reversed (`x - err / C'` made `+`: mean 27) or the bracket's
// acceptance made `==` (mean 27).
#[test]
fn the_visible_slope_is_found_in_a_few_newton_steps() {
    let (mut total, mut count, mut most) = (0u64, 0u64, 0);
    for i in 0..=100 {
        let theta = std::f64::consts::FRAC_PI_2 * (f64::from(i) / 100.0).min(1.0 - 1e-6);
        for k in 1..1000 {
            let u = k as f32 / 1000.0;
            let (_, steps) = visible_slope_x(theta.cos(), theta.sin(), u);
            total += u64::from(steps);
            count += 1;
            most = most.max(steps);
        }
    }
    let mean = total as f64 / count as f64;
    assert!(mean <= 5.0 && most <= 16, "mean {mean}, most {most}");
}

// A `wo` at or below the surface sees no normal: the sampler returns the
// macro normal (density 0) rather than running its solver on a negative
// `cot(theta)`, whose bracket would be empty (`clamp` panicked there).
#[test]
fn nothing_is_visible_from_below_the_surface() {
    let b = Beckmann::new(0.3);
    for wo in [
        -Vec3::Z,
        Vec3::new(0.3, 0.0, -0.95),
        Vec3::new(1.0, 0.0, 0.0),
    ] {
        assert_eq!(b.sample_visible(wo, Vec2::new(0.7, 0.2)), Vec3::Z, "{wo}");
        assert_eq!(b.pdf_visible(wo, Vec3::Z), 0.0, "{wo}");
    }
}
