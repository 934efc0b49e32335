//! How a student's image is judged against the course's.
//!
//! A student's PNG is one noisy render, tone mapped and cut to 8 bits. The
//! reference is not one image but the *distribution* of the images a
//! correct solution renders at the same flags: [`NullModel`] renders `K`
//! of them ([`super::battery::Stage::render`], independent seeds) through
//! the same tone map and truncation, and keeps, per [`BLOCK`]-pixel square and
//! colour channel (a *cell*), the mean display value `mu` and the variance
//! `s^2` of one image's block mean (the pixels' variances over the `K`
//! renders, summed over the block, over `n^2`: pixels are independent;
//! each pixel's at least its 8-bit rounding's, `(1/255)^2 / 12`).
//!
//! A student's cell value `x` then gives
//!
//! ```text
//! z = max(0, |x - mu| - tau mu) / sqrt(s^2 (1 + 1/K))
//! ```
//!
//! (`tau` = [`TOLERANCE`] forgives a systematic difference too small to
//! matter, such as rounding against truncation), and the image passes when
//! `sum min(z^2, 25)` over the `C` cells ([`statistic`]) stays below the chi-square quantile of `C`
//! degrees of freedom at `1 - alpha` (Wilson and Hilferty's approximation,
//! 1931): under a correct renderer each `z^2` is at most a chi-square of
//! one degree, so it fails with probability at most `alpha`. A check
//! holds this test and [`super::scan`]'s, of one region, each at half its
//! rate ([`super::verdict`]): the cap leaves the sum blind to a small
//! region.

use libm::erfc;

use super::student::StudentImage;

/// Block side in pixels.
pub const BLOCK: u32 = 16;

/// The relative difference of a cell's display value forgiven as too
/// small to matter: 1 % of display (about 2 % of radiance).
pub const TOLERANCE: f64 = 0.01;

/// The distribution of a correct solution's cells.
#[derive(Clone, Debug)]
pub struct NullModel {
    pub width: u32,
    pub height: u32,
    /// Per cell: the mean display value and the variance of one render's.
    pub mean: Vec<f64>,
    pub variance: Vec<f64>,
    /// Renders it was made of.
    pub renders: usize,
}

/// The block of pixel `(x, y)` in an image `width` wide.
pub fn block_index(x: u32, y: u32, width: u32) -> usize {
    ((y / BLOCK) * width.div_ceil(BLOCK) + x / BLOCK) as usize
}

/// Per cell, the block mean of `rgb` (8-bit, three channels), in `[0, 1]`.
pub fn cells(width: u32, height: u32, rgb: &[u8]) -> Vec<f64> {
    block_means(width, height, 3, &display_values(rgb))
}

/// 8-bit values as display values in `[0, 1]`.
pub fn display_values(rgb: &[u8]) -> Vec<f64> {
    rgb.iter().map(|&v| v as f64 / 255.0).collect()
}

/// Per cell (block and channel), the block mean of `values` (`channels`
/// a pixel, row-major).
pub fn block_means(width: u32, height: u32, channels: usize, values: &[f64]) -> Vec<f64> {
    let (bw, bh) = (width.div_ceil(BLOCK), height.div_ceil(BLOCK));
    let mut sums = vec![0.0; (bw * bh) as usize * channels];
    let mut counts = vec![0.0; (bw * bh) as usize];
    for y in 0..height {
        for x in 0..width {
            let b = block_index(x, y, width);
            counts[b] += 1.0;
            let pixel = (y * width + x) as usize * channels;
            for c in 0..channels {
                sums[channels * b + c] += values[pixel + c];
            }
        }
    }
    sums.iter()
        .enumerate()
        .map(|(i, s)| s / counts[i / channels])
        .collect()
}

/// The variance of one 8-bit value's rounding, `(1/255)^2 / 12`: the
/// least a display value varies by.
pub const DISPLAY_ROUNDING: f64 = 1.0 / (255.0 * 255.0 * 12.0);

impl NullModel {
    /// The model of `renders` (8-bit images of `width` x `height`).
    pub fn new(width: u32, height: u32, renders: &[Vec<u8>]) -> Self {
        let values: Vec<Vec<f64>> = renders.iter().map(|r| display_values(r)).collect();
        Self::of_values(width, height, 3, &values, DISPLAY_ROUNDING)
    }

