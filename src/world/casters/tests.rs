//! Unit tests of the casters and their cones (`super`).

use super::meshes::tests::light_above;
use super::*;
use glam::Vec2;

fn one(center: Vec3, radius: f32) -> Casters {
    Casters {
        spheres: vec![Caster {
            center,
            radius,
            image_spread: None,
        }],
        lights: Vec::new(),
        meshes: 0,
    }
}

#[test]
fn a_sphere_behind_the_plane_or_around_the_point_is_not_eligible() {
    let casters = one(Vec3::new(0.0, -3.0, 0.0), 1.0);
    assert!(casters.cones(Vec3::ZERO, Vec3::Y).is_empty());
    // Partly above the plane: eligible.
    assert_eq!(casters.cones(Vec3::new(0.0, -2.5, 2.0), Vec3::Y).len(), 1);
    // Inside the sphere.
    assert!(casters.cones(Vec3::new(0.0, -3.2, 0.0), Vec3::Y).is_empty());
    // On it, where it touches a floor, and a rounding error off it:
    // `r / d` would be 1 or more, the cone the whole half-space or
    // NaN (checked with a mutant: a margin of `r^2 / 1.0001` fails).
    let touching = one(Vec3::Y, 1.0);
    for p in [
        Vec3::ZERO,
        Vec3::new(0.0, -1e-6, 0.0),
        Vec3::new(1e-3, 0.0, 0.0),
    ] {
        assert!(touching.cones(p, Vec3::Y).is_empty(), "{p}");
    }
}

fn mirror(center: Vec3, radius: f32) -> Caster {
    Caster {
        center,
        radius,
        image_spread: Some(0.0),
    }
}

fn light(center: Vec3, normal: Vec3) -> ImagedLight {
    ImagedLight {
        center,
        normal,
        radius: 0.5,
    }
}

#[test]
fn an_image_that_a_vertex_does_not_have_is_its_spheres_cone() {
    // The light above the sphere faces up, away from it: no image.
    let center = Vec3::new(0.5, 1.0, 0.0);
    let casters = Casters {
        spheres: vec![mirror(center, 0.3)],
        lights: vec![light(Vec3::new(0.0, 3.0, 0.0), Vec3::Y)],
        meshes: 0,
    };
    let cones = casters.cones(Vec3::ZERO, Vec3::Y);
    assert_eq!(cones.len(), 2);
    let d2 = center.length_squared();
    let sphere = Cone::of_sphere(center, d2, 0.09);
    for i in 0..256 {
        let u = Vec2::new((i % 16) as f32 / 16.0 + 0.01, (i / 16) as f32 / 16.0 + 0.02);
        let w = cones.sample(u, &casters).expect("a sphere-cone sample");
        assert_eq!(cones.pdf(w, &casters), sphere.pdf(w));
    }
}

#[test]
fn a_light_image_is_seen_from_the_vertex_itself() {
    // A vertex away from the origin, a mirror sphere beside it and a
    // light above: the image cone is the one from the vertex, not from
    // the origin (checked with a mutant: the list's vertex left at the
    // origin, `Cones::at` without `p`, fails).
    let p = Vec3::new(2.0, 0.0, -1.5);
    let center = p + Vec3::new(0.8, 0.6, 0.1);
    let lamp = light(p + Vec3::new(-0.3, 3.0, 0.2), Vec3::NEG_Y);
    let normal = images::reflection_normal(p, lamp.center, center, 0.3).expect("an image");
    let image = images::image_cone(p, &mirror(center, 0.3), &lamp, 0.0).expect("a cone");
    let sphere = Cone::of_sphere(center - p, (center - p).length_squared(), 0.09);
    let casters = Casters {
        spheres: vec![mirror(center, 0.3)],
        lights: vec![lamp],
        meshes: 0,
    };
    let cones = casters.cones(p, Vec3::Y);
    assert_eq!(cones.len(), 2);
    // Towards the point that mirrors the light's centre to the vertex.
    let w = (center + 0.3 * normal - p).normalize();
    assert!(image.pdf(w) > sphere.pdf(w) && sphere.pdf(w) > 0.0);
    assert_eq!(cones.pdf(w, &casters), (sphere.pdf(w) + image.pdf(w)) / 2.0);
}

#[test]
fn each_cone_gets_its_share_of_u_x_stretched_back() {
    // Two casters: `u.x` in `[j / 2, (j + 1) / 2)` draws from cone `j`
    // with `2 u.x - j` (checked with mutants: the second cone handed
    // `2 u.x + 1` or `2 u.x / 1`, clamped to its edge, fails).
    let spheres = vec![
        mirror(Vec3::new(-1.0, 1.0, 0.5), 0.3),
        mirror(Vec3::new(1.2, 0.8, -0.4), 0.5),
    ];
    let own: Vec<Cone> = spheres
        .iter()
        .map(|s| Cone::of_sphere(s.center, s.center.length_squared(), s.radius * s.radius))
        .collect();
    let casters = Casters {
        spheres,
        lights: Vec::new(),
        meshes: 0,
    };
    let cones = casters.cones(Vec3::ZERO, Vec3::Y);
    assert_eq!(cones.len(), 2);
    for (j, cone) in own.iter().enumerate() {
        for i in 0..64 {
            let t = (i % 8) as f32 / 8.0 + 0.03;
            let v = (i / 8) as f32 / 8.0 + 0.05;
            let w = cones.sample(Vec2::new((j as f32 + t) / 2.0, v), &casters);
            let expected = cone.sample(Vec2::new(t, v));
            let w = w.expect("a sphere's cone always gives a direction");
            assert!(
                (w - expected).length() < 1e-5,
                "cone {j}, t {t}: {w} {expected}"
            );
        }
    }
    // `u.x = 1`, just outside `[0, 1)`, takes the last cone's edge, not
    // a slot past the list (checked with mutants: the last index as
    // `count + 1` or `count / 1` fails).
    let edge = own[1].sample(Vec2::new(crate::math::float::ONE_BELOW_ONE, 0.5));
    let last = cones
        .sample(Vec2::new(1.0, 0.5), &casters)
        .expect("a direction");
    assert!((last - edge).length() < 1e-5, "{last} {edge}");
}

