//! Part 7 (environment light), the figures of docs/08-environment.md:
//!
//! ```text
//! cargo run --release --example gallery -- part7
//! ```
//!
//! The map is the project's built-in sky (`environment::builtin_sky`, 512
//! x 256, a sun of radius 2 degrees) at [`SKY_SCALE`] of its radiance, so
//! that the sunlit floor and bunny stay below white under the course's
//! tone map; the course's `.exr` maps are not needed.
//!
//! - `w32-part7-probability.png`: the map, its importance-sampling tables
//!   in the course's `probability_debug.png` form (red: the marginal CDF of
//!   the row, `marginal_y`; green: the CDF along the row, `conds_y`) and
//!   the density per steradian relative to uniform sampling, `4 pi p(w)`,
//!   on a log scale from 0.01 to 10^4 (black: 0); each with its colour bar;
//! - `w32-part7-bunny.png`: `bunny_unlit.dae`, diffuse as the file has it
//!   and with the bunny made copper in code (Beckmann roughness
//!   [`COPPER_ALPHA`]), each lit by the map sampled uniformly
//!   (`--env-uniform`) and by importance, at `-s 4 -l 64 -m 5`.

use std::f32::consts::PI;

use glam::Vec2;
use pathtracer::environment::{
    builtin_sky, uv_to_direction, EnvironmentLight, EnvironmentMap, EnvironmentSampling,
};
use pathtracer::math::Rgb;
use pathtracer::render::tone_map;

use crate::maps::{noise, padded, viridis, with_bar};
use crate::metals::metal;
use crate::picture::{grid, Picture};
use crate::setup::{paths, Setup};
use crate::Result;

/// The share of the built-in sky's radiance the figures light with.
pub const SKY_SCALE: f32 = 0.5;

/// Roughness of the copper bunny.
pub const COPPER_ALPHA: f32 = 0.2;

/// Part 7: the two figures above.
pub fn part7(threads: usize) -> Result<()> {
    let sky = builtin_sky()?;
    let (w, h) = (sky.width(), sky.height());
    let texels = (0..(w * h) as i64)
        .map(|k| SKY_SCALE * sky.texel(k % w as i64, k / w as i64))
        .collect();
    let map = EnvironmentMap::new("built-in sky, scaled", w, h, texels)?;
    let light = EnvironmentLight::new(map, EnvironmentSampling::Importance);
    probability(&light)?;
    bunny(&light, threads)
}

/// The map, its tables as the course's `probability_debug.png` draws
/// them, and its density per steradian.
fn probability(light: &EnvironmentLight) -> Result<()> {
    let map = light.map();
    let (w, h) = (map.width(), map.height());
    // p(u, v) of each cell, from the density per steradian at its centre:
    // p(u, v) = p(w) 2 pi^2 sin(theta).
    let mut p_uv = Vec::with_capacity(w * h);
    let mut relative = Vec::with_capacity(w * h);
    for j in 0..h {
        for i in 0..w {
            let uv = Vec2::new((i as f32 + 0.5) / w as f32, (j as f32 + 0.5) / h as f32);
            let p = light.pdf_li(uv_to_direction(uv));
            p_uv.push(p * 2.0 * PI * PI * (PI * uv.y).sin());
            relative.push(4.0 * PI * p);
        }
    }
    // The course's tables: marginal_y[j], the probability of rows 0..=j;
    // conds_y[j w + i], that of columns 0..=i given row j.
    let total: f32 = p_uv.iter().sum();
    let mut debug = Vec::with_capacity(w * h);
    let mut marginal = 0.0;
    for row in p_uv.chunks(w) {
        let row_total: f32 = row.iter().sum();
        marginal += row_total / total;
        let mut conditional = 0.0;
        for &p in row {
            conditional += if row_total > 0.0 { p / row_total } else { 0.0 };
            debug.push(Rgb::new(marginal.min(1.0), conditional.min(1.0), 0.0));
        }
    }
    let (wu, hu) = (w as u32, h as u32);
    let shown: Vec<Rgb> = (0..(w * h) as i64)
        .map(|k| tone_map(map.texel(k % w as i64, k / w as i64)))
        .collect();
    // Red from 0 to 1 on the left, green on the right, white between.
    let two_ramps = |t: f32| {
        if t < 0.48 {
            Rgb::new(t / 0.48, 0.0, 0.0)
        } else if t > 0.52 {
            Rgb::new(0.0, (t - 0.52) / 0.48, 0.0)
        } else {
            Rgb::ONE
        }
    };
    let positive = relative.iter().filter(|&&r| r > 0.0);
    let (low, high) = positive.fold((f32::MAX, 0.0f32), |(l, h), &r| (l.min(r), h.max(r)));
    println!("  4 pi p(w) from {low:.3} to {high:.0} (uniform: 1)");
    // log10(4 pi p) from -2 to 4; black where the density is 0.
    let log_colour = |r: f32| {
        if r > 0.0 {
            viridis((r.log10() + 2.0) / 6.0)
        } else {
            Rgb::ZERO
        }
    };
    let decades = ["0.01", "0.1", "1", "10", "100", "1000", "10⁴"];
    let decade_ticks: Vec<(f32, &str)> = decades
        .iter()
        .enumerate()
        .map(|(k, &text)| (k as f32 / 6.0, text))
        .collect();
    grid(
        "w32-part7-probability.png",
        3,
        &[
            padded(Picture::display("the map (scaled sky)", wu, hu, shown)),
            with_bar(
                Picture::display("probability_debug.png form", wu, hu, debug),
                two_ramps,
                &[
                    (0.0, "0"),
                    (0.24, "red: marginal_y"),
                    (0.48, "1"),
                    (0.52, "0"),
                    (0.76, "green: conds_y"),
                    (1.0, "1"),
                ],
            ),
            with_bar(
                Picture::display(
                    "4π p(ω), log scale (1: uniform)",
                    wu,
                    hu,
                    relative.iter().map(|&r| log_colour(r)).collect(),
                ),
                viridis,
                &decade_ticks,
            ),
        ],
    )
}

/// `bunny_unlit.dae`, diffuse and copper, under uniform and importance
/// sampling of `light`.
fn bunny(light: &EnvironmentLight, threads: usize) -> Result<()> {
    let mut setup = Setup::load("bunny_unlit.dae", threads)?;
    // The bunny's material: the one most triangles have (the floor has 2).
    let mut count = vec![0usize; setup.scene.materials.len()];
    for &m in &setup.scene.mesh.materials {
        count[m as usize] += 1;
    }
    let bunny = (0..count.len()).max_by_key(|&m| count[m]).unwrap_or(0);
    let diffuse = setup.scene.materials[bunny];
    let mut pictures = Vec::new();
    for (name, material) in [
        ("diffuse", diffuse),
        ("copper", metal("copper", COPPER_ALPHA)),
    ] {
        setup.scene.materials[bunny] = material;
        for (how, sampling) in [
            ("uniform", EnvironmentSampling::Uniform),
            ("importance", EnvironmentSampling::Importance),
        ] {
            setup.environment = Some(light.with_sampling(sampling));
            let r = setup.render(&paths(64, 5, true), 4, None, 700);
            let label = format!("{name}, {how}: {}", noise(&r));
            println!("  {label}");
            pictures.push(Picture::of(label, &r));
        }
    }
    grid("w32-part7-bunny.png", 2, &pictures)
}
