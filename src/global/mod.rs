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
//! 3. then continues in one direction sampled from the BSDF (at a diffuse
//!    vertex, from the BSDF mixed with the caustic casters' cones:
//!    [`World::sample_continuation`]), its throughput multiplied by
//!    `f |cos| / pdf`, with `pdf` that sampling's density, and divided by
//!    the Russian roulette probability:
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
//! Russian roulette ([`roulette`]) ends a path with probability `1 - q`
//! and divides the surviving estimate by `q`: unbiased for the sum of
//! bounces up to `-m`, as `E = q (X / q) + (1 - q) 0 = X`. `q` is the
//! course's fixed 0.65 from the second vertex on ([`Roulette::Fixed`]) or
//! follows the path's throughput after [`THROUGHPUT_ROULETTE_AFTER`]
//! bounces ([`Roulette::Throughput`], the default).
//!
//! At the first glass vertices of the camera's chain of delta bounces
//! the path follows both lobes instead of a coin's choice ([`splits`]).
//!
//! Random numbers come from a [`Sampler`], in a fixed order per vertex:
//! the direct-light estimate's, the BSDF's 1D lobe choice and 2D
//! direction, then the roulette's 1D number (drawn whenever roulette
//! applies at the vertex, so that a sample's dimensions line up with its
//! pixel's other samples whatever `q` is). A split vertex draws no lobe
//! choice nor direction; its reflected branch draws its roulette number
//! there, and the rest of its numbers once the refracted path, and every
//! branch pushed after it, has ended. So a branch's numbers do not line
//! up with the pixel's other samples: their stratification is weaker
//! there, their expectation the same.

pub mod emission;
pub mod roulette;
pub mod splits;

pub use emission::{emission_weight, Emitter, PrevVertex};
pub use roulette::{PathWeight, Roulette, CONTINUE_PROBABILITY, THROUGHPUT_ROULETTE_AFTER};
pub use splits::{GLASS_SPLITS, MAX_GLASS_SPLITS};

use splits::{Branches, PathState, Step};

