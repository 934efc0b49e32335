//! The probes of `MirrorBSDF::sample_f` and `RefractionBSDF::sample_f`
//! (part 6): delta lobes, so every sample is checked exactly.
//!
//! The course's contract for a delta lobe that sends the fraction `R` of
//! the light into one direction `wi`: `*pdf` is the probability of the
//! lobe chosen and `sample_f` returns `R / |cos theta_i|` (`|wi.z|`), so
//! that the path's weight `f |cos theta_i| / pdf` is `R`.
//!
//! - Mirror: `wi = reflect(wo)`, `*pdf = 1`, `reflectance / |wi.z|`.
//! - Refraction: `wi = refract(wo)` (the handout's `eta`,
//!   [`reflection`](super::reflection)), `*pdf = 1`, and the course's
//!   `transmittance / |wi.z| / eta^2`: the handout divides by `eta^2`
//!   (`1 / ior` entering), the reciprocal of the physical radiance
//!   scaling. Under total internal reflection the course returns black;
//!   a reflection (`reflect(wo)`, `*pdf = 1`, `transmittance / |wi.z|`)
//!   is accepted too.

use glam::DVec3;

use super::driver::{Driver, Stopped, Transcript};
use super::geometry::{close, num, show, tokens, vec_at};
use super::reflection::{eta, polar, reflect, refract, refract_inverted, same, wrong_axis, REL};
use super::verdict::{failure, Cases, Verdict};
use crate::mistakes::Mistake;

/// One record of the driver's `sample`: `*wi`, `*pdf` and the value.
#[derive(Debug, Clone, Copy)]
pub struct Sample {
    pub wi: DVec3,
    pub pdf: f64,
    pub f: DVec3,
}

/// The `n` records answered to command `i`.
pub fn samples(t: &Transcript, i: usize, n: usize) -> Result<Vec<Sample>, Stopped> {
    Ok(t.exactly(i, 7 * n)?
        .chunks(7)
        .map(|s| Sample {
            wi: vec_at(s, 0),
            pdf: s[3],
            f: vec_at(s, 4),
        })
        .collect())
}

/// Whether two colours agree to [`REL`] in every channel.
pub fn same_colour(a: DVec3, b: DVec3) -> bool {
    (0..3).all(|c| close(a[c], b[c], REL))
}

/// How a sample reads in a report.
pub fn said(s: &Sample) -> String {
    format!(
        "*wi = {}, *pdf = {}, returning {}",
        show(s.wi),
        num(s.pdf),
        show(s.f)
    )
}

/// Whether the samples are the starter's stub's: black, `*wi` unset.
pub fn stub(samples: &[Sample]) -> bool {
    samples.iter().all(|s| s.wi.is_nan() && s.f == DVec3::ZERO)
}

/// Samples asked for per `wo` (a delta lobe gives the same each time).
const PER_WO: usize = 2;

const REFLECTANCE: DVec3 = DVec3::new(0.9, 0.6, 0.3);
const TRANSMITTANCE: DVec3 = DVec3::new(0.9, 0.8, 0.7);
const IOR: f64 = 1.5;

/// Runs `sample` for each `wo` after `setup`: the records per `wo`, or
/// the verdict already reached (the driver broke or stopped, or the
/// records are the starter's stub's).
fn run(
    driver: &Driver,
    name: &str,
    setup: String,
    wos: &[DVec3],
) -> Result<Vec<Vec<Sample>>, Verdict> {
    let mut commands = vec![setup];
    commands.extend(
        wos.iter()
            .map(|wo| format!("sample {} {PER_WO}", tokens(*wo))),
    );
    let t = driver.run(name, commands).map_err(Verdict::Broken)?;
    let runs = (0..wos.len())
        .map(|k| {
            samples(&t, k + 1, PER_WO).map_err(|stop| Verdict::stopped(&stop, t.command(k + 1)))
        })
        .collect::<Result<Vec<_>, _>>()?;
    if stub(&runs.concat()) {
        return Err(Verdict::NotWritten(
            "it returns black and sets neither *wi nor *pdf, the starter's `return Vector3D();`"
                .into(),
        ));
    }
    Ok(runs)
}

/// Probes `MirrorBSDF::sample_f`.
pub fn mirror(driver: &Driver) -> Verdict {
    let wos = [
        polar(0.0, 0.0),
        polar(35.0, 60.0),
        polar(75.0, 200.0),
        polar(88.0, 310.0),
    ];
    let runs = match run(
        driver,
        "mirror_sample_f",
        format!("mirror {}", tokens(REFLECTANCE)),
        &wos,
    ) {
        Ok(r) => r,
        Err(v) => return v,
    };
    let mut cases = Cases::default();
    for (wo, records) in wos.iter().zip(&runs) {
        let want_wi = reflect(*wo);
        let want_f = REFLECTANCE / wo.z.abs();
        for s in records {
            let (what, mistake) = if !same(s.wi, want_wi) {
                let flipped = same(s.wi, wrong_axis(*wo));
                (
                    if flipped {
                        "*wi is wo mirrored through the surface, (wo.x, wo.y, -wo.z), not about the normal"
                    } else {
                        "*wi is not reflect(wo), wo mirrored about the normal (0, 0, 1)"
                    },
                    flipped.then_some(Mistake::ReflectWrongAxis),
                )
            } else if !close(s.pdf, 1.0, REL) {
                (
                    "*pdf is not 1, the probability of the mirror's one delta lobe",
                    None,
                )
            } else if !same_colour(s.f, want_f) {
                (
                    if same_colour(s.f, REFLECTANCE) {
                        "it returns the reflectance, not reflectance / |cos theta_i|: the path tracer's cos / pdf then darkens the mirror by cos theta_i"
                    } else {
                        "the value returned is not reflectance / |cos theta_i|"
                    },
                    None,
                )
            } else {
                cases.record(None);
                continue;
            };
            cases.record(Some(failure(
                format!(
                    "sample_f(wo = {}) of MirrorBSDF(reflectance = {})",
                    show(*wo),
                    show(REFLECTANCE)
                ),
                format!(
                    "*wi = {}, *pdf = 1, returning {}",
                    show(want_wi),
                    show(want_f)
                ),
                said(s),
                what,
                mistake,
            )));
        }
    }
    cases.verdict(None)
}

