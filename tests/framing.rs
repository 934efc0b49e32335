//! The course's camera placement, checked against the course's own render:
//! in `CBbunny_reference_480x360.png` the ceiling light is the only
//! saturated white area; the pixels whose camera ray hits the emissive
//! `light` mesh in our placement must cover the same rectangle.

mod common;

use pathtracer::intersect::{Intersector, Primitives};
use pathtracer::raygen::Camera;
use pathtracer::render::pixel_ray;
use pathtracer::scene::Material;

/// Inclusive pixel bounds `(x0, y0, x1, y1)` of the pixels where `inside` holds.
fn pixel_bounds(
    width: u32,
    height: u32,
    inside: impl Fn(u32, u32) -> bool,
) -> Option<(u32, u32, u32, u32)> {
    let mut bounds: Option<(u32, u32, u32, u32)> = None;
    for y in 0..height {
        for x in 0..width {
            if inside(x, y) {
                bounds = Some(match bounds {
                    None => (x, y, x, y),
                    Some((x0, y0, x1, y1)) => (x0.min(x), y0.min(y), x1.max(x), y1.max(y)),
                });
            }
        }
    }
    bounds
}

#[test]
fn cbbunny_light_lands_where_the_course_render_has_it() {
    let Some(fixture) = common::cbbunny_reference() else {
        return;
    };
    let common::CbbunnyReference {
        scene,
        camera,
        accel,
        width: w,
        height: h,
        ..
    } = &fixture;
    let (w, h) = (*w, *h);
    let reference = fixture.reference.to_rgb8();
    let expected = pixel_bounds(w, h, |x, y| {
        reference.get_pixel(x, y).0.iter().all(|&c| c >= 250)
    })
    .unwrap();
    let ours = pixel_bounds(w, h, |x, y| {
        let centre = glam::Vec2::splat(0.5);
        let ray = pixel_ray(camera, (w, h), (x, y), centre, centre);
        accel.intersect(&ray).is_some_and(|hit| {
            matches!(
                scene.materials[hit.material as usize],
                Material::Emission { .. }
            )
        })
    })
    .unwrap();
    let off = [
        expected.0.abs_diff(ours.0),
        expected.1.abs_diff(ours.1),
        expected.2.abs_diff(ours.2),
        expected.3.abs_diff(ours.3),
    ];
    assert!(
        off.iter().all(|&d| d <= 2),
        "light at {ours:?}, course render has it at {expected:?}"
    );
}

#[test]
fn cornell_boxes_are_framed_as_the_course_frames_them() {
    for (name, z_sign) in [
        ("CBbunny.dae", -1.0),
        ("CBspheres_lambertian.dae", 1.0),
        ("CBempty.dae", 1.0),
    ] {
        let Some(scene) = common::course_scene(name) else {
            continue;
        };
        let bounds = Primitives::from_scene(&scene).bounds();
        let camera = Camera::course_placement(&scene.camera, &bounds, 480, 360);
        let expected = glam::Vec3::new(0.0, 0.75, z_sign * 4.80);
        assert!(
            camera.position.distance(expected) < 0.01,
            "{name}: {}",
            camera.position
        );
        assert!(
            (camera.hfov_deg - 30.7).abs() < 0.05 && (camera.vfov_deg - 23.2).abs() < 0.06,
            "{name}"
        );
    }
}
