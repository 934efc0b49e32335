//! The probe of `PathTracer::at_least_one_bounce_radiance` (part 4): the
//! furnace test. Inside a closed cube whose every wall is diffuse of
//! albedo `rho` and glows `Le` the same every way (the driver's
//! `furnace`), every direction from a wall meets a wall, so with uniform
//! hemisphere sampling (`-H`) a path's `k`-th bounce brings exactly
//! `rho^k Le`. From the camera ray's hit (`r.depth = max_ray_depth = m`):
//!
//! ```text
//! A(1) = rho Le,    A(d) = rho Le + rho A(d - 1)     (accumulating: -o 1)
//! N(1) = rho Le,    N(d) = rho N(d - 1)              (-o 0: the m-th bounce alone)
//! ```
//!
//! so `A(m) = sum_{k=1..m} rho^k Le` and `N(m) = rho^m Le`, whatever the
//! Russian roulette (it divides by its probability, so the means stay).
//! The mean of many calls is z-tested against them ([`means`]), at
//! `m = 3`, with `-o 1`, and with `-o 0` where the tree has the flag
//! (`isAccumBounces`, the 2025 starter's). A failure names the catalogued
//! mistake whose recursion ([`Model`]) fits every configuration.
//!
//! [`means`]: super::means

use glam::DVec3;

use super::driver::Driver;
use super::geometry::{num, show, tokens};
use super::means::{self, always, fits, read, Moments, CALLS};
use super::verdict::{failure, Verdict};
use crate::mistakes::Mistake;

const RHO: DVec3 = DVec3::new(0.5, 0.6, 0.4);
const GLOW: DVec3 = DVec3::new(1.0, 0.5, 0.25);
/// `max_ray_depth`, and the light samples of each bounce.
const DEPTH: u32 = 3;
const NS: usize = 2;

/// How a recursion goes: its bounces, what each adds, and the mistakes
/// that change it.
#[derive(Clone, Copy, Default)]
struct Model {
    /// Bounces more (or fewer) than `max_ray_depth`.
    extra: i32,
    /// The next hit's emission added at every bounce.
    emission_every_bounce: bool,
    /// The throughput `f`, without `cos / pdf` (`rho / pi` a bounce).
    no_cos_pdf: bool,
    /// `-o 0` adding every bounce all the same.
    accumulates_anyway: bool,
}

impl Model {
    /// The mean of `at_least_one_bounce_radiance` at depth `m`.
    fn mean(self, m: u32, accumulate: bool) -> DVec3 {
        let levels = (m as i32 + self.extra).max(1);
        let accumulate = accumulate || self.accumulates_anyway;
        let carry = if self.no_cos_pdf {
            RHO / std::f64::consts::PI
        } else {
            RHO
        };
        let mut value = RHO * GLOW;
        for _ in 1..levels {
            let incoming = value
                + if self.emission_every_bounce {
                    GLOW
                } else {
                    DVec3::ZERO
                };
            let onward = carry * incoming;
            value = if accumulate {
                RHO * GLOW + onward
            } else {
                onward
            };
        }
        value
    }
}

/// The catalogued mistakes of the recursion and their models.
fn suspects() -> Vec<(Mistake, Model)> {
    vec![
        (
            Mistake::DepthOffByOne,
            Model {
                extra: 1,
                ..Model::default()
            },
        ),
        (
            Mistake::EmissionEveryBounce,
            Model {
                emission_every_bounce: true,
                ..Model::default()
            },
        ),
        (
            Mistake::ThroughputWithoutCosPdf,
            Model {
                no_cos_pdf: true,
                ..Model::default()
            },
        ),
        (
            Mistake::NoAccumulationSumsAll,
            Model {
                accumulates_anyway: true,
                ..Model::default()
            },
        ),
    ]
}

