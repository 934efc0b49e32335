//! The probe of `PathTracer::raytrace_pixel` (parts 1 and 5): a camera
//! inside a black furnace, a closed cube whose walls glow `Le` and reflect
//! nothing (the driver's `furnace` with albedo 0), so every camera sample
//! brings exactly `Le` whatever the bounces: a pixel's value must be `Le`,
//! and its count the samples it averaged.
//!
//! - With `samplesPerBatch = ns_aa` (no test before the end) every pixel
//!   takes all `ns_aa = 64` samples: count 64, value `Le`.
//! - With batches of 8 and `maxTolerance` 0.05, the samples agree (`sigma
//!   = 0`, so `I = 1.96 sigma / sqrt(n) = 0 <= maxTolerance mu`): adaptive
//!   sampling stops at the first test, count 8 (up to 16 allowed), value
//!   `Le`, or `Le (n + 1) / n` for the staff's library, which sums the next
//!   sample too (maintainers/checker.md, part 5).
//!
//! - In a grey furnace of albedo 0.9 at `max_ray_depth = 1` (`-H`, one
//!   light sample), a sample is `Le (1 + 2 rho cos theta)` with `cos
//!   theta` uniform: `sigma / mu = 0.27`. With `ns_aa = 256`, batches of
//!   64 and `maxTolerance` 0.03, `I / mu = 1.96 (0.27) / sqrt(n)` is 0.067,
//!   0.047 and 0.039 at the three tests: no pixel stops (count 256). An
//!   `I` over `n` instead of `sqrt(n)` is 0.008 at the first: every pixel
//!   stops at 64.
//!
//! A count left at `ns_aa` with the value `Le n / ns_aa` is the catalogued
//! `adaptive-count-not-updated`; stopping at 64 in the grey furnace,
//! `adaptive-n-not-square-rooted`. `adaptive-population-variance` (`n`
//! for `n - 1`) moves the stopping time by too little to tell: the image
//! checks of part 5 judge it.

use glam::DVec3;

use super::driver::Driver;
use super::geometry::{close, show, tokens};
use super::verdict::{failure, Cases, Verdict};
use crate::mistakes::Mistake;

const GLOW: DVec3 = DVec3::new(1.0, 0.5, 0.25);
/// The starter's placeholder colour.
const PLACEHOLDER: DVec3 = DVec3::new(0.2, 1.0, 0.8);
const NS_AA: usize = 64;
const BATCH: usize = 8;
/// The pixels traced, a 4 x 4 block in the middle of a 480 x 360 frame
/// (the staff's library stamps its mark over the bottom-left corner).
const SIDE: usize = 4;
const BLOCK: &str = "238 178 242 182";
/// The grey furnace's albedo, and its pixels' samples, batch, tolerance.
const GREY: f64 = 0.9;
const NOISY_AA: usize = 256;
const NOISY_BATCH: usize = 64;
const NOISY_TOLERANCE: f64 = 0.03;

