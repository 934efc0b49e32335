//! The probes of `DiffuseBSDF::f` and `DiffuseBSDF::sample_f` (part 3).
//!
//! `f` is the albedo over pi for any pair of directions above the
//! surface. `sample_f` must return directions above the surface, of unit
//! length, the pdf of each, and `f(wo, wi)`; the pdfs it returns must be a
//! density that integrates to 1 over the hemisphere (the course's cosine
//! sampler's `cos(theta) / pi`, or a constant `1 / (2 pi)`), and the
//! directions must be distributed by it ([`warp`]'s chi-square test at
//! `alpha` = 1e-6). Then `f cos(theta) / pdf` averages to the albedo.

use std::f64::consts::PI;

use glam::DVec3;

use super::driver::Driver;
use super::geometry::{close, num, show, tokens, vec_at};
use super::verdict::{failure, Cases, Verdict};
use super::{picture, warp};
use crate::mistakes::Mistake;

const ALBEDO: DVec3 = DVec3::new(0.2, 0.5, 0.8);

/// How many directions `sample_f` is asked for.
const SAMPLES: usize = 100_000;

/// The chi-square test's level: a correct sampler fails it once in 1e6
/// (measured: examples/probe_power.rs).
const ALPHA: f64 = 1e-6;

/// Pairs of directions above the surface.
fn pairs() -> Vec<(DVec3, DVec3)> {
    let d = |x: f64, y: f64, z: f64| DVec3::new(x, y, z).normalize();
    vec![
        (DVec3::Z, DVec3::Z),
        (d(0.3, -0.2, 0.9), d(-0.5, 0.1, 0.4)),
        (d(0.9, 0.1, 0.05), d(0.0, -0.7, 0.7)),
        (d(-0.2, 0.6, 0.3), d(0.8, 0.3, 0.1)),
    ]
}

/// Probes `DiffuseBSDF::f`.
pub fn f(driver: &Driver) -> Verdict {
    let mut commands = vec![format!("diffuse {}", tokens(ALBEDO))];
    commands.extend(
        pairs()
            .iter()
            .map(|(wo, wi)| format!("f {} {}", tokens(*wo), tokens(*wi))),
    );
    let t = match driver.run("diffuse_f", commands) {
        Ok(t) => t,
        Err(e) => return Verdict::Broken(e),
    };
    let want = ALBEDO / PI;
    let mut cases = Cases::default();
    let mut stub_like = true;
    for (k, (wo, wi)) in pairs().iter().enumerate() {
        let got = match t.exactly(k + 1, 3) {
            Ok(v) => vec_at(&v, 0),
            Err(stop) => return Verdict::stopped(&stop, t.command(k + 1)),
        };
        stub_like &= got == DVec3::ONE;
        let right = (0..3).all(|c| close(got[c], want[c], 1e-9));
        cases.record((!right).then(|| {
            let albedo = (0..3).all(|c| close(got[c], ALBEDO[c], 1e-9));
            failure(
                format!(
                    "f(wo = {}, wi = {}) with reflectance {}",
                    show(*wo),
                    show(*wi),
                    show(ALBEDO)
                ),
                format!("{} (reflectance / pi)", show(want)),
                show(got),
                "the diffuse BRDF is not the reflectance over pi",
                albedo.then_some(Mistake::BrdfIsAlbedo),
            )
        }));
    }
    if stub_like {
        return Verdict::NotWritten(
            "it returns 1 for every pair, the starter's `return Vector3D(1.0);`".into(),
        );
    }
    cases.verdict(None)
}

