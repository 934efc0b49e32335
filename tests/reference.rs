//! Our renders of `CBbunny.dae` against the course's own 480 x 360 render
//! (`CBbunny_reference_480x360.png`), which shows the course's framing and
//! a brightness that is *not* a correct course solution's: what a correct
//! solution renders (`--course-exact`, the staff's library and student
//! solutions alike) is about 1.4 times brighter (its light samples are too
//! bright by the distance: the starter's `AreaLight::sample_L` divides by
//! a pdf made with the unnormalised distance vector; measured with the
//! staff's library and an independent solution, which agree within 0.1 %),
//! and the shipped render matches, instead, a solution whose shadow rays
//! end at the light and are blocked by the lamp's own mesh; its brightness
//! is, by that coincidence, the physically correct one. So:
//!
//! - framing, shadows and colour layout: the correlation of block means of
//!   display luminance with the reference, for both renders;
//! - brightness: the project's physically correct render matches the
//!   reference's mean, and the course's image is brighter by the factor
//!   section 8.1 measured (means of linear radiance decoded from 8-bit
//!   values, as from the PNG), each within the noise measured in the
//!   images themselves.

mod common;

use pathtracer::cli::drivers::render_lighting;
use pathtracer::course::{Assignment, Choices, CourseExact, Lamps, StarterDirect, StarterTracer};
use pathtracer::direct::DirectLights;
use pathtracer::global::{DirectStrategy, PathTracer, Roulette};
use pathtracer::math::{luminance, Rgb};
use pathtracer::mistakes::Mistakes;
use pathtracer::render::{render_image, tone_map, Film, Quantization, RenderSettings};
use pathtracer::sampling::SamplerKind;
use pathtracer::world::World;

const COLS: u32 = 24;
const ROWS: u32 = 18;

fn correlation(a: &[f32], b: &[f32]) -> f32 {
    let mean = |v: &[f32]| v.iter().sum::<f32>() / v.len() as f32;
    let (ma, mb) = (mean(a), mean(b));
    let cov: f32 = a.iter().zip(b).map(|(x, y)| (x - ma) * (y - mb)).sum();
    let va: f32 = a.iter().map(|x| (x - ma) * (x - ma)).sum();
    let vb: f32 = b.iter().map(|y| (y - mb) * (y - mb)).sum();
    cov / (va * vb).sqrt()
}

fn block_luminance(film: &Film) -> Vec<f32> {
    film.block_means(COLS, ROWS)
        .into_iter()
        .map(luminance)
        .collect()
}

/// The linear radiance a viewer decodes from an 8-bit value `b` of the
/// course's PNG: the centre of its bin, through the inverse of the tone
/// map `(L sqrt 2)^(1 / 2.2)`.
fn decoded(b: u8) -> f64 {
    ((b as f64 + 0.5) / 255.0).powf(2.2) / std::f64::consts::SQRT_2
}

/// The mean over every channel of every pixel of [`decoded`] values.
fn decoded_mean(bytes: &[u8]) -> f64 {
    bytes.iter().map(|&b| decoded(b)).sum::<f64>() / bytes.len() as f64
}

/// Immerkær's estimate of the standard deviation of a noisy image's
/// pixels (J. Immerkær, "Fast Noise Variance Estimation", *Computer Vision
/// and Image Understanding* 64(2), 1996): the mask
/// `[1 -2 1; -2 4 -2; 1 -2 1]` cancels the image's smooth part, and for
/// independent Gaussian noise of deviation sigma,
/// `sigma = sqrt(pi / 2) / (6 (W - 2) (H - 2)) sum |I * M|`. Edges add to
/// the sum, so it overestimates the noise where the image has them.
fn pixel_noise(values: &[f64], width: usize, height: usize) -> f64 {
    let at = |x: usize, y: usize| values[y * width + x];
    let mut sum = 0.0;
    for y in 1..height - 1 {
        for x in 1..width - 1 {
            let masked = at(x - 1, y - 1) + at(x + 1, y - 1) + at(x - 1, y + 1) + at(x + 1, y + 1)
                - 2.0 * (at(x, y - 1) + at(x - 1, y) + at(x + 1, y) + at(x, y + 1))
                + 4.0 * at(x, y);
            sum += masked.abs();
        }
    }
    (std::f64::consts::PI / 2.0).sqrt() * sum / (6.0 * ((width - 2) * (height - 2)) as f64)
}

/// Per pixel, the mean over its channels of [`decoded`] values.
fn decoded_pixels(bytes: &[u8]) -> Vec<f64> {
    bytes
        .chunks(3)
        .map(|c| c.iter().map(|&b| decoded(b)).sum::<f64>() / 3.0)
        .collect()
}

/// The standard error of an image's mean (8-bit values, decoded) from its
/// pixels' noise: each pixel's noise independent of the others'.
fn standard_error_of_mean(bytes: &[u8], width: u32, height: u32) -> f64 {
    let pixels = decoded_pixels(bytes);
    pixel_noise(&pixels, width as usize, height as usize) / (pixels.len() as f64).sqrt()
}

