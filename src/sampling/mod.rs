//! Where a render's random numbers come from: the [`Sampler`] interface,
//! with the sample index and dimension bookkeeping of pbrt-v4's `Sampler`
//! (Pharr, Jakob and Humphreys, *Physically Based Rendering*, 4th ed.,
//! chapter 8).
//!
//! A render starts each camera sample with
//! [`Sampler::start_pixel_sample`]`(pixel, index)`; every number the
//! sample then needs is the next *dimension*: [`Sampler::get_pixel_2d`]
//! for the film offset, then [`Sampler::get_2d`] for the lens, and per path
//! vertex, in a fixed order, the direct-lighting numbers (per light
//! sample: a 1D light choice and a 2D point), the BSDF's 1D lobe choice
//! and 2D direction, and the 1D Russian roulette number. A sampler may so
//! give sample `i` of a pixel numbers that fill the `d`-th dimension well
//! together with its other samples, which independent numbers cannot.
//!
//! - [`IndependentSampler`] (`--sampler independent`, and `--course`):
//!   independent uniform numbers, the course's stream per pixel.
//! - [`ZSobolSampler`] (`--sampler zsobol`, the default): Owen-scrambled
//!   Sobol' points in Morton order (Ahmed and Wonka 2020): each pixel's
//!   samples in each dimension pair are a (0, m, 2)-net when `spp = 2^m`,
//!   and the error is spread over the screen as blue noise.
//!
//! Both are unbiased: each number is uniform on `[0, 1)` and the numbers
//! of different dimensions are independent. The ZSobol samples of one
//! pixel are not independent of each other: an error estimate that
//! assumes they are (adaptive sampling's confidence interval,
//! [`crate::adaptive`]) overestimates the error, so it is conservative.
//!
//! [`PixelSampler`] is the one the renderer holds: an enum over the two,
//! so that the integrator is compiled once. [`strata`] moves the several
//! samples a vertex takes of an environment map into strata of their own.

pub mod independent;
pub mod sobol;
pub mod strata;
pub mod zsobol;

pub use independent::IndependentSampler;
pub use zsobol::ZSobolSampler;

use glam::Vec2;

/// Numbers for a camera sample, dimension by dimension.
pub trait Sampler {
    /// Starts sample `index` of pixel `pixel = (x, y)` (row 0 at the top)
    /// at dimension 0.
    fn start_pixel_sample(&mut self, pixel: (u32, u32), index: u32);

    /// The next dimension: a number in `[0, 1)`.
    fn get_1d(&mut self) -> f32;

    /// The next two dimensions: a point in `[0, 1)^2`.
    fn get_2d(&mut self) -> Vec2;

    /// The offset of the camera ray in its pixel, in `[0, 1)^2`: the first
    /// two dimensions of a camera sample.
    fn get_pixel_2d(&mut self) -> Vec2 {
        self.get_2d()
    }
}

/// Which sampler a render uses (`--sampler`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum SamplerKind {
    /// Independent uniform numbers (the course's).
    Independent,
    /// Owen-scrambled Sobol' in Morton order.
    #[default]
    ZSobol,
}

impl SamplerKind {
    /// The sampler of a render of `size` pixels with up to `spp` samples
    /// each, seeded by `seed`.
    pub fn for_render(self, seed: u64, size: (u32, u32), spp: u32) -> PixelSampler {
        match self {
            SamplerKind::Independent => {
                PixelSampler::Independent(IndependentSampler::new(seed, size.0))
            }
            SamplerKind::ZSobol => PixelSampler::ZSobol(ZSobolSampler::new(seed, size, spp)),
        }
    }

    /// Its name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            SamplerKind::Independent => "independent",
            SamplerKind::ZSobol => "zsobol",
        }
    }
}

/// The sampler a render holds: one of the two, dispatched by a match.
///
/// The ZSobol variant carries its caches inline (about 3.5 KB): a render makes one
/// per tile and never moves it in a loop, and a box would cost a pointer
/// chase per number.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug)]
pub enum PixelSampler {
    Independent(IndependentSampler),
    ZSobol(ZSobolSampler),
}

impl Sampler for PixelSampler {
    #[inline]
    fn start_pixel_sample(&mut self, pixel: (u32, u32), index: u32) {
        match self {
            PixelSampler::Independent(s) => s.start_pixel_sample(pixel, index),
            PixelSampler::ZSobol(s) => s.start_pixel_sample(pixel, index),
        }
    }

    #[inline]
    fn get_1d(&mut self) -> f32 {
        match self {
            PixelSampler::Independent(s) => s.get_1d(),
            PixelSampler::ZSobol(s) => s.get_1d(),
        }
    }

    #[inline]
    fn get_2d(&mut self) -> Vec2 {
        match self {
            PixelSampler::Independent(s) => s.get_2d(),
            PixelSampler::ZSobol(s) => s.get_2d(),
        }
    }
}
