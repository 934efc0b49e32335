//! Owen-scrambled Sobol' points in Morton (z) order over pixels and
//! samples (Ahmed and Wonka 2020, "Screen-space blue-noise diffusion of
//! Monte Carlo sampling error via hierarchical ordering of pixels", SIGGRAPH
//! Asia; pbrt-v4, section 8.7, `ZSobolSampler`).
//!
//! One 2D (0, 2)-sequence ([`super::sobol`]) serves the whole image. Sample
//! `s` of pixel `(x, y)` gets the sequence index built from
//!
//! ```text
//! m = (morton(x, y) << L) | s,    L = ceil(log2(spp))
//! ```
//!
//! where `morton` interleaves the bits of `x` (even bits) and `y` (odd
//! bits), the image side rounded up to `2^R`. The samples of a pixel are
//! then the aligned block of `2^L` consecutive indices below the pixel's
//! prefix, a (0, L, 2)-net; pixels close on screen have close prefixes.
//!
//! Taken as is, neighbouring pixels would get the same points. The index
//! is therefore shuffled hierarchically: reading `m` as base-4 digits from
//! the top (with a last base-2 digit when `L` is odd), each digit `d` is
//! replaced by `pi(d)`, one of the 24 permutations of `{0, 1, 2, 3}`,
//! chosen by a hash of the digits above it, the dimension and the seed
//! (a single bit is flipped by a hash bit). Digits below a prefix are
//! permuted the same way for every value of the digits below, so the
//! shuffle maps each aligned block onto an aligned block: a pixel's
//! samples stay a (0, L, 2)-net, and the four quadrants of every square of
//! `4^k` pixels visit the sequence's strata in a random order, which
//! spreads the error as blue noise over the screen.
//!
//! The hashes of different digits are independent of each other (each
//! hashes the digits above it with the digit's position and the
//! dimension's key), so they are computed in parallel. (Chaining them, one
//! cheap multiply per digit, was tried and fails the neighbouring-pixel
//! chi-square test of `tests/zsobol.rs`: prefixes one digit apart kept
//! related hashes.) The pixel's own digits (the top `R`) are shuffled once
//! per pixel and dimension and kept (for the first [`CACHED_DIMENSIONS`]
//! dimensions): a pixel's later samples shuffle only their `L` sample
//! digits. Of these, all but the lowest base-4 digit, and the permutation
//! of the lowest, hash the same bits for the samples whose indices differ
//! only there (four consecutive samples when `L` is even, eight when it
//! is odd), so they too are kept per dimension. With `L` even (4, 16, 64
//! samples a pixel) three samples in four hash no digit at all; with `L`
//! odd the last base-2 digit's flip is still hashed at every call. At 64
//! samples a pixel this took the sampler's instructions on the glass
//! bunny under a sun from 979M to 712M (`callgrind`); the numbers are the
//! same, checked against the definition digit by digit.
//!
//! Each call for a dimension pair (`get_2d`) takes Sobol' dimensions 0
//! and 1 at the shuffled index, Owen-scrambled with two seeds hashed from
//! the dimension and the render's seed ([`super::sobol::owen_scramble`]); a
//! 1D dimension takes dimension 0. Different dimensions thus use
//! independent scrambles and index shuffles, which decorrelates them
//! (Burley 2020, section 4, pads dimensions the same way).

use glam::Vec2;

use super::sobol::{scrambled_sobol, to_unit};
use super::Sampler;
use crate::math::rng::splitmix64;

/// Dimensions whose hash keys and shuffled pixel digits are kept; later
/// dimensions compute theirs at each call.
pub const CACHED_DIMENSIONS: usize = 64;

/// The 24 permutations of `{0, 1, 2, 3}`, by Lehmer code.
const PERMUTATIONS: [[u8; 4]; 24] = permutations_of_four();

const fn permutations_of_four() -> [[u8; 4]; 24] {
    let mut table = [[0u8; 4]; 24];
    let mut p = 0;
    while p < 24 {
        let mut left = [0u8, 1, 2, 3];
        let (mut remaining, mut code, mut k) = (4, p, 0);
        while k < 4 {
            // (3 - k)! choices for the digits after position k.
            let radix = [6, 2, 1, 1][k];
            let pick = code / radix;
            code %= radix;
            table[p][k] = left[pick];
            let mut j = pick;
            while j + 1 < remaining {
                left[j] = left[j + 1];
                j += 1;
            }
            remaining -= 1;
            k += 1;
        }
        p += 1;
    }
    table
}

