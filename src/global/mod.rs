//! Part 4: global illumination by path tracing with Russian roulette, and
//! the one integrator loop every lighting part runs.
//!
//! The rendering equation, `L_o = L_e + integral f L_i |cos| dwi`, expanded
//! bounce by bounce. A path starts at the camera; at each vertex it adds
//!
//! 1. the emission its last ray found, weighted by [`emission_weight`]
//!    (the course's `zero_bounce_radiance` for the camera ray);
//! 2. unless the BSDF is a delta lobe, the direct light estimated at the
//!    vertex ([`crate::direct`], the course's `one_bounce_radiance`);
//! 3. then continues in one direction sampled from the BSDF, its
//!    throughput multiplied by `f |cos| / pdf` and divided by the Russian
//!    roulette probability:
//!
//! ```text
//! L = sum over vertices k of  beta_k (w L_e + L_direct),
//! beta_{k+1} = beta_k f(wo, wi) |cos(theta_i)| / (pdf(wi) q_k)
//! ```
//!
//! A vertex is a bounce of light: direct light at vertex `k`, and emission
//! found by the ray leaving vertex `k`, have `k` bounces. Paths count
//! bounces up to `-m` (`-o 1`) or exactly `-m` (`-o 0`); the ray leaving
//! vertex `m` is still traced when the emission it may find counts (with
//! multiple importance sampling it carries the BSDF half of the direct
//! light). A ray that escapes sees the lights at infinity.
//!
//! Russian roulette (Arvo and Kirk 1990) ends a path after its first
//! indirect bounce with probability `1 - q`, `q =` [`CONTINUE_PROBABILITY`],
//! and divides the surviving estimate by `q`: unbiased for the sum of
//! bounces up to `-m`, as `E = q (X / q) + (1 - q) 0 = X`.

pub mod emission;

pub use emission::{emission_weight, Emitter, PrevVertex};

use rand::Rng;

use crate::direct::{DirectHemisphere, DirectLights};
use crate::intersect::{Hit, Intersector, Ray};
use crate::math::rng::{next_2d, Sampler};
use crate::math::Rgb;
use crate::world::{ShadingPoint, World};

/// Probability of continuing a path at each bounce after the first
/// indirect one.
pub const CONTINUE_PROBABILITY: f32 = 0.65;

/// How direct light is estimated at each path vertex.
#[derive(Clone, Copy, Debug)]
pub enum DirectStrategy {
    /// Uniform hemisphere rays at each vertex (`-H`).
    Hemisphere(DirectHemisphere),
    /// Light sampling at each vertex, with or without MIS.
    Lights(DirectLights),
    /// No direct-light estimate: only the BSDF-sampled rays of the path
    /// find emitters (`--bsdf-only`), the reference that light sampling and
    /// MIS improve on. Delta lights stay dark.
    BsdfOnly,
}

impl DirectStrategy {
    /// Whether light sampling is weighted against BSDF sampling.
    pub fn mis(&self) -> bool {
        matches!(self, DirectStrategy::Lights(d) if d.mis)
    }

    /// Whether BSDF-sampled rays after a scattering vertex count (some of)
    /// the lights they find.
    pub fn bsdf_rays_find_lights(&self) -> bool {
        self.mis() || matches!(self, DirectStrategy::BsdfOnly)
    }
}

/// The path tracer of part 4 (and the direct-only renderer of part 3 with
/// `max_depth = 1`).
#[derive(Clone, Copy, Debug)]
pub struct PathTracer {
    pub direct: DirectStrategy,
    /// Maximum number of bounces (`-m`); 0 shows emitters only.
    pub max_depth: u32,
    /// Add every bounce up to `max_depth` (`-o 1`), or only the light of
    /// paths with exactly `max_depth` bounces (`-o 0`).
    pub accumulate: bool,
    /// Russian roulette after the first indirect bounce.
    pub russian_roulette: bool,
}

impl PathTracer {
    /// Whether light with `bounces` bounces is part of the image.
    fn counts(&self, bounces: u32) -> bool {
        if self.accumulate {
            bounces <= self.max_depth
        } else {
            bounces == self.max_depth
        }
    }

