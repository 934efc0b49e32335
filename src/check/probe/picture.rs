//! The warptest picture of a sampler (after Nori's `warptest`): the
//! student's histogram of samples, the counts the pdfs they return
//! expect, and their difference, side by side, each with its colour bar
//! under it. A [`Grid`] lays the cells out: a BSDF's over the hemisphere
//! unrolled with `cos(theta)` down (1 at the top: the normal) and `phi`
//! across ([`hemisphere`]), the environment light's as the map's texels
//! ([`texels`]).
//!
//! The counts are shaded from black (none) to white (the larger of the
//! two panels' largest count), by the square root of the count so that
//! the dim cells beside a peak still show, the difference as the standard score
//! `(observed - expected) / sqrt(expected)` from blue (-4) through white
//! to red (+4). The picture is saved beside the probe's runs, named after
//! the function ([`file_name`]), where the report finds it.

use std::path::{Path, PathBuf};

use super::warp::{Histogram, COS_CELLS, PHI_CELLS};
use crate::math::ratio_colour;

/// A panel's width in pixels.
const PANEL: usize = 240;
/// Rows of a colour bar, and the gap above it and between panels.
const BAR: u32 = 10;
const GAP: u32 = 6;

/// A histogram's cells as a picture: `cols` across, `rows` down, and the
/// cell of the histogram shown at `(row, col)` from the top left.
pub struct Grid<'a> {
    h: &'a Histogram,
    cols: usize,
    rows: usize,
    cell: fn(usize, usize, usize) -> usize,
}

/// [`warp`](super::warp)'s cells (the first `COS_CELLS x PHI_CELLS` of
/// `h`; a cell after them, below the surface, is not drawn), `cos(theta)`
/// from 1 at the top.
pub fn hemisphere(h: &Histogram) -> Grid<'_> {
    Grid {
        h,
        cols: PHI_CELLS,
        rows: COS_CELLS,
        cell: |row, col, cols| (COS_CELLS - 1 - row) * cols + col,
    }
}

/// A `w x h` map's texels, row by row from the top.
pub fn texels(hist: &Histogram, w: usize, h: usize) -> Grid<'_> {
    Grid {
        h: hist,
        cols: w,
        rows: h,
        cell: |row, col, cols| row * cols + col,
    }
}

/// The picture's file for `function` (`DiffuseBSDF::sample_f` gives
/// `DiffuseBSDF-sample_f.png`) in the folder `runs`.
pub fn file_name(runs: &Path, function: &str) -> PathBuf {
    runs.join(format!("{}.png", function.replace("::", "-")))
}

/// The three panels as one RGB image: its width, height and bytes.
pub fn warptest(g: &Grid) -> (u32, u32, Vec<u8>) {
    let size = (PANEL / g.cols) as u32;
    let (pw, ph) = (g.cols as u32 * size, g.rows as u32 * size);
    let (w, height) = (3 * pw + 2 * GAP, ph + GAP + BAR);
    let h = g.h;
    let drawn = (0..g.rows).flat_map(|r| (0..g.cols).map(move |c| (g.cell)(r, c, g.cols)));
    let most = drawn.fold(1.0f64, |a, k| a.max(h.observed[k]).max(h.expected[k]));
    let grey = |v: f64| {
        let g = (255.0 * (v / most).clamp(0.0, 1.0).sqrt()).round() as u8;
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
                    let k = (g.cell)((y / size) as usize, (x / size) as usize, g.cols);
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
                        _ => grey(t * t * most),
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

/// Saves the picture of `g` for `function` into `runs`; a picture that
/// cannot be written is left out of the report, nothing more.
pub fn save(runs: &Path, function: &str, g: &Grid) {
    let (w, height, rgb) = warptest(g);
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
        // A cell below the surface, not drawn, does not set the scale.
        h.observed.push(5000.0);
        h.expected.push(5000.0);
        let (w, _, rgb) = warptest(&hemisphere(&h));
        let at = |x: u32, y: u32| {
            let i = ((y * w + x) * 3) as usize;
            [rgb[i], rgb[i + 1], rgb[i + 2]]
        };
        const CELL: u32 = (PANEL / PHI_CELLS) as u32;
        let pw = PHI_CELLS as u32 * CELL;
        // Observed: 140 is the brightest, white; 100 of 140 grey, shaded
        // by its square root, 255 sqrt(100 / 140) = 215.5.
        assert_eq!(at(1, 1), [255, 255, 255]);
        assert_eq!(at(CELL + 1, 1), [216, 216, 216]);
        // The difference: +4 standard errors red, 0 white.
        let d = 2 * (pw + GAP);
        assert_eq!(at(d + 1, 1), [255, 0, 0]);
        assert_eq!(at(d + CELL + 1, 1), [255, 255, 255]);
    }

    /// A map's texels read row by row from the top left: the first
    /// texel's surplus shows at the top left of the difference.
    #[test]
    fn texels_lie_row_by_row_from_the_top() {
        let (w, h) = (16, 8);
        let mut hist = Histogram {
            observed: vec![100.0; w * h],
            expected: vec![100.0; w * h],
        };
        hist.observed[0] = 60.0;
        let (width, height, rgb) = warptest(&texels(&hist, w, h));
        let size = (PANEL / w) as u32;
        assert_eq!(height, h as u32 * size + GAP + BAR);
        let at = |x: u32, y: u32| {
            let i = ((y * width + x) * 3) as usize;
            [rgb[i], rgb[i + 1], rgb[i + 2]]
        };
        let d = 2 * (w as u32 * size + GAP);
        assert_eq!(at(d + 1, 1), [0, 0, 255]);
        assert_eq!(at(d + 1, size + 1), [255, 255, 255]);
    }

    #[test]
    fn the_file_is_named_after_the_function() {
        assert_eq!(
            file_name(Path::new("runs"), "DiffuseBSDF::sample_f"),
            Path::new("runs/DiffuseBSDF-sample_f.png")
        );
    }
}
