//! The course's pinhole camera.
//!
//! Ray for the normalised image point `(x, y)` in `[0, 1]^2`, `y = 0` at the
//! bottom row (the starter's `Camera::generate_ray`, `src/pathtracer/camera.cpp`):
//!
//! ```text
//! d_cam = ((2x - 1) tan(hFov / 2), (2y - 1) tan(vFov / 2), -1)
//! d     = normalize(c2w * d_cam),   t in [znear, zfar]
//! ```
//!
//! Placement: the course does not put the camera where the file says. It
//! keeps only the file's direction towards the camera `c_dir`, aims at the
//! centre of the bounding box of all geometry and backs off to
//! `1.5 |extent|` ([`Camera::course_placement`]). The field of view depends
//! on the output size: the course fits the file's fov to an 800x600 window
//! ([`course_fov`]), keeps that screen distance in pixels,
//! `D = 600 / (2 tan(vFov / 2))`, and for a `W x H` image uses
//! `hFov = 2 atan(W / 2D)`, `vFov = 2 atan(H / 2D)`.

use glam::{Mat3, Vec2, Vec3};

use crate::depth_of_field::ThinLens;
use crate::intersect::{Aabb, Ray};
use crate::scene::CameraInfo;

/// The window size the course fits the file's field of view to.
pub const COURSE_WINDOW: (u32, u32) = (800, 600);

/// `EPS_F` of the course: nudges the polar angle off the poles.
const POLE_EPSILON: f32 = 1e-5;

/// Where on the film and on the lens a camera ray starts: the normalised
/// image point (`[0, 1]^2`, `y = 0` at the bottom) and a point in
/// `[0, 1)^2` that a thin lens maps to its disk (ignored by a pinhole).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraSample {
    pub film: Vec2,
    pub lens: Vec2,
}

impl CameraSample {
    /// The sample at film point `film` through the lens centre.
    pub fn at(film: Vec2) -> Self {
        CameraSample {
            film,
            lens: Vec2::splat(0.5),
        }
    }
}

/// A pinhole camera, or with [`Camera::lens`] a thin-lens one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// Eye position, world space.
    pub position: Vec3,
    /// Camera-to-world rotation: columns are the camera's x (right),
    /// y (up) and z (backwards: the camera looks along -z).
    pub c2w: Mat3,
    /// Horizontal field of view, degrees.
    pub hfov_deg: f32,
    /// Vertical field of view, degrees.
    pub vfov_deg: f32,
    pub znear: f32,
    pub zfar: f32,
    /// The lens (part 8); a pinhole by default.
    pub lens: ThinLens,
    /// `(tan(hFov / 2), tan(vFov / 2))`, computed once by the constructors
    /// (every camera ray needs them; the fields of view are fixed there).
    tan_half_fov: Vec2,
}

/// `(tan(hFov / 2), tan(vFov / 2))` of fields of view in degrees.
fn tan_half_fov(hfov_deg: f32, vfov_deg: f32) -> Vec2 {
    Vec2::new(
        (0.5 * hfov_deg.to_radians()).tan(),
        (0.5 * vfov_deg.to_radians()).tan(),
    )
}

impl Camera {
    /// A camera at `position` looking at `target` with `up` roughly up.
    pub fn look_at(position: Vec3, target: Vec3, up: Vec3, hfov_deg: f32, vfov_deg: f32) -> Self {
        let z = (position - target).normalize();
        let x = up.cross(z).normalize();
        let y = z.cross(x);
        Camera {
            position,
            c2w: Mat3::from_cols(x, y, z),
            hfov_deg,
            vfov_deg,
            znear: 0.0,
            zfar: f32::INFINITY,
            lens: ThinLens::PINHOLE,
            tan_half_fov: tan_half_fov(hfov_deg, vfov_deg),
        }
    }

