//! The probes of `MicrofacetBSDF::D` and `f` (part 6), and the closed
//! forms they and [`microfacet_sample`](super::microfacet_sample) compare
//! with (`F`'s are [`conductor`](super::conductor)'s).
//!
//! - `D` is Beckmann's distribution of microfacet normals (Walter et al.
//!   2007, eq. 25), with `tan^2 theta_h = (h.x^2 + h.y^2) / h.z^2`:
//!   `D(h) = exp(-tan^2 theta_h / alpha^2) / (pi alpha^2 cos^4 theta_h)`,
//!   checked pointwise and for its normalisation,
//!   `integral of D(h) cos theta_h d omega = 1` over the hemisphere
//!   (midpoint rule in `theta_h` on the student's own values, `phi_h`
//!   varied from point to point).
//! - `f(wo, wi) = F(wi) G(wo, wi) D(h) / (4 cos theta_o cos theta_i)` with
//!   `h = normalize(wo + wi)` (Walter 2007, eq. 20), held to the student's
//!   own `F`, `G` (the starter's) and `D` at the same directions (asked
//!   of the driver), so that a mistake of `F` or `D` shows at its own
//!   function; `F` at `wo . h` (the physical choice) is accepted too, and
//!   so are the closed forms (an `f` that computes `F` and `D` itself).

use std::f64::consts::PI;

use glam::DVec3;

use super::conductor::{exact_fresnel, handout_fresnel};
use super::driver::Driver;
use super::geometry::{num, show, tokens, vec_at};
use super::reflection::polar;
use super::verdict::{failure, Cases, Verdict};
use crate::mistakes::Mistake;

/// Relative error allowed in values.
pub const REL: f64 = 1e-5;

/// Copper's complex index (Mitsuba's preset, Palik 1985), R G B.
pub const ETA: DVec3 = DVec3::new(0.200438, 0.924033, 1.102212);
pub const K: DVec3 = DVec3::new(3.912949, 2.452848, 2.142188);

/// Whether `a` and `b` agree to `REL` of the larger (or both below 1e-12).
pub fn near(a: f64, b: f64) -> bool {
    a == b || (a - b).abs() <= REL * a.abs().max(b.abs()) + 1e-12
}

/// [`near`] in every channel.
pub fn near3(a: DVec3, b: DVec3) -> bool {
    (0..3).all(|c| near(a[c], b[c]))
}

/// `tan^2` of a unit vector's angle to the normal.
fn tan2(h: DVec3) -> f64 {
    (h.x * h.x + h.y * h.y) / (h.z * h.z)
}

/// Beckmann's `D(h)` for a unit `h` above the surface.
pub fn beckmann(h: DVec3, alpha: f64) -> f64 {
    let a2 = alpha * alpha;
    let c2 = h.z * h.z;
    (-tan2(h) / a2).exp() / (PI * a2 * c2 * c2)
}

/// `D` without the `cos^4` of its denominator: `microfacet-d-no-cos4`.
fn beckmann_no_cos4(h: DVec3, alpha: f64) -> f64 {
    (-tan2(h) / (alpha * alpha)).exp() / (PI * alpha * alpha)
}

/// Points of the normalisation's midpoint rule in `theta_h`.
const QUADRATURE: usize = 512;

/// The `h` of quadrature point `k`: `theta_h` the midpoint, `phi_h` by
/// the golden angle.
fn quadrature_h(k: usize) -> DVec3 {
    let theta = (k as f64 + 0.5) * (PI / 2.0) / QUADRATURE as f64;
    polar(theta.to_degrees(), 137.507_764 * k as f64)
}

/// `2 pi sum D cos sin d theta` over the quadrature points' values.
fn normalisation(values: &[f64]) -> f64 {
    let dtheta = (PI / 2.0) / QUADRATURE as f64;
    (0..QUADRATURE)
        .map(|k| {
            let h = quadrature_h(k);
            values[k] * h.z * (1.0 - h.z * h.z).sqrt()
        })
        .sum::<f64>()
        * dtheta
        * 2.0
        * PI
}

