//! The course's direct lighting, with its two differences from this
//! project (the library's `LightConvention::Course`, `--course-lights` on
//! the command line), for measuring how much they change an image.
//!
//! - Area light: the course's `sample_L` takes the light's cosine from the
//!   unnormalised vector `d = q - p`, so `cos' = r cos_l` and its pdf is
//!   `r^2 / (A r cos_l) = p_w / r`: each sample is `r` times too large.
//! - Point light: the course returns the intensity `I` as the radiance,
//!   without the `1 / r^2` falloff: each sample is `r^2` times too large.

use pathtracer::direct::DirectLights;
use pathtracer::lights::LightConvention;
use pathtracer::math::Rgb;
use pathtracer::render::{render_image, Rendered};
use pathtracer::world::{World, WorldOptions};

use crate::setup::Setup;

/// Direct lighting from the scene's lights alone (part 3 less the
/// emission the camera sees, which both share): the library's
/// `DirectLights`, or with `course` the course's factors.
pub fn render_direct(setup: &Setup, spp: u32, samples_per_light: u32, course: bool) -> Rendered {
    let light_convention = if course {
        LightConvention::Course
    } else {
        LightConvention::Physical
    };
    let options = WorldOptions {
        light_convention,
        ..WorldOptions::default()
    };
    let scene = World::with_options(&setup.scene, &setup.accel, options);
    let settings = setup.settings(spp, 1);
    // Light sampling alone: without the BSDF half, no MIS weights.
    let direct = DirectLights {
        samples_per_light,
        environment_samples: None,
        mis: false,
    };
    render_image(&setup.camera, &settings, None, |ray, rng| {
        match scene.trace(ray) {
            Some(point) => direct.estimate(&scene, &point, rng),
            None => Rgb::ZERO,
        }
    })
}
