//! The probe of `EnvironmentLight::sample_L` (part 7), through the
//! driver's `envmap` (which constructs the light, so runs `init`), on
//! [`envmap`]'s map.
//!
//! `sample_L` must draw texel `(i, j)` with its probability `P` (the
//! starter's `pdf_envmap`, normalised) and return a direction in it (its
//! centre, its corner, or any point of it), an infinite `*distToLight`,
//! the radiance there (the texel's, or the lookup's at the direction),
//! and the handout's density per steradian
//! `*pdf = P w h / (2 pi^2 sin theta)`, `theta` the direction's or the
//! texel's centre's. The directions are chi-square-tested per texel
//! against `P` (at `alpha` = 1e-5; a pole's row pooled into one cell when
//! directions land on the pole, where the column is lost).
//!
//! A density without the `sin theta`, or without the `2 pi^2`, is the
//! catalogue's `env-pdf-no-sin` or `env-pdf-no-jacobian`; a direction
//! mirrored in `u` or `v` ([`environment`](super::environment)'s flips),
//! `env-map-u-flipped` or `env-map-v-flipped`.

use std::f64::consts::PI;

use glam::DVec3;

use super::driver::Driver;
use super::environment::{flip_words, flipped};
use super::envmap::{self, candidates, lookup, probabilities, texel, xy, H, W};
use super::geometry::{num, show, vec_at};
use super::microfacet::{near, near3};
use super::picture;
use super::verdict::{failure, Cases, Failure, Verdict};
use super::warp::{self, Histogram};
use crate::mistakes::Mistake;

/// The samples the chi-square test takes, and its level.
pub const SAMPLES: usize = 20_000;
pub const LEVEL: f64 = 1e-5;

/// One record of `env_sample`.
struct LightSample {
    wi: DVec3,
    dist: f64,
    pdf: f64,
    l: DVec3,
}

/// Probes `EnvironmentLight::sample_L`.
pub fn sample_l(driver: &Driver) -> Verdict {
    let commands = vec![format!("env_sample {SAMPLES}")];
    let t = match envmap::run(driver, "environment_sample_L", commands) {
        Ok(t) => t,
        Err(v) => return v,
    };
    let records: Vec<LightSample> = match t.exactly(1, 8 * SAMPLES) {
        Ok(v) => v
            .chunks(8)
            .map(|s| LightSample {
                wi: vec_at(s, 0),
                dist: s[3],
                pdf: s[4],
                l: vec_at(s, 5),
            })
            .collect(),
        Err(stop) => return Verdict::stopped(&stop, t.command(stop.at)),
    };
    let uniform = 1.0 / (4.0 * PI);
    if records.iter().all(|s| near(s.pdf, uniform)) {
        let black = records.iter().all(|s| s.l == DVec3::ZERO);
        return Verdict::NotWritten(if black {
            "it samples uniformly (*pdf = 1 / (4 pi)) and returns black, the starter's body".into()
        } else {
            "it samples uniformly (*pdf = 1 / (4 pi)), the handout's first step: importance sampling is not written yet".into()
        });
    }
    let p = probabilities();
    let input = format!("sample_L(p = (0, 0, 0)) with the {W} x {H} map, {SAMPLES} times");
    let mut cases = Cases::default();
    let mut texels = Vec::with_capacity(records.len());
    for s in &records {
        match judge(s, &p) {
            Ok(t) => {
                texels.push(t);
                cases.record(None);
            }
            Err(f) => cases.record(Some(Failure {
                input: input.clone(),
                ..f
            })),
        }
    }
    if !cases.all_pass() {
        return cases.verdict(None);
    }
    let counts = texel_counts(&texels, &p);
    picture::save(
        &driver.work,
        "EnvironmentLight::sample_L",
        &picture::texels(&counts, W, H),
    );
    let (stat, dof, pass) = warp::chi_square(&pooled(&records, &counts), LEVEL);
    if !pass {
        return Verdict::Fail(failure(
            input,
            "directions in each texel as often as its probability (luminance times sin theta, normalised)",
            format!("chi-square {} with {dof} degrees of freedom", num(stat)),
            "the texels are not drawn with the map's probabilities (chi-square test, alpha 1e-5)",
            None,
        ));
    }
    let bright = texels.iter().filter(|t| **t == envmap::BRIGHT).count();
    Verdict::Pass {
        cases: records.len(),
        note: Some(format!(
            "chi-square {} on {dof} degrees of freedom; the bright texel drawn {bright} times, {} expected",
            num(stat),
            num(p[envmap::BRIGHT.1 * W + envmap::BRIGHT.0] * SAMPLES as f64)
        )),
    }
}

