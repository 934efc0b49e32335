//! The two direct-lighting estimators of part 3.

use glam::{Vec2, Vec3};

use crate::global::emission::{found_emission, PrevVertex};
use crate::global::DirectStrategy;
use crate::intersect::Intersector;
use crate::lights::{Light, LightChoice, LightPdf, LightSample, LightSet, LightStrategy};
use crate::math::mis::power_heuristic;
use crate::math::warp::{sample_uniform_hemisphere, uniform_hemisphere_pdf};
use crate::math::Rgb;
use crate::sampling::strata::stratum_point;
use crate::sampling::Sampler;
use crate::world::{ShadingPoint, World};

/// Light samples drawn at once, so that the cache misses of one light's
/// samples overlap ([`Light::prefetch_sample_guide`]: an environment map's
/// tables are megabytes read at random).
const BATCH: usize = 8;

/// Direct lighting by uniform hemisphere sampling (`-H`).
///
/// `N` directions uniform on the hemisphere of the shading normal,
/// `pdf = 1 / (2 pi)`; each ray brings the light it finds: an emissive
/// surface, a rectangle light it crosses, the lights at infinity if it
/// escapes (the same lights light sampling samples; a surface that only
/// stands in for a rectangle light is not counted twice):
///
/// ```text
/// L_o = 1/N sum_j f(wo, wj) L_e(wj) cos(theta_j) / (1 / 2 pi)
/// ```
///
/// Point and directional lights are never hit by a random ray, so this
/// estimator cannot see them (light sampling can).
#[derive(Clone, Copy, Debug)]
pub struct DirectHemisphere {
    /// Directions per estimate: the course uses (number of lights) x `-l`.
    pub samples: u32,
}

impl DirectHemisphere {
    #[doc(alias = "estimate_direct_lighting_hemisphere")]
    pub fn estimate<I: Intersector>(
        &self,
        world: &World<I>,
        point: &ShadingPoint,
        sampler: &mut impl Sampler,
    ) -> Rgb {
        let n = self.samples.max(1);
        let mut sum = Rgb::ZERO;
        // Every light a ray can find, in full, as BSDF sampling alone counts it.
        let from = PrevVertex::Scattering {
            p: point.hit.p,
            bsdf_pdf: uniform_hemisphere_pdf(Vec3::Z),
            splits_map: world.splits_map(&point.bsdf),
        };
        for _ in 0..n {
            let wi_local = sample_uniform_hemisphere(sampler.get_2d());
            let wi = point.frame.to_world(wi_local);
            let ray = point.hit.spawn_ray(wi);
            let next = world.intersector.intersect(&ray);
            let incoming =
                found_emission(world, &DirectStrategy::BsdfOnly, &ray, next.as_ref(), &from);
            let f = point.bsdf.f(point.wo, wi_local);
            sum += f * incoming * wi_local.z / uniform_hemisphere_pdf(wi_local);
        }
        sum / n as f32
    }
}

/// Direct lighting by sampling the lights (light importance sampling).
///
/// Light sample `j` is a direction `wj` towards light `l_j` with density
/// `p(wj)` per steradian, drawn with probability `P(l_j)`, and a shadow
/// ray. The lights are chosen as the light set says ([`LightChoice`]):
/// every light with its own `N_l` samples (`N_l = 1` for a delta light,
/// else `-l`, and `P = 1`), or `N = -l` samples in all, each of a light
/// chosen by power:
///
/// ```text
/// L_o = sum over lights 1/N_l sum_j w(wj) f(wo, wj) L(wj) V(wj) |cos(theta_j)| / p(wj)
/// L_o = 1/N sum_j w(wj) f(wo, wj) L(wj) V(wj) |cos(theta_j)| / (P(l_j) p(wj))
/// ```
///
/// For a delta light the density is the pmf alone and `w = 1`. Without
/// multiple importance sampling `w = 1`; with it, `w` is the power
/// heuristic of the light strategy, density `N P(l) p(w)`, against the one
/// BSDF sample the integrator takes at the same point ([`power_heuristic`]).
#[derive(Clone, Copy, Debug)]
pub struct DirectLights {
    /// Samples per non-delta light, or in all when lights are chosen by
    /// power (`-l`).
    pub samples_per_light: u32,
    /// Samples of an environment light where every light is sampled;
    /// `None`: `samples_per_light`, as for the others (the render plan
    /// sets it where `-l` is not given: [`crate::plan::light_samples`]).
    pub environment_samples: Option<u32>,
    /// Weight light samples against BSDF sampling (off: `--no-mis`, the
    /// course's estimator).
    pub mis: bool,
}