/// Probes `MicrofacetBSDF::D`.
pub fn d(driver: &Driver) -> Verdict {
    let alphas = [0.5, 0.2];
    let points = [
        polar(8.0, 10.0),
        polar(20.0, 100.0),
        polar(35.0, 200.0),
        polar(50.0, 300.0),
        polar(65.0, 45.0),
        polar(78.0, 250.0),
    ];
    let mut commands = Vec::new();
    for alpha in alphas {
        commands.push(format!("microfacet {} {} {alpha}", tokens(ETA), tokens(K)));
        commands.extend(points.iter().map(|h| format!("mf_D {}", tokens(*h))));
        commands.extend((0..QUADRATURE).map(|k| format!("mf_D {}", tokens(quadrature_h(k)))));
    }
    let t = match driver.run("microfacet_D", commands) {
        Ok(t) => t,
        Err(e) => return Verdict::Broken(e),
    };
    let mut cases = Cases::default();
    let mut stub_like = true;
    let mut integrals = Vec::new();
    let mut i = 0;
    for alpha in alphas {
        i += 1;
        let value = |i: usize| t.exactly(i, 1).map(|v| v[0]);
        let mut got = Vec::new();
        for k in 0..points.len() + QUADRATURE {
            match value(i + k) {
                Ok(v) => got.push(v),
                Err(stop) => return Verdict::stopped(&stop, t.command(i + k)),
            }
        }
        i += points.len() + QUADRATURE;
        stub_like &= got.iter().all(|v| *v == 1.0);
        let no_cos4 = points
            .iter()
            .zip(&got)
            .all(|(h, v)| near(*v, beckmann_no_cos4(*h, alpha)));
        for (h, v) in points.iter().zip(&got) {
            let want = beckmann(*h, alpha);
            cases.record((!near(*v, want)).then(|| {
                failure(
                    format!("D(h = {}) with alpha = {alpha}", show(*h)),
                    format!("{} (Beckmann's)", num(want)),
                    num(*v),
                    if no_cos4 {
                        "D is exp(-tan^2 theta_h / alpha^2) / (pi alpha^2), without the cos^4 theta_h of its denominator"
                    } else {
                        "D(h) is not Beckmann's exp(-tan^2 theta_h / alpha^2) / (pi alpha^2 cos^4 theta_h)"
                    },
                    no_cos4.then_some(Mistake::MicrofacetDNoCos4),
                )
            }));
        }
        let integral = normalisation(&got[points.len()..]);
        integrals.push(format!("{} at alpha {alpha}", num(integral)));
        cases.record(((integral - 1.0).abs() > 2e-3).then(|| {
            failure(
                format!("D(h) cos theta_h over the hemisphere with alpha = {alpha} ({QUADRATURE} points in theta_h)"),
                "an integral of 1: D cos theta_h is the density of the microfacet normals",
                format!("an integral of {}", num(integral)),
                "D is not normalised",
                no_cos4.then_some(Mistake::MicrofacetDNoCos4),
            )
        }));
    }
    if stub_like {
        return Verdict::NotWritten("it returns 1 for every h, the starter's `return 1.0;`".into());
    }
    cases.verdict(Some(format!(
        "integral of D cos theta_h: {}",
        integrals.join(", ")
    )))
}

