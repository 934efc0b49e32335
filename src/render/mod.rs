//! Rendering infrastructure: the film, tiles on all cores, the progress
//! bar, pixel sampling and image output.
//!
//! Reproducibility: every camera sample starts its numbers with
//! [`Sampler::start_pixel_sample`]`((x, y), index)` on the render's
//! sampler ([`crate::sampling`], `RenderSettings::sampler`), so an image
//! depends on (seed, pixel, sample index) only, never on the number of
//! threads or the order tiles finish in.

pub mod film;
pub mod memory;
pub mod output;
pub mod rendered;
pub mod tiles;

pub use film::Film;
pub use output::{
    check_output_path, quantize_display, tone_map, write_image, write_image_quantized, write_png,
    write_png_quantized, OutputError, OutputFormat, Quantization, OUTPUT_FORMATS,
};
pub use rendered::Rendered;
pub use tiles::{render_tiles, RenderSettings, RenderStats};

use crate::adaptive::{Adaptive, LuminanceStats};

use glam::Vec2;

use crate::intersect::Ray;
use crate::math::Rgb;
use crate::raygen::{Camera, CameraSample};
use crate::sampling::{PixelSampler, Sampler};

/// The normalised film point of pixel `(x, y)` (row 0 at the top of the
/// image) at the sub-pixel offset `offset` in `[0, 1)^2`: the course
/// samples `((x + u) / w, (y' + v) / h)` with `y'` counted from the bottom
/// row.
pub fn film_point((width, height): (u32, u32), (x, y): (u32, u32), offset: Vec2) -> Vec2 {
    let y_from_bottom = (height - 1 - y) as f32;
    Vec2::new(
        (x as f32 + offset.x) / width as f32,
        (y_from_bottom + offset.y) / height as f32,
    )
}

/// The camera ray through pixel `(x, y)` (row 0 at the top of the image)
/// at the sub-pixel offset `offset` in `[0, 1)^2` ([`film_point`]),
/// through the lens point `lens` in `[0, 1)^2` if the camera has a lens.
#[doc(alias = "generate_ray")]
pub fn pixel_ray(
    camera: &Camera,
    size: (u32, u32),
    pixel: (u32, u32),
    offset: Vec2,
    lens: Vec2,
) -> Ray {
    let film = film_point(size, pixel, offset);
    camera.generate_ray(&CameraSample { film, lens })
}

/// What a pixel's samples gave.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PixelEstimate {
    /// Mean radiance of the accepted samples.
    pub radiance: Rgb,
    /// Camera rays traced for the pixel (accepted or not).
    pub samples: u32,
    /// Samples rejected for a NaN or infinite radiance (left out of the mean).
    pub rejected: u32,
    /// Squared standard error of the mean luminance (0 with one sample).
    pub variance_of_mean: f64,
}

/// Which pixel of which image, with up to how many samples.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelTask {
    pub size: (u32, u32),
    pub pixel: (u32, u32),
    pub max_samples: u32,
}

/// Estimates pixel `(x, y)` with up to `max_samples` camera rays: one ray
/// through the pixel centre when `max_samples == 1` (as the course does),
/// otherwise rays at offsets in the pixel from `sampler`
/// ([`Sampler::get_pixel_2d`], uniform over the pixel), stopping early
/// when `adaptive` says the pixel has converged. Sample `i` starts with
/// `sampler.start_pixel_sample((x, y), i)`; a lens sample is drawn only
/// for a lens. `radiance` gives each ray's radiance estimate from the
/// sampler's next dimensions; non-finite ones are counted and left out.
#[doc(alias = "raytrace_pixel")]
pub fn estimate_pixel(
    camera: &Camera,
    size: (u32, u32),
    pixel: (u32, u32),
    max_samples: u32,
    adaptive: Option<Adaptive>,
    sampler: &mut PixelSampler,
    radiance: impl FnMut(&Ray, &mut PixelSampler) -> Rgb,
) -> PixelEstimate {
    let task = PixelTask {
        size,
        pixel,
        max_samples,
    };
    estimate_pixel_with(
        task,
        !camera.lens.is_pinhole(),
        |sample| camera.generate_ray(sample),
        |stats| adaptive.is_some_and(|a| a.should_stop(stats)),
        sampler,
        radiance,
    )
}

/// [`estimate_pixel`] with the camera rays made by `generate` (which takes
/// a lens sample when `has_lens`) and the pixel stopped when `stop` says,
/// after each sample: the loop the course's renderer shares
/// ([`crate::course::pixel`]).
pub fn estimate_pixel_with(
    task: PixelTask,
    has_lens: bool,
    generate: impl Fn(&CameraSample) -> Ray,
    stop: impl Fn(&LuminanceStats) -> bool,
    sampler: &mut PixelSampler,
    mut radiance: impl FnMut(&Ray, &mut PixelSampler) -> Rgb,
) -> PixelEstimate {
    let mut stats = LuminanceStats::default();
    // Summed in f64: finite samples near f32::MAX cannot add up to infinity.
    let mut sum = glam::DVec3::ZERO;
    let mut estimate = PixelEstimate::default();
    while estimate.samples < task.max_samples.max(1) {
        sampler.start_pixel_sample(task.pixel, estimate.samples);
        let offset = if task.max_samples <= 1 {
            Vec2::splat(0.5)
        } else {
            sampler.get_pixel_2d()
        };
        // A lens sample only for a lens, so pinhole renders stay as they were.
        let lens = if has_lens {
            sampler.get_2d()
        } else {
            Vec2::splat(0.5)
        };
        let film = film_point(task.size, task.pixel, offset);
        let ray = generate(&CameraSample { film, lens });
        let l = radiance(&ray, sampler);
        estimate.samples += 1;
        if !l.is_finite() {
            estimate.rejected += 1;
            continue;
        }
        sum += l.as_dvec3();
        stats.push(l);
        if stop(&stats) {
            break;
        }
    }
    if stats.n > 0 {
        estimate.radiance = (sum / stats.n as f64).as_vec3();
    }
    estimate.variance_of_mean = stats.variance_of_mean();
    estimate
}