/// `digit`, the one at bit `shift` of an index whose bits above it are
/// `above`, permuted by the permutation a hash of (`above`, `shift`,
/// `key`) picks.
#[inline]
fn permute(above: u64, shift: u32, key: u64, digit: u64) -> u64 {
    permutation(above, shift, key)[digit as usize] as u64
}

/// The permutation that [`permute`] applies to the digit at bit `shift`
/// below `above`.
#[inline]
fn permutation(above: u64, shift: u32, key: u64) -> [u8; 4] {
    let h = splitmix64(((above << 6) | shift as u64) ^ key);
    let p = ((h >> 32) * 24) >> 32;
    PERMUTATIONS[p as usize]
}

/// What a dimension draws from: the key of its index shuffle and the
/// seeds of its two scrambles.
#[derive(Clone, Copy, Debug, Default)]
struct DimensionKeys {
    shuffle: u64,
    scramble: u64,
}

impl DimensionKeys {
    fn new(seed: u64, dimension: u32) -> Self {
        let shuffle = splitmix64(seed ^ (dimension as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15));
        DimensionKeys {
            shuffle,
            scramble: splitmix64(shuffle),
        }
    }
}

/// A pixel's digits shuffled for one dimension.
#[derive(Clone, Copy, Debug, Default)]
struct PixelDigits {
    /// `morton(x, y) + 1` of the pixel (0: none yet).
    tag: u64,
    /// The pixel's base-4 digits, shuffled.
    digits: u64,
}

/// The shuffled sample digits shared by a group of consecutive samples of
/// a pixel, for one dimension: the samples whose indices differ only in
/// their lowest base-4 digit and, when `L` is odd, the base-2 digit below
/// it (four samples, or eight). Their digits above it, and the
/// permutation of that digit, hash the same bits, so they are shuffled
/// once for the group; the base-2 digit's flip is not kept.
#[derive(Clone, Copy, Debug)]
struct SampleGroup {
    /// The Morton index above the group's lowest digit (`u64::MAX`: none yet).
    tag: u64,
    /// The shuffled digits above the lowest, in place.
    upper: u64,
    /// The permutation of the lowest digit.
    lowest: [u8; 4],
}

impl SampleGroup {
    const NONE: SampleGroup = SampleGroup {
        tag: u64::MAX,
        upper: 0,
        lowest: [0, 1, 2, 3],
    };
}

/// The ZSobol sampler of one render: every sample computed from (seed,
/// pixel, sample index, dimension) alone; it keeps only a cache.
#[derive(Clone, Debug)]
pub struct ZSobolSampler {
    /// `L`: the sample count rounded up to `2^L`.
    log2_spp: u32,
    /// `R`: the image's larger side rounded up to `2^R`.
    log2_side: u32,
    seed: u64,
    /// `morton(x, y)` of the current pixel.
    pixel: u64,
    /// The current sample index `s`.
    sample: u64,
    dimension: u32,
    keys: [DimensionKeys; CACHED_DIMENSIONS],
    cache: [PixelDigits; CACHED_DIMENSIONS],
    groups: [SampleGroup; CACHED_DIMENSIONS],
}

impl ZSobolSampler {
    /// The sampler of a `width x height` render with up to `spp` samples
    /// per pixel.
    pub fn new(seed: u64, (width, height): (u32, u32), spp: u32) -> Self {
        let seed = splitmix64(seed ^ 0x5A50_B01D);
        ZSobolSampler {
            log2_spp: spp.max(1).next_power_of_two().trailing_zeros(),
            log2_side: width
                .max(height)
                .max(1)
                .next_power_of_two()
                .trailing_zeros(),
            seed,
            pixel: 0,
            sample: 0,
            dimension: 0,
            keys: std::array::from_fn(|d| DimensionKeys::new(seed, d as u32)),
            cache: [PixelDigits::default(); CACHED_DIMENSIONS],
            groups: [SampleGroup::NONE; CACHED_DIMENSIONS],
        }
    }

    /// Samples per pixel in the index space: `2^L`.
    pub fn samples_per_pixel(&self) -> u64 {
        1 << self.log2_spp
    }