impl DirectLights {
    /// How the light strategy samples light `index` of `lights` at a
    /// vertex that splits an environment map's samples or not
    /// (`splits_map`: [`World::splits_map`]).
    pub fn strategy(&self, lights: &LightSet, index: usize, splits_map: bool) -> LightStrategy {
        let light = &lights.lights[index];
        let samples = match (light, self.environment_samples) {
            (Light::Environment(_), Some(n))
                if splits_map && matches!(lights.choice(), LightChoice::EveryLight) =>
            {
                n
            }
            _ => self.samples_per_light,
        };
        lights.choice().strategy(index, light, samples)
    }

    #[doc(alias = "estimate_direct_lighting_importance")]
    pub fn estimate<I: Intersector>(
        &self,
        world: &World<I>,
        point: &ShadingPoint,
        sampler: &mut impl Sampler,
    ) -> Rgb {
        let lights = &world.lights;
        let splits_map = world.splits_map(&point.bsdf);
        match lights.choice() {
            LightChoice::EveryLight => {
                let mut total = Rgb::ZERO;
                for (index, light) in lights.lit() {
                    let strategy = self.strategy(lights, index, splits_map);
                    // An environment map's samples in strata of the
                    // coordinate its rows are drawn from (`sampling::
                    // strata`); an area light's count is the course's
                    // `-l`, its samples independent.
                    let n = strategy.samples as usize;
                    let in_strata = n > 1 && matches!(light, Light::Environment(_));
                    let mut sum = Rgb::ZERO;
                    let mut left = n;
                    while left > 0 {
                        // A batch's numbers are drawn in the order one
                        // sample at a time would draw them, so the image
                        // is the same; their misses overlap.
                        let (first, count) = (n - left, left.min(BATCH));
                        let mut batch = [(0.0, Vec2::ZERO); BATCH];
                        // One sample has no misses to overlap (and its
                        // sampling prefetches its own texels).
                        let prefetch = count > 1;
                        for (i, number) in batch[..count].iter_mut().enumerate() {
                            let (uc, u) = (sampler.get_1d(), sampler.get_2d());
                            let k = first + i;
                            *number = (uc, if in_strata { stratum_point(u, k, n) } else { u });
                            if prefetch {
                                light.prefetch_sample_guide(number.1);
                            }
                        }
                        if prefetch {
                            for &(_, u) in &batch[..count] {
                                light.prefetch_sample_cdf(u);
                            }
                        }
                        for &(uc, u) in &batch[..count] {
                            if let Some(sample) = light.sample_li(point.hit.p, uc, u) {
                                sum += self.contribution(world, point, &sample, strategy);
                            }
                        }
                        left -= count;
                    }
                    total += sum / strategy.samples as f32;
                }
                total
            }
            LightChoice::ByPower(pmf) => {
                let n = self.samples_per_light.max(1);
                let mut sum = Rgb::ZERO;
                for _ in 0..n {
                    let index = pmf.sample(sampler.get_1d()).cell;
                    let strategy = self.strategy(lights, index, splits_map);
                    let uc = sampler.get_1d();
                    let light = &lights.lights[index];
                    if let Some(sample) = light.sample_li(point.hit.p, uc, sampler.get_2d()) {
                        sum += self.contribution(world, point, &sample, strategy);
                    }
                }
                sum / n as f32
            }
        }
    }

    /// One light sample's term `w f L |cos| / (P p)` (`f L |cos| / P` for
    /// a delta light), or zero when the BSDF does not scatter that way or
    /// a shadow ray finds the light blocked.
    fn contribution<I: Intersector>(
        &self,
        world: &World<I>,
        point: &ShadingPoint,
        sample: &LightSample,
        strategy: LightStrategy,
    ) -> Rgb {
        let wi_local = point.frame.to_local(sample.wi);
        let (f, bsdf_pdf) = point.bsdf.eval(point.wo, wi_local);
        if f == Rgb::ZERO || sample.radiance == Rgb::ZERO {
            return Rgb::ZERO;
        }
        let shadow = point.hit.spawn_shadow_ray(sample.wi, sample.distance);
        if world.intersector.occluded(&shadow) {
            return Rgb::ZERO;
        }
        let chosen = strategy.probability;
        let weight = match sample.pdf {
            LightPdf::Delta => 1.0 / chosen,
            LightPdf::SolidAngle(pdf) if self.mis => {
                let light_pdf = chosen * pdf;
                // The density with which the path's continuation (the
                // other strategy) would have drawn `wi`.
                let bsdf_pdf = world.continuation_pdf(point, sample.wi, bsdf_pdf);
                power_heuristic(strategy.samples as f32, light_pdf, 1.0, bsdf_pdf) / light_pdf
            }
            LightPdf::SolidAngle(pdf) => 1.0 / (chosen * pdf),
        };
        f * sample.radiance * wi_local.z.abs() * weight
    }
}
