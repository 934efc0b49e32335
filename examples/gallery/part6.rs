//! Part 6 (mirror, glass and microfacet materials), the figures of
//! docs/07-materials.md:
//!
//! ```text
//! cargo run --release --example gallery -- part6
//! ```
//!
//! - `w32-part6-depth.png`: `CBspheres.dae` (a mirror and a glass sphere)
//!   at `-m 0, 1, 2, 3, 4, 5, 100`, `-s 64 -l 4`, with the ratio of
//!   `-m 100` to `-m 5`;
//! - `w32-part6-alpha.png`: `CBspheres_microfacet_al_ag.dae` with both
//!   spheres' Beckmann roughness set in code to 0.005, 0.05, 0.25 and 0.5,
//!   `-s 128 -l 1 -m 5`;
//! - `w32-part6-sampling.png`: the same scene with its microfacet BSDFs
//!   sampled from the cosine-weighted hemisphere, from the Beckmann half
//!   vector (the course's importance sampling) and by the project's default
//!   (`--microfacet-sampling cosine | half-vector | auto`) at `-s 64 -l 1
//!   -m 5`, with the ratio of the last two;
//! - `w32-part6-metals.png`: the same scene's spheres made of gold, silver,
//!   aluminium and copper from their `(eta, k)` ([`METALS`]), `-s 64 -l 1
//!   -m 5`.

use pathtracer::materials::MicrofacetSampling;
use pathtracer::math::luminance;
use pathtracer::render::Rendered;

use crate::maps::{noise, padded, ratio_map};
use crate::metals::{set_microfacets, METALS};
use crate::picture::{grid, Picture};
use crate::setup::{paths, Setup};
use crate::Result;

/// The microfacet spheres: aluminium (roughness 0.025) and silver (0.25).
const MICROFACET: &str = "CBspheres_microfacet_al_ag.dae";

/// Part 6: the four figures above.
pub fn part6(threads: usize) -> Result<()> {
    depth(threads)?;
    roughness(threads)?;
    sampling(threads)?;
    metals(threads)
}

/// Mean luminance of a render.
fn mean(r: &Rendered) -> f64 {
    let pixels = &r.film.pixels;
    pixels.iter().map(|&l| f64::from(luminance(l))).sum::<f64>() / pixels.len() as f64
}

/// `CBspheres.dae` at `-m 0` to `100` and the ratio of the last two.
fn depth(threads: usize) -> Result<()> {
    let setup = Setup::load("CBspheres.dae", threads)?;
    let renders: Vec<(u32, Rendered)> = [0, 1, 2, 3, 4, 5, 100]
        .into_iter()
        .map(|m| {
            (
                m,
                setup.render(&paths(4, m, true), 64, None, 600 + u64::from(m)),
            )
        })
        .collect();
    let (m5, m100) = (&renders[5].1, &renders[6].1);
    println!(
        "  mean luminance: -m 5 {:.4}, -m 100 {:.4}, ratio {:.4}",
        mean(m5),
        mean(m100),
        mean(m100) / mean(m5)
    );
    let mut pictures: Vec<Picture> = renders
        .iter()
        .map(|(m, r)| padded(Picture::of(format!("-m {m}"), r)))
        .collect();
    pictures.push(ratio_map("-m 100 / -m 5, 4 x 4 blocks", m100, m5, 1.25));
    grid("w32-part6-depth.png", 4, &pictures)
}

/// The microfacet spheres at four roughnesses.
fn roughness(threads: usize) -> Result<()> {
    let mut setup = Setup::load(MICROFACET, threads)?;
    let mut pictures = Vec::new();
    for alpha in [0.005, 0.05, 0.25, 0.5] {
        set_microfacets(&mut setup.scene, Some(alpha), None);
        let r = setup.render(&paths(1, 5, true), 128, None, 610);
        pictures.push(Picture::of(format!("alpha {alpha}"), &r));
    }
    grid("w32-part6-alpha.png", 4, &pictures)
}

/// Cosine-hemisphere, half-vector and the default sampling of the
/// microfacet BSDFs at equal samples, and the ratio of the last two.
fn sampling(threads: usize) -> Result<()> {
    let mut setup = Setup::load(MICROFACET, threads)?;
    let mut renders = Vec::new();
    for (name, how) in [
        ("cosine", MicrofacetSampling::CosineHemisphere),
        ("half-vector", MicrofacetSampling::HalfVector),
        ("auto (default)", MicrofacetSampling::Auto),
    ] {
        setup.options.bsdf.microfacet = how;
        let r = setup.render(&paths(1, 5, true), 64, None, 620);
        println!("  {name}: {}, mean luminance {:.4}", noise(&r), mean(&r));
        renders.push((name, r));
    }
    let mut pictures: Vec<Picture> = renders
        .iter()
        .map(|(name, r)| padded(Picture::of(format!("{name}: {}", noise(r)), r)))
        .collect();
    let (half, auto) = (&renders[1].1, &renders[2].1);
    pictures.push(ratio_map("half-vector / auto", half, auto, 1.25));
    grid("w32-part6-sampling.png", 4, &pictures)
}

/// The microfacet spheres made of each metal of [`METALS`], their
/// roughness kept.
fn metals(threads: usize) -> Result<()> {
    let mut setup = Setup::load(MICROFACET, threads)?;
    let mut pictures = Vec::new();
    for (name, _, _) in METALS {
        set_microfacets(&mut setup.scene, None, Some(name));
        let r = setup.render(&paths(1, 5, true), 64, None, 630);
        pictures.push(Picture::of(name, &r));
    }
    grid("w32-part6-metals.png", 4, &pictures)
}
