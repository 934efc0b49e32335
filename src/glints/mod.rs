//! Glints: more camera samples for the pixels that see a small, bright
//! part of an environment map (a sun) along a chain of mirror or glass
//! bounces.
//!
//! Such a pixel's value is the map seen over the small set of directions
//! its chain reflects the pixel into; where that set covers the sun in
//! part, a sample finds the sun with a small probability `p` and the
//! pixel's variance is about `p L_sun^2` a sample, which no strategy but
//! the pixel's own samples reduces (no vertex of the chain chooses
//! anything). These few pixels can hold almost all of an image's error.
//!
//! Before the render, a deterministic *pilot* traces, for each pixel, the
//! chains of delta bounces ([`pilot`]) from its centre and its four
//! corners, and matches their leaves by the lobes taken. A leaf seen by
//! `k` of the five rays escapes over a disk of directions whose radius
//! `r` is the largest angle from their mean direction; over that disk
//! the map's luminance lies in `[m, M]` with mean `mu` ([`bounds`]). A
//! sample of the pixel then sees `w L` with probability `a = k / 5`,
//! where `w` is the chain's throughput, so its variance is at most
//!
//! ```text
//! sigma_p^2 = sum over leaves of  a w^2 ((M - mu)(mu - m) + (1 - a) mu^2)
//! ```
//!
//! Samples then follow Neyman's allocation with costs (Neyman 1934, "On
//! the two different aspects of the representative method", *J. R. Stat.
//! Soc.* 97; Cochran, *Sampling Techniques*, 3rd ed., 1977, 5.5): for a
//! fixed total cost `sum n_p c_p`, the variance `sum sigma_p^2 / n_p` is
//! least when `n_p` is proportional to `sigma_p / sqrt(c_p)`. A sample's
//! cost `c_p` is counted in rays ([`sample_cost`]). Pixel `p` gets
//! `spp k_p` samples, `k_p` the power of four at most
//!
//! ```text
//! (sigma_p / L_mean) sqrt(c_mean / c_p),   between 1 and K
//! ```
//!
//! with `L_mean` the map's mean luminance over the sphere (the radiance
//! scale of the rest of the image, whose pixels keep `spp`) and `c_mean`
//! the mean cost. `K` starts at [`MAX_FACTOR`] (less where ZSobol's
//! 32-bit index would not hold it: [`factor_fitting`]) and is divided by
//! 4 while the extra samples would cost more than half of the render's.
//! Powers of four keep ZSobol's nets ([`factors`]).
//!
//! The allocation depends on the scene alone, not on any random number of
//! the render, so each pixel's estimate is still the mean of independent
//! (or stratified) unbiased samples: the image's expectation does not
//! change. What changes is the number of samples: a pixel's sample count
//! shows in the sample-rate image.

pub mod bounds;
pub mod pilot;

use std::time::Instant;

use std::f32::consts::PI;

use glam::{Vec2, Vec3};
use rayon::prelude::*;

use crate::intersect::Intersector;
use crate::lights::Light;
use crate::raygen::Camera;
use crate::render::tiles::thread_pool;
use crate::render::{pixel_ray, RenderSettings};
use crate::world::World;
use bounds::MapBounds;
use pilot::{chain_leaves, Leaves};

/// The most a pixel's samples are multiplied by.
pub const MAX_FACTOR: u32 = 16;

/// The fewest samples a pixel (`-s`) at which the plan runs the pilot:
/// at 480 x 360 it took 0.15 s of a 64-sample render of the mirror bunny
/// under a sun (3.5 s without it), about 4 %; the chains' part of it
/// grows as `-s` falls (the map's pyramid, 50 to 75 ms for a 4k map, is
/// a fixed cost).
pub const MIN_SAMPLES: u32 = 16;

/// The pixel offsets of the pilot's rays: the centre and the corners.
pub const PILOT_OFFSETS: [Vec2; 5] = [
    Vec2::new(0.5, 0.5),
    Vec2::new(0.0, 0.0),
    Vec2::new(1.0, 0.0),
    Vec2::new(0.0, 1.0),
    Vec2::new(1.0, 1.0),
];

/// Radius (radians, about 3 degrees) of the disk a leaf seen by one
/// pilot ray alone is given: its spread is unknown.
const LONE_LEAF_RADIUS: f32 = 0.05;

/// The start of the render plan's line.
pub const LINE: &str = "plan: glint samples:";

/// The render plan's decision ([`crate::plan::Plan::glints`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Decision {
    On,
    NoEnvironment,
    NoDelta,
    Lens,
    /// Turned off by a flag.
    Asked,
    /// `-s` below [`MIN_SAMPLES`].
    FewSamples,
    /// `-a`: the course's adaptive sampling decides each pixel's samples.
    Adaptive,
}

