//! The starter's `PathTracer::raytrace_pixel` and
//! `Camera::generate_ray` / `generate_ray_for_thin_lens` as a correct
//! student solution writes them, with the catalogue's mistakes of parts 1,
//! 5 and 8 at the lines a student would get wrong.
//!
//! ```text
//! for i in 0..ns_aa:
//!     ray through (x + u, y + v) / (w, h)      (the pixel's centre if ns_aa = 1)
//!     L += est_radiance_global_illumination(ray); s1 += x_k; s2 += x_k^2
//!     every samplesPerBatch samples: stop if 1.96 sigma / sqrt(n) <= maxTolerance * mu
//! pixel = L / n;  sampleCount = n
//! ```
//!
//! The loop is the project's ([`estimate_pixel_with`]); with no mistake
//! the rays are the camera's own and the stopping rule the course's, so
//! the pixel is [`crate::render::estimate_pixel`]'s, bit for bit.

use glam::Vec3;

use crate::adaptive::{Adaptive, LuminanceStats, Z_95};
use crate::intersect::Ray;
use crate::math::warp::sample_uniform_disk_concentric;
use crate::math::Rgb;
use crate::mistakes::{Mistake, Mistakes};
use crate::raygen::{Camera, CameraSample};
use crate::render::{
    estimate_pixel_with, render_tiles, PixelEstimate, PixelTask, RenderSettings, Rendered,
};
use crate::sampling::PixelSampler;

/// `Camera::generate_ray` (and `generate_ray_for_thin_lens` when the
/// camera has a lens) for the normalised film point of `sample`.
pub fn generate_ray(camera: &Camera, sample: &CameraSample, mistakes: Mistakes) -> Ray {
    let camera_mistakes = [
        Mistake::FovFullAngle,
        Mistake::FovInDegrees,
        Mistake::RayInCameraSpace,
        Mistake::LensRadiusUnscaled,
        Mistake::FocusOnASphere,
    ];
    if !camera_mistakes.iter().any(|&m| mistakes.has(m)) {
        return camera.generate_ray(sample);
    }
    // The pinhole direction through the film point, camera space, z = -1.
    let half = |fov_deg: f32| {
        let angle = if mistakes.has(Mistake::FovInDegrees) {
            fov_deg
        } else {
            fov_deg.to_radians()
        };
        if mistakes.has(Mistake::FovFullAngle) {
            angle.tan()
        } else {
            (0.5 * angle).tan()
        }
    };
    let (x, y) = (sample.film.x, sample.film.y);
    let d_cam = Vec3::new(
        (2.0 * x - 1.0) * half(camera.hfov_deg),
        (2.0 * y - 1.0) * half(camera.vfov_deg),
        -1.0,
    );
    let lens = camera.lens;
    let (origin, dir) = if lens.is_pinhole() {
        (Vec3::ZERO, d_cam)
    } else {
        let radius = if mistakes.has(Mistake::LensRadiusUnscaled) {
            1.0
        } else {
            lens.radius
        };
        let disk = radius * sample_uniform_disk_concentric(sample.lens);
        let p_lens = Vec3::new(disk.x, disk.y, 0.0);
        // The point in focus: on the plane z = -d, or (the mistake) at
        // distance d along the pinhole ray.
        let p_focus = if mistakes.has(Mistake::FocusOnASphere) {
            lens.focal_distance * d_cam.normalize()
        } else {
            lens.focal_distance * d_cam
        };
        (p_lens, p_focus - p_lens)
    };
    let c2w = if mistakes.has(Mistake::RayInCameraSpace) {
        glam::Mat3::IDENTITY
    } else {
        camera.c2w
    };
    Ray {
        origin: camera.position + c2w * origin,
        dir: (c2w * dir).normalize(),
        t_min: camera.znear,
        t_max: camera.zfar,
    }
}

/// When a pixel's convergence test runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StopRule {
    /// Every `batch` samples, over those samples (the handout's loop).
    EveryBatch,
    /// The staff library's (3-2): one sample later, after `k batch + 1`
    /// samples, over all of them; a pixel that stops is then written as
    /// having taken one sample fewer ([`StopRule::write_stopped`]).
    /// Measured on the 3-2 starter: a pixel stops at 2 of `-a 2` with the
    /// chance that three samples agree, not two.
    StaffOneLate,
}

impl StopRule {
    /// Writes the pixels of `rendered` that stopped before `max_samples`
    /// as the rule's solution does: as they are, or with
    /// [`StopRule::StaffOneLate`] as the staff's library, measured on the
    /// 3-2 starter: having taken `n` samples it writes their sum over
    /// `n - 1` and records `n - 1` samples, `n / (n - 1)` of their mean
    /// (a constant pixel read 1.51, 1.34 and 1.26 at 2, 3 and 4 recorded;
    /// at `-a 32 0.05` a pixel that stops is 1/32 too bright).
    pub fn write_stopped(self, rendered: &mut Rendered, max_samples: u32) {
        if self != StopRule::StaffOneLate {
            return;
        }
        for (pixel, estimate) in rendered.film.pixels.iter_mut().zip(&mut rendered.estimates) {
            let n = estimate.samples;
            if n > 1 && n < max_samples {
                let factor = n as f32 / (n - 1) as f32;
                *pixel *= factor;
                estimate.radiance *= factor;
                estimate.samples = n - 1;
            }
        }
    }
}