/// Renders an image: every pixel estimated by [`estimate_pixel`] from
/// `radiance`, up to `settings.samples_per_pixel` camera rays each,
/// stopping early where `adaptive` says so, on tiles in parallel.
pub fn render_image(
    camera: &Camera,
    settings: &RenderSettings,
    adaptive: Option<Adaptive>,
    radiance: impl Fn(&Ray, &mut PixelSampler) -> Rgb + Sync,
) -> Rendered {
    render_image_with_factors(camera, settings, None, adaptive, radiance)
}

/// [`render_image`] with pixel `(x, y)` taking `factors[y * width + x]`
/// times `settings.samples_per_pixel` samples (`None`: once); the sampler
/// is built for the largest factor.
///
/// # Panics
///
/// If `factors` has not one factor a pixel.
pub fn render_image_with_factors(
    camera: &Camera,
    settings: &RenderSettings,
    factors: Option<&[u32]>,
    adaptive: Option<Adaptive>,
    radiance: impl Fn(&Ray, &mut PixelSampler) -> Rgb + Sync,
) -> Rendered {
    let size = (settings.width, settings.height);
    if let Some(f) = factors {
        assert_eq!(f.len(), (size.0 * size.1) as usize, "one factor a pixel");
    }
    let largest = factors.and_then(|f| f.iter().copied().max()).unwrap_or(1);
    let sampler_settings = RenderSettings {
        samples_per_pixel: settings.samples_per_pixel * largest,
        ..*settings
    };
    let (estimates, stats) = render_tiles(&sampler_settings, |x, y, sampler| {
        let factor = factors.map_or(1, |f| f[(y * size.0 + x) as usize]);
        estimate_pixel(
            camera,
            size,
            (x, y),
            settings.samples_per_pixel * factor,
            adaptive,
            sampler,
            &radiance,
        )
    });
    Rendered::new(settings.width, settings.height, estimates, stats)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampling::SamplerKind;
    use std::sync::Mutex;

    /// Pixels with factors 1, 4 and 16 at 4 samples take 4, 16 and 64,
    /// and with ZSobol (built for 64) each pixel's numbers in a dimension
    /// pair are a (0, m, 2)-net: each of the `2^m` elementary boxes
    /// `2^-a x 2^-(m-a)` holds one. Checked by hand: with the sampler
    /// built for 4 samples (samples past 4 are other pixels' points), and
    /// with factors 1, 2 and 8 (an odd number of base-4 digits between a
    /// pixel's count and the sampler's), boxes hold two or none.
    #[test]
    fn a_pixels_factor_multiplies_its_samples_which_stay_a_net() {
        let settings = RenderSettings {
            width: 3,
            height: 1,
            samples_per_pixel: 4,
            threads: Some(1),
            seed: 3,
            sampler: SamplerKind::ZSobol,
            progress: false,
        };
        let camera = Camera::look_at(glam::Vec3::Z, glam::Vec3::ZERO, glam::Vec3::Y, 60.0, 20.0);
        let points = Mutex::new(vec![Vec::new(); 3]);
        let factors = [1, 4, 16];
        let rendered =
            render_image_with_factors(&camera, &settings, Some(&factors), None, |ray, sampler| {
                // The pixel from the ray's direction: thirds of the field.
                let x = ray.dir.x / -ray.dir.z / (30f32.to_radians().tan());
                let pixel = ((x + 1.0) * 1.5).clamp(0.0, 2.0) as usize;
                points.lock().unwrap()[pixel].push(sampler.get_2d());
                Rgb::ONE
            });
        let samples: Vec<u32> = rendered.estimates.iter().map(|e| e.samples).collect();
        assert_eq!(samples, [4, 16, 64]);
        for (pixel, points) in points.into_inner().unwrap().iter().enumerate() {
            let m = points.len().trailing_zeros();
            assert_eq!(points.len(), 4 * factors[pixel] as usize);
            for a in 0..=m {
                let (nx, ny) = (1u32 << a, 1u32 << (m - a));
                let mut boxes = vec![0; points.len()];
                for p in points {
                    let (i, j) = ((p.x * nx as f32) as u32, (p.y * ny as f32) as u32);
                    boxes[(j * nx + i) as usize] += 1;
                }
                assert!(
                    boxes.iter().all(|&n| n == 1),
                    "pixel {pixel}, {nx} x {ny}: {boxes:?}"
                );
            }
        }
    }

    #[test]
    fn samples_near_the_float_maximum_average_to_a_finite_pixel() {
        let task = PixelTask {
            size: (1, 1),
            pixel: (0, 0),
            max_samples: 16,
        };
        let mut sampler = SamplerKind::Independent.for_render(1, (1, 1), 16);
        let mut k = 0;
        let estimate = estimate_pixel_with(
            task,
            false,
            |_| Ray::new(glam::Vec3::ZERO, glam::Vec3::Z),
            |_| false,
            &mut sampler,
            |_, _| {
                k += 1;
                // Every fourth sample is not finite: counted, left out.
                if k % 4 == 0 {
                    Rgb::splat(f32::NAN)
                } else {
                    Rgb::splat(f32::MAX)
                }
            },
        );
        assert_eq!((estimate.samples, estimate.rejected), (16, 4));
        // An f32 sum would overflow to infinity at the second sample.
        assert_eq!(estimate.radiance, Rgb::splat(f32::MAX));
    }
}
