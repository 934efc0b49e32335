//! The two direct-lighting estimators of part 3.

use glam::Vec3;

use crate::global::emission::{found_emission, PrevVertex};
use crate::global::DirectStrategy;
use crate::intersect::Intersector;
use crate::lights::{Light, LightPdf, LightSample};
use crate::math::mis::power_heuristic;
use crate::math::warp::{sample_uniform_hemisphere, uniform_hemisphere_pdf};
use crate::math::Rgb;
use crate::sampling::Sampler;
use crate::world::{ShadingPoint, World};

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
/// For each light, `N` samples (`N = 1` for a delta light, else `-l`),
/// each with a shadow ray:
///
/// ```text
/// L_o = sum over lights 1/N sum_j w(wj) f(wo, wj) L(wj) V(wj) |cos(theta_j)| / p(wj)
/// ```
///
/// For a delta light the sum has a single term, no division by a density
/// and `w = 1`. Without multiple importance sampling `w = 1`; with it,
/// `w` is the power heuristic of `N` light samples against the one BSDF
/// sample the integrator takes at the same point ([`power_heuristic`]).
#[derive(Clone, Copy, Debug)]
pub struct DirectLights {
    /// Samples per non-delta light (`-l`).
    pub samples_per_light: u32,
    /// Weight light samples against BSDF sampling (off: `--no-mis`, the
    /// course's estimator).
    pub mis: bool,
}

impl DirectLights {
    /// Samples taken of `light` at each point.
    pub fn samples_of(&self, light: &Light) -> u32 {
        if light.is_delta() {
            1
        } else {
            self.samples_per_light.max(1)
        }
    }

    #[doc(alias = "estimate_direct_lighting_importance")]
    pub fn estimate<I: Intersector>(
        &self,
        world: &World<I>,
        point: &ShadingPoint,
        sampler: &mut impl Sampler,
    ) -> Rgb {
        let mut total = Rgb::ZERO;
        for light in &world.lights.lights {
            let n = self.samples_of(light);
            let mut sum = Rgb::ZERO;
            for _ in 0..n {
                let uc = sampler.get_1d();
                if let Some(sample) = light.sample_li(point.hit.p, uc, sampler.get_2d()) {
                    sum += self.contribution(world, point, &sample, n);
                }
            }
            total += sum / n as f32;
        }
        total
    }

    /// One light sample's term `w f L |cos| / p` (`f L |cos|` for a delta
    /// light), or zero when the BSDF does not scatter that way or a shadow
    /// ray finds the light blocked.
    fn contribution<I: Intersector>(
        &self,
        world: &World<I>,
        point: &ShadingPoint,
        sample: &LightSample,
        n: u32,
    ) -> Rgb {
        let wi_local = point.frame.to_local(sample.wi);
        let f = point.bsdf.f(point.wo, wi_local);
        if f == Rgb::ZERO || sample.radiance == Rgb::ZERO {
            return Rgb::ZERO;
        }
        let shadow = if sample.distance.is_finite() {
            point
                .hit
                .spawn_ray_to(point.hit.p + sample.distance * sample.wi)
        } else {
            point.hit.spawn_ray(sample.wi)
        };
        if world.intersector.occluded(&shadow) {
            return Rgb::ZERO;
        }
        let weight = match sample.pdf {
            LightPdf::Delta => 1.0,
            LightPdf::SolidAngle(pdf) if self.mis => {
                let bsdf_pdf = point.bsdf.pdf(point.wo, wi_local);
                power_heuristic(n as f32, pdf, 1.0, bsdf_pdf) / pdf
            }
            LightPdf::SolidAngle(pdf) => 1.0 / pdf,
        };
        f * sample.radiance * wi_local.z.abs() * weight
    }
}
