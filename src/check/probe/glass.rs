//! The probe of `GlassBSDF::sample_f` (part 6): a smooth dielectric that
//! reflects the share `F` of the light and transmits the rest, sampled by
//! choosing the reflection with probability `F` (the handout's "Fresnel
//! coefficient as the probability of reflection").
//!
//! `F` is Schlick's approximation at `wo`'s cosine on either side, as the
//! course computes it:
//!
//! ```text
//! R0 = ((1 - ior) / (1 + ior))^2,    F = R0 + (1 - R0) (1 - |wo.z|)^5
//! ```
//!
//! Each sample is one of two delta lobes, checked exactly:
//!
//! - reflection: `wi = reflect(wo)`, `*pdf = F`, returning
//!   `F reflectance / |wi.z|`;
//! - refraction: `wi = refract(wo)`, `*pdf = 1 - F`, returning
//!   `(1 - F) transmittance / |wi.z| / eta^2` (the handout's `eta`,
//!   [`reflection`](super::reflection)).
//!
//! Under total internal reflection (`refract` fails) every sample
//! reflects with `*pdf = 1`, returning `reflectance / |wi.z|`. Over the
//! samples of one `wo` the count of reflections `k` of `n` must be
//! binomial with probability `F`: inside the counts an exact two-sided
//! binomial test at `alpha` = 1e-5 accepts (each tail beyond them at most
//! `alpha / 2`).

use glam::DVec3;

use super::driver::Driver;
use super::geometry::{close, num, show, tokens};
use super::reflection::{eta, polar, reflect, refract, refract_inverted, same, wrong_axis, REL};
use super::specular::{said, same_colour, samples, stub, transmitted, Sample};
use super::verdict::{failure, Cases, Verdict};
use crate::check::stats::binomial_range;
use crate::mistakes::Mistake;

const TRANSMITTANCE: DVec3 = DVec3::new(0.9, 0.8, 0.7);
const REFLECTANCE: DVec3 = DVec3::new(0.95, 0.85, 0.6);
pub const IOR: f64 = 1.5;

/// The binomial test's level.
pub const ALPHA: f64 = 1e-5;

/// The `wo`s the probe samples from and the samples of each: entering at
/// three angles, leaving below the critical angle (41.8 degrees for ior
/// 1.5) and beyond it.
pub fn plan() -> [(DVec3, usize); 7] {
    [
        (polar(10.0, 30.0), 4000),
        (polar(60.0, 200.0), 4000),
        (polar(80.0, 120.0), 2000),
        (polar(150.0, 300.0), 4000),
        (polar(165.0, 20.0), 4000),
        (polar(130.0, 70.0), 50),
        (polar(105.0, 250.0), 50),
    ]
}

/// Whether `k` reflections of `n` samples are binomial with probability
/// `f` (an exact two-sided test at [`ALPHA`]), and the counts it accepts.
pub fn binomial_passes(k: u64, n: u64, f: f64) -> (bool, (u64, u64)) {
    let (lo, hi) = binomial_range(n, f, ALPHA);
    ((lo..=hi).contains(&k), (lo, hi))
}

/// Schlick's `F` at `cos` with `R0 = r0^2`; `r0` the unsquared ratio.
fn schlick_r0(r0_squared: f64, cos: f64) -> f64 {
    r0_squared + (1.0 - r0_squared) * (1.0 - cos).powi(5)
}

/// The course's Schlick `F` for `wo`.
pub fn schlick(wo: DVec3, ior: f64) -> f64 {
    let r0 = (1.0 - ior) / (1.0 + ior);
    schlick_r0(r0 * r0, wo.z.abs())
}