    /// The model of `renders`, each `channels` values a pixel, where no
    /// value varies by less than `rounding` (a variance: that of the
    /// quantisation the values went through).
    pub fn of_values(
        width: u32,
        height: u32,
        channels: usize,
        renders: &[Vec<f64>],
        rounding: f64,
    ) -> Self {
        let k = renders.len();
        assert!(k >= 2, "a null model needs two renders or more");
        let n = (width * height) as usize * channels;
        // Per pixel channel: the variance over the renders.
        let mut pixel_var = vec![0.0; n];
        for (i, v) in pixel_var.iter_mut().enumerate() {
            let values = renders.iter().map(|r| r[i]);
            let mean = values.clone().sum::<f64>() / k as f64;
            *v = values.map(|x| (x - mean) * (x - mean)).sum::<f64>() / (k - 1) as f64;
        }
        let per_render: Vec<Vec<f64>> = renders
            .iter()
            .map(|r| block_means(width, height, channels, r))
            .collect();
        let c = per_render[0].len();
        let mean = (0..c)
            .map(|i| per_render.iter().map(|r| r[i]).sum::<f64>() / k as f64)
            .collect();
        // The sum of the pixels' variances over n^2, per cell, each pixel's
        // at least `rounding`, so that a cell no render varies in (black,
        // or clipped white) still has a finite scale: the block mean of
        // the variances over the block's n pixels.
        let mut pixels = vec![0.0; c / channels];
        for y in 0..height {
            for x in 0..width {
                pixels[block_index(x, y, width)] += 1.0;
            }
        }
        let variance = block_means(width, height, channels, &pixel_var)
            .iter()
            .enumerate()
            .map(|(i, v)| (v + rounding) / pixels[i / channels])
            .collect();
        NullModel {
            width,
            height,
            mean,
            variance,
            renders: k,
        }
    }

    /// Each cell's `z` (see the module docs) of the cells `x` against
    /// this model: its mean, and its noise (a render's, and the mean's
    /// own over [`NullModel::renders`]).
    pub fn z_scores(&self, x: &[f64]) -> Vec<f64> {
        let inflate = 1.0 + 1.0 / self.renders as f64;
        x.iter()
            .zip(&self.mean)
            .zip(&self.variance)
            .map(|((&x, &mu), &s2)| {
                let excess = ((x - mu).abs() - TOLERANCE * mu).max(0.0);
                excess / (s2 * inflate).sqrt()
            })
            .collect()
    }

    /// This model with each cell's variance at least `other`'s: a model
    /// of two renders sees no noise in a cell whose pixels vary rarely
    /// (a lamp's edge, clipped in most samples); the null model's eight
    /// renders see more of it.
    pub fn widened(mut self, other: &NullModel) -> Self {
        for (v, w) in self.variance.iter_mut().zip(&other.variance) {
            *v = v.max(*w);
        }
        self
    }
}

/// The statistic: `sum z^2` over the cells, each cell's share capped at
/// [`CELL_CAP`] so that one cell cannot decide alone (capping only lowers
/// the sum, so the chi-square bound on false alarms still holds).
pub fn statistic(z: &[f64]) -> f64 {
    z.iter().map(|z| (z * z).min(CELL_CAP)).sum()
}

/// The most one cell adds to [`statistic`]: a difference of 5 standard
/// errors.
pub const CELL_CAP: f64 = 25.0;

/// The chi-square quantile of `dof` degrees of freedom at `1 - alpha`
/// (Wilson and Hilferty's cube-root normal approximation).
pub fn chi_square_quantile(dof: f64, alpha: f64) -> f64 {
    let z = normal_upper_quantile(alpha);
    let a = 2.0 / (9.0 * dof);
    dof * (1.0 - a + z * a.sqrt()).powi(3)
}

