//! Variance of the one-sample estimator of a rough conductor's directional
//! albedo, `f cos(theta_i) / p` (0 for a discarded draw), under half-vector
//! sampling (Walter et al. 2007) and visible-normal sampling (Heitz and
//! d'Eon 2014), for a conductor with `F = 1` (index `i`), so that the
//! variance comes from the sampling strategy alone.
//!
//! Run: `cargo run --release --example microfacet_variance`. Prints a
//! Markdown table: roughness, `cos(theta_o)`, albedo, the variance of one
//! sample under each strategy, and their ratio (the gain of visible
//! normals). Seeds are fixed, so the table is reproducible.

use glam::Vec3;
use pathtracer::materials::{Conductor, MicrofacetSampling};
use pathtracer::math::rng::{next_2d, sampler};
use pathtracer::math::Rgb;

/// Samples per configuration.
const N: usize = 1_000_000;

/// Mean and variance of the one-sample albedo estimator.
fn moments(alpha: f32, cos_o: f32, sampling: MicrofacetSampling, seed: u64) -> (f64, f64) {
    let bsdf = Conductor::new(alpha, Rgb::ZERO, Rgb::ONE, sampling);
    let s = (1.0 - cos_o * cos_o).max(0.0).sqrt();
    let wo = Vec3::new(s, 0.0, cos_o);
    let mut rng = sampler(seed, 0);
    let (mut s1, mut s2) = (0.0f64, 0.0f64);
    for _ in 0..N {
        let x = bsdf
            .sample(wo, next_2d(&mut rng))
            .map_or(0.0, |b| f64::from(b.weight().x));
        s1 += x;
        s2 += x * x;
    }
    let mean = s1 / N as f64;
    (
        mean,
        (s2 / N as f64 - mean * mean).max(0.0) * N as f64 / (N - 1) as f64,
    )
}

fn main() {
    println!("| alpha | cos theta_o | albedo | variance, half vector | variance, visible normals | ratio |");
    println!("| --- | --- | --- | --- | --- | --- |");
    for (i, alpha) in [0.01f32, 0.1, 0.3, 0.5, 1.0].into_iter().enumerate() {
        for (j, cos_o) in [1.0f32, 0.7, 0.3, 0.1, 0.02].into_iter().enumerate() {
            let seed = (10 * i + j) as u64;
            let (mean, half) = moments(alpha, cos_o, MicrofacetSampling::HalfVector, seed);
            let (_, visible) = moments(alpha, cos_o, MicrofacetSampling::VisibleNormals, seed);
            // Below 1e-9 the visible-normal estimator is constant up to
            // rounding (its weight F G / G1 is 1 when nothing is masked).
            let ratio = if visible > 1e-9 {
                format!("{:.1}", half / visible)
            } else if half > 1e-9 {
                "constant".into()
            } else {
                "-".into()
            };
            println!("| {alpha} | {cos_o} | {mean:.4} | {half:.2e} | {visible:.2e} | {ratio} |");
        }
    }
}
