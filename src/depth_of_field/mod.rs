//! Part 8: depth of field with a thin lens (assignment 3-2, part 4).
//!
//! A pinhole camera sends every ray of a pixel through one point, so all
//! of the scene is sharp. A thin lens of radius `b` (`-b`) focused at
//! distance `d` (`-d`) sends them through points of a disk instead; the
//! rays of one film point all meet where its pinhole ray meets the plane
//! of focus `z = -d` (camera space), so that plane is sharp and the rest
//! blurs in proportion to its distance from it (pbrt-v4, section 5.2.3;
//! the course's `Camera::generate_ray_for_thin_lens`).
//!
//! In camera space, with the pinhole direction `d_cam = (x, y, -1)` of the
//! film point and a point `p_lens = b (u, v, 0)` uniform on the lens disk:
//!
//! ```text
//! p_focus = d * d_cam                        (the pinhole ray at z = -d)
//! ray     = p_lens + t normalize(p_focus - p_lens)
//! ```
//!
//! With `b = 0` every ray is the pinhole's, and no lens sample is drawn.

use glam::{Vec2, Vec3};

use crate::math::warp::sample_uniform_disk_concentric;

/// The course's default focal distance (`-d`), scene units.
pub const COURSE_FOCAL_DISTANCE: f32 = 4.7;

/// A thin lens: radius and the distance of the plane of focus.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ThinLens {
    /// Radius of the lens (aperture), scene units; 0 is a pinhole.
    pub radius: f32,
    /// Distance from the lens to the plane of focus along the view axis.
    pub focal_distance: f32,
}

impl Default for ThinLens {
    fn default() -> Self {
        ThinLens::PINHOLE
    }
}

impl ThinLens {
    /// No lens: every ray through the camera's position.
    pub const PINHOLE: ThinLens = ThinLens {
        radius: 0.0,
        focal_distance: COURSE_FOCAL_DISTANCE,
    };

    /// Whether rays pass through a disk (and need a lens sample).
    pub fn is_pinhole(&self) -> bool {
        self.radius <= 0.0
    }

    /// The ray through the film point whose pinhole direction is `d_cam`
    /// (camera space, `z = -1`), through the lens point chosen by `u` in
    /// `[0, 1)^2`: origin and unit direction, camera space.
    pub fn ray(&self, d_cam: Vec3, u: Vec2) -> (Vec3, Vec3) {
        if self.is_pinhole() {
            return (Vec3::ZERO, d_cam.normalize());
        }
        let disk = self.radius * sample_uniform_disk_concentric(u);
        let p_lens = Vec3::new(disk.x, disk.y, 0.0);
        // Point on the plane of focus.
        let p_focus = self.focal_distance * d_cam;
        (p_lens, (p_focus - p_lens).normalize())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::rng::{next_2d, sampler};

    #[test]
    fn rays_of_one_film_point_meet_on_the_plane_of_focus() {
        let mut rng = sampler(3, 0);
        for focal_distance in [0.5f32, 4.7, 80.0] {
            let lens = ThinLens {
                radius: 0.3,
                focal_distance,
            };
            for _ in 0..200 {
                let f = next_2d(&mut rng) * 2.0 - Vec2::ONE;
                let d_cam = Vec3::new(f.x, f.y, -1.0);
                let target = focal_distance * d_cam;
                let (origin, dir) = lens.ray(d_cam, next_2d(&mut rng));
                assert!(origin.z == 0.0 && origin.truncate().length() <= 0.3 * (1.0 + 1e-6));
                assert!((dir.length() - 1.0).abs() < 1e-5);
                // Where the ray reaches the plane z = -d.
                let t = -focal_distance / dir.z;
                let meet = origin + t * dir;
                assert!(
                    meet.distance(target) <= 1e-4 * target.length(),
                    "{meet} vs {target}"
                );
            }
        }
    }

    #[test]
    fn a_pinhole_ignores_the_lens_sample() {
        let d_cam = Vec3::new(0.3, -0.2, -1.0);
        let expected = (Vec3::ZERO, d_cam.normalize());
        for u in [Vec2::ZERO, Vec2::splat(0.5), Vec2::new(0.9, 0.1)] {
            assert_eq!(ThinLens::PINHOLE.ray(d_cam, u), expected);
        }
    }
}