    /// The current pixel's digits shuffled with `key`.
    fn shuffle_pixel(&self, key: u64) -> PixelDigits {
        let mut digits = 0;
        for i in 0..self.log2_side {
            let digit = (self.pixel >> (2 * i)) & 3;
            let above = self.pixel >> (2 * i + 2);
            digits |= permute(above, self.log2_spp + 2 * i, key, digit) << (2 * i);
        }
        PixelDigits {
            tag: self.pixel + 1,
            digits,
        }
    }

    /// The shuffled sample digits of the group of the current sample
    /// (Morton index `morton`), with `key`: every digit above the lowest
    /// (and above the last base-2 digit, when `L` is odd), and the
    /// permutation of the lowest. Needs `L >= 2`.
    fn shuffle_group(&self, morton: u64, key: u64) -> SampleGroup {
        let odd = self.log2_spp & 1;
        let mut upper = 0;
        for i in 1..self.log2_spp / 2 {
            let shift = odd + 2 * i;
            let digit = (self.sample >> shift) & 3;
            upper |= permute(morton >> (shift + 2), shift, key, digit) << shift;
        }
        SampleGroup {
            tag: morton >> (odd + 2),
            upper,
            lowest: permutation(morton >> (odd + 2), odd, key),
        }
    }

    /// The Sobol' index of the current pixel sample in `dimension`, and
    /// the dimension's scramble seeds: the Morton index
    /// `(morton(x, y) << L) | s` with its digits shuffled.
    #[inline]
    fn sequence_index(&mut self, dimension: u32) -> (u64, u64) {
        let d = dimension as usize;
        let (prefix, keys) = if d < CACHED_DIMENSIONS {
            let keys = self.keys[d];
            if self.cache[d].tag != self.pixel + 1 {
                self.cache[d] = self.shuffle_pixel(keys.shuffle);
            }
            (self.cache[d], keys)
        } else {
            let keys = DimensionKeys::new(self.seed, dimension);
            (self.shuffle_pixel(keys.shuffle), keys)
        };
        let odd = self.log2_spp & 1;
        let morton = (self.pixel << self.log2_spp) | self.sample;
        let mut low = 0;
        if self.log2_spp >= 2 {
            let group = if d < CACHED_DIMENSIONS {
                if self.groups[d].tag != morton >> (odd + 2) {
                    self.groups[d] = self.shuffle_group(morton, keys.shuffle);
                }
                self.groups[d]
            } else {
                self.shuffle_group(morton, keys.shuffle)
            };
            let digit = (self.sample >> odd) & 3;
            low = group.upper | (group.lowest[digit as usize] as u64) << odd;
        }
        if odd == 1 {
            let flip = splitmix64(((morton >> 1) << 6) ^ keys.shuffle) >> 63;
            low |= (self.sample & 1) ^ flip;
        }
        ((prefix.digits << self.log2_spp) | low, keys.scramble)
    }
}

/// Interleaves the bits of `x` (even positions) and `y` (odd positions).
pub fn morton2(x: u32, y: u32) -> u64 {
    spread(x) | (spread(y) << 1)
}

/// Bits of `v` moved to the even positions of a 64-bit word.
fn spread(v: u32) -> u64 {
    let mut v = v as u64;
    v = (v | (v << 16)) & 0x0000_FFFF_0000_FFFF;
    v = (v | (v << 8)) & 0x00FF_00FF_00FF_00FF;
    v = (v | (v << 4)) & 0x0F0F_0F0F_0F0F_0F0F;
    v = (v | (v << 2)) & 0x3333_3333_3333_3333;
    (v | (v << 1)) & 0x5555_5555_5555_5555
}

impl Sampler for ZSobolSampler {
    fn start_pixel_sample(&mut self, (x, y): (u32, u32), index: u32) {
        debug_assert!((index as u64) < self.samples_per_pixel());
        self.pixel = morton2(x, y);
        self.sample = index as u64;
        self.dimension = 0;
    }

    #[inline]
    fn get_1d(&mut self) -> f32 {
        let (index, seeds) = self.sequence_index(self.dimension);
        self.dimension += 1;
        to_unit(scrambled_sobol(index, 0, seeds as u32))
    }

    #[inline]
    fn get_2d(&mut self) -> Vec2 {
        let (index, seeds) = self.sequence_index(self.dimension);
        self.dimension += 2;
        Vec2::new(
            to_unit(scrambled_sobol(index, 0, seeds as u32)),
            to_unit(scrambled_sobol(index, 1, (seeds >> 32) as u32)),
        )
    }
}

#[cfg(test)]
mod tests;
