//! Unit tests of the interface's own code: how a file's area light
//! becomes a rectangle.

use super::*;

/// The rectangle [`Light::from_scene`] makes of an area light with these
/// edges and emitting direction.
fn rectangle(dim_x: Vec3, dim_y: Vec3, direction: Vec3) -> RectLight {
    let area = SceneLight::Area {
        radiance: Rgb::new(0.5, 2.0, 4.0),
        center: Vec3::ZERO,
        direction,
        dim_x,
        dim_y,
    };
    match Light::from_scene(&area, LightConvention::Physical) {
        Light::Rect(rect) => rect,
        other => panic!("an area light became a {} light", other.kind()),
    }
}

// Each of these fails with a mutant of `plane_normal`'s guards: `d > 0`
// made `false` or `d < 0` made `true` or `false` returns the file's
// direction or the wrong side; `>` made `>=` or `<` made `<=` returns the
// plane's normal for a direction in the plane.

#[test]
fn an_area_light_faces_the_side_its_file_names_with_the_planes_unit_normal() {
    // X x Z = -Y. The file's direction is tilted and not of unit length:
    // the normal is the plane's, on the direction's side.
    let (x, z) = (Vec3::X * 2.0, Vec3::Z * 0.5);
    let down = rectangle(x, z, Vec3::new(0.3, -2.0, 0.1));
    assert_eq!(down.normal, Vec3::NEG_Y);
    let up = rectangle(x, z, Vec3::new(-0.3, 2.0, 0.1));
    assert_eq!(up.normal, Vec3::Y);
    // The edges in the other order span the same plane.
    assert_eq!(
        rectangle(z, x, Vec3::new(0.3, -2.0, 0.1)).normal,
        Vec3::NEG_Y
    );
}

// Edges of 1e-12 have a cross product whose squared length (1e-48) is
// below f32's smallest normal: `normalize_or_zero` gave no normal and the
// file's tilted direction was kept. Fails with that code.
#[test]
fn a_tiny_area_light_still_faces_along_its_planes_normal() {
    for side in [1e-10, 1e-12, 1e-19] {
        let tilted = Vec3::new(0.3, -2.0, 0.1);
        let down = rectangle(Vec3::X * side, Vec3::Z * side, tilted);
        assert_eq!(down.normal, Vec3::NEG_Y, "sides of {side}");
    }
}

#[test]
fn a_file_that_contradicts_itself_keeps_its_stated_direction() {
    let stated = Vec3::new(1.0, 0.0, 0.5);
    // The direction lies in the plane of the edges.
    assert_eq!(rectangle(Vec3::X, Vec3::Z, stated).normal, stated);
    // The edges are parallel and span no plane.
    assert_eq!(rectangle(Vec3::X, Vec3::X * 3.0, stated).normal, stated);
}

/// One light of every kind, with its `kind()`, whether it is a delta
/// distribution and whether it lies at infinity.
fn every_kind() -> Vec<(Light, &'static str, bool, bool)> {
    use crate::environment::{EnvironmentLight, EnvironmentMap, EnvironmentSampling};
    // Colours, not 1: a power's `* L` made `/ L` must show.
    let colour = Rgb::new(0.5, 2.0, 4.0);
    let map = EnvironmentMap::from_fn("grey", 8, 4, |_| Rgb::splat(1.0)).unwrap();
    let triangle = {
        let mut scene = crate::scene::builtin::cornell_box();
        scene.lights.clear();
        let lights = LightSet::new(&scene, LightConvention::Physical);
        lights.emissive_triangles().unwrap().clone()
    };
    vec![
        (
            Light::Rect(rectangle(Vec3::X * 2.0, Vec3::Z * 1.5, Vec3::NEG_Y)),
            "area",
            false,
            false,
        ),
        (
            Light::Point(PointLight {
                intensity: colour,
                position: Vec3::ZERO,
                convention: LightConvention::Physical,
            }),
            "point",
            true,
            false,
        ),
        (
            Light::Spot(SpotLight {
                intensity: colour,
                position: Vec3::ZERO,
                direction: Vec3::NEG_Y,
            }),
            "spot",
            true,
            false,
        ),
        (
            Light::Directional(DirectionalLight {
                radiance: colour,
                direction: Vec3::Y,
            }),
            "directional",
            true,
            true,
        ),
        (
            Light::Sky(AmbientSky { radiance: colour }),
            "ambient",
            false,
            true,
        ),
        (
            Light::Triangles(triangle),
            "emissive triangles",
            false,
            false,
        ),
        (
            Light::Environment(EnvironmentLight::new(map, EnvironmentSampling::Importance)),
            "environment",
            false,
            true,
        ),
    ]
}

// Fails if `is_delta` or `is_infinite` answers `true` for every light, or
// `kind` gives "" or another name (the mutants of each).
#[test]
fn each_kind_of_light_says_what_it_is() {
    for (light, kind, delta, infinite) in every_kind() {
        assert_eq!(light.kind(), kind);
        assert_eq!(light.is_delta(), delta, "{kind}");
        assert_eq!(light.is_infinite(), infinite, "{kind}");
    }
}

