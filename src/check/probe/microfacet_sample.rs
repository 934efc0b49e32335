//! The probe of `MicrofacetBSDF::sample_f` (part 6): importance sampling
//! of the Beckmann lobe by the half vector, as the handout does it.
//!
//! `h` is drawn with the density `p_h(h) = D(h) cos theta_h` (`tan^2
//! theta_h = -alpha^2 ln(1 - u1)`, `phi_h = 2 pi u2`), then `wo` reflected
//! about it, `wi = 2 (wo . h) h - wo`, whose density per steradian is
//! `p(wi) = p_h(h) / (4 |wo . h|)` with `h = normalize(wo + wi)` (Walter
//! et al. 2007, eq. 14). Every `wi` above the surface must come back with
//! that `*pdf` (the catalogue's `microfacet-pdf-no-jacobian` returns
//! `p_h`), and with the value `f(wo, wi)` the student's own `f` gives (a
//! second run asks it). A `wi` below the surface is the handout's to
//! discard: its `*pdf` and value are not judged, and it counts in the
//! chi-square test's cell below the surface. The directions are tested
//! against `p` ([`density`], its cells integrated
//! numerically, at `alpha` = 1e-5); `f cos theta_i / pdf` then averages
//! to the lobe's albedo, reported.

use glam::DVec3;

use super::density;
use super::driver::Driver;
use super::geometry::{num, show, tokens, vec_at};
use super::microfacet::{beckmann, near, near3, ETA, K};
use super::picture;
use super::reflection::polar;
use super::specular::{said, samples, Sample};
use super::verdict::{failure, Cases, Verdict};
use super::warp;
use crate::mistakes::Mistake;

/// The lobe's roughness, and the samples the chi-square test takes.
pub const ALPHA: f64 = 0.5;
pub const SAMPLES: usize = 20_000;
/// Samples whose value is compared with the student's `f`.
const VALUES: usize = 100;
/// The chi-square test's level.
pub const LEVEL: f64 = 1e-5;

/// The `wo` the probe samples from.
pub fn probe_wo() -> DVec3 {
    polar(40.0, 30.0)
}

/// The handout's sample of `wi` from `wo` for the uniform numbers `u1`,
/// `u2`: the half vector of Beckmann roughness `alpha`, `tan^2 theta_h =
/// -alpha^2 ln(1 - u1)`, `phi_h = 2 pi u2`, and `wo` reflected about it.
pub fn handout_sample(wo: DVec3, alpha: f64, u1: f64, u2: f64) -> DVec3 {
    let theta = (-alpha * alpha * (1.0 - u1).ln()).sqrt().atan();
    let h = polar(theta.to_degrees(), 360.0 * u2);
    2.0 * wo.dot(h) * h - wo
}

/// The course's density of `wi` sampled from `wo` (both unit, `wo`
/// above the surface), over the whole sphere.
pub fn pdf(wo: DVec3, wi: DVec3, alpha: f64) -> f64 {
    let mut h = (wo + wi).normalize_or_zero();
    if h.z < 0.0 {
        h = -h;
    }
    if h == DVec3::ZERO || h.z == 0.0 {
        return 0.0;
    }
    beckmann(h, alpha) * h.z / (4.0 * wo.dot(h).abs())
}

