//! Rendering infrastructure: the film, tiles on all cores, the progress
//! bar, pixel sampling and image output.
//!
//! Reproducibility: pixel `(x, y)` draws its random numbers from
//! `sampler(seed, y * width + x)`, so an image depends on the seed only,
//! never on the number of threads or the order tiles finish in.

pub mod film;
pub mod output;
pub mod tiles;

pub use film::Film;
pub use output::{tone_map, write_image, OutputError};
pub use tiles::{render_tiles, RenderSettings, RenderStats};

use glam::Vec2;

use crate::intersect::Ray;
use crate::math::rng::{next_2d, Sampler};
use crate::math::Rgb;
use crate::raygen::Camera;

/// The camera ray through pixel `(x, y)` (row 0 at the top of the image)
/// at the sub-pixel offset `offset` in `[0, 1)^2`.
///
/// The course samples the normalised point `((x + u) / w, (y' + v) / h)`
/// with `y'` counted from the bottom row.
#[doc(alias = "generate_ray")]
pub fn pixel_ray(camera: &Camera, width: u32, height: u32, x: u32, y: u32, offset: Vec2) -> Ray {
    let y_from_bottom = (height - 1 - y) as f32;
    camera.ray(
        (x as f32 + offset.x) / width as f32,
        (y_from_bottom + offset.y) / height as f32,
    )
}

/// The mean of `samples` radiance estimates for pixel `(x, y)`: one ray
/// through the pixel centre when `samples == 1` (as the course does),
/// otherwise rays at uniformly random offsets in the pixel.
#[doc(alias = "raytrace_pixel")]
pub fn sample_pixel(
    camera: &Camera,
    width: u32,
    height: u32,
    (x, y): (u32, u32),
    samples: u32,
    rng: &mut Sampler,
    mut radiance: impl FnMut(&Ray, &mut Sampler) -> Rgb,
) -> Rgb {
    if samples <= 1 {
        let ray = pixel_ray(camera, width, height, x, y, Vec2::splat(0.5));
        return radiance(&ray, rng);
    }
    let mut sum = Rgb::ZERO;
    for _ in 0..samples {
        let ray = pixel_ray(camera, width, height, x, y, next_2d(rng));
        sum += radiance(&ray, rng);
    }
    sum / samples as f32
}