    /// The course's placement of the file's camera for a `width x height`
    /// image over a scene whose geometry fills `bounds`.
    #[doc(alias = "place")]
    pub fn course_placement(info: &CameraInfo, bounds: &Aabb, width: u32, height: u32) -> Self {
        let (target, distance) = if bounds.is_empty() {
            (Vec3::ZERO, 1.0)
        } else {
            // canonical = |extent| / 2 * 1.5; the view distance is twice that.
            (bounds.centroid(), 1.5 * bounds.extent().length())
        };
        // Spherical angles of c_dir, as the course's Camera::place takes them.
        let dir = info.dir_to_camera.normalize_or(Vec3::Z);
        let mut phi = dir.y.clamp(-1.0, 1.0).acos();
        if phi.sin() == 0.0 {
            phi += POLE_EPSILON;
        }
        let theta = dir.x.atan2(dir.z);
        let (sin_phi, cos_phi) = phi.sin_cos();
        let to_camera = Vec3::new(sin_phi * theta.sin(), cos_phi, sin_phi * theta.cos());
        let up = Vec3::new(0.0, if sin_phi > 0.0 { 1.0 } else { -1.0 }, 0.0);
        let x = up.cross(to_camera).normalize();
        let y = to_camera.cross(x).normalize();
        let (hfov_deg, vfov_deg) = course_fov(info.hfov_deg, info.vfov_deg, width, height);
        Camera {
            position: target + distance * to_camera,
            c2w: Mat3::from_cols(x, y, to_camera),
            hfov_deg,
            vfov_deg,
            znear: info.znear,
            zfar: info.zfar,
            lens: ThinLens::PINHOLE,
            tan_half_fov: tan_half_fov(hfov_deg, vfov_deg),
        }
    }

    /// The same camera with the thin lens `lens`.
    pub fn with_lens(self, lens: ThinLens) -> Self {
        Camera { lens, ..self }
    }

    /// The pinhole direction through the normalised image point `(x, y)`,
    /// camera space, with `z = -1`.
    fn film_direction(&self, x: f32, y: f32) -> Vec3 {
        let t = self.tan_half_fov;
        Vec3::new((2.0 * x - 1.0) * t.x, (2.0 * y - 1.0) * t.y, -1.0)
    }

    /// The pinhole ray through the normalised image point `(x, y)`,
    /// `y = 0` at the bottom (the lens, if any, is not used).
    pub fn ray(&self, x: f32, y: f32) -> Ray {
        Ray {
            origin: self.position,
            dir: (self.c2w * self.film_direction(x, y)).normalize(),
            t_min: self.znear,
            t_max: self.zfar,
        }
    }

    /// The camera ray of `sample`: through the lens point it picks when
    /// the camera has a lens ([`ThinLens::ray`]), else the pinhole ray.
    #[doc(alias = "generate_ray_for_thin_lens")]
    pub fn generate_ray(&self, sample: &CameraSample) -> Ray {
        if self.lens.is_pinhole() {
            return self.ray(sample.film.x, sample.film.y);
        }
        let d_cam = self.film_direction(sample.film.x, sample.film.y);
        let (origin, dir) = self.lens.ray(d_cam, sample.lens);
        Ray {
            origin: self.position + self.c2w * origin,
            dir: (self.c2w * dir).normalize(),
            t_min: self.znear,
            t_max: self.zfar,
        }
    }

    /// The unit viewing direction (camera -z in world space).
    pub fn view_direction(&self) -> Vec3 {
        -self.c2w.z_axis
    }
}

