//! How often the statistical tests of `check --source`'s sampler probes
//! fail a correct function (over 10,000 seeds), and how small a wrong one
//! they catch (the share of 200 seeds that fail), each test run on
//! samples drawn here exactly as the probe runs it on a student's:
//!
//! - `DiffuseBSDF::sample_f`: directions of density `(k + 1) cos^k(theta)
//!   / (2 pi)` (Malley's method at `k` = 1) against `cos(theta) / pi`,
//!   100,000 directions in 10 x 20 cells at alpha 1e-6;
//! - `MicrofacetBSDF::sample_f`: the handout's sampler at roughness `s
//!   alpha` against the pdf at `alpha` = 0.5, 20,000 directions, alpha
//!   1e-5;
//! - `EnvironmentLight::sample_L`: texels drawn with probabilities in
//!   proportion to luminance times `sin^s theta` (`s` = 0: the tables
//!   built without the `sin theta`) against `s` = 1, 20,000 samples over
//!   128 texels, alpha 1e-5;
//! - `GlassBSDF::sample_f`: the reflection chosen with probability `s F`
//!   at the probe's five angles that refract, each an exact binomial test
//!   at alpha 1e-5.
//!
//! `cargo run --release --example probe_power`

use std::f64::consts::PI;

use glam::DVec3;
use pathtracer::check::probe::{
    density, env_sample, envmap, glass, microfacet_sample, reflection, warp,
};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

/// The share of the seeds `0..runs` for which `fails` says the test fails.
fn failing(runs: u64, fails: impl Fn(u64) -> bool) -> f64 {
    (0..runs).filter(|&seed| fails(seed)).count() as f64 / runs as f64
}

/// The diffuse probe on directions of exponent `k`.
fn diffuse(k: f64, seed: u64) -> bool {
    let mut rng = Pcg64::seed_from_u64(seed);
    let dirs: Vec<DVec3> = (0..100_000)
        .map(|_| {
            let z = rng.gen::<f64>().powf(1.0 / (k + 1.0));
            let r = (1.0 - z * z).max(0.0).sqrt();
            let phi = 2.0 * PI * rng.gen::<f64>();
            DVec3::new(r * phi.cos(), r * phi.sin(), z)
        })
        .collect();
    let h = warp::histogram(&dirs, warp::cosine(1.0 / PI));
    !warp::chi_square(&h, 1e-6).2
}

/// The microfacet probe on the handout's sampler at roughness `s alpha`,
/// its cells' masses `masses` (at `alpha`).
fn microfacet(s: f64, seed: u64, masses: &[f64]) -> bool {
    use microfacet_sample::{handout_sample, probe_wo, ALPHA, LEVEL, SAMPLES};
    let mut rng = Pcg64::seed_from_u64(seed);
    let wo = probe_wo();
    let dirs: Vec<DVec3> = (0..SAMPLES)
        .map(|_| handout_sample(wo, s * ALPHA, rng.gen(), rng.gen()))
        .collect();
    !warp::chi_square(&density::histogram(&dirs, masses), LEVEL).2
}

/// The environment probe on texels drawn in proportion to luminance
/// times `sin^s theta`.
fn environment(s: f64, seed: u64) -> bool {
    let p = envmap::probabilities();
    let weights: Vec<f64> = (0..p.len())
        .map(|k| p[k] * envmap::row_theta(k / envmap::W).sin().powf(s - 1.0))
        .collect();
    let total: f64 = weights.iter().sum();
    let cdf: Vec<f64> = weights
        .iter()
        .scan(0.0, |sum, w| {
            *sum += w / total;
            Some(*sum)
        })
        .collect();
    let mut rng = Pcg64::seed_from_u64(seed);
    let texels: Vec<(usize, usize)> = (0..env_sample::SAMPLES)
        .map(|_| {
            let u: f64 = rng.gen();
            let k = cdf.partition_point(|c| *c < u).min(cdf.len() - 1);
            (k % envmap::W, k / envmap::W)
        })
        .collect();
    let h = env_sample::texel_counts(&texels, &p);
    !warp::chi_square(&h, env_sample::LEVEL).2
}

/// The glass probe's binomial tests on reflections chosen with
/// probability `s F`.
fn glass(s: f64, seed: u64) -> bool {
    let mut rng = Pcg64::seed_from_u64(seed);
    glass::plan().iter().any(|&(wo, n)| {
        if reflection::refract(wo, glass::IOR).is_none() {
            return false;
        }
        let f = glass::schlick(wo, glass::IOR);
        let k = (0..n).filter(|_| rng.gen::<f64>() < s * f).count();
        !glass::binomial_passes(k as u64, n as u64, f).0
    })
}

/// One probe's test: the function, the parameter's name, whether the
/// test fails at a value of it (1 is right) and a seed, and the wrong
/// values tried.
struct Trial<'a> {
    function: &'a str,
    name: &'a str,
    fails: Box<dyn Fn(f64, u64) -> bool + 'a>,
    wrong: &'a [f64],
}

fn main() {
    let runs = 10_000;
    let wo = microfacet_sample::probe_wo();
    let alpha = microfacet_sample::ALPHA;
    let masses = density::cell_masses(|wi| microfacet_sample::pdf(wo, wi, alpha));
    let trials = [
        Trial {
            function: "DiffuseBSDF::sample_f",
            name: "k",
            fails: Box::new(diffuse),
            wrong: &[0.90, 0.93, 0.95, 1.05, 1.07, 1.10],
        },
        Trial {
            function: "MicrofacetBSDF::sample_f",
            name: "s",
            fails: Box::new(|s, seed| microfacet(s, seed, &masses)),
            wrong: &[0.90, 0.94, 0.96, 0.98, 1.02, 1.04, 1.06, 1.10],
        },
        Trial {
            function: "EnvironmentLight::sample_L",
            name: "s",
            fails: Box::new(environment),
            wrong: &[0.0, 0.6, 0.8, 0.9, 1.1, 1.2, 1.4],
        },
        Trial {
            function: "GlassBSDF::sample_f",
            name: "s",
            fails: Box::new(glass),
            wrong: &[0.80, 0.90, 0.95, 1.05, 1.10, 1.20],
        },
    ];
    for t in &trials {
        let correct = failing(runs, |seed| (t.fails)(1.0, seed));
        println!(
            "{}: correct ({} = 1) fails {} of {runs} seeds",
            t.function,
            t.name,
            (correct * runs as f64).round()
        );
        for value in t.wrong {
            let share = failing(200, |seed| (t.fails)(*value, 1_000_000 + seed));
            println!(
                "  {} = {value:.2}: {:.0} % of 200 seeds fail",
                t.name,
                100.0 * share
            );
        }
    }
}