    /// Radiance arriving at the camera along `ray`.
    #[doc(alias = "est_radiance_global_illumination")]
    #[doc(alias = "at_least_one_bounce_radiance")]
    pub fn radiance<I: Intersector>(
        &self,
        world: &World<I>,
        camera_ray: &Ray,
        rng: &mut Sampler,
    ) -> Rgb {
        let mut l = Rgb::ZERO;
        let mut beta = Rgb::ONE;
        let mut ray = *camera_ray;
        let mut prev = PrevVertex::CameraOrDelta;
        // Vertices so far: the light the next ray finds has this many bounces.
        let mut bounces = 0;
        loop {
            let next = world.intersector.intersect(&ray);
            if self.counts(bounces) {
                l += beta * self.found_emission(world, &ray, next.as_ref(), &prev);
            }
            let Some(hit) = next else {
                return l;
            };
            bounces += 1;
            if bounces > self.max_depth {
                return l;
            }
            // Shading only where the path goes on (not for the last ray).
            let point = world.shade(hit, -ray.dir);
            if point.bsdf.is_black() {
                return l;
            }
            let estimates_direct = !matches!(self.direct, DirectStrategy::BsdfOnly);
            if estimates_direct && self.counts(bounces) && !point.bsdf.is_delta() {
                l += beta * self.one_bounce(world, &point, rng);
            }
            let last = bounces == self.max_depth;
            if last && !self.last_ray_can_count(world, point.bsdf.is_delta()) {
                return l;
            }
            let uc = rng.gen::<f32>();
            let u = next_2d(rng);
            let Some(sample) = point.bsdf.sample(point.wo, uc, u) else {
                return l;
            };
            // Russian roulette, never on the first indirect bounce nor on
            // the last ray, which only looks for emission.
            let q = if self.russian_roulette && bounces > 1 && !last {
                CONTINUE_PROBABILITY
            } else {
                1.0
            };
            if q < 1.0 && rng.gen::<f32>() >= q {
                return l;
            }
            beta *= sample.weight() / q;
            if !beta.is_finite() {
                // Counted by the render as a rejected sample, not hidden.
                return Rgb::splat(f32::NAN);
            }
            if beta == Rgb::ZERO {
                return l;
            }
            prev = if sample.is_delta() {
                PrevVertex::CameraOrDelta
            } else {
                PrevVertex::Scattering {
                    p: point.hit.p,
                    bsdf_pdf: sample.pdf(),
                }
            };
            ray = point.hit.spawn_ray(point.frame.to_world(sample.wi));
        }
    }

    /// Direct light at `point`, by the chosen strategy.
    #[doc(alias = "one_bounce_radiance")]
    pub fn one_bounce<I: Intersector>(
        &self,
        world: &World<I>,
        point: &ShadingPoint,
        rng: &mut Sampler,
    ) -> Rgb {
        match self.direct {
            DirectStrategy::Hemisphere(h) => h.estimate(world, point, rng),
            DirectStrategy::Lights(d) => d.estimate(world, point, rng),
            DirectStrategy::BsdfOnly => Rgb::ZERO,
        }
    }

    /// Whether the ray leaving the last vertex (whose BSDF is all delta
    /// lobes when `delta`) can find emission that counts.
    fn last_ray_can_count<I: Intersector>(&self, world: &World<I>, delta: bool) -> bool {
        delta
            || self.direct.bsdf_rays_find_lights()
            || (matches!(self.direct, DirectStrategy::Lights(_))
                && world.lights.has_unsampled_emitters())
    }

    /// Emission that `ray`, leaving `prev`, finds ([`emission::found_emission`]).
    #[doc(alias = "zero_bounce_radiance")]
    pub fn found_emission<I: Intersector>(
        &self,
        world: &World<I>,
        ray: &Ray,
        next: Option<&Hit>,
        prev: &PrevVertex,
    ) -> Rgb {
        emission::found_emission(world, &self.direct, ray, next, prev)
    }
}
