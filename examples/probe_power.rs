//! How often the sampler probes' chi-square test (`check --source`,
//! `check::probe::warp`) fails a correct sampler, and how small a wrong
//! distribution it catches: cosine-weighted directions (Malley's method)
//! from 10,000 seeds, then directions of density `(k + 1) cos^k(theta) /
//! (2 pi)` for `k` near 1, each tested as the probe does (100,000
//! directions, 10 x 20 cells, alpha 1e-6) against `cos(theta) / pi`.
//!
//! `cargo run --release --example probe_power`

use std::f64::consts::PI;

use glam::DVec3;
use pathtracer::check::probe::warp;
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

/// The probe's sample count and level.
const N: usize = 100_000;
const ALPHA: f64 = 1e-6;

/// `N` directions of density `(k + 1) cos^k / (2 pi)`: `cos(theta) =
/// xi^(1 / (k + 1))`.
fn directions(k: f64, seed: u64) -> Vec<DVec3> {
    let mut rng = Pcg64::seed_from_u64(seed);
    (0..N)
        .map(|_| {
            let z = rng.gen::<f64>().powf(1.0 / (k + 1.0));
            let r = (1.0 - z * z).max(0.0).sqrt();
            let phi = 2.0 * PI * rng.gen::<f64>();
            DVec3::new(r * phi.cos(), r * phi.sin(), z)
        })
        .collect()
}

/// The share of `runs` seeds whose directions of exponent `k` fail.
fn failing(k: f64, runs: u64) -> f64 {
    let failed = (0..runs)
        .filter(|&seed| {
            let h = warp::histogram(&directions(k, seed), warp::cosine(1.0 / PI));
            !warp::chi_square(&h, ALPHA).2
        })
        .count();
    failed as f64 / runs as f64
}

fn main() {
    let runs = 10_000;
    println!(
        "correct (k = 1): {} of {runs} seeds fail (alpha {ALPHA})",
        (failing(1.0, runs) * runs as f64).round()
    );
    println!("k      share of 200 seeds that fail");
    for k in [0.90, 0.93, 0.95, 0.96, 0.97, 1.03, 1.04, 1.05, 1.07, 1.10] {
        println!("{k:.2}   {:.3}", failing(k, 200));
    }
}
