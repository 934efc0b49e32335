//! The rough conductor BSDF (`materials::microfacet`) beyond its sampler,
//! which `samplers.rs` checks against its density:
//!
//! - white furnace: with `F = 1` (a purely imaginary index, `eta = 0`,
//!   `k = 1`, reflects everything at every angle), the directional albedo
//!   `integral f cos dwi`, estimated by importance sampling, is at most 1
//!   (energy conservation) and close to 1 for moderate roughness at normal
//!   incidence: single-scattering microfacet models lose the light that
//!   bounces more than once between microfacets, more at high roughness
//!   and grazing angles (observed: see the printed table);
//! - the two sampling strategies estimate the same albedo (z-tests);
//! - reciprocity `f(wo, wi) = f(wi, wo)`;
//! - `f`, `pdf` and sampled weights finite from `alpha = 1e-4` to 1 and at
//!   grazing angles and `cos = 0`.
//!
//! Seeds are fixed; each statistical test has significance
//! [`common::ALPHA`] split among its comparisons (Bonferroni).

mod common;

use common::{assert_means_agree_within, held_above_floor, z_two_sided, MeanEstimate, ALPHA};
use glam::{Vec2, Vec3};
use pathtracer::materials::{Conductor, MicrofacetSampling};
use pathtracer::math::rng::{next_2d, sampler};
use pathtracer::math::Rgb;

const STRATEGIES: [MicrofacetSampling; 2] = [
    MicrofacetSampling::HalfVector,
    MicrofacetSampling::VisibleNormals,
];

/// A conductor that reflects everything: `eta + i k = i`.
fn white(alpha: f32, sampling: MicrofacetSampling) -> Conductor {
    Conductor::new(alpha, Rgb::ZERO, Rgb::ONE, sampling)
}

fn copper(alpha: f32, sampling: MicrofacetSampling) -> Conductor {
    Conductor::new(
        alpha,
        Rgb::new(0.2, 1.0, 1.2),
        Rgb::new(3.0, 2.5, 2.4),
        sampling,
    )
}

/// The outgoing direction at `cos theta = cos_o`, azimuth 0.7.
fn outgoing(cos_o: f32) -> Vec3 {
    let s = (1.0 - cos_o * cos_o).max(0.0).sqrt();
    Vec3::new(s * 0.7f32.cos(), s * 0.7f32.sin(), cos_o)
}

/// The one-sample estimates `f cos / pdf` of the albedo (red channel),
/// 0 for a discarded draw.
fn albedo(bsdf: &Conductor, wo: Vec3, n: usize, seed: u64) -> MeanEstimate {
    let mut rng = sampler(seed, 0);
    MeanEstimate::of((0..n).map(|_| {
        bsdf.sample(wo, next_2d(&mut rng))
            .map_or(0.0, |s| f64::from(s.f.x * s.wi.z / s.pdf()))
    }))
}

#[test]
fn white_furnace_albedo_is_at_most_one() {
    let alphas = [1e-4f32, 0.01, 0.1, 0.3, 0.5, 1.0];
    let angles = [1.0f32, 0.7, 0.3, 0.05, 1e-3];
    let comparisons = alphas.len() * angles.len() * STRATEGIES.len();
    // One-sided bound at level ALPHA / comparisons (the two-sided z is larger).
    let z = z_two_sided(ALPHA / comparisons as f64);
    for (i, sampling) in STRATEGIES.into_iter().enumerate() {
        for (j, &alpha) in alphas.iter().enumerate() {
            let mut row = format!("{sampling:?} alpha {alpha}:");
            for (k, &cos_o) in angles.iter().enumerate() {
                let seed = (i * 100 + j * 10 + k) as u64;
                let e = albedo(&white(alpha, sampling), outgoing(cos_o), 160_000, seed);
                row += &format!(" {:.4} (se {:.0e})", e.mean, e.se);
                assert!(
                    e.mean <= 1.0 + z * held_above_floor("albedo", e, z, 1e-5) + 1e-5,
                    "{sampling:?}, alpha {alpha}, cos_o {cos_o}: albedo {} (se {:.2e}) above 1",
                    e.mean,
                    e.se
                );
                if alpha <= 0.5 && cos_o == 1.0 {
                    assert!(
                        e.mean >= 0.9,
                        "{sampling:?}, alpha {alpha}: albedo {} at normal incidence",
                        e.mean
                    );
                }
            }
            eprintln!("{row}");
        }
    }
}

#[test]
fn the_two_strategies_estimate_the_same_albedo() {
    let alphas = [1e-4f32, 0.01, 0.1, 0.5, 1.0];
    let angles = [1.0f32, 0.5, 0.05];
    let alpha_each = ALPHA / (alphas.len() * angles.len()) as f64;
    for (j, &alpha) in alphas.iter().enumerate() {
        for (k, &cos_o) in angles.iter().enumerate() {
            let wo = outgoing(cos_o);
            let seed = 1000 + (j * 10 + k) as u64 * 2;
            let half = albedo(&copper(alpha, STRATEGIES[0]), wo, 400_000, seed);
            let visible = albedo(&copper(alpha, STRATEGIES[1]), wo, 400_000, seed + 1);
            // Near a mirror both estimators are nearly constant (standard
            // errors down to 1e-10), below the f32 rounding of `F` and `G`
            // at the rounded half vector: a floor of 1e-5 absorbs it.
            let label =
                format!("copper, alpha {alpha}, cos_o {cos_o}: half-vector and visible-normal");
            assert_means_agree_within(&label, half, visible, alpha_each, 1e-5);
        }
    }
}