/// The exact Fresnel reflectance for unpolarised light (Born and Wolf,
/// section 1.5) with the handout's `eta = n_i / n_t`; 1 under total
/// internal reflection.
fn exact_fresnel(wo: DVec3, ior: f64) -> f64 {
    let e = eta(wo, ior);
    let cos_i = wo.z.abs();
    let sin2_t = e * e * (1.0 - cos_i * cos_i);
    if sin2_t >= 1.0 {
        return 1.0;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    let r_s = (e * cos_i - cos_t) / (e * cos_i + cos_t);
    let r_p = (cos_i - e * cos_t) / (cos_i + e * cos_t);
    0.5 * (r_s * r_s + r_p * r_p)
}

/// What a reflection's `*pdf` of `pdf` says, when it is not `F`: the
/// catalogued mistake and what is wrong.
fn wrong_f(wo: DVec3, pdf: f64, reflected: bool) -> (&'static str, Option<Mistake>) {
    let r0 = (1.0 - IOR) / (1.0 + IOR);
    let share = |f: f64| if reflected { f } else { 1.0 - f };
    let is = |f: f64| close(pdf, share(f), REL);
    if is(schlick_r0(r0.abs(), wo.z.abs())) || is(schlick_r0(r0, wo.z.abs())) {
        (
            "Schlick's R0 = ((1 - ior) / (1 + ior))^2 is taken without its square",
            Some(Mistake::SchlickR0NotSquared),
        )
    } else if wo.z < 0.0 && is(schlick_r0(r0 * r0, wo.z)) {
        (
            "Schlick's cos theta is wo.z, negative inside the glass, where the course takes |wo.z|",
            None,
        )
    } else if is(exact_fresnel(wo, IOR)) {
        (
            "F is the exact Fresnel reflectance, where the handout asks for Schlick's approximation",
            None,
        )
    } else {
        (
            "*pdf is not the probability of the lobe chosen, Schlick's F for a reflection, 1 - F for a refraction",
            None,
        )
    }
}

/// Probes `GlassBSDF::sample_f`.
pub fn sample_f(driver: &Driver) -> Verdict {
    let plan = plan();
    let mut commands = vec![format!(
        "glass {} {} 0 {IOR}",
        tokens(TRANSMITTANCE),
        tokens(REFLECTANCE)
    )];
    commands.extend(
        plan.iter()
            .map(|(wo, n)| format!("sample {} {n}", tokens(*wo))),
    );
    let t = match driver.run("glass_sample_f", commands) {
        Ok(t) => t,
        Err(e) => return Verdict::Broken(e),
    };
    let mut runs = Vec::new();
    for (k, (_, n)) in plan.iter().enumerate() {
        match samples(&t, k + 1, *n) {
            Ok(s) => runs.push(s),
            Err(stop) => return Verdict::stopped(&stop, t.command(k + 1)),
        }
    }
    if runs.iter().all(|r| stub(r)) {
        return Verdict::NotWritten(
            "it returns black and sets neither *wi nor *pdf, the starter's `return Vector3D();`"
                .into(),
        );
    }
    let mut cases = Cases::default();
    let mut shares = Vec::new();
    for ((wo, n), records) in plan.iter().zip(&runs) {
        let input = format!(
            "sample_f(wo = {}) of GlassBSDF(transmittance = {}, reflectance = {}, ior = {IOR}), {}, {n} times",
            show(*wo),
            show(TRANSMITTANCE),
            show(REFLECTANCE),
            if wo.z > 0.0 { "entering" } else { "leaving" }
        );
        let total_internal = refract(*wo, IOR).is_none();
        let f = if total_internal {
            1.0
        } else {
            schlick(*wo, IOR)
        };
        let mut reflected = 0usize;
        for s in records {
            reflected += usize::from(same(s.wi, reflect(*wo)));
            cases.record(
                judge(*wo, f, total_internal, s).map(|(expected, what, mistake)| {
                    failure(input.clone(), expected, said(s), what, mistake)
                }),
            );
        }
        if total_internal || !cases.all_pass() {
            continue;
        }
        let (pass, (lo, hi)) = binomial_passes(reflected as u64, *n as u64, f);
        shares.push(format!("{}/{}", reflected, records.len()));
        cases.record((!pass).then(|| {
            failure(
                input.clone(),
                format!(
                    "about {} reflections (Schlick's F = {}): from {lo} to {hi}",
                    num(*n as f64 * f),
                    num(f)
                ),
                format!("{reflected} reflections"),
                "the reflection is not chosen with probability F (an exact binomial test at alpha 1e-5)",
                None,
            )
        }));
    }
    cases.verdict(Some(format!(
        "reflected {} of the samples at the angles that refract",
        shares.join(", ")
    )))
}

/// One sample against the lobe it chose: `None` when right, else what was
/// expected, what is wrong, and the mistake it is.
fn judge(
    wo: DVec3,
    f: f64,
    total_internal: bool,
    s: &Sample,
) -> Option<(String, &'static str, Option<Mistake>)> {
    let want_r = REFLECTANCE * f / wo.z.abs();
    let reflection = format!(
        "*wi = {}, *pdf = {}, returning {}",
        show(reflect(wo)),
        num(f),
        show(want_r)
    );
    if total_internal {
        let what = if s.f == DVec3::ZERO {
            return Some((
                reflection,
                "it returns no light under total internal reflection, where all light reflects",
                Some(Mistake::NoTotalInternalReflection),
            ));
        } else if !same(s.wi, reflect(wo)) {
            "under total internal reflection *wi is not reflect(wo)"
        } else if !close(s.pdf, 1.0, REL) {
            "under total internal reflection *pdf is not 1: the reflection is certain"
        } else if !same_colour(s.f, want_r) {
            "under total internal reflection the value is not reflectance / |cos theta_i|"
        } else {
            return None;
        };
        return Some((reflection, what, None));
    }
    if same(s.wi, reflect(wo)) {
        let (what, mistake) = if !close(s.pdf, f, REL) {
            wrong_f(wo, s.pdf, true)
        } else if same_colour(s.f, want_r) {
            return None;
        } else if same_colour(s.f, REFLECTANCE / wo.z.abs()) {
            (
                "the reflected value is not multiplied by F, the lobe's probability: the weight f cos / pdf is then reflectance / F",
                None,
            )
        } else {
            (
                "the reflected value is not F reflectance / |cos theta_i|",
                None,
            )
        };
        return Some((reflection, what, mistake));
    }
    if let Some(d) = refract(wo, IOR).filter(|d| same(s.wi, *d)) {
        if !close(s.pdf, 1.0 - f, REL) {
            let (what, mistake) = wrong_f(wo, s.pdf, false);
            let expected = format!("*wi = {}, *pdf = 1 - F = {}", show(d), num(1.0 - f));
            return Some((expected, what, mistake));
        }
        return transmitted(wo, IOR, TRANSMITTANCE * (1.0 - f), 1.0 - f, s);
    }
    let expected = format!("{reflection}, or a refraction");
    if same(s.wi, wrong_axis(wo)) {
        return Some((
            expected,
            "*wi is wo mirrored through the surface, (wo.x, wo.y, -wo.z), not about the normal",
            Some(Mistake::ReflectWrongAxis),
        ));
    }
    if refract_inverted(wo, IOR).is_some_and(|d| same(s.wi, d)) {
        return Some((
            expected,
            "*wi bends the wrong way: Snell's law with the ratio of indices upside down",
            Some(Mistake::RefractionRatioInverted),
        ));
    }
    Some((expected, "*wi is neither reflect(wo) nor refract(wo)", None))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn schlick_and_fresnel_agree_at_normal_incidence() {
        let wo = polar(0.0, 0.0);
        assert!(close(schlick(wo, 1.5), 0.04, 1e-12));
        assert!(close(exact_fresnel(wo, 1.5), 0.04, 1e-12));
        // The same R0 from inside.
        assert!(close(schlick(-wo, 1.5), 0.04, 1e-12));
        assert!(close(exact_fresnel(-wo, 1.5), 0.04, 1e-12));
        // Without the square R0 is 0.2, five times as much.
        let (what, mistake) = wrong_f(wo, 0.2, true);
        assert_eq!(mistake, Some(Mistake::SchlickR0NotSquared), "{what}");
        assert!(exact_fresnel(polar(130.0, 0.0), 1.5) == 1.0);
    }
}
