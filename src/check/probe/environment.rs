//! The probe of `EnvironmentLight::sample_dir` (part 7), on
//! [`envmap`]'s map, and the catalogue's two flips it and
//! [`env_sample`](super::env_sample) name.
//!
//! `sample_dir` must return the map's radiance along the ray: each
//! texel's own through its centre, the bilinear lookup between centres
//! (wrapping across the seam, clamped at the poles). A radiance read at
//! the direction mirrored in `u` (`z` negated) or in `v` (`y` negated) is
//! the catalogue's `env-map-u-flipped` or `env-map-v-flipped`.

use glam::DVec3;

use super::driver::Driver;
use super::envmap::{self, candidates, flip_u, flip_v, lookup, texel, xy, H, W};
use super::geometry::{show, tokens, vec_at};
use super::microfacet::near3;
use super::verdict::{failure, Cases, Verdict};
use crate::mistakes::Mistake;

/// The map positions `sample_dir` is asked about: every texel's centre,
/// then points between centres (across the seam, near the poles, beside
/// the bright texel).
fn positions() -> Vec<(f64, f64)> {
    let mut out: Vec<(f64, f64)> = (0..H)
        .flat_map(|j| (0..W).map(move |i| (i as f64 + 0.5, j as f64 + 0.5)))
        .collect();
    out.extend([
        (3.25, 2.75),
        (0.2, 4.6),
        (15.8, 3.3),
        (7.6, 0.3),
        (9.4, 7.8),
        (11.9, 2.2),
    ]);
    out
}

/// The catalogued flip whose reading `got` is, at `d`.
pub fn flipped(d: DVec3, got: DVec3) -> Option<Mistake> {
    let reads = |d: DVec3| {
        let (x, y) = xy(d);
        near3(got, lookup(x, y)) || candidates(d).iter().any(|&(i, j)| near3(got, texel(i, j)))
    };
    if reads(flip_u(d)) {
        Some(Mistake::EnvMapUFlipped)
    } else if reads(flip_v(d)) {
        Some(Mistake::EnvMapVFlipped)
    } else {
        None
    }
}

/// What a flip does, for the report.
pub fn flip_words(m: Option<Mistake>) -> &'static str {
    match m {
        Some(Mistake::EnvMapUFlipped) => {
            "the map is read with u flipped: the radiance is that of the direction mirrored in z"
        }
        Some(Mistake::EnvMapVFlipped) => {
            "the map is read with v flipped: the radiance is that of the direction mirrored in y"
        }
        _ => "the radiance is not the map's in that direction (bilinear between texel centres)",
    }
}

/// Probes `EnvironmentLight::sample_dir`.
pub fn sample_dir(driver: &Driver) -> Verdict {
    let points = positions();
    let commands = points
        .iter()
        .map(|&(x, y)| format!("env_dir {}", tokens(envmap::direction(x, y))))
        .collect();
    let t = match envmap::run(driver, "environment_sample_dir", commands) {
        Ok(t) => t,
        Err(v) => return v,
    };
    let mut cases = Cases::default();
    let mut stub_like = true;
    for (k, &(x, y)) in points.iter().enumerate() {
        let got = match t.exactly(k + 1, 3) {
            Ok(v) => vec_at(&v, 0),
            Err(stop) => return Verdict::stopped(&stop, t.command(k + 1)),
        };
        stub_like &= got == DVec3::ZERO;
        let d = envmap::direction(x, y);
        let want = lookup(x, y);
        cases.record((!near3(got, want)).then(|| {
            let mistake = flipped(d, got);
            failure(
                format!(
                    "sample_dir(Ray(0, {})), map position ({x}, {y}) of {W} x {H}",
                    show(d)
                ),
                if x.fract() == 0.5 && y.fract() == 0.5 {
                    format!("{}, texel ({}, {})", show(want), x.floor(), y.floor())
                } else {
                    format!("{} (bilinear)", show(want))
                },
                show(got),
                flip_words(mistake),
                mistake,
            )
        }));
    }
    if stub_like {
        return Verdict::NotWritten(
            "it returns black for every ray, the starter's `return Vector3D();`".into(),
        );
    }
    cases.verdict(None)
}