/// The course's output-size-dependent field of view (degrees) for a file
/// camera with fields of view `file_hfov_deg` x `file_vfov_deg`.
///
/// The course first fits the file's camera to its 800 x 600 window
/// (`Camera::configure`): when the file's aspect `tan(h/2) / tan(v/2)` is
/// wider than the window's, the vertical fov is widened to
/// `2 atan(tan(h/2) / (800/600))`; when narrower, the horizontal one is (and
/// the vertical kept). The screen distance `D = 600 / (2 tan(v/2))` pixels
/// is then kept for any output size.
pub fn course_fov(file_hfov_deg: f32, file_vfov_deg: f32, width: u32, height: u32) -> (f32, f32) {
    let window_aspect = COURSE_WINDOW.0 as f32 / COURSE_WINDOW.1 as f32;
    let tan_h = (0.5 * file_hfov_deg.to_radians()).tan();
    let tan_v = (0.5 * file_vfov_deg.to_radians()).tan();
    let fitted_tan_v = if tan_h / tan_v > window_aspect {
        tan_h / window_aspect
    } else {
        tan_v
    };
    let screen_distance = COURSE_WINDOW.1 as f32 / (2.0 * fitted_tan_v);
    let fov = |pixels: u32| {
        2.0 * (pixels as f32 / (2.0 * screen_distance))
            .atan()
            .to_degrees()
    };
    (fov(width), fov(height))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cornell_info() -> CameraInfo {
        CameraInfo {
            dir_to_camera: Vec3::Z,
            hfov_deg: 49.13434,
            vfov_deg: 2.0
                * ((0.5f32 * 49.13434f32.to_radians()).tan() / 1.333333)
                    .atan()
                    .to_degrees(),
            znear: 0.1,
            zfar: 100.0,
        }
    }

    fn cornell_bounds() -> Aabb {
        Aabb {
            min: Vec3::new(-1.0, 0.0, -1.0),
            max: Vec3::new(1.0, 1.5, 1.0),
        }
    }

    #[test]
    fn cornell_box_framing_matches_the_course() {
        let cam = Camera::course_placement(&cornell_info(), &cornell_bounds(), 480, 360);
        // 1.5 |extent| = 1.5 sqrt(2^2 + 1.5^2 + 2^2) = 4.802 (the course's "4.80").
        let distance = 1.5 * 10.25f32.sqrt();
        let expected = Vec3::new(0.0, 0.75, distance);
        assert!(cam.position.distance(expected) < 1e-5, "{}", cam.position);
        assert!((cam.hfov_deg - 30.7).abs() < 0.05, "{}", cam.hfov_deg);
        assert!((cam.vfov_deg - 23.2).abs() < 0.05, "{}", cam.vfov_deg);
        let cam = Camera::course_placement(&cornell_info(), &cornell_bounds(), 800, 600);
        assert!((cam.hfov_deg - 49.13).abs() < 0.02 && (cam.vfov_deg - 37.85).abs() < 0.05);
        assert!(cam.view_direction().distance(-Vec3::Z) < 1e-6);
    }

    #[test]
    fn a_wide_file_camera_is_fitted_to_the_course_window() {
        // CBbunny.dae: xfov 49.13434 with aspect 16:9 frames like the 4:3 boxes.
        let wide_vfov = 2.0
            * ((0.5f32 * 49.13434f32.to_radians()).tan() / 1.777778)
                .atan()
                .to_degrees();
        let (h, v) = course_fov(49.13434, wide_vfov, 480, 360);
        assert!(
            (h - 30.7).abs() < 0.05 && (v - 23.2).abs() < 0.05,
            "{h} {v}"
        );
        // A narrow camera keeps its vertical fov at 800 x 600.
        let (h, v) = course_fov(30.0, 40.0, 800, 600);
        assert!((v - 40.0).abs() < 1e-3 && h > 40.0, "{h} {v}");
    }

    #[test]
    fn image_corners_span_the_field_of_view() {
        let cam = Camera::course_placement(&cornell_info(), &cornell_bounds(), 800, 600);
        let centre = cam.ray(0.5, 0.5);
        assert!(centre.dir.distance(-Vec3::Z) < 1e-6);
        assert_eq!(centre.t_min, 0.1);
        let right = cam.ray(1.0, 0.5).dir;
        let angle = right.angle_between(centre.dir).to_degrees();
        assert!((angle - cam.hfov_deg / 2.0).abs() < 1e-3);
        // y = 1 is the top of the image: the ray points up.
        assert!(cam.ray(0.5, 1.0).dir.y > 0.0);
    }

    #[test]
    fn a_camera_straight_above_still_has_a_frame() {
        let info = CameraInfo {
            dir_to_camera: Vec3::Y,
            ..cornell_info()
        };
        let cam = Camera::course_placement(&info, &cornell_bounds(), 64, 48);
        assert!(cam.ray(0.3, 0.7).dir.is_finite());
        assert!(cam.view_direction().y < -0.999);
    }
}
