//! Reproducible randomness: one generator per (seed, stream), so a render
//! depends on (seed, pixel, sample index), never on the thread schedule.

use rand::{Rng, SeedableRng};
use rand_pcg::Pcg32;

/// The project's random number generator: PCG32 (O'Neill 2014), small,
/// fast and stable across versions of `rand`.
pub type Sampler = Pcg32;

/// A generator for stream `stream` of the run seeded with `seed`
/// (for example stream = pixel index).
pub fn sampler(seed: u64, stream: u64) -> Sampler {
    // Mix the two words so neighbouring streams start far apart.
    Pcg32::new(splitmix64(seed ^ splitmix64(stream)), stream | 1)
}

/// SplitMix64 finaliser (Steele, Lea and Flood 2014): a bijective mixer.
pub fn splitmix64(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// Two uniform numbers in `[0, 1)`.
pub fn next_2d(rng: &mut Sampler) -> glam::Vec2 {
    glam::Vec2::new(rng.gen(), rng.gen())
}

/// Keeps `SeedableRng` in scope for callers that seed directly.
pub fn from_seed(seed: u64) -> Sampler {
    Sampler::seed_from_u64(seed)
}