/// Whether a pixel with `stats` may stop: the course's test every `batch`
/// samples (or one later, the staff's), or a student's mistaken one.
fn converged(
    adaptive: &Adaptive,
    rule: StopRule,
    stats: &LuminanceStats,
    mistakes: Mistakes,
) -> bool {
    let square_rooted = !mistakes.has(Mistake::AdaptiveNotSquareRooted);
    let sample_variance = !mistakes.has(Mistake::AdaptivePopulationVariance);
    let batch = adaptive.batch.max(1);
    if rule == StopRule::StaffOneLate {
        return stats.n > batch
            && (stats.n - 1) % batch == 0
            && stats.converged(adaptive.tolerance);
    }
    if square_rooted && sample_variance {
        return adaptive.should_stop(stats);
    }
    let n = stats.n as f64;
    // sigma^2 over n where n - 1 belongs: the population variance.
    let variance = if sample_variance {
        stats.variance()
    } else {
        stats.variance() * (n - 1.0) / n
    };
    // I = 1.96 sigma / n where sqrt(n) belongs.
    let half_width = Z_95 * variance.sqrt() / if square_rooted { n.sqrt() } else { n };
    stats.n % adaptive.batch.max(1) == 0
        && stats.n >= 2
        && half_width <= adaptive.tolerance as f64 * stats.mean()
}

/// The pixel `task` asks for, by up to `task.max_samples` camera rays,
/// each estimated by `radiance`, stopping where `adaptive` says (see the
/// module docs).
pub fn raytrace_pixel(
    camera: &Camera,
    task: PixelTask,
    adaptive: Option<(Adaptive, StopRule)>,
    mistakes: Mistakes,
    sampler: &mut PixelSampler,
    radiance: impl FnMut(&Ray, &mut PixelSampler) -> Rgb,
) -> PixelEstimate {
    let mut estimate = estimate_pixel_with(
        task,
        !camera.lens.is_pinhole(),
        |sample| generate_ray(camera, sample, mistakes),
        |stats| adaptive.is_some_and(|(a, rule)| converged(&a, rule, stats, mistakes)),
        sampler,
        radiance,
    );
    if mistakes.has(Mistake::AdaptiveCountNotUpdated) {
        // The count stays at ns_aa: the sum is divided by it, and the
        // rate image reads every pixel as having taken every sample.
        let max = task.max_samples.max(1);
        let taken = estimate.samples - estimate.rejected;
        estimate.radiance *= taken as f32 / max as f32;
        estimate.samples = max;
    }
    estimate
}

/// Renders an image as the course's `raytrace_pixel` does, with
/// `mistakes`: [`raytrace_pixel`] for every pixel, on tiles in parallel.
pub fn render(
    camera: &Camera,
    settings: &RenderSettings,
    adaptive: Option<(Adaptive, StopRule)>,
    mistakes: Mistakes,
    radiance: impl Fn(&Ray, &mut PixelSampler) -> Rgb + Sync,
) -> Rendered {
    let size = (settings.width, settings.height);
    let (estimates, stats) = render_tiles(settings, |x, y, sampler| {
        let task = PixelTask {
            size,
            pixel: (x, y),
            max_samples: settings.samples_per_pixel,
        };
        raytrace_pixel(camera, task, adaptive, mistakes, sampler, &radiance)
    });
    Rendered::new(settings.width, settings.height, estimates, stats)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::RenderStats;

    fn rendered(samples: [u32; 3]) -> Rendered {
        let estimates = samples.map(|samples| PixelEstimate {
            radiance: Rgb::splat(0.5),
            samples,
            ..PixelEstimate::default()
        });
        let stats = RenderStats {
            seconds: 0.0,
            threads: 1,
        };
        Rendered::new(3, 1, estimates.to_vec(), stats)
    }

    /// The staff's rule: a pixel that stopped early having taken `n`
    /// samples is `n / (n - 1)` of their mean and records `n - 1`; one
    /// that took every sample is as it is; the handout's rule changes
    /// nothing.
    #[test]
    fn pixels_that_stop_early_take_the_staffs_factor_by_the_staffs_rule_only() {
        let mut image = rendered([33, 64, 96]);
        StopRule::StaffOneLate.write_stopped(&mut image, 64);
        let values: Vec<f32> = image.film.pixels.iter().map(|p| p.x).collect();
        assert_eq!(values, [0.5 * 33.0 / 32.0, 0.5, 0.5]);
        assert_eq!(image.estimates[0].radiance.x, 0.5 * 33.0 / 32.0);
        assert_eq!(image.estimates[0].samples, 32);
        let mut image = rendered([32, 64, 96]);
        StopRule::EveryBatch.write_stopped(&mut image, 64);
        assert!(image.film.pixels.iter().all(|p| p.x == 0.5));
        assert_eq!(image.estimates[0].samples, 32);
    }
}