/// One sample: its texel, or what is wrong (input filled in by the
/// caller).
fn judge(s: &LightSample, p: &[f64]) -> Result<(usize, usize), Failure> {
    let said = format!(
        "*wi = {}, *distToLight = {}, *pdf = {}, returning {}",
        show(s.wi),
        num(s.dist),
        num(s.pdf),
        show(s.l)
    );
    let fail = |expected: String, what: &str, mistake| {
        Err(failure("", expected, said.clone(), what, mistake))
    };
    if !s.wi.is_finite() || (s.wi.length() - 1.0).abs() > 1e-6 {
        return fail("*wi a unit vector".into(), "*wi is not a unit vector", None);
    }
    if s.dist.is_nan() || s.dist < 1e30 {
        return fail(
            "*distToLight = INF_D".into(),
            "*distToLight is not infinite: the light is at infinity",
            None,
        );
    }
    let around = candidates(s.wi);
    let (x, y) = xy(s.wi);
    let by_radiance = around
        .iter()
        .copied()
        .find(|&(i, j)| near3(s.l, texel(i, j)));
    if by_radiance.is_none() && !near3(s.l, lookup(x, y)) {
        let mistake = flipped(s.wi, s.l);
        let (i, j) = around[0];
        return fail(
            format!(
                "the map's radiance where *wi points: texel ({i}, {j})'s {}, or the bilinear lookup there, {}",
                show(texel(i, j)),
                show(lookup(x, y))
            ),
            if mistake.is_some() {
                flip_words(mistake)
            } else {
                "the radiance returned is not the map's where *wi points"
            },
            mistake,
        );
    }
    let theta = s.wi.normalize().y.clamp(-1.0, 1.0).acos();
    let k = |(i, j): (usize, usize)| p[j * W + i] * (W * H) as f64;
    let jacobian = 2.0 * PI * PI;
    let right = |t: (usize, usize)| {
        let centre = envmap::row_theta(t.1).sin();
        near(s.pdf, k(t) / (jacobian * theta.sin())) || near(s.pdf, k(t) / (jacobian * centre))
    };
    let order: Vec<(usize, usize)> = by_radiance
        .into_iter()
        .chain(around.iter().copied())
        .collect();
    if let Some(t) = order.iter().copied().find(|t| right(*t)) {
        return Ok(t);
    }
    let t = order[0];
    let centre = envmap::row_theta(t.1).sin();
    let expected = format!(
        "*pdf = P w h / (2 pi^2 sin theta) = {} (texel ({}, {}), P = {}, theta = {})",
        num(k(t) / (jacobian * theta.sin())),
        t.0,
        t.1,
        num(p[t.1 * W + t.0]),
        num(theta)
    );
    let (what, mistake) = if order.iter().any(|t| near(s.pdf, k(*t) / jacobian)) {
        (
            "*pdf has no 1 / sin theta: the lat-long map's Jacobian is 2 pi^2 sin theta",
            Some(Mistake::EnvPdfNoSin),
        )
    } else if order
        .iter()
        .any(|t| near(s.pdf, k(*t) / theta.sin()) || near(s.pdf, k(*t) / centre))
    {
        (
            "*pdf has no 1 / (2 pi^2): the lat-long map's Jacobian is 2 pi^2 sin theta",
            Some(Mistake::EnvPdfNoJacobian),
        )
    } else if order.iter().any(|t| near(s.pdf, p[t.1 * W + t.0])) {
        ("*pdf is the texel's probability, not a density per steradian: it needs the w h / (2 pi^2 sin theta) of the map's Jacobian", None)
    } else {
        (
            "*pdf is not the texel's probability times w h / (2 pi^2 sin theta)",
            None,
        )
    };
    fail(expected, what, mistake)
}

