//! The course's direct lighting, with its two differences from this
//! project, for measuring how much they change an image. Only here, never
//! in the library.
//!
//! - Area light: the course's `sample_L` takes the light's cosine from the
//!   unnormalised vector `d = q - p`, so `cos' = r cos_l` and its pdf is
//!   `r^2 / (A r cos_l) = p_w / r`: each sample is `r` times too large.
//! - Point light: the course returns the intensity `I` as the radiance,
//!   without the `1 / r^2` falloff: each sample is `r^2` times too large.

use pathtracer::bvh::BvhAccel;
use pathtracer::direct::lights::{sample_light, LightPdf};
use pathtracer::direct::{DirectLights, SceneTracer, ShadingPoint};
use pathtracer::intersect::Intersector;
use pathtracer::math::rng::{next_2d, Sampler};
use pathtracer::math::Rgb;
use pathtracer::render::{estimate_pixel, render_tiles, Rendered};
use pathtracer::scene::Light;

use crate::measure::Setup;

/// How much larger the course's sample of `light` is than this project's,
/// for a sample at distance `r`.
fn course_factor(light: &Light, r: f32) -> f32 {
    match light {
        Light::Area { .. } => r,
        Light::Point { .. } => r * r,
        _ => 1.0,
    }
}

/// [`pathtracer::direct::DirectLights`] with the course's factors: its
/// loop repeated on purpose, so the library keeps no hook for a wrong pdf.
fn course_direct(
    scene: &SceneTracer<&BvhAccel>,
    point: &ShadingPoint,
    samples_per_light: u32,
    rng: &mut Sampler,
) -> Rgb {
    let mut total = Rgb::ZERO;
    for light in scene.lights {
        let n = if pathtracer::direct::lights::is_delta(light) {
            1
        } else {
            samples_per_light
        };
        let mut sum = Rgb::ZERO;
        for _ in 0..n {
            let Some(sample) = sample_light(light, point.hit.p, next_2d(rng)) else {
                continue;
            };
            let wi_local = point.frame.to_local(sample.wi);
            if wi_local.z <= 0.0 {
                continue;
            }
            let shadow = point
                .hit
                .spawn_ray_to(point.hit.p + sample.distance * sample.wi);
            if scene.intersector.occluded(&shadow) {
                continue;
            }
            let weight = match sample.pdf {
                LightPdf::Delta => 1.0,
                LightPdf::SolidAngle(pdf) => 1.0 / pdf,
            };
            let f = point.bsdf.f(point.wo, wi_local);
            sum +=
                f * sample.radiance * wi_local.z * weight * course_factor(light, sample.distance);
        }
        total += sum / n as f32;
    }
    total
}

/// Direct lighting from the scene's lights alone (part 3 less the
/// emission the camera sees, which both share): the library's
/// `DirectLights`, or with `course` the course's factors.
pub fn render_direct(setup: &Setup, spp: u32, samples_per_light: u32, course: bool) -> Rendered {
    let scene = SceneTracer::new(&setup.scene, &setup.accel);
    let settings = setup.settings(spp, 1);
    let size = (setup.width, setup.height);
    let (estimates, stats) = render_tiles(&settings, |x, y, rng| {
        estimate_pixel(
            &setup.camera,
            size,
            (x, y),
            spp,
            None,
            rng,
            |ray, rng| match scene.trace(ray) {
                Some(point) if course => course_direct(&scene, &point, samples_per_light, rng),
                Some(point) => DirectLights { samples_per_light }.estimate(&scene, &point, rng),
                None => Rgb::ZERO,
            },
        )
    });
    Rendered::new(setup.width, setup.height, estimates, stats)
}