/// Pairs of directions above the surface, from uniform numbers.
fn direction_pairs(n: usize) -> impl Iterator<Item = (Vec3, Vec3)> {
    let mut rng = sampler(7, 0);
    let mut up = move || {
        let u = next_2d(&mut rng);
        let z = u.x.max(1e-3);
        let s = (1.0 - z * z).sqrt();
        let phi = 2.0 * std::f32::consts::PI * u.y;
        Vec3::new(s * phi.cos(), s * phi.sin(), z)
    };
    (0..n).map(move |_| (up(), up()))
}

#[test]
fn f_is_reciprocal() {
    for alpha in [0.05f32, 0.3, 1.0] {
        let bsdf = copper(alpha, MicrofacetSampling::VisibleNormals);
        let mut nonzero = 0;
        for (wo, wi) in direction_pairs(20_000) {
            let (a, b) = (bsdf.f(wo, wi), bsdf.f(wi, wo));
            assert!(
                (a - b).abs().max_element() <= 1e-5 * a.max_element().max(1e-6),
                "alpha {alpha}: f({wo}, {wi}) = {a}, f({wi}, {wo}) = {b}"
            );
            nonzero += usize::from(a.max_element() > 0.0);
        }
        assert!(
            nonzero > 1000,
            "alpha {alpha}: only {nonzero} pairs with f > 0"
        );
    }
}

#[test]
fn values_stay_finite_from_mirror_like_to_rough_and_at_grazing() {
    let cosines = [1.0f32, 0.5, 0.05, 1e-3, 1e-4, 0.0];
    let us = [0.0f32, 1e-7, 0.25, 0.5, 0.999, 1.0 - f32::EPSILON];
    for sampling in STRATEGIES {
        for alpha in [0.0f32, 1e-4, 1e-3, 0.01, 0.1, 0.5, 1.0] {
            let bsdf = copper(alpha, sampling);
            for &co in &cosines {
                let wo = outgoing(co);
                for &ci in &cosines {
                    for wi in [outgoing(ci), -outgoing(ci), Vec3::new(-wo.x, -wo.y, ci)] {
                        let (f, pdf) = (bsdf.f(wo, wi), bsdf.pdf(wo, wi));
                        assert!(
                            f.is_finite()
                                && f.min_element() >= 0.0
                                && pdf.is_finite()
                                && pdf >= 0.0,
                            "{sampling:?} alpha {alpha}: f {f}, pdf {pdf} at {wo}, {wi}"
                        );
                    }
                }
                for &u1 in &us {
                    for &u2 in &us {
                        let Some(s) = bsdf.sample(wo, Vec2::new(u1, u2)) else {
                            continue;
                        };
                        let w = s.weight();
                        assert!(
                            s.wi.is_finite()
                                && (s.wi.length() - 1.0).abs() < 1e-4
                                && s.wi.z > 0.0
                                && s.pdf() > 0.0
                                && s.pdf().is_finite()
                                && w.is_finite()
                                && w.min_element() >= 0.0,
                            "{sampling:?} alpha {alpha}, wo {wo}, u ({u1}, {u2}): {s:?}"
                        );
                    }
                }
            }
        }
    }
}

/// At normal incidence with a small roughness, nearly every draw of either
/// strategy lands close to the mirror direction with weight close to `F`.
#[test]
fn a_smooth_conductor_behaves_like_a_mirror() {
    for sampling in STRATEGIES {
        let bsdf = copper(1e-3, sampling);
        let wo = outgoing(0.6);
        let mirror = Vec3::new(-wo.x, -wo.y, wo.z);
        let f0 = pathtracer::materials::fresnel::conductor(wo.z, bsdf.eta, bsdf.k);
        let mut rng = sampler(3, 0);
        for _ in 0..1000 {
            let s = bsdf.sample(wo, next_2d(&mut rng)).expect("kept");
            assert!(s.wi.dot(mirror) > 1.0 - 1e-4, "{sampling:?}: {}", s.wi);
            assert!(
                (s.weight() - f0).abs().max_element() < 0.02,
                "{:?}",
                s.weight()
            );
        }
    }
}

/// The starter's `Lambda` at `a = 1 / (alpha tan theta)` against values
/// computed apart (Python's `math.erfc`, `math.exp`): 1.13194 at
/// `a = 0.1`, 0.149169 at 0.3, -0.0201 at 1, where the exact `Lambda`
/// is 2.34911, 0.523697 and 0.0251273.
#[test]
fn the_starters_lambda_has_pi_for_sqrt_pi() {
    let b = pathtracer::materials::beckmann::Beckmann::new(0.5);
    for (a, starter, exact) in [
        (0.1, 1.131_944_7, 2.349_110_5),
        (0.3, 0.149_168_93, 0.523_697_47),
        (1.0, -0.020_099_772, 0.025_127_271),
    ] {
        // tan(theta) = 1 / (alpha a).
        let tan = 1.0 / (0.5 * a);
        let w = Vec3::new(tan as f32, 0.0, 1.0).normalize();
        let got = b.starter_lambda(w);
        assert!(
            (got - starter).abs() < 1e-4 * starter.abs().max(0.1),
            "a {a}: {got}"
        );
        let exact_got = f64::from(b.lambda(w));
        assert!(
            (exact_got - exact).abs() < 1e-4 * exact.max(0.1),
            "a {a}: {exact_got}"
        );
    }
    assert_eq!(b.starter_lambda(Vec3::Z), 0.0);
    assert!(b.starter_lambda(-Vec3::Z).is_infinite());
}
