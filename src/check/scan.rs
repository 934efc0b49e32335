//! The scan statistic: a test for a difference confined to one region (a
//! ball, a wall), which the sum over all cells ([`super::stats::statistic`])
//! misses when the region is small, since each cell adds at most
//! [`super::stats::CELL_CAP`] to it.
//!
//! The three channels of a block are not independent (a bright sample
//! brightens all three), so each block counts once: its term is the mean
//! over its channels of their `z` signed by the difference and clamped
//! to `+-3`, whose variance under a correct renderer is at most 1 however
//! the channels correlate. Every window of `3 x 3` neighbouring blocks
//! sums its `m = 9` terms:
//!
//! ```text
//! t_b = mean_c clamp(sign(x_bc - mu_bc) z_bc, -3, 3)
//! S_w = sum_{b in w} t_b / sqrt(m)
//! ```
//!
//! Under a correct renderer the terms are about symmetric about 0 (a
//! block mean of 256 pixels is near normal), their variance at most 1
//! (the tolerance only shrinks `z`), and the blocks independent, so `S_w`
//! is about a standard normal: the image fails when `max_w |S_w|` exceeds
//! the two-sided normal quantile at `alpha / W` over the `W` windows
//! (Bonferroni, conservative however the windows overlap). The rate is a
//! normal approximation, not a bound; `tests/check.rs` measures it.
//! A region brighter or darker than the course's shifts every term of its
//! windows the same way, `S_w` by up to `3 sqrt(m)` = 9; a block with a
//! firefly moves its one term, `S_w` by at most `3 / sqrt(m)` = 1, well
//! below the battery's thresholds (about 4.8).

use super::stats::{normal_upper_quantile, NullModel, BLOCK};

/// A window's side, in blocks.
pub const WINDOW: u32 = 3;

/// The most one cell's signed `z` counts for in a window.
pub const Z_CAP: f64 = 3.0;

/// The window that differs most and the test's threshold.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scan {
    /// `max |S_w|` (0 for an image smaller than a window).
    pub value: f64,
    /// The two-sided normal quantile at `alpha / W`.
    pub threshold: f64,
    /// The upper left pixel of the window where the maximum lies.
    pub at: (u32, u32),
    /// Whether that window is brighter (else darker) than the course's.
    pub brighter: bool,
}

impl Scan {
    pub fn passes(&self) -> bool {
        self.value <= self.threshold
    }
}

