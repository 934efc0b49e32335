//! Part 4 (global illumination): direct and indirect light, bounces,
//! Russian roulette, samples per pixel.

use pathtracer::math::{luminance, Rgb};
use pathtracer::render::Rendered;

use crate::picture::{grid, Picture};
use crate::setup::{paths, Setup};
use crate::{Result, SIZE};

/// Part 4: direct against indirect light, each bounce alone and
/// accumulated, Russian roulette at several depths, samples per pixel.
pub fn part4(threads: usize) -> Result<()> {
    let setup = Setup::load("CBbunny.dae", threads)?;
    let spp = 256;
    // The m-th bounce alone (-o 0) for m = 0..5: unbiased estimates of
    // disjoint parts of the image, so bounces 0 + 1 are the direct light
    // and 2 to 5 the indirect light of `-m 5`, exactly as defined.
    let bounces: Vec<Rendered> = (0..=5)
        .map(|m| setup.render(&paths(4, m, false), spp, None, 10 + m as u64))
        .collect();
    let (w, h) = SIZE;
    let sum = |range: std::ops::RangeInclusive<usize>| -> Vec<Rgb> {
        (0..(w * h) as usize)
            .map(|i| range.clone().map(|m| bounces[m].film.pixels[i]).sum())
            .collect()
    };
    let direct_light = sum(0..=1);
    let indirect = sum(2..=5);
    let total = setup.render(&paths(4, 5, true), spp, None, 20);
    let mean = |v: &[Rgb]| v.iter().map(|&l| luminance(l) as f64).sum::<f64>() / v.len() as f64;
    println!(
        "  mean luminance: direct {:.4} + indirect {:.4} = {:.4}; -m 5 -o 1 renders {:.4}",
        mean(&direct_light),
        mean(&indirect),
        mean(&direct_light) + mean(&indirect),
        mean(&total.film.pixels)
    );
    grid(
        "w31-part4-direct-indirect.png",
        3,
        &[
            Picture::radiance("direct (bounces 0, 1)", w, h, &direct_light),
            Picture::radiance("indirect (bounces 2-5)", w, h, &indirect),
            Picture::of("both: -m 5", &total),
        ],
    )?;

    let mut pictures: Vec<Picture> = bounces
        .iter()
        .enumerate()
        .map(|(m, r)| Picture::of(format!("-m {m} -o 0"), r))
        .collect();
    for m in 0..=5 {
        let r = setup.render(&paths(4, m, true), spp, None, 30 + m as u64);
        pictures.push(Picture::of(format!("-m {m} -o 1"), &r));
    }
    grid("w31-part4-bounces.png", 6, &pictures)?;

    let mut pictures = Vec::new();
    for m in [0, 1, 2, 3, 4, 100] {
        let r = setup.render(&paths(4, m, true), spp, None, 40 + m as u64);
        pictures.push(Picture::of(format!("-m {m}"), &r));
    }
    grid("w31-part4-roulette.png", 6, &pictures)?;

    let mut pictures = Vec::new();
    for s in [1, 2, 4, 8, 16, 64, 1024] {
        let r = setup.render(&paths(4, 5, true), s, None, 50 + s as u64);
        pictures.push(Picture::of(format!("-s {s}"), &r));
    }
    grid("w31-part4-samples.png", 4, &pictures)
}
