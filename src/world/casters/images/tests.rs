//! Unit tests of the light images (`super`): the reflection point, the
//! image cone, which casters and lights take part.

use super::*;

/// A light rectangle of `CBspheres.dae`: centre (0, 1.49, 0), facing
/// down, 0.6 x 0.8.
fn ceiling_light() -> (ImagedLight, Vec3, Vec3) {
    let light = ImagedLight {
        center: Vec3::new(0.0, 1.49, 0.0),
        normal: Vec3::NEG_Y,
        radius: 0.5,
    };
    (light, Vec3::new(0.3, 0.0, 0.0), Vec3::new(0.0, 0.0, 0.4))
}

/// A mirror sphere of radius 0.3 on the floor under
/// [`ceiling_light`], off its centre.
fn cornell_mirror() -> Caster {
    Caster {
        center: Vec3::new(-0.4, 0.3, -0.3),
        radius: 0.3,
        image_spread: Some(0.0),
    }
}

fn reflect(d: Vec3, n: Vec3) -> Vec3 {
    d - 2.0 * d.dot(n) * n
}

/// Which casters show light images, as [`image_spread`] states it:
/// images change the variance, not the mean, so no estimator test
/// sees a sphere get one it should not (checked with mutants: every
/// kind given `Some(0)`, `Some(1)` or `Some(-1)`, or the roughness
/// limit dropped, fails).
#[test]
fn mirrors_and_smooth_conductors_show_images_glass_and_rough_metal_not() {
    use crate::scene::Material;
    let metal = |alpha| Material::Microfacet {
        alpha,
        eta: Vec3::splat(0.2),
        k: Vec3::splat(3.0),
    };
    let mirror = Material::Mirror {
        reflectance: Vec3::ONE,
    };
    assert_eq!(image_spread(&mirror), Some(0.0));
    assert_eq!(image_spread(&metal(0.02)), Some(IMAGE_LOBE * 0.02));
    assert_eq!(
        image_spread(&metal(IMAGE_ALPHA)),
        Some(IMAGE_LOBE * IMAGE_ALPHA)
    );
    assert_eq!(image_spread(&metal(0.2)), None);
    let glass = Material::Glass {
        reflectance: Vec3::ONE,
        transmittance: Vec3::ONE,
        roughness: 0.0,
        ior: 1.5,
    };
    assert_eq!(image_spread(&glass), None);
    assert_eq!(image_spread(&Material::DEFAULT), None);
}

/// The lights that images look for: each rectangle that emits, as the
/// disc around its centre that holds it (radius half its diagonal),
/// facing its emitting side; a dark one and a point light have none
/// (checked with mutants: a dark rectangle kept, or the radius as
/// `0.5 + diagonal` or `0.5 / diagonal`, fails).
#[test]
fn lights_are_imaged_as_the_discs_that_hold_the_emitting_rectangles() {
    use crate::lights::{LightConvention, LightSet};
    use crate::scene::{Light, Scene};
    let rect = |radiance| Light::Area {
        radiance,
        center: Vec3::new(0.5, 2.0, -0.5),
        direction: Vec3::NEG_Y,
        dim_x: Vec3::new(1.2, 0.0, 0.0),
        dim_y: Vec3::new(0.0, 0.0, 1.6),
    };
    let point = Light::Point {
        intensity: Vec3::ONE,
        position: Vec3::Y,
    };
    let scene = Scene {
        lights: vec![rect(Vec3::ZERO), point, rect(Vec3::new(0.0, 0.0, 2.0))],
        ..Scene::default()
    };
    let imaged = ImagedLight::of(&LightSet::new(&scene, LightConvention::Physical));
    assert_eq!(
        imaged,
        vec![ImagedLight {
            center: Vec3::new(0.5, 2.0, -0.5),
            normal: Vec3::NEG_Y,
            radius: 1.0,
        }]
    );
}

#[test]
fn the_reflection_normal_bisects_the_two_directions() {
    let (c, r) = (Vec3::new(-0.4, 0.3, -0.3), 0.3);
    let y = Vec3::new(0.0, 1.49, 0.0);
    for x in [
        Vec3::new(0.5, 0.0, 0.5),
        Vec3::new(-1.0, 0.7, 0.2),
        Vec3::new(0.2, 1.0, -1.0),
    ] {
        let n = reflection_normal(x, y, c, r).expect("an image");
        let s = c + r * n;
        let bisector = ((x - s).normalize() + (y - s).normalize()).normalize();
        assert!(bisector.dot(n) > 1.0 - 1e-4, "{x}: {}", bisector.dot(n));
    }
    // The light behind the sphere as seen from x: no reflection point.
    assert!(reflection_normal(
        Vec3::new(0.0, 0.3, 2.0),
        Vec3::new(0.0, 0.3, -2.0),
        Vec3::new(0.0, 0.3, 0.0),
        0.3
    )
    .is_none());
}

/// Where two steps leave the reflection point unsettled, there is no
/// image: here the last step moved `n` by 0.149, past [`SETTLED`]
/// (checked with mutants: the test as `step < SETTLED + SETTLED`, `/`,
/// or `||` with the side test, fails).
#[test]
fn an_unsettled_reflection_point_gives_no_image() {
    let x = Vec3::new(1.2, 0.0, 0.0);
    let y = Vec3::new(1.060_660_1, 1.060_660_1, 0.45);
    assert_eq!(reflection_normal(x, y, Vec3::ZERO, 1.0), None);
}

