//! The two direct-lighting estimators of part 3.

use rand::Rng;

use super::lights::{is_delta, sample_light, LightPdf, LightSample};
use super::shading::{SceneTracer, ShadingPoint};
use crate::intersect::Intersector;
use crate::math::rng::{next_2d, Sampler};
use crate::math::warp::{sample_uniform_hemisphere, uniform_hemisphere_pdf};
use crate::math::Rgb;

/// Direct lighting by uniform hemisphere sampling (`-H`).
///
/// `N` directions uniform on the hemisphere of the shading normal,
/// `pdf = 1 / (2 pi)`; each ray that hits an emissive surface brings its
/// emission, each that escapes upwards the ambient sky:
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
        scene: &SceneTracer<I>,
        point: &ShadingPoint,
        rng: &mut Sampler,
    ) -> Rgb {
        let n = self.samples.max(1);
        let mut sum = Rgb::ZERO;
        for _ in 0..n {
            let wi_local = sample_uniform_hemisphere(next_2d(rng));
            let wi = point.frame.to_world(wi_local);
            let incoming = scene.emitted(&point.hit.spawn_ray(wi));
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
/// L_o = sum over lights 1/N sum_j f(wo, wj) L(wj) V(wj) cos(theta_j) / p(wj)
/// ```
///
/// For a delta light the sum has a single term and no division by a density.
#[derive(Clone, Copy, Debug)]
pub struct DirectLights {
    /// Samples per non-delta light (`-l`).
    pub samples_per_light: u32,
}

impl DirectLights {
    #[doc(alias = "estimate_direct_lighting_importance")]
    pub fn estimate<I: Intersector>(
        &self,
        scene: &SceneTracer<I>,
        point: &ShadingPoint,
        rng: &mut Sampler,
    ) -> Rgb {
        let samples = self.samples_per_light.max(1);
        let mut total = Rgb::ZERO;
        for light in scene.lights {
            let n = if is_delta(light) { 1 } else { samples };
            let mut sum = Rgb::ZERO;
            for _ in 0..n {
                if let Some(sample) = sample_light(light, point.hit.p, next_2d(rng)) {
                    let convention = scene.light_convention.factor(light, sample.distance);
                    sum += convention * unoccluded_contribution(scene, point, &sample);
                }
            }
            total += sum / n as f32;
        }
        // Emissive triangles that stand in for no light, as one more area light.
        if !scene.emitters.is_empty() {
            let mut sum = Rgb::ZERO;
            for _ in 0..samples {
                let pick = rng.gen::<f32>();
                if let Some(sample) = scene.emitters.sample(point.hit.p, pick, next_2d(rng)) {
                    sum += unoccluded_contribution(scene, point, &sample);
                }
            }
            total += sum / samples as f32;
        }
        total
    }
}

/// One light sample's term `f L cos / p` (`f L cos` for a delta light), or
/// zero when the light is below the surface or a shadow ray finds it blocked.
fn unoccluded_contribution<I: Intersector>(
    scene: &SceneTracer<I>,
    point: &ShadingPoint,
    sample: &LightSample,
) -> Rgb {
    let wi_local = point.frame.to_local(sample.wi);
    if wi_local.z <= 0.0 {
        return Rgb::ZERO;
    }
    let shadow = if sample.distance.is_finite() {
        point
            .hit
            .spawn_ray_to(point.hit.p + sample.distance * sample.wi)
    } else {
        point.hit.spawn_ray(sample.wi)
    };
    if scene.intersector.occluded(&shadow) {
        return Rgb::ZERO;
    }
    let weight = match sample.pdf {
        LightPdf::Delta => 1.0,
        LightPdf::SolidAngle(pdf) => 1.0 / pdf,
    };
    point.bsdf.f(point.wo, wi_local) * sample.radiance * wi_local.z * weight
}
