//! The means a check's report shows: of the null renders' images and
//! rate images, and the student's cells over the course's per block.

use super::battery::Render;
use crate::math::{luminance, Rgb};

/// Per pixel, the mean fraction of samples over `renders`' rate images.
pub fn mean_fractions(renders: &[Render]) -> Vec<f64> {
    let all: Vec<&Vec<f64>> = renders.iter().filter_map(|r| r.rates.as_ref()).collect();
    let n = all.len().max(1) as f64;
    (0..all.first().map_or(0, |f| f.len()))
        .map(|i| all.iter().map(|f| f[i]).sum::<f64>() / n)
        .collect()
}

/// The per-value mean of 8-bit images.
pub fn mean_image(images: &[Vec<u8>]) -> Vec<u8> {
    let n = images.len().max(1) as f64;
    (0..images.first().map_or(0, Vec::len))
        .map(|i| (images.iter().map(|im| im[i] as f64).sum::<f64>() / n).round() as u8)
        .collect()
}

/// Per block, the luminance ratio of cells `x` over `mean`, in radiance.
pub fn block_ratios(x: &[f64], mean: &[f64]) -> Vec<f64> {
    let lum = |c: &[f64]| luminance(Rgb::new(c[0] as f32, c[1] as f32, c[2] as f32)) as f64;
    x.chunks(3)
        .zip(mean.chunks(3))
        .map(|(a, b)| match (lum(a), lum(b)) {
            (a, b) if a <= 0.0 && b <= 0.0 => 1.0,
            (a, b) => (a / b).powf(2.2),
        })
        .collect()
}