use crate::direct::{DirectHemisphere, DirectLights};
use crate::intersect::{Hit, Intersector, Ray};
use crate::materials::{Bsdf, BsdfSample};
use crate::math::Rgb;
use crate::sampling::Sampler;
use crate::world::{ShadingPoint, World};

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
    /// Russian roulette and its rule (where it starts depends on the rule).
    pub roulette: Roulette,
    /// Glass vertices, along the camera's chain of delta bounces, at which
    /// the path follows both lobes instead of choosing one (`--glass-splits`,
    /// [`GLASS_SPLITS`] where the render plan asks; 0 is the course's coin).
    pub glass_splits: u32,
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
        sampler: &mut impl Sampler,
    ) -> Rgb {
        let mut branches = Branches::default();
        let mut state = PathState {
            ray: *camera_ray,
            path: PathWeight::START,
            prev: PrevVertex::CameraOrDelta,
            bounces: 0,
            splits: self.glass_splits.min(MAX_GLASS_SPLITS),
        };
        let mut l = Rgb::ZERO;
        loop {
            l += self.trace(world, state, &mut branches, sampler);
            match branches.pop() {
                Some(branch) if !l.is_nan() => state = branch,
                _ => return l,
            }
        }
    }

    /// The light a path in `state` gathers from its next ray on; the
    /// reflected branches of the glass vertices it splits wait in
    /// `branches`. NaN for a rejected sample.
    #[inline(always)]
    fn trace<I: Intersector>(
        &self,
        world: &World<I>,
        state: PathState,
        branches: &mut Branches,
        sampler: &mut impl Sampler,
    ) -> Rgb {
        let PathState {
            mut ray,
            mut path,
            mut prev,
            mut bounces,
            mut splits,
        } = state;
        let mut l = Rgb::ZERO;
        loop {
            let next = world.intersector.intersect(&ray);
            if self.counts(bounces) {
                l += path.beta * self.found_emission(world, &ray, next.as_ref(), &prev);
            }
            let Some(hit) = next else {
                return l;
            };
            bounces += 1;
            if bounces > self.max_depth {
                return l;
            }
            // Shading only where the path goes on (not for the last ray),
            // and the casters' cones only where it may go on from here.
            let mut point = world.shade_surface(hit, -ray.dir);
            if point.bsdf.is_black() {
                return l;
            }
            let last = bounces == self.max_depth;
            let lights_alone = last && self.lights_alone_at_last(world, &point);
            if !lights_alone {
                world.add_caster_cones(&mut point);
            }
            let estimates_direct = !matches!(self.direct, DirectStrategy::BsdfOnly);
            if estimates_direct && self.counts(bounces) && !point.bsdf.is_delta() {
                l += path.beta
                    * if lights_alone {
                        self.one_bounce_lights_alone(world, &point, sampler)
                    } else {
                        self.one_bounce(world, &point, sampler)
                    };
            }
            if last && (lights_alone || !self.last_ray_can_count(world, point.bsdf.is_delta())) {
                return l;
            }
            let lobes = match point.bsdf {
                Bsdf::Glass(glass) if splits > 0 => glass.both_lobes(point.wo),
                _ => None,
            };
            let sample = match lobes {
                // Both lobes, on the camera's chain of delta bounces: the
                // reflection as a path of its own, the refraction here.
                Some([reflected, refracted]) => {
                    splits -= 1;
                    match self.step(world, &point, path, bounces, last, reflected, sampler) {
                        Step::On(branch) => branches.push(PathState { splits, ..branch }),
                        Step::Invalid => return Rgb::splat(f32::NAN),
                        Step::End => {}
                    }
                    refracted
                }
                None => {
                    if !point.bsdf.is_delta() {
                        splits = 0;
                    }
                    let uc = sampler.get_1d();
                    let u = sampler.get_2d();
                    let Some(sample) = world.sample_continuation(&point, uc, u) else {
                        return l;
                    };
                    sample
                }
            };
            match self.step(world, &point, path, bounces, last, sample, sampler) {
                Step::On(onward) => {
                    ray = onward.ray;
                    path = onward.path;
                    prev = onward.prev;
                    // What the ray reads of the environment if it escapes
                    // loads while it is traced (a miss overlapped, not
                    // waited for), where the light it finds counts; not
                    // for a ray refracted into a denser medium (into glass
                    // from the air), which meets a closed object's far
                    // side first (the hint as a whole was 2.6 % of the
                    // glass bunny's time under a sun; skipping it here
                    // saved 1.5 %), nor for a branch, which waits. Only
                    // speed depends on this.
                    let enters_denser = sample.transmission && sample.eta > 1.0;
                    if self.counts(bounces) && !enters_denser {
                        for (_, light) in world.lights.infinite() {
                            light.prefetch_escape(ray.dir);
                        }
                    }
                }
                Step::Invalid => return Rgb::splat(f32::NAN),
                Step::End => return l,
            }
        }
    }

    /// The path past `point` along `sample`: roulette where its rule
    /// applies, the new throughput and the ray that leaves.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn step<I: Intersector>(
        &self,
        world: &World<I>,
        point: &ShadingPoint,
        path: PathWeight,
        bounces: u32,
        last: bool,
        sample: BsdfSample,
        sampler: &mut impl Sampler,
    ) -> Step {
        let onward = path.scattered(sample.weight(), sample.transmission.then_some(sample.eta));
        // Russian roulette, where its rule applies, never on the last
        // ray, which only looks for emission.
        let q = if self.roulette.applies_at(bounces) && !last {
            let q = self
                .roulette
                .continue_probability(onward.beta, onward.eta_scale);
            if sampler.get_1d() >= q {
                return Step::End;
            }
            q
        } else {
            1.0
        };
        let path = onward.survived(q);
        if !path.beta.is_finite() {
            // Counted by the render as a rejected sample, not hidden.
            return Step::Invalid;
        }
        if path.beta == Rgb::ZERO {
            return Step::End;
        }
        let prev = if sample.is_delta() {
            PrevVertex::CameraOrDelta
        } else {
            PrevVertex::Scattering {
                p: point.hit.p,
                bsdf_pdf: sample.pdf(),
                splits_map: world.splits_map(&point.bsdf),
            }
        };
        let ray = point.hit.spawn_ray(point.frame.to_world(sample.wi));
        Step::On(PathState {
            ray,
            path,
            prev,
            bounces,
            splits: 0,
        })
    }

    /// Direct light at `point`, by the chosen strategy.
    #[doc(alias = "one_bounce_radiance")]
    pub fn one_bounce<I: Intersector>(
        &self,
        world: &World<I>,
        point: &ShadingPoint,
        sampler: &mut impl Sampler,
    ) -> Rgb {
        match self.direct {
            DirectStrategy::Hemisphere(h) => h.estimate(world, point, sampler),
            DirectStrategy::Lights(d) => d.estimate(world, point, sampler),
            DirectStrategy::BsdfOnly => Rgb::ZERO,
        }
    }

    /// Whether the last vertex (`point`) takes its direct light from light
    /// samples alone, unweighted, and traces no continuation ray.
    ///
    /// With MIS the last vertex's continuation ray only looks for emission,
    /// the BSDF side of the light samples' weights: a full trace for a
    /// share of light that the light samples find as well, wherever every
    /// emitter is sampled by a light (light sampling alone is then unbiased,
    /// as with `--no-mis`) and the BSDF has no peak that light samples
    /// would miss. A diffuse BSDF has none, so there the light samples take
    /// the whole weight and the ray is not traced. The choice depends on
    /// the vertex alone, so each vertex still uses one unbiased estimator;
    /// glossy, glass and mirror vertices keep MIS and the ray.
    fn lights_alone_at_last<I: Intersector>(&self, world: &World<I>, point: &ShadingPoint) -> bool {
        self.direct.mis()
            && matches!(point.bsdf, Bsdf::Diffuse(_))
            && !world.lights.has_unsampled_emitters()
    }

    /// Direct light at `point` by the light samples of [`DirectStrategy::Lights`]
    /// without MIS ([`PathTracer::lights_alone_at_last`]).
    fn one_bounce_lights_alone<I: Intersector>(
        &self,
        world: &World<I>,
        point: &ShadingPoint,
        sampler: &mut impl Sampler,
    ) -> Rgb {
        match self.direct {
            DirectStrategy::Lights(d) => {
                DirectLights { mis: false, ..d }.estimate(world, point, sampler)
            }
            _ => self.one_bounce(world, point, sampler),
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