/// Probes `raytrace_pixel`.
pub fn raytrace_pixel(driver: &Driver) -> Verdict {
    let commands = vec![
        format!("furnace {} {}", tokens(DVec3::ZERO), tokens(GLOW)),
        "tracer 1 1 1".into(),
        "accumulate 1".into(),
        // Inside the cube: 0.5 from its centre, looking at it.
        "camera 50 40 480 360 0 0 0 0.3 1.2 0.5 0.01 100".into(),
        format!("pixels 480 360 {NS_AA} {NS_AA} 0.05 {BLOCK}"),
        format!("pixels 480 360 {NS_AA} {BATCH} 0.05 {BLOCK}"),
        format!(
            "furnace {} {}",
            tokens(DVec3::splat(GREY)),
            tokens(DVec3::ONE)
        ),
        "tracer 1 1 1".into(),
        "accumulate 1".into(),
        format!("pixels 480 360 {NOISY_AA} {NOISY_BATCH} {NOISY_TOLERANCE} {BLOCK}"),
    ];
    let t = match driver.run("raytrace_pixel", commands) {
        Ok(t) => t,
        Err(e) => return Verdict::Broken(e),
    };
    let mut runs = Vec::new();
    for at in [4, 5, 9] {
        match t.exactly(at, 4 * SIDE * SIDE) {
            Ok(v) => runs.push(
                v.chunks(4)
                    .map(|p| (DVec3::new(p[0], p[1], p[2]), p[3]))
                    .collect::<Vec<_>>(),
            ),
            Err(stop) => return Verdict::stopped(&stop, t.command(at)),
        }
    }
    let near = |a: DVec3, b: DVec3| (0..3).all(|c| close(a[c], b[c], 1e-9));
    if runs.iter().flatten().all(|(v, _)| near(*v, PLACEHOLDER)) {
        return Verdict::NotWritten(
            "every pixel is the starter's placeholder colour (0.2, 1, 0.8)".into(),
        );
    }
    let input = |batch: usize| {
        format!(
            "raytrace_pixel of the {SIDE} x {SIDE} pixels at (238, 178) of a 480 x 360 image from inside a closed box whose walls glow {} and reflect nothing, ns_aa = {NS_AA}, samplesPerBatch = {batch}, maxTolerance = 0.05",
            show(GLOW)
        )
    };
    let mut cases = Cases::default();
    for (v, n) in &runs[0] {
        cases.record((!(near(*v, GLOW) && *n == NS_AA as f64)).then(|| {
            failure(
                input(NS_AA),
                format!(
                    "each pixel {} (every sample brings it), count {NS_AA}",
                    show(GLOW)
                ),
                format!("{}, count {n}", show(*v)),
                if near(*v, GLOW) {
                    "the count written is not the samples taken"
                } else {
                    "the value written is not the mean of the pixel's samples"
                },
                None,
            )
        }));
    }
    if !cases.all_pass() {
        return cases.verdict(None);
    }
    let adaptive = &runs[1];
    if adaptive
        .iter()
        .all(|(v, n)| near(*v, GLOW) && *n == NS_AA as f64)
    {
        return Verdict::NotWritten(
            "every pixel takes all ns_aa samples though they all agree: adaptive sampling is not written yet".into(),
        );
    }
    for (v, n) in adaptive {
        let stopped = *n >= 1.0 && *n <= 2.0 * BATCH as f64;
        let right = stopped && (near(*v, GLOW) || near(*v, GLOW * (n + 1.0) / n));
        let unupdated =
            *n == NS_AA as f64 && (1..=2 * BATCH).any(|k| near(*v, GLOW * k as f64 / NS_AA as f64));
        cases.record((!right).then(|| {
            failure(
                input(BATCH),
                format!(
                    "each pixel stopping at its first test (its samples agree: I = 0), count {BATCH}, value {}",
                    show(GLOW)
                ),
                format!("{}, count {n}", show(*v)),
                if unupdated {
                    "the pixel stops early but its count is left at ns_aa"
                } else if stopped {
                    "the value written is not the mean of the samples taken"
                } else {
                    "the pixel does not stop at a test its agreeing samples pass"
                },
                unupdated.then_some(Mistake::AdaptiveCountNotUpdated),
            )
        }));
    }
    if !cases.all_pass() {
        return cases.verdict(None);
    }
    let noisy = &runs[2];
    let at_first = noisy
        .iter()
        .all(|(_, n)| *n >= NOISY_BATCH as f64 && *n <= NOISY_BATCH as f64 + 1.0);
    for (v, n) in noisy {
        cases.record((*n != NOISY_AA as f64).then(|| {
            failure(
                format!(
                    "raytrace_pixel of the {SIDE} x {SIDE} pixels at (238, 178) of a 480 x 360 image in a closed box of albedo {GREY} glowing (1, 1, 1), max_ray_depth = 1, -H, ns_aa = {NOISY_AA}, samplesPerBatch = {NOISY_BATCH}, maxTolerance = {NOISY_TOLERANCE}"
                ),
                format!(
                    "no pixel stopping: sigma / mu is about 0.27, so 1.96 sigma / sqrt(n) stays above {NOISY_TOLERANCE} mu at n = 64, 128 and 192; count {NOISY_AA}"
                ),
                format!("{}, count {n}", show(*v)),
                if at_first {
                    "the pixels stop at the first test, where 1.96 sigma / sqrt(n) is still twice the tolerance: I is divided by n, not sqrt(n)"
                } else {
                    "noisy pixels stop before 1.96 sigma / sqrt(n) falls under maxTolerance mu"
                },
                at_first.then_some(Mistake::AdaptiveNotSquareRooted),
            )
        }));
    }
    let counts: Vec<String> = {
        let mut c: Vec<i64> = adaptive.iter().map(|(_, n)| *n as i64).collect();
        c.sort_unstable();
        c.dedup();
        c.iter().map(i64::to_string).collect()
    };
    cases.verdict(Some(format!(
        "every pixel {} from {NS_AA} samples; with batches of {BATCH} each stops, count {}; noisy pixels take all {NOISY_AA}",
        show(GLOW),
        counts.join(" or ")
    )))
}