#[test]
fn light_images_never_take_a_casters_place() {
    // Eight mirrors and two lights: eight cones and four images fit.
    let spheres = (0..MAX_CASTERS)
        .map(|i| mirror(Vec3::new(i as f32 - 3.5, 1.0, -2.0), 0.2))
        .collect();
    let lights = vec![
        light(Vec3::new(0.0, 3.0, 0.0), Vec3::NEG_Y),
        light(Vec3::new(1.0, 3.0, 1.0), Vec3::NEG_Y),
    ];
    let casters = Casters {
        spheres,
        lights,
        meshes: 0,
    };
    let cones = casters.cones(Vec3::ZERO, Vec3::Y);
    assert_eq!(cones.len(), MAX_CONES);
    for caster in &casters.spheres {
        let w = caster.center.normalize();
        assert!(
            cones.pdf(w, &casters) > 0.0,
            "no cone towards {}",
            caster.center
        );
    }
}

#[test]
fn cone_samples_hit_the_sphere_and_have_its_solid_angle_density() {
    let center = Vec3::new(0.3, 2.0, -0.5);
    let radius = 0.4;
    let casters = one(center, radius);
    let cones = casters.cones(Vec3::ZERO, Vec3::Y);
    let d = center.length();
    let solid_angle = 2.0 * std::f32::consts::PI * (1.0 - (1.0 - (radius / d).powi(2)).sqrt());
    for i in 0..64 {
        let u = Vec2::new((i % 8) as f32 / 8.0 + 0.06, (i / 8) as f32 / 8.0 + 0.03);
        let w = cones.sample(u, &casters).unwrap();
        assert!((w.length() - 1.0).abs() < 1e-5);
        // The ray from the origin along w meets the sphere.
        let b = w.dot(center);
        let disc = b * b - (center.length_squared() - radius * radius);
        assert!(disc >= -1e-5, "sample {i} misses the sphere: {disc}");
        assert!((cones.pdf(w, &casters) * solid_angle - 1.0).abs() < 1e-3);
    }
    // Away from the sphere the density is zero.
    assert_eq!(cones.pdf(-Vec3::Y, &casters), 0.0);
}

#[test]
fn a_small_far_sphere_keeps_its_own_samples_inside() {
    // r / d = 1e-3, 3e-4 and 1e-4, seen from far from the origin: the
    // `cos >= sqrt(1 - r^2 / d^2)` test rejected a share of these.
    let p = Vec3::new(137.0, 0.0, -52.0);
    for (d, radius) in [(10.0, 0.01), (30.0, 0.01), (100.0, 0.01)] {
        let center = p + Vec3::new(0.3, 1.0, -0.2).normalize() * d;
        let casters = one(center, radius);
        let cones = casters.cones(p, Vec3::Y);
        let solid_angle = 2.0 * std::f64::consts::PI * (radius as f64 / d as f64).powi(2) / 2.0;
        for i in 0..4096 {
            let u = Vec2::new(
                (i % 64) as f32 / 64.0 + 0.007,
                (i / 64) as f32 / 64.0 + 0.003,
            );
            let w = cones.sample(u, &casters).unwrap();
            let pdf = cones.pdf(w, &casters) as f64;
            assert!(
                (pdf * solid_angle - 1.0).abs() < 1e-2,
                "d {d}: sample {i} has density {pdf}, expected {}",
                1.0 / solid_angle
            );
        }
    }
}

#[test]
fn only_smooth_spheres_cast_mirror_like_ones_show_lights_and_the_rule_decides() {
    use crate::scene::Sphere;
    let rgb = crate::math::Rgb::ONE;
    let materials = vec![
        Material::Diffuse { albedo: rgb },
        Material::Microfacet {
            alpha: 0.025,
            eta: rgb,
            k: rgb,
        },
        Material::Microfacet {
            alpha: 0.5,
            eta: rgb,
            k: rgb,
        },
        Material::Mirror { reflectance: rgb },
    ];
    let spheres = (0..4)
        .map(|material| Sphere {
            center: Vec3::new(material as f32, 0.0, 0.0),
            radius: 0.3,
            material,
        })
        .collect();
    let scene = Scene {
        materials,
        spheres,
        lights: vec![light_above()],
        ..Scene::default()
    };
    let lights = LightSet::new(&scene, Default::default());
    let casters = Casters::new(&scene, &lights, CasterRule::Auto);
    let centers: Vec<f32> = casters.spheres.iter().map(|c| c.center.x).collect();
    assert_eq!(centers, vec![1.0, 3.0]);
    // Both the mirror and the conductor with alpha 0.025 show the light.
    assert_eq!(casters.images(), 2);
    assert!(Casters::new(&scene, &lights, CasterRule::Off).is_empty());
    let spheres = Casters::new(&scene, &lights, CasterRule::Spheres);
    assert_eq!(spheres.spheres, casters.spheres);
    assert_eq!(spheres.images(), 0);
}