/// The reflection point moves with the scene: the same normal, to
/// rounding, with everything moved 50 units along each axis either
/// way (checked with mutants: the side test on `x + s` or `y + s`
/// instead of `x - s`, `y - s`, fails).
#[test]
fn the_reflection_normal_does_not_depend_on_where_the_scene_is() {
    let (c, r) = (Vec3::new(-0.4, 0.3, -0.3), 0.3);
    let y = Vec3::new(0.0, 1.49, 0.0);
    for x in [Vec3::new(0.5, 0.0, 0.5), Vec3::new(-1.0, 0.7, 0.2)] {
        let n = reflection_normal(x, y, c, r).expect("an image");
        for axis in [Vec3::X, Vec3::Y, Vec3::Z] {
            for t in [50.0 * axis, -50.0 * axis] {
                let moved = reflection_normal(x + t, y + t, c + t, r);
                let moved = moved.unwrap_or_else(|| panic!("{x} moved by {t}: no image"));
                assert!(
                    (moved - n).length() < 1e-3,
                    "{x} moved by {t}: {moved}, {n}"
                );
            }
        }
    }
}

/// A glossy conductor's image is the mirror's widened by its lobe:
/// the same axis, a wider cone (checked with a mutant: the spread
/// subtracted from the light's sine instead of added fails).
#[test]
fn a_glossy_casters_image_is_the_mirrors_widened() {
    let caster = cornell_mirror();
    let (light, _, _) = ceiling_light();
    let x = Vec3::new(0.3, 0.0, 0.2);
    let mirror = image_cone(x, &caster, &light, 0.0).expect("an image cone");
    let glossy = image_cone(x, &caster, &light, 0.05).expect("an image cone");
    let axis = mirror.sample(glam::Vec2::ZERO);
    assert!(glossy.pdf(axis) > 0.0 && glossy.solid_angle() > 1.1 * mirror.solid_angle());
}

/// Where the light's image would fill more than the sphere's own cone
/// (a large light in the roughest conductor that gets images, seen
/// from below the sphere's centre), the vertex keeps the sphere's cone
/// alone (checked with mutants: the sphere's squared sine as
/// `r^2 d^2`, `r^2 % d^2` or `r + r / d^2`, which let the image
/// through, fail).
#[test]
fn an_image_wider_than_its_sphere_is_no_image() {
    let caster = Caster {
        image_spread: Some(IMAGE_LOBE * IMAGE_ALPHA),
        ..cornell_mirror()
    };
    let (light, _, _) = ceiling_light();
    let large = ImagedLight {
        radius: 2.0,
        ..light
    };
    let x = Vec3::new(0.5, -0.5, 0.0);
    assert!(reflection_normal(x, light.center, caster.center, caster.radius).is_some());
    assert!(image_cone(x, &caster, &light, 0.0).is_some());
    assert!(image_cone(x, &caster, &large, IMAGE_LOBE * IMAGE_ALPHA).is_none());
}

/// Directions uniform in the sphere's cone from points of a Cornell
/// box's floor and walls, reflected by the mirror sphere: every one
/// that reaches the light is inside the image cone, which is narrower
/// than the sphere's and not much wider than those directions.
#[test]
fn the_image_cone_holds_the_directions_that_reach_the_light() {
    let caster = cornell_mirror();
    let (light, half_x, half_z) = ceiling_light();
    let points = [
        Vec3::new(0.3, 0.0, 0.2),
        Vec3::new(-0.8, 0.0, 0.6),
        Vec3::new(0.8, 0.0, -0.8),
        Vec3::new(-1.0, 0.5, 0.3),
        Vec3::new(-1.0, 1.2, -0.6),
        Vec3::new(0.4, 0.9, -1.0),
    ];
    for x in points {
        let to_center = caster.center - x;
        let d2 = to_center.length_squared();
        let sphere = Cone::of_sphere(to_center, d2, caster.radius * caster.radius);
        let image = image_cone(x, &caster, &light, 0.0).expect("an image cone");
        assert!(image.solid_angle() < sphere.solid_angle());
        let mut reaching = 0;
        let axis = image.sample(glam::Vec2::ZERO);
        let mut widest = 0.0f32;
        for i in 0..40_000 {
            let u = glam::Vec2::new(
                (i % 200) as f32 / 200.0 + 0.002,
                (i / 200) as f32 / 200.0 + 0.001,
            );
            let w = sphere.sample(u);
            // The sphere hit, the reflection, the light's plane.
            let oc = x - caster.center;
            let b = w.dot(oc);
            let disc = b * b - (oc.length_squared() - caster.radius * caster.radius);
            if disc <= 0.0 {
                continue;
            }
            let s = x + (-b - disc.sqrt()) * w;
            let rdir = reflect(w, (s - caster.center).normalize());
            if rdir.y <= 0.0 {
                continue;
            }
            let q = s + (light.center.y - s.y) / rdir.y * rdir - light.center;
            if q.x.abs() > half_x.x || q.z.abs() > half_z.z {
                continue;
            }
            reaching += 1;
            widest = widest.max(w.cross(axis).length());
            assert!(
                image.pdf(w) > 0.0,
                "{x}: direction {w} reaches the light outside the image cone"
            );
        }
        assert!(
            reaching > 20,
            "{x}: only {reaching} directions reach the light"
        );
        // Not much wider than the directions that reach the light: 1.1
        // to 1.7 times their cone's solid angle at these points when
        // written (the disc that holds the light, and the sines for
        // angles), under 2.2 here (checked with a mutant: the
        // magnification `1 + 2 a cos / r` as `2 a cos / r` fails).
        let reach = Cone::around(axis, widest).solid_angle();
        let ratio = image.solid_angle() / reach;
        assert!(ratio < 2.2, "{x}: the image cone is {ratio} times too wide");
    }
}