impl Decision {
    /// On where an environment map lights a scene with mirror or glass,
    /// seen through a pinhole (the pilot traces pinhole rays).
    pub fn new(environment: bool, delta: bool, pinhole: bool) -> Self {
        match (environment, delta, pinhole) {
            (false, _, _) => Decision::NoEnvironment,
            (_, false, _) => Decision::NoDelta,
            (_, _, false) => Decision::Lens,
            _ => Decision::On,
        }
    }

    /// Why the flags turn glint samples off, if they do: `allowed`
    /// false (`--glints off`, `--course`, `--no-plan`), `-s` below
    /// [`MIN_SAMPLES`], or adaptive sampling.
    pub fn off_by_flags(allowed: bool, samples_per_pixel: u32, adaptive: bool) -> Option<Self> {
        if !allowed {
            Some(Decision::Asked)
        } else if samples_per_pixel < MIN_SAMPLES {
            Some(Decision::FewSamples)
        } else if adaptive {
            Some(Decision::Adaptive)
        } else {
            None
        }
    }

    pub fn on(self) -> bool {
        self == Decision::On
    }

    pub fn line(self) -> String {
        let why = match self {
            Decision::On => {
                return format!(
                    "{LINE} on: pixels whose chains of mirror and glass bounces may see a small, \
                     bright part of the map take up to {MAX_FACTOR} times -s samples (a pilot of \
                     {} rays a pixel decides; at most half again the render's cost)",
                    PILOT_OFFSETS.len()
                )
            }
            Decision::NoEnvironment => "no environment map",
            Decision::NoDelta => "no mirror or glass",
            Decision::Lens => "a thin lens: the pilot traces pinhole rays",
            Decision::Asked => "--glints off, --course or --no-plan",
            Decision::FewSamples => {
                return format!(
                    "{LINE} off (-s below {MIN_SAMPLES}: the pilot would cost a large part of the render): every pixel takes -s samples"
                )
            }
            Decision::Adaptive => "-a: adaptive sampling decides each pixel's samples",
        };
        format!("{LINE} off ({why}): every pixel takes -s samples")
    }
}

/// How a render's samples were shared out.
#[derive(Clone, Debug, PartialEq)]
pub struct Allocation {
    /// Each pixel's factor on `-s`, row by row (row 0 at the top): a power
    /// of four from 1 to [`MAX_FACTOR`].
    pub factors: Vec<u32>,
    /// What the extra samples cost, as a fraction of the render's without
    /// them, by the pilot's count ([`sample_cost`]): at most 1/2.
    pub extra_cost: f64,
    /// Seconds the pilot took.
    pub seconds: f64,
}

impl Allocation {
    /// The largest factor (1 with no pixels).
    pub fn largest(&self) -> u32 {
        self.factors.iter().copied().max().unwrap_or(1)
    }

    /// Pixels that take more than `-s` samples.
    pub fn pixels_above_one(&self) -> usize {
        self.factors.iter().filter(|&&k| k > 1).count()
    }

    /// The extra samples over the render's `-s` a pixel, as a fraction.
    pub fn extra_fraction(&self) -> f64 {
        let extra: u64 = self.factors.iter().map(|&k| k as u64 - 1).sum();
        extra as f64 / self.factors.len().max(1) as f64
    }
}

/// Each pixel's sample factor for a render of `settings`' size, from a
/// pilot of the chains of delta bounces up to `max_bounces` bounces: all 1
/// where the scene has no environment map or no pixel sees one along such
/// a chain with any variance.
pub fn allocate<I: Intersector + Sync>(
    world: &World<I>,
    camera: &Camera,
    settings: &RenderSettings,
    max_bounces: u32,
) -> Allocation {
    let start = Instant::now();
    let size = (settings.width, settings.height);
    let env = world.lights.infinite().find_map(|(_, light)| match light {
        Light::Environment(env) => Some(env),
        _ => None,
    });
    let pixels = (size.0 * size.1) as usize;
    let Some(env) = env else {
        return Allocation {
            factors: vec![1; pixels],
            extra_cost: 0.0,
            seconds: start.elapsed().as_secs_f64(),
        };
    };
    let pilots: Vec<Pilot> = thread_pool(settings).install(|| {
        let bounds = MapBounds::new(env.map());
        let reference = bounds.sphere_mean.max(f32::MIN_POSITIVE);
        (0..size.1)
            .into_par_iter()
            .flat_map_iter(|y| (0..size.0).map(move |x| (x, y)))
            .map(|(x, y)| {
                let chains = PILOT_OFFSETS.map(|offset| {
                    let ray = pixel_ray(camera, size, (x, y), offset, Vec2::splat(0.5));
                    chain_leaves(world, &ray, max_bounces)
                });
                Pilot {
                    ratio: pixel_deviation(&chains, &bounds) / reference,
                    cost: chains.iter().map(sample_cost).sum::<f32>() / chains.len() as f32,
                }
            })
            .collect()
    });
    let cap = factor_fitting(size, settings.samples_per_pixel);
    let (factors, extra_cost) = factors(&pilots, cap);
    Allocation {
        factors,
        extra_cost,
        seconds: start.elapsed().as_secs_f64(),
    }
}