/// Probes `MicrofacetBSDF::sample_f`.
pub fn sample_f(driver: &Driver) -> Verdict {
    let wo = probe_wo();
    let setup = format!("microfacet {} {} {ALPHA}", tokens(ETA), tokens(K));
    let t = match driver.run(
        "microfacet_sample_f",
        vec![setup.clone(), format!("sample {} {SAMPLES}", tokens(wo))],
    ) {
        Ok(t) => t,
        Err(e) => return Verdict::Broken(e),
    };
    let all = match samples(&t, 1, SAMPLES) {
        Ok(s) => s,
        Err(stop) => return Verdict::stopped(&stop, t.command(1)),
    };
    if all
        .iter()
        .all(|s| near(s.pdf, s.wi.z / std::f64::consts::PI))
    {
        return Verdict::NotWritten(
            "every *pdf is cos(theta) / pi: it still samples the cosine-weighted hemisphere, the starter's baseline".into(),
        );
    }
    let input = format!(
        "sample_f(wo = {}) of MicrofacetBSDF(copper, alpha = {ALPHA}), {SAMPLES} times",
        show(wo)
    );
    let mut cases = Cases::default();
    for s in &all {
        cases.record(judge(wo, s).map(|(expected, what, mistake)| {
            failure(input.clone(), expected, said(s), what, mistake)
        }));
    }
    if !cases.all_pass() {
        return cases.verdict(None);
    }
    // The values: the student's own f at the first directions above.
    let above: Vec<&Sample> = all.iter().filter(|s| s.wi.z > 0.0).take(VALUES).collect();
    let mut commands = vec![setup];
    commands.extend(
        above
            .iter()
            .map(|s| format!("f {} {}", tokens(wo), tokens(s.wi))),
    );
    let t = match driver.run("microfacet_sample_f_values", commands) {
        Ok(t) => t,
        Err(e) => return Verdict::Broken(e),
    };
    for (k, s) in above.iter().enumerate() {
        let f = match t.exactly(k + 1, 3) {
            Ok(v) => vec_at(&v, 0),
            Err(stop) => return Verdict::stopped(&stop, t.command(k + 1)),
        };
        cases.record((!near3(s.f, f)).then(|| {
            failure(
                input.clone(),
                format!("returning f(wo, *wi) = {}", show(f)),
                said(s),
                "the value returned is not f(wo, *wi)",
                None,
            )
        }));
    }
    if !cases.all_pass() {
        return cases.verdict(None);
    }
    let dirs: Vec<DVec3> = all.iter().map(|s| s.wi).collect();
    let hist = density::histogram(&dirs, &density::cell_masses(|wi| pdf(wo, wi, ALPHA)));
    picture::save(
        &driver.work,
        "MicrofacetBSDF::sample_f",
        &picture::hemisphere(&hist),
    );
    let (stat, dof, pass) = warp::chi_square(&hist, LEVEL);
    let below = all.iter().filter(|s| s.wi.z <= 0.0).count();
    if !pass {
        return Verdict::Fail(failure(
            input,
            "directions distributed as D(h) cos theta_h / (4 |wo . h|)",
            format!("chi-square {} with {dof} degrees of freedom", num(stat)),
            "the directions do not follow the pdf returned (chi-square test, alpha 1e-5)",
            None,
        ));
    }
    let albedo = all
        .iter()
        .filter(|s| s.wi.z > 0.0 && s.pdf > 0.0)
        .map(|s| s.f * s.wi.z / s.pdf)
        .sum::<DVec3>()
        / SAMPLES as f64;
    Verdict::Pass {
        cases: all.len(),
        note: Some(format!(
            "chi-square {} on {dof} degrees of freedom; {below} directions below the surface; f cos / pdf averages {}",
            num(stat),
            show(albedo)
        )),
    }
}

/// One sample: `None` when right, else what was expected, what is wrong
/// and the mistake it is.
fn judge(wo: DVec3, s: &Sample) -> Option<(String, &'static str, Option<Mistake>)> {
    if !s.wi.is_finite() || (s.wi.length() - 1.0).abs() > 1e-6 {
        return Some(("*wi a unit vector".into(), "*wi is not a unit vector", None));
    }
    if s.wi.z <= 0.0 {
        return None;
    }
    let h = (wo + s.wi).normalize();
    let want = pdf(wo, s.wi, ALPHA);
    if near(s.pdf, want) {
        return None;
    }
    let expected = format!(
        "*pdf = D(h) cos theta_h / (4 wo . h) = {} (h = {})",
        num(want),
        show(h)
    );
    Some(if near(s.pdf, beckmann(h, ALPHA) * h.z) {
        (
            expected,
            "*pdf is the half vector's density D(h) cos theta_h, without the 1 / (4 wo . h) of reflecting wo about h",
            Some(Mistake::MicrofacetPdfNoJacobian),
        )
    } else {
        (
            expected,
            "*pdf is not the density of the direction returned",
            None,
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_pcg::Pcg64;

    /// Directions drawn as the handout draws them pass against `pdf`,
    /// which integrates to 1 over the sphere; the half vector's density
    /// (no Jacobian) does not describe them.
    #[test]
    fn the_handouts_sampler_passes_against_its_pdf() {
        let wo = probe_wo();
        let mut rng = Pcg64::seed_from_u64(3);
        let dirs: Vec<DVec3> = (0..SAMPLES)
            .map(|_| handout_sample(wo, ALPHA, rng.gen(), rng.gen()))
            .collect();
        let masses = density::cell_masses(|wi| pdf(wo, wi, ALPHA));
        let below = masses.last().unwrap();
        assert!(*below > 0.0 && *below < 0.2, "{below}");
        assert!(warp::chi_square(&density::histogram(&dirs, &masses), LEVEL).2);
        let wrong = density::cell_masses(|wi| {
            let h = (wo + wi).normalize();
            if wi.z > 0.0 {
                beckmann(h, ALPHA) * h.z
            } else {
                0.0
            }
        });
        assert!(!warp::chi_square(&density::histogram(&dirs, &wrong), LEVEL).2);
    }
}
