//! Patterns of single pixels in a failed image, in words: holes, acne and
//! fireflies.
//!
//! The decision ([`super::stats`]) reads 16 x 16 blocks, where a pattern
//! of single pixels shows only as a block a little off. Here each pixel of
//! the student's image is held against the mean of a correct solution's
//! renders and against its own neighbours (display values, `v / 255`,
//! luminance `Y`; `Y_ref` the reference's, `Y_near` the median of the
//! pixel's four neighbours in the student's image, so that a region that
//! changes as a whole is no pattern), among the pixels the reference
//! lights (`Y_ref > 0.1`):
//!
//! - a **hole**: black (`Y = 0`) among lit neighbours (`Y_near > 0.1`),
//!   as where a ray misses what it should hit;
//! - **acne**: darker than half the reference and than half its
//!   neighbours, not black, as where a shadow ray hits the surface it
//!   leaves;
//!
//! and among all pixels:
//!
//! - a **firefly**: brighter than the reference and than its neighbours
//!   by more than 0.3 of the display range, as from a sample divided by
//!   a tiny pdf.
//!
//! A correct render has some of each at a few samples per pixel (a pixel
//! whose samples all miss a small lamp is black). So each count is held
//! against a correct render's own, one of the reference renders against
//! the mean of the others: a pattern is named when the student's share
//! is at least [`FACTOR`] times that, and at least [`FLOOR`] of the
//! pixels it counts among. This only describes a failure; it decides
//! nothing.

use crate::math::{luminance, Rgb};

/// How many times a correct render's share a pattern must reach.
pub const FACTOR: f64 = 3.0;

/// The smallest share of the pixels (0.2 %) a pattern is named at.
pub const FLOOR: f64 = 0.002;

/// The reference luminance above which a pixel counts as lit.
const LIT: f64 = 0.1;

/// The shares of the pixels in each pattern.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Shares {
    /// Black pixels among the lit ones.
    pub holes: f64,
    /// Darker than half the reference, not black, among the lit ones.
    pub acne: f64,
    /// Brighter than the reference by 0.3 of the range, among all.
    pub fireflies: f64,
}

/// Per pixel, the display luminance of an 8-bit RGB image.
fn luminances(rgb: &[u8]) -> Vec<f64> {
    rgb.chunks_exact(3)
        .map(|p| {
            let c = Rgb::new(p[0] as f32, p[1] as f32, p[2] as f32) / 255.0;
            luminance(c) as f64
        })
        .collect()
}

/// The per-pixel mean luminance of `renders`.
fn mean_luminances(renders: &[&[u8]]) -> Vec<f64> {
    let all: Vec<Vec<f64>> = renders.iter().map(|r| luminances(r)).collect();
    let n = all.len().max(1) as f64;
    (0..all.first().map_or(0, Vec::len))
        .map(|i| all.iter().map(|l| l[i]).sum::<f64>() / n)
        .collect()
}

/// Per pixel of luminances `y` (rows of `width`), the median of its four
/// neighbours (at the border, of those inside, mirrored).
fn neighbour_medians(y: &[f64], width: usize) -> Vec<f64> {
    let height = y.len() / width.max(1);
    if width < 2 || height < 2 || y.len() != width * height {
        // No four neighbours (or not an image of this width): each pixel
        // is its own, and no pixel stands out.
        return y.to_vec();
    }
    (0..y.len())
        .map(|i| {
            let (x, row) = (i % width, i / width);
            let at = |x: usize, row: usize| y[row * width + x];
            let left = if x > 0 { x - 1 } else { x + 1 };
            let right = if x + 1 < width { x + 1 } else { x - 1 };
            let up = if row > 0 { row - 1 } else { row + 1 };
            let down = if row + 1 < height { row + 1 } else { row - 1 };
            let mut n = [at(left, row), at(right, row), at(x, up), at(x, down)];
            n.sort_by(f64::total_cmp);
            0.5 * (n[1] + n[2])
        })
        .collect()
}

/// The shares of `image`'s pixels (rows of `width`) in each pattern
/// against the reference luminances `reference`.
pub fn shares(image: &[u8], width: usize, reference: &[f64]) -> Shares {
    let y = luminances(image);
    let near = neighbour_medians(&y, width);
    let (mut lit, mut holes, mut acne, mut fireflies) = (0usize, 0usize, 0usize, 0usize);
    for ((&y, &r), &m) in y.iter().zip(reference).zip(&near) {
        if r > LIT {
            lit += 1;
            if y == 0.0 && m > LIT {
                holes += 1;
            } else if y > 0.0 && y < 0.5 * r && y < 0.5 * m {
                acne += 1;
            }
        }
        if y > r + 0.3 && y > m + 0.3 {
            fireflies += 1;
        }
    }
    let share = |n: usize, of: usize| n as f64 / of.max(1) as f64;
    Shares {
        holes: share(holes, lit),
        acne: share(acne, lit),
        fireflies: share(fireflies, y.len()),
    }
}

