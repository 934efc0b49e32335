//! The independent sampler: every number a fresh uniform draw, as the
//! course's renderer takes them.
//!
//! Pixel `(x, y)` of a `width`-wide image has its own PCG32 stream
//! [`crate::math::rng::sampler`]`(seed, y * width + x)`, started at the
//! pixel's sample 0 and drawn from in order across all its samples, so the
//! course-mode images are exactly the ones rendered before the sampler
//! interface existed. Dimensions mean nothing here: `get_2d` is two
//! `get_1d` in a row. A pixel's samples must be started in order
//! `0, 1, 2, ...` (as [`crate::render::estimate_pixel`] takes them): the
//! stream has no random access.
//!
//! Statistical tests whose statistics assume independent samples (t-tests,
//! confidence intervals, chi-square of a warp) use this sampler.

use glam::Vec2;
use rand::Rng;

use super::Sampler;
use crate::math::rng::{self, Sampler as Pcg32};

/// Uniform, independent numbers from one PCG32 stream per pixel.
#[derive(Clone, Debug)]
pub struct IndependentSampler {
    seed: u64,
    width: u32,
    rng: Pcg32,
}

impl IndependentSampler {
    /// The sampler of a render `width` pixels wide.
    pub fn new(seed: u64, width: u32) -> Self {
        IndependentSampler {
            seed,
            width,
            rng: rng::sampler(seed, 0),
        }
    }

    /// One stream, `sampler(seed, stream)`, for estimates outside a render
    /// (tests, examples): draw from it without starting a pixel sample.
    pub fn from_stream(seed: u64, stream: u64) -> Self {
        IndependentSampler {
            seed,
            width: 0,
            rng: rng::sampler(seed, stream),
        }
    }
}

impl Sampler for IndependentSampler {
    fn start_pixel_sample(&mut self, (x, y): (u32, u32), index: u32) {
        if index == 0 {
            self.rng = rng::sampler(self.seed, y as u64 * self.width as u64 + x as u64);
        }
    }

    #[inline]
    fn get_1d(&mut self) -> f32 {
        self.rng.gen()
    }

    #[inline]
    fn get_2d(&mut self) -> Vec2 {
        rng::next_2d(&mut self.rng)
    }
}