/// The scan of the cells `x` (per block, `channels` each, in the order of
/// [`super::stats::block_means`]), whose `z` against `model` are `z`, at
/// false-alarm rate `alpha`.
///
/// # Panics
///
/// If `channels` is 0 or `x` and `z` have not `channels` cells a block.
pub fn scan(model: &NullModel, x: &[f64], z: &[f64], channels: usize, alpha: f64) -> Scan {
    let (bw, bh) = (model.width.div_ceil(BLOCK), model.height.div_ceil(BLOCK));
    assert!(channels > 0 && x.len() == (bw * bh) as usize * channels && z.len() == x.len());
    let term: Vec<f64> = (0..x.len() / channels)
        .map(|b| {
            let cells = b * channels..(b + 1) * channels;
            let signed =
                cells.map(|i| (z[i] * (x[i] - model.mean[i]).signum()).clamp(-Z_CAP, Z_CAP));
            signed.sum::<f64>() / channels as f64
        })
        .collect();
    // Where a window's upper left block may lie.
    let (across, down) = (bw.saturating_sub(WINDOW - 1), bh.saturating_sub(WINDOW - 1));
    let windows = across * down;
    let mut best = Scan {
        value: 0.0,
        threshold: normal_upper_quantile(alpha / (2.0 * windows.max(1) as f64)),
        at: (0, 0),
        brighter: true,
    };
    let m = (WINDOW * WINDOW) as f64;
    for by in 0..down {
        for bx in 0..across {
            let mut sum = 0.0;
            for dy in 0..WINDOW {
                for dx in 0..WINDOW {
                    sum += term[((by + dy) * bw + bx + dx) as usize];
                }
            }
            let s = sum / m.sqrt();
            if s.abs() > best.value {
                best = Scan {
                    value: s.abs(),
                    at: (bx * BLOCK, by * BLOCK),
                    brighter: s > 0.0,
                    ..best
                };
            }
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::stats::{cells, chi_square_quantile};

    /// A model of a `width x height` image of `cells` cells, each grey
    /// 0.5 with standard error 0.01.
    fn grey_model(width: u32, height: u32, cells: usize) -> NullModel {
        NullModel {
            width,
            height,
            mean: vec![0.5; cells],
            variance: vec![1e-4; cells],
            renders: 1_000_000,
        }
    }

    /// The grey model of an 8 x 6 block RGB image and the cells of an
    /// image `value(block)`.
    fn model_and_cells(value: impl Fn(u32, u32) -> f64) -> (NullModel, Vec<f64>) {
        let (w, h) = (8 * BLOCK, 6 * BLOCK);
        let model = grey_model(w, h, 8 * 6 * 3);
        let mut rgb = vec![0u8; (w * h * 3) as usize];
        for y in 0..h {
            for x in 0..w {
                let v = (value(x / BLOCK, y / BLOCK) * 255.0).round() as u8;
                rgb[(3 * (y * w + x)) as usize..][..3].fill(v);
            }
        }
        (model, cells(w, h, &rgb))
    }

    fn scanned(value: impl Fn(u32, u32) -> f64) -> Scan {
        let (model, x) = model_and_cells(value);
        let z = model.z_scores(&x);
        scan(&model, &x, &z, 3, 0.01)
    }

    /// The threshold is the normal quantile at `alpha / (2 W)`: 24
    /// windows of 3 x 3 in 8 x 6 blocks, `alpha = 0.01`: the quantile at
    /// 2.08e-4, 3.529 (tables: `P(Z > 3.5) = 2.33e-4`).
    #[test]
    fn the_threshold_is_bonferronis() {
        let s = scanned(|_, _| 0.5);
        assert_eq!(s.value, 0.0);
        assert!((s.threshold - 3.5294).abs() < 1e-3, "{}", s.threshold);
        assert!(s.passes());
    }

    /// Nine blocks 4 % darker (0.48 against 0.5, 1 % forgiven: z = 1.66 a
    /// cell) make the window that holds them `9 * 1.66 / 3` = 4.97: found,
    /// where it is, darker; the sum of `z^2` over the image's 144 cells
    /// (74) passes its own test (186 at the same `alpha`).
    #[test]
    fn a_darker_region_fails_where_it_is() {
        let region = |x, y| (3..6).contains(&x) && (2..5).contains(&y);
        let (model, x) = model_and_cells(|x, y| if region(x, y) { 0.48 } else { 0.5 });
        let z = model.z_scores(&x);
        let s = scan(&model, &x, &z, 3, 0.01);
        assert!((s.value - 4.97).abs() < 0.01, "{s:?}");
        assert!(!s.passes(), "{s:?}");
        assert!(!s.brighter);
        assert_eq!(s.at, (3 * BLOCK, 2 * BLOCK));
        let sum = crate::check::stats::statistic(&z);
        assert!(sum < chi_square_quantile(144.0, 0.01), "{sum}");
    }

    /// One channel (the rate image's cells), a brighter region, and the
    /// last row of blocks only partly in the image (5.5 blocks high): the
    /// window over the region's 3 x 3 blocks, brighter, 9 * 3 / 3 = 9;
    /// an image of fewer than 3 x 3 blocks has no window and passes.
    #[test]
    fn one_channel_a_brighter_region_and_a_partial_row() {
        let (w, h) = (8 * BLOCK, 5 * BLOCK + BLOCK / 2);
        let blocks = 8 * 6;
        let model = grey_model(w, h, blocks);
        let region = |b: usize| (4..7).contains(&(b % 8)) && (3..6).contains(&(b / 8));
        let x: Vec<f64> = (0..blocks)
            .map(|b| if region(b) { 0.6 } else { 0.5 })
            .collect();
        let z = model.z_scores(&x);
        let s = scan(&model, &x, &z, 1, 0.01);
        assert!((s.value - 9.0).abs() < 1e-9, "{s:?}");
        assert!(s.brighter && !s.passes());
        assert_eq!(s.at, (4 * BLOCK, 3 * BLOCK));
        let small = grey_model(2 * BLOCK, 2 * BLOCK, 4);
        let far = [1.0; 4];
        let s = scan(&small, &far, &small.z_scores(&far), 1, 0.01);
        assert_eq!(s.value, 0.0);
        assert!(s.passes());
    }

    /// One block as bright as can be (a firefly's worst) counts `Z_CAP`:
    /// `3 / sqrt(9)` = 1 in each window that holds it, and passes; its
    /// `z` uncapped (49.5 a channel) would fail.
    #[test]
    fn one_far_block_moves_a_window_by_its_cap_alone() {
        let (model, x) = model_and_cells(|x, y| if (x, y) == (4, 3) { 1.0 } else { 0.5 });
        let z = model.z_scores(&x);
        let s = scan(&model, &x, &z, 3, 0.01);
        assert!((s.value - 1.0).abs() < 1e-9, "{s:?}");
        assert!(s.passes(), "{s:?}");
    }
}