/// Probes `MicrofacetBSDF::f`.
pub fn f(driver: &Driver) -> Verdict {
    let alpha = 0.3;
    let pairs = [
        (polar(30.0, 0.0), polar(45.0, 170.0)),
        (polar(10.0, 40.0), polar(20.0, 220.0)),
        (polar(60.0, 300.0), polar(50.0, 90.0)),
        (polar(75.0, 10.0), polar(40.0, 200.0)),
        (polar(20.0, 80.0), polar(70.0, 120.0)),
    ];
    let mut commands = vec![format!("microfacet {} {} {alpha}", tokens(ETA), tokens(K))];
    for (wo, wi) in pairs {
        let h = (wo + wi).normalize();
        let c = wo.dot(h);
        commands.push(format!("f {} {}", tokens(wo), tokens(wi)));
        for w in [wi, wo, h, DVec3::new((1.0 - c * c).sqrt(), 0.0, c)] {
            commands.push(format!("mf_F {}", tokens(w)));
        }
        commands.push(format!("mf_G {} {}", tokens(wo), tokens(wi)));
        commands.push(format!("mf_D {}", tokens(h)));
    }
    let t = match driver.run("microfacet_f", commands) {
        Ok(t) => t,
        Err(e) => return Verdict::Broken(e),
    };
    let mut cases = Cases::default();
    let mut stub_like = true;
    for (p, (wo, wi)) in pairs.iter().enumerate() {
        let i = 1 + 7 * p;
        let mut read = Vec::new();
        for (j, n) in [3, 3, 3, 3, 3, 1, 1].into_iter().enumerate() {
            match t.exactly(i + j, n) {
                Ok(v) => read.push(v),
                Err(stop) => return Verdict::stopped(&stop, t.command(i + j)),
            }
        }
        let got = vec_at(&read[0], 0);
        stub_like &= got == DVec3::ZERO;
        let [f_wi, f_wo, f_h, f_c] = [1, 2, 3, 4].map(|j| vec_at(&read[j], 0));
        let (g, d) = (read[5][0], read[6][0]);
        let h = (*wo + *wi).normalize();
        let denominator = 4.0 * wo.z * wi.z;
        let closed_d = beckmann(h, alpha);
        let right = [
            f_wi * g * d,
            f_c * g * d,
            handout_fresnel(wi.z, ETA, K) * g * closed_d,
            exact_fresnel(wo.dot(h), ETA, K) * g * closed_d,
        ]
        .map(|v| v / denominator);
        if right.iter().any(|r| near3(got, *r)) {
            cases.record(None);
            continue;
        }
        let is = |v: DVec3| near3(got, v);
        let (what, mistake) = if right.iter().any(|r| is(*r * 4.0)) {
            (
                "the denominator has no 4: F G D / (cos theta_o cos theta_i)",
                Some(Mistake::MicrofacetNoFour),
            )
        } else if is(f_wo * g * d / denominator) || is(f_h * g * d / denominator) {
            (
                "F is evaluated at wo or at h, where the handout's is F(wi)",
                None,
            )
        } else if is(f_wi * d / denominator) {
            ("G, the shadowing-masking term, is left out", None)
        } else {
            (
                "f is not F(wi) G(wo, wi) D(h) / (4 cos theta_o cos theta_i)",
                None,
            )
        };
        cases.record(Some(failure(
            format!(
                "f(wo = {}, wi = {}) with alpha = {alpha}, copper",
                show(*wo),
                show(*wi)
            ),
            format!(
                "{} from your F(wi) = {}, G = {}, D(h) = {}",
                show(right[0]),
                show(f_wi),
                num(g),
                num(d)
            ),
            show(got),
            what,
            mistake,
        )));
    }
    if stub_like {
        return Verdict::NotWritten(
            "it returns black for every pair, the starter's `return Vector3D();` (or F still returns black)".into(),
        );
    }
    cases.verdict(None)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn beckmann_is_normalised_by_the_probes_quadrature() {
        for alpha in [0.5, 0.2] {
            let values: Vec<f64> = (0..QUADRATURE)
                .map(|k| beckmann(quadrature_h(k), alpha))
                .collect();
            assert!((normalisation(&values) - 1.0).abs() < 1e-4, "{alpha}");
            let wrong: Vec<f64> = (0..QUADRATURE)
                .map(|k| beckmann_no_cos4(quadrature_h(k), alpha))
                .collect();
            assert!((normalisation(&wrong) - 1.0).abs() > 2e-2, "{alpha}");
        }
    }
}
