//! Part 5: adaptive sampling.
//!
//! A pixel stops taking samples once its mean is known well enough. For
//! the samples' luminances `x_k` (`0.2126 r + 0.7152 g + 0.0722 b`), keep
//! `s1 = sum x_k` and `s2 = sum x_k^2`; after `n` samples
//!
//! ```text
//! mu = s1 / n,   sigma^2 = (s2 - s1^2 / n) / (n - 1),   I = 1.96 sigma / sqrt(n)
//! ```
//!
//! `I` is the half-width of the 95 % confidence interval of the mean (normal
//! approximation). Every `batch` samples (`-a BATCH TOL`, defaults 32 and
//! 0.05) the pixel stops when `I <= TOL mu`, else at the `-s` limit.
//!
//! The interval assumes independent samples. With a low-discrepancy
//! sampler ([`crate::sampling::ZSobolSampler`], the default) a pixel's
//! samples are stratified: the mean's true error is below `sigma / sqrt(n)`,
//! so `I` overestimates it and the test is conservative (pixels stop
//! later than they need, never earlier).
//!
//! The running sums are kept in `f64`, so `s2 - s1^2 / n` does not lose
//! the variance to cancellation at the sample counts used here (the test
//! compares against a two-pass computation).

pub mod rate_image;

pub use rate_image::rate_colour;

use crate::math::{luminance, Rgb};

/// The course's confidence multiplier: 95 % two-sided, normal distribution.
pub const Z_95: f64 = 1.96;

/// Running luminance statistics of one pixel's samples.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LuminanceStats {
    pub s1: f64,
    pub s2: f64,
    pub n: u32,
}

impl LuminanceStats {
    pub fn push(&mut self, radiance: Rgb) {
        let x = luminance(radiance) as f64;
        self.s1 += x;
        self.s2 += x * x;
        self.n += 1;
    }

    pub fn mean(&self) -> f64 {
        if self.n == 0 {
            0.0
        } else {
            self.s1 / self.n as f64
        }
    }

    /// Unbiased sample variance (0 for fewer than two samples).
    pub fn variance(&self) -> f64 {
        if self.n < 2 {
            return 0.0;
        }
        let n = self.n as f64;
        ((self.s2 - self.s1 * self.s1 / n) / (n - 1.0)).max(0.0)
    }

    /// Variance of the mean, `sigma^2 / n`: the squared standard error.
    pub fn variance_of_mean(&self) -> f64 {
        if self.n < 2 {
            0.0
        } else {
            self.variance() / self.n as f64
        }
    }

    /// `I = 1.96 sigma / sqrt(n)`.
    pub fn confidence_half_width(&self) -> f64 {
        Z_95 * self.variance_of_mean().sqrt()
    }

    /// The course's test: `I <= tolerance * mu`.
    pub fn converged(&self, tolerance: f32) -> bool {
        self.n >= 2 && self.confidence_half_width() <= tolerance as f64 * self.mean()
    }
}

/// `-a BATCH TOL`: test convergence every `batch` samples with tolerance `tolerance`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Adaptive {
    pub batch: u32,
    pub tolerance: f32,
}

impl Default for Adaptive {
    fn default() -> Self {
        Adaptive {
            batch: 32,
            tolerance: 0.05,
        }
    }
}

impl Adaptive {
    /// Whether a pixel with `stats` may stop now (called after each sample).
    pub fn should_stop(&self, stats: &LuminanceStats) -> bool {
        stats.n % self.batch.max(1) == 0 && stats.converged(self.tolerance)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn running_statistics_equal_a_two_pass_computation() {
        let values: Vec<f32> = (0..1000)
            .map(|i| ((i * 7919) % 1000) as f32 / 100.0 + 5.0)
            .collect();
        let mut stats = LuminanceStats::default();
        for &v in &values {
            stats.push(Rgb::splat(v));
        }
        let xs: Vec<f64> = values
            .iter()
            .map(|&v| luminance(Rgb::splat(v)) as f64)
            .collect();
        let n = xs.len() as f64;
        let mean = xs.iter().sum::<f64>() / n;
        let variance = xs.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / (n - 1.0);
        assert!((stats.mean() - mean).abs() <= 1e-12 * mean);
        assert!(
            (stats.variance() - variance).abs() <= 1e-9 * variance,
            "{} {variance}",
            stats.variance()
        );
        let half_width = 1.96 * (variance / n).sqrt();
        assert!((stats.confidence_half_width() - half_width).abs() <= 1e-9 * half_width);
    }

    #[test]
    fn a_constant_pixel_converges_at_the_first_batch() {
        let adaptive = Adaptive::default();
        let mut stats = LuminanceStats::default();
        for i in 1..=32 {
            stats.push(Rgb::splat(0.5));
            assert_eq!(adaptive.should_stop(&stats), i == 32);
        }
    }

    #[test]
    fn a_black_pixel_converges_and_a_noisy_one_does_not() {
        let mut black = LuminanceStats::default();
        let mut noisy = LuminanceStats::default();
        for i in 0..64 {
            black.push(Rgb::ZERO);
            noisy.push(Rgb::splat(if i % 2 == 0 { 0.0 } else { 2.0 }));
        }
        assert!(black.converged(0.05));
        assert!(!noisy.converged(0.05));
    }
}