/// The patterns `image` (rows of `width` pixels) shows beyond a correct
/// render of `renders` (two or more), in words, or `None`.
pub fn describe(image: &[u8], width: usize, renders: &[Vec<u8>]) -> Option<String> {
    let all: Vec<&[u8]> = renders.iter().map(Vec::as_slice).collect();
    let (first, others) = all.split_first()?;
    if others.is_empty() {
        return None;
    }
    let theirs = shares(image, width, &mean_luminances(&all));
    let correct = shares(first, width, &mean_luminances(others));
    let named: Vec<String> = [
        (
            "holes: black pixels among lit ones",
            theirs.holes,
            correct.holes,
        ),
        (
            "acne: lit pixels darker than half the course's and their neighbours",
            theirs.acne,
            correct.acne,
        ),
        (
            "fireflies: single pixels far brighter than the course's and their neighbours",
            theirs.fireflies,
            correct.fireflies,
        ),
    ]
    .into_iter()
    .filter(|&(_, share, baseline)| share >= FLOOR && share >= FACTOR * baseline)
    .map(|(name, share, baseline)| {
        format!(
            "{name} ({:.1} % of them; a correct render {:.1} %)",
            100.0 * share,
            100.0 * baseline
        )
    })
    .collect();
    (!named.is_empty()).then(|| named.join("; "))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An image of `n` pixels (rows of 100), all grey `v` but every 97th
    /// from `seed`, at `v / 3`: a correct render's own dark speckles.
    fn noisy(n: usize, v: u8, seed: usize) -> Vec<u8> {
        (0..n)
            .flat_map(|i| {
                let w = if (i + seed) % 97 == 0 { v / 3 } else { v };
                [w, w, w]
            })
            .collect()
    }

    fn renders() -> Vec<Vec<u8>> {
        (0..8).map(|s| noisy(10_000, 150, s * 13)).collect()
    }

    /// A correct render shows no pattern; each pattern planted in 4 % of
    /// the pixels is named, alone.
    #[test]
    fn each_pattern_is_named_where_planted() {
        let renders = renders();
        assert_eq!(describe(&noisy(10_000, 150, 5), 100, &renders), None);
        let planted = |value: u8| {
            let mut image = noisy(10_000, 150, 5);
            for p in image.chunks_exact_mut(3).step_by(23) {
                p.fill(value);
            }
            describe(&image, 100, &renders).unwrap_or_default()
        };
        let holes = planted(0);
        assert!(
            holes.starts_with("holes") && !holes.contains("acne"),
            "{holes}"
        );
        let acne = planted(40);
        assert!(
            acne.starts_with("acne") && !acne.contains("fireflies"),
            "{acne}"
        );
        let fireflies = planted(255);
        assert!(fireflies.starts_with("fireflies"), "{fireflies}");
    }

    /// A uniformly darker image is darker, not acne, and a region black,
    /// dark or white as a whole is no hole, no acne and no firefly (its
    /// pixels are like their neighbours); black pixels where the
    /// course's image is dark are no holes; odd sizes are nothing.
    #[test]
    fn a_uniform_change_is_no_pattern() {
        let renders = renders();
        assert_eq!(describe(&noisy(10_000, 100, 5), 100, &renders), None);
        for value in [0, 40, 255] {
            let mut image = noisy(10_000, 150, 5);
            image[..3 * 2_000].fill(value);
            assert_eq!(describe(&image, 100, &renders), None, "{value}");
        }
        // Black pixels among lit ones where the course's image is dark
        // (0.08) are no holes.
        let dark: Vec<Vec<u8>> = (0..8).map(|s| noisy(10_000, 20, s)).collect();
        let mut image = noisy(10_000, 60, 5);
        for p in image.chunks_exact_mut(3).step_by(23) {
            p.fill(0);
        }
        assert_eq!(describe(&image, 100, &dark), None);
        // Not an image of that width, or too narrow for neighbours: none.
        assert_eq!(describe(&[0; 9], 0, &renders), None);
        assert_eq!(describe(&[0; 9], 1, &renders), None);
    }
}
