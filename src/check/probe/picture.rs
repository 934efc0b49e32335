//! The warptest picture of a sampler (after Nori's `warptest`): the
//! student's histogram of directions, the counts the pdfs they return
//! expect, and their difference, side by side, each over the hemisphere
//! unrolled with `cos(theta)` down (1 at the top: the normal) and `phi`
//! across, each with its colour bar under it.
//!
//! The counts are shaded from black (none) to white (the larger of the
//! two panels' largest count), the difference as the standard score
//! `(observed - expected) / sqrt(expected)` from blue (-4) through white
//! to red (+4). The picture is saved beside the probe's runs, named after
//! the function ([`file_name`]), where the report finds it.

use std::path::{Path, PathBuf};

use super::warp::{Histogram, COS_CELLS, PHI_CELLS};
use crate::math::ratio_colour;

/// Pixels per cell.
const CELL: u32 = 12;
/// Rows of a colour bar, and the gap above it and between panels.
const BAR: u32 = 10;
const GAP: u32 = 6;

/// The picture's file for `function` (`DiffuseBSDF::sample_f` gives
/// `DiffuseBSDF-sample_f.png`) in the folder `runs`.
pub fn file_name(runs: &Path, function: &str) -> PathBuf {
    runs.join(format!("{}.png", function.replace("::", "-")))
}

/// The three panels as one RGB image: its width, height and bytes.
pub fn warptest(h: &Histogram) -> (u32, u32, Vec<u8>) {
    let (pw, ph) = (PHI_CELLS as u32 * CELL, COS_CELLS as u32 * CELL);
    let (w, height) = (3 * pw + 2 * GAP, ph + GAP + BAR);
    let most = h
        .observed
        .iter()
        .chain(&h.expected)
        .fold(1.0f64, |a, b| a.max(*b));
    let grey = |v: f64| {
        let g = (255.0 * (v / most).clamp(0.0, 1.0)).round() as u8;
        [g, g, g]
    };
    let score = |t: f64| {
        ratio_colour(t as f32)
            .to_array()
            .map(|c| (255.0 * c).round() as u8)
    };
    let mut rgb = vec![255u8; (w * height * 3) as usize];
    for panel in 0..3u32 {
        let x0 = panel * (pw + GAP);
        for y in 0..height {
            for x in 0..pw {
                let colour = if y < ph {
                    // cos(theta) from 1 at the top: cell row COS_CELLS - 1 first.
                    let row = COS_CELLS - 1 - (y / CELL) as usize;
                    let k = row * PHI_CELLS + (x / CELL) as usize;
                    let (o, e) = (h.observed[k], h.expected[k]);
                    match panel {
                        0 => grey(o),
                        1 => grey(e),
                        _ => score((o - e) / e.max(1e-9).sqrt() / 4.0),
                    }
                } else if y >= ph + GAP {
                    let t = x as f64 / (pw - 1) as f64;
                    match panel {
                        2 => score(2.0 * t - 1.0),
                        _ => grey(t * most),
                    }
                } else {
                    continue;
                };
                let i = ((y * w + x0 + x) * 3) as usize;
                rgb[i..i + 3].copy_from_slice(&colour);
            }
        }
    }
    (w, height, rgb)
}

/// Saves the picture of `h` for `function` into `runs`; a picture that
/// cannot be written is left out of the report, nothing more.
pub fn save(runs: &Path, function: &str, h: &Histogram) {
    let (w, height, rgb) = warptest(h);
    if let Some(image) = image::RgbImage::from_raw(w, height, rgb) {
        let _ = std::fs::create_dir_all(runs);
        let _ = image.save(file_name(runs, function));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_panels_show_counts_and_scores() {
        let n = COS_CELLS * PHI_CELLS;
        let mut h = Histogram {
            observed: vec![100.0; n],
            expected: vec![100.0; n],
        };
        // The top-left cell (cos theta near 1, phi near 0) has 4 standard
        // errors too many.
        h.observed[(COS_CELLS - 1) * PHI_CELLS] = 140.0;
        let (w, _, rgb) = warptest(&h);
        let at = |x: u32, y: u32| {
            let i = ((y * w + x) * 3) as usize;
            [rgb[i], rgb[i + 1], rgb[i + 2]]
        };
        let pw = PHI_CELLS as u32 * CELL;
        // Observed: 140 is the brightest, white; 100 of 140 grey.
        assert_eq!(at(1, 1), [255, 255, 255]);
        assert_eq!(at(CELL + 1, 1), [182, 182, 182]);
        // The difference: +4 standard errors red, 0 white.
        let d = 2 * (pw + GAP);
        assert_eq!(at(d + 1, 1), [255, 0, 0]);
        assert_eq!(at(d + CELL + 1, 1), [255, 255, 255]);
    }

    #[test]
    fn the_file_is_named_after_the_function() {
        assert_eq!(
            file_name(Path::new("runs"), "DiffuseBSDF::sample_f"),
            Path::new("runs/DiffuseBSDF-sample_f.png")
        );
    }
}