/// `z` with `P(Z > z) = p` for a standard normal `Z`, by bisection on
/// `erfc` (to 1e-10).
pub fn normal_upper_quantile(p: f64) -> f64 {
    let (mut lo, mut hi) = (-40.0, 40.0);
    while hi - lo > 1e-10 {
        let mid = 0.5 * (lo + hi);
        if 0.5 * erfc(mid / std::f64::consts::SQRT_2) > p {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The cells of a student's image.
pub fn student_cells(image: &StudentImage) -> Vec<f64> {
    cells(image.width, image.height, &image.rgb)
}

/// The counts a two-sided exact binomial test at level `alpha` accepts
/// for `n` trials of probability `p`: the least `lo` with
/// `P(X <= lo) > alpha / 2` and the most `hi` with `P(X >= hi) > alpha /
/// 2`. Exact (the probabilities summed in log space), so that a correct
/// sampler fails at most `alpha` of the time, where the normal
/// approximation's thin tails would fail a small `p` more often.
pub fn binomial_range(n: u64, p: f64, alpha: f64) -> (u64, u64) {
    if p <= 0.0 || p >= 1.0 {
        let k = if p <= 0.0 { 0 } else { n };
        return (k, k);
    }
    // ln P(X = k), by P(k + 1) / P(k) = (n - k) / (k + 1) p / (1 - p).
    let step = (p / (1.0 - p)).ln();
    let mut log = vec![n as f64 * (1.0 - p).ln()];
    for k in 0..n {
        let next = log[k as usize] + ((n - k) as f64 / (k + 1) as f64).ln() + step;
        log.push(next);
    }
    let top = log.iter().fold(f64::NEG_INFINITY, |a, b| a.max(*b));
    let pmf: Vec<f64> = log.iter().map(|l| (l - top).exp()).collect();
    let total: f64 = pmf.iter().sum();
    let cut = alpha / 2.0 * total;
    let (mut below, mut lo) = (0.0, 0);
    for (k, q) in pmf.iter().enumerate() {
        below += q;
        if below > cut {
            lo = k as u64;
            break;
        }
    }
    let (mut above, mut hi) = (0.0, n);
    for (k, q) in pmf.iter().enumerate().rev() {
        above += q;
        if above > cut {
            hi = k as u64;
            break;
        }
    }
    (lo, hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The range's ends against statrs's binomial distribution: the tail
    /// beyond each end is at most `alpha / 2`, and with the end it is more.
    #[test]
    fn the_binomial_range_cuts_the_exact_tails() {
        use statrs::distribution::{Binomial, Discrete, DiscreteCDF};
        for (n, p) in [(4000u64, 0.04), (2000, 0.43), (4000, 0.5), (50, 0.9)] {
            let alpha = 1e-5;
            let (lo, hi) = binomial_range(n, p, alpha);
            let b = Binomial::new(p, n).unwrap();
            let upper = |k: u64| 1.0 - b.cdf(k) + b.pmf(k);
            assert!(lo == 0 || b.cdf(lo - 1) <= alpha / 2.0, "{n} {p} {lo}");
            assert!(b.cdf(lo) > alpha / 2.0, "{n} {p} {lo}");
            assert!(
                hi == n || upper(hi + 1) <= alpha / 2.0 * (1.0 + 1e-9),
                "{n} {p} {hi}"
            );
            assert!(upper(hi) > alpha / 2.0, "{n} {p} {hi}");
        }
        assert_eq!(binomial_range(10, 0.0, 1e-5), (0, 0));
        assert_eq!(binomial_range(10, 1.0, 1e-5), (10, 10));
    }

    #[test]
    fn quantiles_match_tables() {
        assert!((normal_upper_quantile(0.025) - 1.959964).abs() < 1e-5);
        assert!((normal_upper_quantile(1e-4) - 3.719016).abs() < 1e-5);
        // chi-square(100) at 0.99: 135.807 (tables).
        assert!((chi_square_quantile(100.0, 0.01) - 135.807).abs() < 0.2);
        // chi-square(500) at 0.999: 603.446.
        assert!((chi_square_quantile(500.0, 0.001) - 603.446).abs() < 0.5);
    }

    #[test]
    fn cells_average_blocks_per_channel() {
        // Two blocks side by side: the left red at 255, the right blue at 51.
        let (w, h) = (2 * BLOCK, BLOCK);
        let mut rgb = vec![0u8; (w * h * 3) as usize];
        for y in 0..h {
            for x in 0..w {
                let i = (3 * (y * w + x)) as usize;
                if x < BLOCK {
                    rgb[i] = 255;
                } else {
                    rgb[i + 2] = 51;
                }
            }
        }
        let expected = [1.0, 0.0, 0.0, 0.0, 0.0, 0.2];
        let found = cells(w, h, &rgb);
        assert_eq!(found.len(), expected.len());
        assert!(
            found
                .iter()
                .zip(expected)
                .all(|(a, b)| (a - b).abs() < 1e-12),
            "{found:?}"
        );
    }

    #[test]
    fn the_null_models_variance_is_that_of_a_block_mean() {
        // Two renders of an 8 x 8 image, every value 0 in one and 2/255 in
        // the other: per value variance (1/255)^2 * 2 plus the rounding
        // floor, a block mean's the same over 64 (the sum of 64 variances
        // over 64^2).
        let a = vec![0u8; 8 * 8 * 3];
        let b = vec![2u8; 8 * 8 * 3];
        let model = NullModel::new(8, 8, &[a, b]);
        let per_value = 2.0 * (1.0f64 / 255.0).powi(2) + (1.0f64 / 255.0).powi(2) / 12.0;
        for v in &model.variance {
            assert!((v - per_value / 64.0).abs() < 1e-15);
        }
        assert!(model.mean.iter().all(|m| (m - 1.0 / 255.0).abs() < 1e-15));
    }
}