/// Probes `at_least_one_bounce_radiance`.
pub fn at_least_one_bounce(driver: &Driver) -> Verdict {
    // On the floor of the cube, seen from its middle.
    let (o, d, t) = (DVec3::new(0.1, 0.2, 0.0), DVec3::NEG_Z, 1.0);
    let call = format!(
        "bounces {CALLS} {} {} {t} {}",
        tokens(o),
        tokens(d),
        tokens(DVec3::Z)
    );
    let commands = vec![
        format!("furnace {} {}", tokens(RHO), tokens(GLOW)),
        format!("tracer {NS} {DEPTH} 1"),
        "accumulate 1".into(),
        call.clone(),
        "accumulate 0".into(),
        call,
    ];
    let t = match driver.run("at_least_one_bounce", commands) {
        Ok(t) => t,
        Err(e) => return Verdict::Broken(e),
    };
    let has_flag = match t.exactly(2, 1) {
        Ok(v) => v[0] == 1.0,
        Err(stop) => return Verdict::stopped(&stop, t.command(2)),
    };
    // The configurations, by whether they accumulate: -o 1, then -o 0
    // where the tree has the flag (without it, the 2023 starters'
    // accumulate, and the second run repeats the first).
    let configurations: Vec<(usize, bool)> = [(3, true), (5, false)]
        .into_iter()
        .filter(|(_, accumulate)| *accumulate || has_flag)
        .collect();
    let observed: Moments = match configurations.iter().map(|(at, _)| read(&t, *at)).collect() {
        Ok(m) => m,
        Err(v) => return v,
    };
    if always(&observed, DVec3::ZERO) {
        return Verdict::NotWritten(
            "it returns black every time, the starter's `return L_out;` of (0, 0, 0)".into(),
        );
    }
    if always(&observed, DVec3::ONE) {
        return Verdict::NotWritten(
            "it returns (1, 1, 1) every time, as the starter's one_bounce_radiance does".into(),
        );
    }
    let expect = |model: Model| -> Vec<DVec3> {
        configurations
            .iter()
            .map(|(_, accumulate)| model.mean(DEPTH, *accumulate))
            .collect()
    };
    let right = expect(Model::default());
    if fits(&observed, &right) {
        return Verdict::Pass {
            cases: CALLS * observed.len(),
            note: Some(format!(
                "in the furnace, {} with -o 1{}, as sum rho^k Le (largest |z| {} of {})",
                show(observed[0].0),
                if observed.len() > 1 {
                    format!(", {} with -o 0", show(observed[1].0))
                } else {
                    String::new()
                },
                num(means::largest(&observed, &right)),
                num(means::z_critical(observed.len()))
            )),
        };
    }
    let mistake = suspects()
        .into_iter()
        .find(|(_, model)| fits(&observed, &expect(*model)))
        .map(|(m, _)| m);
    let worst = means::worst(&observed, &right);
    let accumulates = configurations[worst].1;
    let flag = if accumulates { "-o 1" } else { "-o 0" };
    Verdict::Fail(failure(
        format!(
            "{CALLS} calls at the floor of a closed cube whose walls are diffuse of albedo {} and glow {} (the furnace), max_ray_depth = {DEPTH}, {flag}, -H, ns_area_light = {NS}",
            show(RHO),
            show(GLOW)
        ),
        format!(
            "a mean of {} ({})",
            show(right[worst]),
            if accumulates {
                "rho Le + rho^2 Le + rho^3 Le"
            } else {
                "rho^3 Le, the third bounce alone"
            }
        ),
        format!("a mean of {}", show(observed[worst].0)),
        format!(
            "the bounces do not add up to the furnace's radiance ({} times it)",
            show(observed[worst].0 / right[worst])
        ),
        mistake,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_recursion_sums_the_bounces() {
        let le = GLOW;
        let right = Model::default();
        let sum = RHO * le + RHO * RHO * le + RHO * RHO * RHO * le;
        assert!((right.mean(3, true) - sum).length() < 1e-12);
        assert!((right.mean(3, false) - RHO * RHO * RHO * le).length() < 1e-12);
        // One bounce more; -o 0 adding up anyway.
        let deeper = Model {
            extra: 1,
            ..Model::default()
        };
        assert!((deeper.mean(3, true) - (sum + RHO.powf(4.0) * le)).length() < 1e-12);
        let adds = Model {
            accumulates_anyway: true,
            ..Model::default()
        };
        assert!((adds.mean(3, false) - sum).length() < 1e-12);
    }
}