/// Probes `DiffuseBSDF::sample_f`.
pub fn sample_f(driver: &Driver) -> Verdict {
    let wo = DVec3::new(0.3, -0.2, 0.9).normalize();
    let commands = vec![
        format!("diffuse {}", tokens(ALBEDO)),
        format!("sample {} {SAMPLES}", tokens(wo)),
    ];
    let t = match driver.run("diffuse_sample_f", commands) {
        Ok(t) => t,
        Err(e) => return Verdict::Broken(e),
    };
    let v = match t.exactly(1, 7 * SAMPLES) {
        Ok(v) => v,
        Err(stop) => return Verdict::stopped(&stop, t.command(1)),
    };
    let samples: Vec<(DVec3, f64, DVec3)> = v
        .chunks(7)
        .map(|s| (vec_at(s, 0), s[3], vec_at(s, 4)))
        .collect();
    if samples.iter().all(|(wi, ..)| wi.is_nan()) {
        return Verdict::NotWritten(
            "it sets neither *wi nor *pdf, the starter's `return Vector3D(1.0);`".into(),
        );
    }
    let input = format!(
        "sample_f(wo = {}) with reflectance {}, {SAMPLES} times",
        show(wo),
        show(ALBEDO)
    );
    let mut cases = Cases::default();
    let want_f = ALBEDO / PI;
    for (wi, pdf, f) in &samples {
        let what = if !wi.is_finite() || !close(wi.length(), 1.0, 1e-6) {
            "a direction that is not unit length"
        } else if wi.z < 0.0 {
            "a direction below the surface"
        } else if !(pdf.is_finite() && *pdf > 0.0) {
            "a pdf that is not a positive number"
        } else if !(0..3).all(|c| close(f[c], want_f[c], 1e-9)) {
            "the value returned is not f(wo, *wi), the reflectance over pi"
        } else {
            cases.record(None);
            continue;
        };
        cases.record(Some(failure(
            input.clone(),
            format!(
                "*wi unit with wi.z >= 0, *pdf > 0, returning {}",
                show(want_f)
            ),
            format!(
                "*wi = {}, *pdf = {}, returning {}",
                show(*wi),
                num(*pdf),
                show(*f)
            ),
            what,
            None,
        )));
    }
    if !cases.all_pass() {
        return cases.verdict(None);
    }
    distribution(driver, &input, &samples)
}

/// The pdfs the function returned, read as a density, and the directions
/// tested against it.
fn distribution(driver: &Driver, input: &str, samples: &[(DVec3, f64, DVec3)]) -> Verdict {
    let cosine = samples
        .iter()
        .all(|(wi, pdf, _)| close(*pdf, wi.z / PI, 1e-6));
    let first = samples[0].1;
    let constant = samples.iter().all(|(_, pdf, _)| close(*pdf, first, 1e-9));
    // The density's name and its integral over the hemisphere.
    let (name, integral, hist) = if cosine {
        let dirs: Vec<DVec3> = samples.iter().map(|s| s.0).collect();
        (
            "cos(theta) / pi",
            1.0,
            warp::histogram(&dirs, warp::cosine(1.0 / PI)),
        )
    } else if constant {
        let dirs: Vec<DVec3> = samples.iter().map(|s| s.0).collect();
        (
            "a constant",
            first * 2.0 * PI,
            warp::histogram(&dirs, warp::constant(1.0 / (2.0 * PI))),
        )
    } else {
        let ratio = samples
            .iter()
            .map(|(wi, pdf, _)| pdf / (wi.z / PI))
            .fold(0.0, f64::max);
        let (wi, pdf, _) = samples[0];
        return Verdict::Fail(failure(
            input,
            format!("*pdf = cos(theta) / pi = {} for *wi = {}", num(wi.z / PI), show(wi)),
            format!("*pdf = {}", num(pdf)),
            format!("the pdfs returned are neither cos(theta) / pi nor a constant (up to {} times cos(theta) / pi)", num(ratio)),
            None,
        ));
    };
    if !close(integral, 1.0, 1e-6) {
        return Verdict::Fail(failure(
            input,
            "a pdf that integrates to 1 over the hemisphere",
            format!(
                "{name} = {} at theta = 0, integrating to {}",
                num(samples[0].1.max(first)),
                num(integral)
            ),
            "the pdf returned is not a probability density",
            None,
        ));
    }
    picture::save(
        &driver.work,
        "DiffuseBSDF::sample_f",
        &picture::hemisphere(&hist),
    );
    let (stat, dof, pass) = warp::chi_square(&hist, ALPHA);
    if !pass {
        return Verdict::Fail(failure(
            input,
            format!("directions distributed as the pdf returned, {name}"),
            format!("chi-square {} with {dof} degrees of freedom", num(stat)),
            "the directions do not follow the pdf returned (Nori's chi-square test, alpha 1e-6)",
            None,
        ));
    }
    Verdict::Pass {
        cases: samples.len(),
        note: Some(format!(
            "pdf {name}; chi-square {} on {dof} degrees of freedom",
            num(stat)
        )),
    }
}
