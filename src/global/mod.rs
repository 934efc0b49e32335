//! Part 4: global illumination by path tracing with Russian roulette.
//!
//! The rendering equation, `L_o = L_e + integral f L_i cos dwi`, expanded
//! bounce by bounce: the camera sees the emission of the first surface
//! ([`crate::direct::zero_bounce`]), plus at each surface point the direct
//! light ([`crate::direct`]), plus light that arrives after more bounces,
//! estimated by continuing the path in one direction sampled from the BSDF:
//!
//! ```text
//! L(p, wo) = L_direct(p, wo) + f(wo, wi) L(p', -wi) cos(theta_i) / (pdf(wi) q)
//! ```
//!
//! where `p'` is the next hit. Paths have at most `-m` bounces. Russian
//! roulette (Arvo and Kirk 1990) ends a path after its first indirect
//! bounce with probability `1 - q`, `q =` [`CONTINUE_PROBABILITY`], and
//! divides the surviving estimate by `q`: unbiased, as
//! `E = q (X / q) + (1 - q) 0 = X`.
//!
//! Light is counted once: scene lights and emissive triangles by light
//! sampling at each vertex (or by the hemisphere estimator's rays), the
//! emission of surfaces that stand in for lights only when the camera sees
//! them, and the emission of other emissive spheres when a light-sampling
//! path's continuation ray hits them (with `-H` the hemisphere rays already
//! count them).

use crate::direct::{zero_bounce, DirectHemisphere, DirectLights, SceneTracer, ShadingPoint};
use crate::intersect::{Intersector, Ray};
use crate::math::rng::{next_2d, Sampler};
use crate::math::Rgb;
use rand::Rng;

/// Probability of continuing a path at each bounce after the first
/// indirect one.
pub const CONTINUE_PROBABILITY: f32 = 0.65;

/// How direct light is estimated at each path vertex.
#[derive(Clone, Copy, Debug)]
pub enum DirectStrategy {
    Hemisphere(DirectHemisphere),
    Lights(DirectLights),
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
    /// Radiance arriving at the camera along `ray`.
    #[doc(alias = "est_radiance_global_illumination")]
    pub fn radiance<I: Intersector>(
        &self,
        scene: &SceneTracer<I>,
        ray: &Ray,
        rng: &mut Sampler,
    ) -> Rgb {
        let Some(point) = scene.trace(ray) else {
            return Rgb::ZERO;
        };
        let mut l = Rgb::ZERO;
        if self.accumulate || self.max_depth == 0 {
            l += zero_bounce(&point);
        }
        if self.max_depth > 0 {
            l += self.at_least_one_bounce(scene, &point, self.max_depth, rng);
        }
        l
    }

    /// Direct light at `point`, by the chosen strategy.
    #[doc(alias = "one_bounce_radiance")]
    pub fn one_bounce<I: Intersector>(
        &self,
        scene: &SceneTracer<I>,
        point: &ShadingPoint,
        rng: &mut Sampler,
    ) -> Rgb {
        match self.direct {
            DirectStrategy::Hemisphere(h) => h.estimate(scene, point, rng),
            DirectStrategy::Lights(d) => d.estimate(scene, point, rng),
        }
    }

    /// Light leaving `point` after at least one bounce, with `depth`
    /// bounces left (the course's recursion, written as a loop).
    ///
    /// At each vertex: the direct light; with light sampling, also the
    /// emission of a surface that light sampling does not cover (an
    /// emissive sphere), found by the BSDF-sampled ray; then, if bounces are
    /// left and Russian roulette lets it, the same ray continues the path.
    #[doc(alias = "at_least_one_bounce_radiance")]
    pub fn at_least_one_bounce<I: Intersector>(
        &self,
        scene: &SceneTracer<I>,
        point: &ShadingPoint,
        depth: u32,
        rng: &mut Sampler,
    ) -> Rgb {
        let light_sampling = matches!(self.direct, DirectStrategy::Lights(_));
        let mut l = Rgb::ZERO;
        let mut throughput = Rgb::ONE;
        let mut point = *point;
        let mut depth = depth;
        loop {
            // Light with exactly (max_depth - depth + 1) bounces arrives here.
            let counts_here = self.accumulate || depth == 1;
            if counts_here {
                l += throughput * self.one_bounce(scene, &point, rng);
            }
            let picks_up_emitters = light_sampling && counts_here && scene.has_uncovered_emitters;
            if depth <= 1 && !picks_up_emitters {
                return l;
            }
            let uc = rng.gen::<f32>();
            let Some(sample) = point.bsdf.sample(point.wo, uc, next_2d(rng)) else {
                return l;
            };
            if sample.pdf().is_nan() || sample.pdf() <= 0.0 || sample.wi.z <= 0.0 {
                return l;
            }
            let wi = point.frame.to_world(sample.wi);
            let Some(next) = scene.trace(&point.hit.spawn_ray(wi)) else {
                return l;
            };
            let bounce_weight = sample.weight();
            if picks_up_emitters && !scene.is_covered(&next) {
                l += throughput * bounce_weight * next.emission;
            }
            if depth <= 1 {
                return l;
            }
            // Russian roulette, never on the first indirect bounce.
            let first_indirect = depth == self.max_depth;
            let q = if self.russian_roulette && !first_indirect {
                CONTINUE_PROBABILITY
            } else {
                1.0
            };
            if q < 1.0 && rng.gen::<f32>() >= q {
                return l;
            }
            throughput *= bounce_weight / q;
            if !throughput.is_finite() {
                return l;
            }
            depth -= 1;
            point = next;
        }
    }
}