// What a ray that escapes the scene sees, and the density that multiple
// importance sampling asks for with it: only when asked (`with_pdf`), and
// only where the light shines. Fails if the guard's `&&` becomes `||` or
// its `!=` becomes `==`, or if the environment's radiance goes missing
// from `escaped_radiance`.
#[test]
fn an_escaped_ray_sees_the_lights_at_infinity_with_their_density_when_asked() {
    let radiance = Rgb::new(0.5, 1.0, 2.0);
    let sky = Light::Sky(AmbientSky { radiance });
    let (up, down) = (Vec3::new(0.6, 0.8, 0.0), Vec3::new(0.6, -0.8, 0.0));
    let hemisphere = 1.0 / (2.0 * std::f32::consts::PI);
    assert_eq!(sky.escaped(up, true), (radiance, hemisphere));
    assert_eq!(sky.escaped(up, false), (radiance, 0.0));
    assert_eq!(sky.escaped(down, true), (Rgb::ZERO, 0.0));
    assert_eq!(sky.escaped(down, false), (Rgb::ZERO, 0.0));
    for (light, kind, _, infinite) in every_kind() {
        let seen = light.escaped_radiance(up);
        assert_eq!(
            seen != Rgb::ZERO,
            infinite && kind != "directional",
            "{kind}"
        );
        assert_eq!(light.escaped(up, false), (seen, 0.0), "{kind}");
        if kind == "environment" {
            assert!(
                (seen - Rgb::splat(1.0)).abs().max_element() < 1e-6,
                "{seen}"
            );
        }
    }
}

// The course's starter weights a point light's sample by `I` (no
// `1 / r^2`) and an area light's by `r` times the physical one. Fails if
// either factor is 1 or `r * r` becomes `r + r` or `r / r`: at `r = 3`
// these differ.
#[test]
fn the_course_convention_scales_samples_as_the_starter_does() {
    let intensity = Rgb::new(1.0, 2.0, 3.0);
    let point = |convention| PointLight {
        intensity,
        position: Vec3::new(0.0, 3.0, 0.0),
        convention,
    };
    let physical = point(LightConvention::Physical)
        .sample_li(Vec3::ZERO)
        .unwrap();
    let course = point(LightConvention::Course)
        .sample_li(Vec3::ZERO)
        .unwrap();
    assert_eq!((physical.distance, physical.wi), (3.0, Vec3::Y));
    assert_eq!(physical.pdf, LightPdf::Delta);
    // At the light itself there is no direction to it.
    let at = Vec3::new(0.0, 3.0, 0.0);
    assert_eq!(point(LightConvention::Physical).sample_li(at), None);
    assert!((physical.radiance - intensity / 9.0).abs().max_element() < 1e-6);
    assert!((course.radiance - intensity).abs().max_element() < 1e-5);

    let mut rect = rectangle(Vec3::X, Vec3::Z, Vec3::NEG_Y);
    rect.center = Vec3::new(0.0, 3.0, 0.0);
    let u = Vec2::new(0.3, 0.8);
    let physical = rect.sample_li(Vec3::ZERO, u).unwrap();
    rect.convention = LightConvention::Course;
    let course = rect.sample_li(Vec3::ZERO, u).unwrap();
    assert_eq!(course.pdf, physical.pdf);
    assert!(physical.distance > 3.0);
    let r = physical.distance;
    assert!(
        (course.radiance - r * physical.radiance)
            .abs()
            .max_element()
            < 1e-5
    );
    // A BSDF-sampled ray that meets the light counts it the same way.
    assert_eq!(rect.radiance_at(r), r * rect.radiance);
}

// Each kind's radiant power by its formula (module docs): what the light
// choice by power weighs, and what decides that a light emits at all (a
// light of zero power is never sampled). Fails where a formula's factor
// or operator changes, or a power is zero.
#[test]
fn each_kind_of_light_has_the_power_of_its_formula() {
    use std::f32::consts::PI;
    let radius = 3.0;
    let close = |a: Rgb, b: Rgb| (a - b).abs().max_element() <= 1e-5 * b.max_element();
    for (light, kind, _, _) in every_kind() {
        let power = light.power(radius);
        let expected = match &light {
            Light::Rect(l) => PI * l.area() * l.radiance,
            Light::Point(l) => 4.0 * PI * l.intensity,
            Light::Spot(_) => Rgb::ZERO,
            Light::Directional(l) => PI * radius * radius * l.radiance,
            Light::Sky(l) => 2.0 * PI * PI * radius * radius * l.radiance,
            Light::Triangles(_) => {
                // Both sides of the Cornell box's lamp, two triangles.
                let scene = crate::scene::builtin::cornell_box();
                let crate::scene::Light::Area {
                    dim_x,
                    dim_y,
                    radiance,
                    ..
                } = scene.lights[0]
                else {
                    panic!("the box's light is an area light")
                };
                2.0 * PI * dim_x.cross(dim_y).length() * radiance
            }
            Light::Environment(_) => continue,
        };
        assert!(close(power, expected), "{kind}: {power} against {expected}");
    }
    // Numbers, not only the formulas above restated: a 2 x 1.5 rectangle
    // of radiance (0.5, 2, 4) emits 3 pi times that.
    let square = rectangle(Vec3::X * 2.0, Vec3::Z * 1.5, Vec3::NEG_Y);
    let expected = Rgb::new(0.5, 2.0, 4.0) * 3.0 * PI;
    assert!((square.power() - expected).abs().max_element() < 1e-5);
}

#[test]
fn the_light_choice_describes_itself_for_info() {
    let every = LightChoice::EveryLight.describe();
    let by_power =
        LightChoice::ByPower(crate::math::distribution::Distribution1D::new(&[1.0])).describe();
    assert!(every.contains("every light"), "{every}");
    assert!(by_power.contains("by power"), "{by_power}");
}