/// Probes `RefractionBSDF::sample_f`.
pub fn refraction(driver: &Driver) -> Verdict {
    // Entering, leaving, and leaving beyond the critical angle (41.8
    // degrees from the normal for ior 1.5).
    let wos = [
        polar(0.0, 0.0),
        polar(40.0, 30.0),
        polar(75.0, 250.0),
        polar(160.0, 120.0),
        polar(145.0, 300.0),
        polar(125.0, 45.0),
        polar(100.0, 190.0),
    ];
    let setup = format!("refraction {} 0 {IOR}", tokens(TRANSMITTANCE));
    let runs = match run(driver, "refraction_sample_f", setup, &wos) {
        Ok(r) => r,
        Err(v) => return v,
    };
    let mut cases = Cases::default();
    for (wo, records) in wos.iter().zip(&runs) {
        let input = format!(
            "sample_f(wo = {}) of RefractionBSDF(transmittance = {}, ior = {IOR}), {}",
            show(*wo),
            show(TRANSMITTANCE),
            if wo.z > 0.0 { "entering" } else { "leaving" }
        );
        for s in records {
            cases.record(match refract(*wo, IOR) {
                Some(_) => transmitted(*wo, IOR, TRANSMITTANCE, 1.0, s).map(
                    |(expected, what, mistake)| {
                        failure(input.clone(), expected, said(s), what, mistake)
                    },
                ),
                None => {
                    let black = s.f == DVec3::ZERO;
                    let reflected = same(s.wi, reflect(*wo))
                        && close(s.pdf, 1.0, REL)
                        && same_colour(s.f, TRANSMITTANCE / wo.z.abs());
                    (!black && !reflected).then(|| {
                        failure(
                            input.clone(),
                            format!(
                                "black (the course's), or *wi = {}, *pdf = 1, returning {}",
                                show(reflect(*wo)),
                                show(TRANSMITTANCE / wo.z.abs())
                            ),
                            said(s),
                            "under total internal reflection nothing refracts: the course returns black",
                            None,
                        )
                    })
                }
            });
        }
    }
    cases.verdict(None)
}

/// A refraction sample against the course's, the lobe chosen with
/// probability `pdf` and carrying `weight` (`transmittance` times `pdf`):
/// `None` when right, else what was expected, what is wrong, and the
/// mistake it is.
pub fn transmitted(
    wo: DVec3,
    ior: f64,
    weight: DVec3,
    pdf: f64,
    s: &Sample,
) -> Option<(String, &'static str, Option<Mistake>)> {
    let e = eta(wo, ior);
    let Some(want_wi) = refract(wo, ior) else {
        return Some((
            "a reflection: no direction refracts".into(),
            "a refraction under total internal reflection",
            None,
        ));
    };
    let cos_t = want_wi.z.abs();
    let want_f = weight / cos_t / (e * e);
    let expected = format!(
        "*wi = {}, *pdf = {}, returning {} (|cos theta_t| = {}, eta = {})",
        show(want_wi),
        num(pdf),
        show(want_f),
        num(cos_t),
        num(e)
    );
    let wrong = |what, mistake| Some((expected.clone(), what, mistake));
    if !same(s.wi, want_wi) {
        return match refract_inverted(wo, ior) {
            Some(d) if same(s.wi, d) => wrong(
                "*wi bends the wrong way: Snell's law with the ratio of indices upside down",
                Some(Mistake::RefractionRatioInverted),
            ),
            _ => wrong(
                "*wi is not refract(wo), the direction Snell's law gives",
                None,
            ),
        };
    }
    if !close(s.pdf, pdf, REL) {
        return wrong("*pdf is not the probability of the lobe chosen", None);
    }
    if same_colour(s.f, want_f) {
        None
    } else if same_colour(s.f, weight / cos_t) {
        wrong(
            "the transmitted value is not divided by eta^2 as the handout asks",
            Some(Mistake::NoEtaSquared),
        )
    } else if same_colour(s.f, weight / cos_t * e * e) {
        wrong(
            "the transmitted value is multiplied by eta^2 where the handout divides by it (eta inverted, or the physical radiance scaling)",
            None,
        )
    } else if same_colour(s.f, weight / (e * e)) {
        wrong(
            "the transmitted value is not divided by |cos theta_t|",
            None,
        )
    } else {
        wrong("the transmitted value is not transmittance / |cos theta_t| / eta^2 (times the lobe's probability)", None)
    }
}