/// What the pilot says of a pixel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pilot {
    /// The bound on its per-sample deviation over the reference.
    pub ratio: f32,
    /// What a sample costs, in rays ([`sample_cost`]).
    pub cost: f32,
}

/// Rays a path traces past a surface that is not a delta BSDF, as the
/// pilot counts a sample's cost: about two bounces of a continuation and
/// a light sample's shadow ray each.
pub const SCATTERED_COST: f32 = 4.0;

/// The rays a camera sample along `chain` costs, about: the chain's own
/// and [`SCATTERED_COST`] for each way that goes on from a surface.
pub fn sample_cost(chain: &Leaves) -> f32 {
    chain.rays as f32 + SCATTERED_COST * chain.scattered as f32
}

/// The factors for the pixels the pilot saw: by Neyman's allocation with
/// costs (`n_p` proportional to `sigma_p / sqrt(c_p)`), the power of four
/// at most `ratio sqrt(c_mean / c_p)`, from 1 to a cap that starts at
/// `max_factor` (a power of four) and is divided by 4 while the extra
/// samples would cost more than half of the render's. Powers of four
/// keep each pixel's samples a (0, m, 2)-net: ZSobol shuffles base-4
/// digits, so a pixel's first `2^j` of `2^L` samples are an aligned block
/// only when `L - j` is even. Returns them and the extra cost as a
/// fraction of the render's without them.
pub fn factors(pilots: &[Pilot], max_factor: u32) -> (Vec<u32>, f64) {
    let total: f64 = pilots.iter().map(|p| p.cost as f64).sum();
    let mean_cost = (total / pilots.len().max(1) as f64) as f32;
    let factor = |p: &Pilot, cap: u32| -> u32 {
        let wanted = p.ratio * (mean_cost / p.cost.max(1.0)).sqrt();
        // `max` takes a NaN to 1.
        let k = wanted.max(1.0).min(cap as f32) as u32;
        // The power of four at most k.
        1 << ((31 - k.leading_zeros()) & !1)
    };
    let extra_cost = |cap: u32| -> f64 {
        pilots
            .iter()
            .map(|p| (factor(p, cap) - 1) as f64 * p.cost as f64)
            .sum()
    };
    let mut cap = max_factor;
    while cap > 1 && 2.0 * extra_cost(cap) > total {
        cap /= 4;
    }
    let factors = pilots.iter().map(|p| factor(p, cap)).collect();
    (factors, extra_cost(cap) / total.max(f64::MIN_POSITIVE))
}

/// The largest factor a render of `size` at `spp` samples may take: ZSobol
/// indexes a sample by 32 bits, `2 R` for the pixel (the image side
/// rounded up to `2^R`) and `L` for the sample (`spp` rounded up to `2^L`),
/// and the factor's bits must fit beside them.
pub fn factor_fitting(size: (u32, u32), spp: u32) -> u32 {
    let side = size
        .0
        .max(size.1)
        .max(1)
        .next_power_of_two()
        .trailing_zeros();
    let sample = spp.max(1).next_power_of_two().trailing_zeros();
    let free = 32u32.saturating_sub(2 * side + sample) & !1;
    MAX_FACTOR.min(1 << free.min(31))
}

/// The bound `sigma_p` on a pixel's per-sample deviation from the leaves
/// of its pilot chains.
fn pixel_deviation(chains: &[Leaves], bounds: &MapBounds) -> f32 {
    let mut variance = 0.0;
    for (i, chain) in chains.iter().enumerate() {
        for leaf in chain.iter() {
            // Each key once: at the first chain that has it.
            if chains[..i]
                .iter()
                .any(|c| c.iter().any(|l| l.key == leaf.key))
            {
                continue;
            }
            let same = || {
                chains[i..]
                    .iter()
                    .filter_map(|c| c.iter().find(|l| l.key == leaf.key))
            };
            let mean = same().map(|l| l.dir).sum::<Vec3>().normalize_or_zero();
            let seen_by = same().count();
            let radius = if mean == Vec3::ZERO {
                // Directions that cancel: the whole sphere.
                PI
            } else if seen_by == 1 {
                LONE_LEAF_RADIUS
            } else {
                same()
                    .map(|l| l.dir.dot(mean).clamp(-1.0, 1.0).acos())
                    .fold(0.0, f32::max)
            };
            let weight = same().map(|l| l.weight).fold(0.0, f32::max);
            let range = bounds.over_disk(if mean == Vec3::ZERO { leaf.dir } else { mean }, radius);
            let a = seen_by as f32 / chains.len() as f32;
            variance += a
                * weight
                * weight
                * (range.variance_bound() + (1.0 - a) * range.mean * range.mean);
        }
    }
    variance.sqrt()
}