/// The directions' texels against their probabilities, each texel a
/// cell, row by row.
pub fn texel_counts(texels: &[(usize, usize)], p: &[f64]) -> Histogram {
    let mut observed = vec![0.0; W * H];
    for &(i, j) in texels {
        observed[j * W + i] += 1.0;
    }
    let n = texels.len() as f64;
    Histogram {
        observed,
        expected: p.iter().map(|q| n * q).collect(),
    }
}

/// `counts` ([`texel_counts`]) with a pole's row one cell when a
/// direction lies on that pole (its column is lost there).
fn pooled(records: &[LightSample], counts: &Histogram) -> Histogram {
    let pooled: Vec<usize> = [0, H - 1]
        .into_iter()
        .filter(|&j| {
            records
                .iter()
                .any(|s| envmap::at_pole(s.wi) && (s.wi.y > 0.0) == (j == 0))
        })
        .collect();
    let mut h = Histogram {
        observed: Vec::new(),
        expected: Vec::new(),
    };
    for j in 0..H {
        let row = j * W..(j + 1) * W;
        let (o, e) = (&counts.observed[row.clone()], &counts.expected[row]);
        if pooled.contains(&j) {
            h.observed.push(o.iter().sum());
            h.expected.push(e.iter().sum());
        } else {
            h.observed.extend(o);
            h.expected.extend(e);
        }
    }
    h
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::probe::envmap::{flip_u, flip_v};

    /// A sample of texel `(i, j)` at map position `(x, y)` with the
    /// handout's density at the direction's `theta`.
    fn sample(i: usize, j: usize, x: f64, y: f64, l: DVec3) -> LightSample {
        let p = probabilities()[j * W + i];
        let wi = envmap::direction(x, y);
        let theta = wi.y.clamp(-1.0, 1.0).acos();
        LightSample {
            wi,
            dist: f64::INFINITY,
            pdf: p * (W * H) as f64 / (2.0 * PI * PI * theta.sin()),
            l,
        }
    }

    #[test]
    fn centres_corners_and_points_inside_a_texel_all_pass() {
        let p = probabilities();
        let centre = sample(5, 3, 5.5, 3.5, texel(5, 3));
        assert_eq!(judge(&centre, &p).ok(), Some((5, 3)));
        // The top-left corner, the radiance the texel's own.
        let corner = sample(5, 3, 5.0, 3.0, texel(5, 3));
        assert_eq!(judge(&corner, &p).ok(), Some((5, 3)));
        // A corner of row 0 is the pole: its column is lost, its pdf infinite.
        let pole = sample(9, 0, 9.0, 0.0, texel(9, 0));
        assert!(pole.pdf.is_infinite());
        assert_eq!(judge(&pole, &p).ok(), Some((9, 0)));
        // Inside the texel, with the lookup's radiance there.
        let inside = sample(5, 3, 5.3, 3.9, lookup(5.3, 3.9));
        assert_eq!(judge(&inside, &p).ok(), Some((5, 3)));
    }

    #[test]
    fn the_catalogued_mistakes_are_named() {
        let p = probabilities();
        let right = || sample(5, 3, 5.3, 3.9, lookup(5.3, 3.9));
        let (wi, pdf) = (right().wi, right().pdf);
        let theta = wi.y.acos();
        let wrong = [
            (pdf * theta.sin(), wi, Mistake::EnvPdfNoSin),
            (pdf * 2.0 * PI * PI, wi, Mistake::EnvPdfNoJacobian),
            // The direction mirrored, the radiance and pdf the texel's own.
            (pdf, flip_u(wi), Mistake::EnvMapUFlipped),
            (pdf, flip_v(wi), Mistake::EnvMapVFlipped),
        ];
        for (pdf, wi, mistake) in wrong {
            let s = LightSample { wi, pdf, ..right() };
            assert_eq!(judge(&s, &p).unwrap_err().mistake, Some(mistake));
        }
    }
}
