//! What a ray finds of a rectangle light (`global::emission::found_emission`),
//! one ray at a time, where only time or a small share of an image would
//! show a mistake: a rectangle light is not geometry, so whether the ray
//! reaches it before the surface it hits is decided by comparing
//! distances, with a relative tolerance for surfaces on the light's plane
//! and a slack for its stand-in quad; and the course's light convention
//! scales only what the BSDF side of MIS counts.
//!
//! Each test is exact (no sampling): a ray from a floor point straight up
//! to a light facing down, after a scattering vertex (the BSDF side of
//! MIS) or from the camera. Checked by the mutants of `.ci/mutants global`
//! that survived the estimator tests, each named in its test's comment.

mod common;

use common::{accel, diffuse, rect_corners, rect_light, tracer, SceneBuilder, LIGHTS};
use glam::Vec3;
use pathtracer::global::PrevVertex;
use pathtracer::intersect::{Intersector, Ray};
use pathtracer::lights::LightConvention;
use pathtracer::math::Rgb;
use pathtracer::scene::{Light, Material, Scene};
use pathtracer::world::{World, WorldOptions};

const RADIANCE: f32 = 4.0;
const FLOOR_POINT: Vec3 = Vec3::new(0.1, 0.0, 0.05);

/// The light, 1.2 x 0.9 (diagonal 1.5), facing down at height 1.
fn light() -> Light {
    rect_light(RADIANCE, Vec3::new(0.0, 1.0, 0.0), -Vec3::Y, 1.2, 0.9)
}

/// A floor, the light and, where given, a quad of `material` at height
/// `y` over `[-2, 2]^2` (over the light's own corners when `on_light`).
fn scene_with(surface: Option<(Material, f32, bool)>) -> Scene {
    let mut b = SceneBuilder::new();
    let floor = b.material(diffuse(0.5));
    b.floor(floor, 2.0);
    if let Some((material, y, on_light)) = surface {
        let m = b.material(material);
        let corners = if on_light {
            rect_corners(&light()).map(|c| Vec3::new(c.x, y, c.z))
        } else {
            [
                Vec3::new(-2.0, y, -2.0),
                Vec3::new(2.0, y, -2.0),
                Vec3::new(2.0, y, 2.0),
                Vec3::new(-2.0, y, 2.0),
            ]
        };
        b.quad(m, corners);
    }
    b.light(light());
    b.finish()
}

/// The emission the ray from `origin` straight up finds, after a
/// scattering vertex there (BSDF density `1 / pi`, as a cosine sample
/// straight up has) or, with `camera`, from a camera there.
fn found(scene: &Scene, convention: LightConvention, origin: Vec3, camera: bool) -> Rgb {
    let bvh = accel(scene);
    let options = WorldOptions {
        light_convention: convention,
        ..WorldOptions::default()
    };
    let world = World::with_options(scene, &bvh, options);
    let mut ray = Ray::new(origin, Vec3::Y);
    ray.t_min = 1e-4;
    let next = world.intersector.intersect(&ray);
    let prev = if camera {
        PrevVertex::CameraOrDelta
    } else {
        PrevVertex::Scattering {
            p: origin,
            bsdf_pdf: std::f32::consts::FRAC_1_PI,
            splits_map: true,
        }
    };
    tracer(LIGHTS, 2, false).found_emission(&world, &ray, next.as_ref(), &prev)
}

/// [`found`] after a scattering vertex at `origin`, the physical convention.
fn bsdf_ray_finds(scene: &Scene, origin: Vec3) -> Rgb {
    found(scene, LightConvention::Physical, origin, false)
}

/// A surface on the light's plane does not hide the light from a BSDF
/// ray (the ceiling of the course's boxes holds its light flush), a
/// stand-in quad on it neither, and a surface in front of it does.
/// Without anything behind the light, the ray counts `L w_bsdf > 0`; with
/// a grey ceiling or the stand-in on the light's plane, exactly as much;
/// with the ceiling half-way down, nothing. Checked by the mutants: the
/// plane's tolerance `t_hit (1 + 1e-3)` made `t_hit (1 - 1e-3)` or
/// `t_hit / (1 + 1e-3)` (the ceiling hides the light), or `t_hit + (1 +
/// 1e-3)` (the lower ceiling does not); the stand-in's slack subtracted
/// (it hides the light), or given to every surface but the stand-in (the
/// stand-in just in front of the light, seen from near it, hides it). The
/// slack's size, `0.02` of the diagonal, only needs to pass the stand-in
/// rule's `1e-4` of it, so its mutants (`0.02 + d`, `0.02 / d`) change
/// nothing a valid stand-in can show.
#[test]
fn surfaces_on_the_light_s_plane_do_not_hide_it_and_those_in_front_do() {
    let open = bsdf_ray_finds(&scene_with(None), FLOOR_POINT);
    assert!(open.x > 0.0 && open.x < RADIANCE, "{open}");
    let grey = diffuse(0.5);
    let stand_in = Material::Emission {
        radiance: Rgb::splat(RADIANCE),
    };
    for (what, surface) in [
        ("a ceiling on the light's plane", (grey, 1.0, false)),
        ("the light's stand-in", (stand_in, 1.0, true)),
    ] {
        let seen = bsdf_ray_finds(&scene_with(Some(surface)), FLOOR_POINT);
        assert!(
            (seen - open).abs().max_element() <= 1e-6 * open.x,
            "{what}: {seen} against {open}"
        );
    }
    // Near the light (0.05 below it) a stand-in 1e-4 in front of it (the
    // stand-in rule allows 1e-4 of the diagonal, here 1.5e-4) lies
    // farther from the light than the plane's relative tolerance reaches
    // (5e-5): the stand-in's slack keeps the light seen.
    let near = Vec3::new(0.1, 0.95, 0.05);
    let open_near = bsdf_ray_finds(&scene_with(None), near);
    let in_front = (stand_in, 1.0 - 1e-4, true);
    let seen = bsdf_ray_finds(&scene_with(Some(in_front)), near);
    assert!(
        (seen - open_near).abs().max_element() <= 1e-5 * open_near.x,
        "a stand-in just in front: {seen} against {open_near}"
    );
    let lower = bsdf_ray_finds(&scene_with(Some((grey, 0.5, false))), FLOOR_POINT);
    assert_eq!(lower, Rgb::ZERO, "a ceiling in front of the light hides it");
}

/// The course's light convention scales the light by the distance only
/// where the BSDF side of MIS counts it against light samples, which are
/// scaled alike (`RectLight::radiance_at`); the camera sees the light's
/// own radiance. Checked by the mutant that scales after the camera too
/// (`after_scattering || mis`): the camera, 1 below the light, would see
/// it at `L 1`, no different; so the camera here stands 0.6 below it
/// (`L 0.6`).
#[test]
fn the_camera_sees_a_rectangle_light_s_own_radiance_in_the_course_s_convention() {
    let below = Vec3::new(0.1, 0.4, 0.05);
    let seen = found(&scene_with(None), LightConvention::Course, below, true);
    assert_eq!(seen, Rgb::splat(RADIANCE));
}