/// The standard error of `mean / reference`, each mean with its own
/// independent error (first order).
fn brightness_error(mean: f64, error: f64, reference: f64, reference_error: f64) -> f64 {
    (mean / reference) * ((error / mean).powi(2) + (reference_error / reference).powi(2)).sqrt()
}

/// A render's display values (the course's tone map) and its 8-bit values
/// as the course's PNG truncates them.
fn as_the_course_writes_it(film: &Film) -> (Film, Vec<u8>) {
    let display = Film {
        pixels: film.pixels.iter().map(|&l| tone_map(l)).collect(),
        ..film.clone()
    };
    let bytes = display
        .pixels
        .iter()
        .flat_map(|p| p.to_array().map(|v| Quantization::Truncate.apply(v)))
        .collect();
    (display, bytes)
}

#[test]
fn cbbunny_framing_and_brightness_against_the_course_render() {
    let Some(fixture) = common::cbbunny_reference() else {
        return;
    };
    let (w, h) = (fixture.width, fixture.height);
    let reference_bytes = fixture.reference.to_rgb8().into_raw();
    let reference = Film {
        width: w,
        height: h,
        pixels: reference_bytes
            .chunks(3)
            .map(|c| Rgb::new(c[0] as f32, c[1] as f32, c[2] as f32) / 255.0)
            .collect(),
    };
    let reference_mean = decoded_mean(&reference_bytes);
    let (scene, camera, accel) = (&fixture.scene, &fixture.camera, &fixture.accel);
    let settings = RenderSettings {
        width: w,
        height: h,
        samples_per_pixel: 16,
        seed: 1,
        sampler: SamplerKind::Independent,
        ..RenderSettings::default()
    };
    // The project's physically correct render.
    let physical = World::new(scene, accel);
    let tracer = PathTracer {
        direct: DirectStrategy::Lights(DirectLights {
            samples_per_light: 1,
            environment_samples: None,
            mis: true,
        }),
        max_depth: 5,
        accumulate: true,
        roulette: Roulette::Fixed,
        glass_splits: 0,
    };
    let project = render_lighting(&physical, &tracer, camera, &settings, None);
    // The course's image (--course-exact=3-1).
    let exact = CourseExact {
        assignment: Assignment::PathTracer1,
    };
    let course_world = World::with_options(scene, accel, exact.world_options());
    let starter = StarterTracer {
        direct: StarterDirect::Importance,
        light_samples: 1,
        max_depth: 5,
        accumulate: true,
        lamps: Lamps::MeshFaces,
        choices: Choices::of(Assignment::PathTracer1),
        mistakes: Mistakes::NONE,
    };
    let course = render_image(camera, &settings, None, |ray, sampler| {
        starter.radiance(&course_world, ray, sampler)
    });
    let reference_error = standard_error_of_mean(&reference_bytes, w, h);
    let mut ratios = Vec::new();
    for (name, rendered) in [("project", &project), ("course-exact", &course)] {
        let (display, bytes) = as_the_course_writes_it(&rendered.film);
        let r = correlation(&block_luminance(&display), &block_luminance(&reference));
        let mean = decoded_mean(&bytes);
        let error = standard_error_of_mean(&bytes, w, h);
        let ratio = mean / reference_mean;
        let ratio_error = brightness_error(mean, error, reference_mean, reference_error);
        eprintln!(
            "{name}: correlation of {COLS} x {ROWS} block luminances {r:.4}, \
             mean radiance over the course render's {ratio:.4} +- {ratio_error:.1e}"
        );
        // 0.982 (project) and 0.995 (course-exact) here; a field of view
        // 10 % too wide already gives 0.88.
        assert!(r > 0.95, "{name}: correlation {r}");
        ratios.push((ratio, ratio_error));
    }
    // Brightness, within the noise the images show (about 3e-4 of the
    // ratio for both: `standard_error_of_mean`, the reference's noise and
    // the render's). The expected ratios are not 1 and 1.40 exactly: the
    // shipped render is not a correct solution but, by coincidence, close
    // to the physical brightness (section 8.1: within 1 % per block), so
    // each expected ratio is the one measured here (16 samples, seed 1),
    // and the bound allows that measurement's noise as well as this one's
    // (sqrt 2 times the error, 4.5 standard deviations: a false failure
    // after a change of seeds or sampler in fewer than 1 in 10^4). A
    // change of 0.3 % in the project's brightness fails.
    let within_noise = |(ratio, error): (f64, f64), expected: f64| {
        (ratio - expected).abs() <= 4.5 * std::f64::consts::SQRT_2 * error
    };
    // Physically correct: 0.9949 of the shipped render.
    assert!(within_noise(ratios[0], 0.9949), "project: {:?}", ratios[0]);
    // A correct course solution: 1.3832 of it (section 8.1 measured 1.40
    // for the staff's library, to two figures); with physical light
    // samples it would be the project's.
    assert!(
        within_noise(ratios[1], 1.3832),
        "course-exact: {:?}",
        ratios[1]
    );
    assert!((ratios[1].0 - 1.40).abs() < 0.025, "{:?}", ratios[1]);
}
