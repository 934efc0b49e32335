//! The starter's two direct lighting estimators, as a correct solution
//! writes them (the formulas are in [`super`]'s docs):
//! `estimate_direct_lighting_hemisphere` ([`StarterTracer::direct_hemisphere`])
//! and `estimate_direct_lighting_importance`
//! ([`StarterTracer::direct_importance`]), with the catalogue's mistakes
//! of part 3 at the lines a student would get wrong.

use crate::intersect::Intersector;
use crate::lights::{Light, LightPdf};
use crate::math::warp::{sample_uniform_hemisphere, uniform_hemisphere_pdf};
use crate::math::Rgb;
use crate::mistakes::{self, Mistake};
use crate::sampling::Sampler;
use crate::world::{ShadingPoint, World};

use super::StarterTracer;

impl StarterTracer {
    /// `N = lights x -l` directions uniform on the hemisphere; each brings
    /// what its first hit emits ([`Self::zero_bounce_radiance`]).
    #[doc(alias = "estimate_direct_lighting_hemisphere")]
    pub fn direct_hemisphere<I: Intersector>(
        &self,
        world: &World<I>,
        point: &ShadingPoint,
        sampler: &mut impl Sampler,
    ) -> Rgb {
        let n = (world.lights.lights.len().max(1) as u32 * self.light_samples).max(1);
        let mut sum = Rgb::ZERO;
        for _ in 0..n {
            let wi = sample_uniform_hemisphere(sampler.get_2d());
            let ray = point.hit.spawn_ray(point.frame.to_world(wi));
            let emitted = match world.intersector.intersect(&ray) {
                Some(hit) => self.zero_bounce_radiance(world, &ray, &hit),
                // In 3-2 a lamp's quad is a primitive of its own: a ray
                // that meets no surface may still meet one (measured on
                // the 3-2 starter: a box without a ceiling, 4.4 times as
                // bright as when these rays were dropped).
                None => self.quads_radiance(world, &ray, f32::INFINITY),
            };
            let pdf = if self.mistakes.has(Mistake::HemispherePdfOneOverPi) {
                std::f32::consts::FRAC_1_PI
            } else {
                uniform_hemisphere_pdf(wi)
            };
            let f = self.f(&point.bsdf, point.wo, wi);
            sum += self.over_pdf(f * emitted * self.cos_theta(wi), pdf);
        }
        sum / n as f32
    }

    /// Every light, `-l` samples each (one for a delta light), by its
    /// `sample_L`; samples from below the surface and blocked ones add
    /// nothing.
    #[doc(alias = "estimate_direct_lighting_importance")]
    pub fn direct_importance<I: Intersector>(
        &self,
        world: &World<I>,
        point: &ShadingPoint,
        sampler: &mut impl Sampler,
    ) -> Rgb {
        let mut total = Rgb::ZERO;
        for (_, light) in world.lights.lit() {
            let n = if light.is_delta() {
                1
            } else {
                self.light_samples.max(1)
            };
            let mut sum = Rgb::ZERO;
            for _ in 0..n {
                let (uc, u) = (sampler.get_1d(), sampler.get_2d());
                let sample = match light {
                    Light::Rect(rect) if self.mistakes.has(Mistake::LightFromBehind) => {
                        mistakes::two_sided_rect_sample(rect, point.hit.p, u)
                    }
                    Light::Environment(env) if mistakes::environment::any(self.mistakes) => {
                        mistakes::environment::sample(env, u, self.mistakes)
                    }
                    _ => light.sample_li(point.hit.p, uc, u),
                };
                let Some(sample) = sample else {
                    continue;
                };
                let wi = point.frame.to_local(sample.wi);
                if wi.z < 0.0 {
                    continue;
                }
                let shadow = if self.mistakes.has(Mistake::ShadowAcne) {
                    mistakes::shadow_ray_without_offset(&point.hit, &sample)
                } else if self.mistakes.has(Mistake::ShadowRayReachesLight) {
                    mistakes::shadow_ray_to_the_light(&point.hit, &sample)
                } else {
                    point.hit.spawn_shadow_ray(sample.wi, sample.distance)
                };
                if world.intersector.occluded(&shadow) {
                    continue;
                }
                let pdf = match sample.pdf {
                    LightPdf::Delta => 1.0,
                    LightPdf::SolidAngle(pdf) => pdf,
                };
                let f = self.f(&point.bsdf, point.wo, wi);
                let radiance = if self.mistakes.has(Mistake::NoPdf) {
                    mistakes::starter_radiance(light, &sample)
                } else {
                    sample.radiance
                };
                sum += self.over_pdf(f * radiance * self.cos_theta(wi), pdf);
            }
            total += if self.mistakes.has(Mistake::LightSamplesNotAveraged) {
                sum
            } else {
                sum / n as f32
            };
        }
        total
    }
}
