//! Light transport through delta bounces and multiple importance sampling,
//! against closed forms and across strategies:
//!
//! - a mirror that sees the light: the floor gets the light directly and
//!   through the mirror, each counted exactly once, whichever strategy
//!   and whether or not an emissive quad stands in for the light;
//! - a glass sphere of index 1 and transmittance 1 changes nothing.
//!
//! Fixed seeds; each test's comparisons share [`ALPHA`] = 1e-4
//! (Bonferroni), so a correct renderer fails a test less than once in 10^4
//! seeds. Each test was checked once by hand to fail for a wrong library
//! (named in its comment; none is committed).

mod common;

use std::f64::consts::PI;

use common::*;
use glam::{DVec3, Vec3};
use pathtracer::direct::{DirectHemisphere, DirectLights};
use pathtracer::global::DirectStrategy;
use pathtracer::scene::{Light, Material, Scene};
use pathtracer::world::World;

/// The strategies the integrator offers.
fn strategies() -> [(&'static str, DirectStrategy); 4] {
    let lights = |mis| {
        DirectStrategy::Lights(DirectLights {
            samples_per_light: 1,
            environment_samples: None,
            mis,
        })
    };
    [
        ("MIS", lights(true)),
        ("light sampling alone", lights(false)),
        (
            "hemisphere",
            DirectStrategy::Hemisphere(DirectHemisphere { samples: 1 }),
        ),
        ("BSDF sampling alone", DirectStrategy::BsdfOnly),
    ]
}

/// A grey diffuse floor `[-3, 1] x [-3, 3]` at `y = 0` and a light facing
/// down at height 1; with `stand_in`, an emissive quad on the light (as the
/// course's Cornell boxes have); with `mirror`, a vertical mirror of
/// reflectance `R` at `x = 1` facing the light.
fn floor_light_mirror(albedo: f32, light: Light, stand_in: bool, mirror: Option<f32>) -> Scene {
    let mut b = SceneBuilder::new();
    let floor = b.material(diffuse(albedo));
    b.quad(
        floor,
        [
            Vec3::new(-3.0, 0.0, -3.0),
            Vec3::new(1.0, 0.0, -3.0),
            Vec3::new(1.0, 0.0, 3.0),
            Vec3::new(-3.0, 0.0, 3.0),
        ],
    );
    if let Some(r) = mirror {
        let m = b.material(Material::Mirror {
            reflectance: Vec3::splat(r),
        });
        b.quad(
            m,
            [
                Vec3::new(1.0, 0.0, -3.0),
                Vec3::new(1.0, 3.0, -3.0),
                Vec3::new(1.0, 3.0, 3.0),
                Vec3::new(1.0, 0.0, 3.0),
            ],
        );
    }
    if stand_in {
        let Light::Area { radiance, .. } = light else {
            unreachable!()
        };
        let quad = b.material(Material::Emission { radiance });
        b.quad(quad, rect_corners(&light));
    }
    b.light(light);
    b.finish()
}

/// The floor at `x` sees the light and its mirror image: with albedo `a`,
/// `L = a / pi (E_light + R E_image)`, both irradiances from Lambert's
/// polygon formula (the image's corners reflected through `x = 1`; it is
/// seen whole through the mirror). Paths of up to 2 bounces (floor, then
/// mirror) carry all of it, and no other light exists (the floor cannot
/// see itself in the mirror within 2 bounces). Each strategy, with and
/// without a stand-in quad (without one, the rectangle itself is seen
/// through the mirror), must give it: light counted once. Checked by hand:
/// counting a stand-in's emission after a scattering bounce too fails
/// (MIS 95 % over, by 98 standard errors).
#[test]
fn a_mirror_shows_the_light_and_it_is_counted_once() {
    let (albedo, r, radiance) = (0.6f32, 0.8f32, 3.0f32);
    let light = rect_light(radiance, Vec3::new(-0.2, 1.0, 0.1), -Vec3::Y, 0.6, 0.4);
    let x = Vec3::new(0.3, 0.0, 0.0);
    let corners = rect_corners(&light).map(|c| c.as_dvec3());
    let image = corners.map(|c| DVec3::new(2.0 - c.x, c.y, c.z));
    let e_light = polygon_irradiance(x.as_dvec3(), DVec3::Y, &corners, radiance as f64);
    let e_image = polygon_irradiance(x.as_dvec3(), DVec3::Y, &image, radiance as f64);
    let expected = albedo as f64 / PI * (e_light + r as f64 * e_image);
    let ray = ray_towards(Vec3::new(-1.0, 1.5, 1.0), x);

    let cases = [true, false].map(|stand_in| {
        let scene = floor_light_mirror(albedo, light, stand_in, Some(r));
        (stand_in, scene)
    });
    let alpha = ALPHA / 8.0;
    for (stand_in, scene) in &cases {
        let bvh = accel(scene);
        let world = World::new(scene, &bvh);
        for (k, (name, direct)) in strategies().into_iter().enumerate() {
            let est = estimate(
                &world,
                &tracer(direct, 2, false),
                &ray,
                200_000,
                31 + k as u64,
            );
            let label = format!("{name}, stand-in {stand_in}");
            assert_mean_matches(&label, est, expected, alpha, 0.0);
        }
    }
}

/// The course's intent for a lamp: its emissive quad is the lamp's visible
/// face, its area light lights the room, whatever their radiances. A quad
/// of radiance 6 on a light of radiance 3: the floor is lit by the light
/// alone (`a / pi E_light`, Lambert's polygon formula) and a camera ray
/// that meets the quad sees 6, under every strategy. Checked by hand:
/// the earlier rule, which asked the quad for the light's radiance, made
/// the quad a light of its own and the floor three times as bright (MIS
/// off by hundreds of standard errors).
#[test]
fn a_brighter_quad_shows_the_lamp_and_its_light_lights_the_room() {
    let (albedo, radiance) = (0.6f32, 3.0f32);
    let light = rect_light(radiance, Vec3::new(-0.2, 1.0, 0.1), -Vec3::Y, 0.6, 0.4);
    let mut scene = floor_light_mirror(albedo, light, true, None);
    let quad = scene
        .materials
        .iter()
        .position(|m| matches!(m, Material::Emission { .. }))
        .expect("the quad's material");
    scene.materials[quad] = Material::Emission {
        radiance: Vec3::splat(2.0 * radiance),
    };
    let x = Vec3::new(0.3, 0.0, 0.0);
    let corners = rect_corners(&light).map(|c| c.as_dvec3());
    let e_light = polygon_irradiance(x.as_dvec3(), DVec3::Y, &corners, radiance as f64);
    let expected = albedo as f64 / PI * e_light;
    let to_floor = ray_towards(Vec3::new(-1.0, 1.5, 1.0), x);
    let to_lamp = ray_towards(Vec3::new(0.3, 0.2, 0.0), Vec3::new(-0.2, 1.0, 0.1));
    let bvh = accel(&scene);
    let world = World::new(&scene, &bvh);
    let alpha = ALPHA / 4.0;
    for (k, (name, direct)) in strategies().into_iter().enumerate() {
        let t = tracer(direct, 2, false);
        let floor = estimate(&world, &t, &to_floor, 100_000, 71 + k as u64);
        assert_mean_matches(&format!("floor, {name}"), floor, expected, alpha, 0.0);
        let lamp = estimate(&world, &t, &to_lamp, 1_000, 81 + k as u64);
        // The quad reflects nothing: the camera sees its emission alone.
        assert!(
            (lamp.mean - 2.0 * radiance as f64).abs() < 1e-4,
            "lamp, {name}: the camera sees {:.4}, not the quad's {}",
            lamp.mean,
            2.0 * radiance
        );
    }
}

/// A glass sphere of index 1 and transmittance 1 (exact Fresnel reflects
/// nothing at index 1) lets light through unchanged: the floor seen
/// through it, and the floor in its shadow (lit only by paths through the
/// glass, as shadow rays stop at it), are as bright as without it. Two
/// points, three strategies, two-sample z-tests. Checked by hand: a
/// transmittance of 0.9 fails (ray 0 by 54 standard errors).
#[test]
fn glass_of_index_one_changes_nothing() {
    let albedo = 0.5;
    let light = rect_light(4.0, Vec3::new(0.0, 1.5, 0.0), -Vec3::Y, 1.0, 1.0);
    let clear = floor_light_mirror(albedo, light, true, None);
    let mut with_glass = clear.clone();
    with_glass.materials.push(Material::Glass {
        reflectance: Vec3::ONE,
        transmittance: Vec3::ONE,
        roughness: 0.0,
        ior: 1.0,
    });
    with_glass.spheres.push(pathtracer::scene::Sphere {
        center: Vec3::new(-0.5, 0.6, 0.0),
        radius: 0.3,
        material: (with_glass.materials.len() - 1) as u32,
    });
    let (a1, a2) = (accel(&clear), accel(&with_glass));
    let (w1, w2) = (World::new(&clear, &a1), World::new(&with_glass, &a2));
    let eye = Vec3::new(-0.5, 1.2, 0.2);
    let rays = [
        // Through the sphere onto the floor.
        ray_towards(eye, Vec3::new(-0.5, 0.0, -0.2)),
        // The floor under the sphere, in its shadow, seen past it.
        ray_towards(Vec3::new(0.8, 1.0, 0.8), Vec3::new(-0.5, 0.0, 0.0)),
    ];
    let alpha = ALPHA / 8.0;
    for (i, ray) in rays.iter().enumerate() {
        for (k, (name, direct)) in strategies().into_iter().enumerate() {
            let t = tracer(direct, 5, false);
            let seed = 100 + 10 * i as u64 + k as u64;
            let a = estimate(&w1, &t, ray, 100_000, seed);
            let b = estimate(&w2, &t, ray, 100_000, seed + 1000);
            assert_means_agree(&format!("ray {i}, {name}"), a, b, alpha);
        }
    }
}

/// A glossy floor (a Beckmann copper of roughness 0.15) whose highlight
/// shows a light: light sampling alone, BSDF sampling alone and their
/// combination by MIS estimate the same radiance, for a rectangle light
/// with its stand-in, an emissive quad sampled as triangles, and the
/// ambient sky. Two two-sample z-tests per light. MIS must also beat the
/// worse of the two single strategies (lower standard error at equal
/// samples). Checked by hand: leaving the number of light samples out of
/// the BSDF side's weight fails with `-l 4` (MIS 10 % over, by 108
/// standard errors).
#[test]
fn strategies_agree_on_a_glossy_floor() {
    let copper = Material::Microfacet {
        alpha: 0.15,
        eta: Vec3::new(0.2, 0.92, 1.1),
        k: Vec3::new(3.9, 2.45, 2.14),
    };
    let light = rect_light(5.0, Vec3::new(0.6, 1.0, 0.0), -Vec3::Y, 0.4, 0.4);
    let with_stand_in = {
        let mut s = floor_light_mirror(0.5, light, true, None);
        s.materials[0] = copper;
        s
    };
    let emissive_quad = {
        let mut s = with_stand_in.clone();
        s.lights.clear();
        s
    };
    let sky = {
        let mut s = emissive_quad.clone();
        s.mesh.triangles.truncate(2);
        s.mesh.materials.truncate(2);
        s.lights.push(Light::Ambient {
            radiance: Vec3::splat(0.8),
        });
        s
    };
    // The mirror direction of this ray meets the light's centre.
    let ray = ray_towards(Vec3::new(-0.6, 1.0, 0.0), Vec3::ZERO);
    let with = |mis, samples_per_light| {
        DirectStrategy::Lights(DirectLights {
            samples_per_light,
            environment_samples: None,
            mis,
        })
    };
    let alpha = ALPHA / 8.0;
    for (name, scene) in [
        ("rectangle light", &with_stand_in),
        ("emissive quad", &emissive_quad),
        ("sky", &sky),
    ] {
        let bvh = accel(scene);
        let world = World::new(scene, &bvh);
        let n = 100_000;
        let mis = estimate(&world, &tracer(with(true, 1), 1, false), &ray, n, 51);
        let lights = estimate(&world, &tracer(with(false, 1), 1, false), &ray, n, 52);
        let bsdf = estimate(
            &world,
            &tracer(DirectStrategy::BsdfOnly, 1, false),
            &ray,
            n,
            53,
        );
        assert_means_agree(
            &format!("{name}: MIS and light sampling"),
            mis,
            lights,
            alpha,
        );
        assert_means_agree(&format!("{name}: MIS and BSDF sampling"), mis, bsdf, alpha);
        eprintln!(
            "{name}: standard errors MIS {:.2e}, lights {:.2e}, BSDF {:.2e}",
            mis.se, lights.se, bsdf.se
        );
        assert!(
            mis.se < lights.se.max(bsdf.se),
            "{name}: MIS is noisier than both"
        );
    }
    // Several light samples: the BSDF side's weight counts them.
    let bvh = accel(&with_stand_in);
    let world = World::new(&with_stand_in, &bvh);
    let mis4 = estimate(&world, &tracer(with(true, 4), 1, false), &ray, 50_000, 54);
    let lights4 = estimate(&world, &tracer(with(false, 4), 1, false), &ray, 50_000, 55);
    assert_means_agree("-l 4: MIS and light sampling", mis4, lights4, alpha);
}

/// A diffuse floor under twelve lights, five rectangles and seven points
/// of powers spread over two orders of magnitude: `L = a / pi sum E_l`,
/// rectangles by Lambert's polygon formula and a point light of intensity
/// `I` at height `h` and distance `r` giving `E = I h / r^3`. Light
/// sampling with lights chosen by power (each sample picks one light with
/// probability proportional to its power, divided out) must give it, with
/// and without MIS, as must sampling every light; `Auto` picks power for
/// twelve lights. Direct light only (depth 1). Checked by hand: leaving the
/// choice probability out of the light sample's density (weight and
/// divisor) fails (MIS 14 % under, by 145 standard errors).
#[test]
fn many_lights_chosen_by_power_give_the_closed_form() {
    use pathtracer::lights::{LightChoice, LightChoiceRule};
    use pathtracer::world::WorldOptions;
    let albedo = 0.7f32;
    let x = Vec3::new(-0.4, 0.0, 0.3);
    let mut scene = floor_light_mirror(
        albedo,
        rect_light(0.5, Vec3::new(-1.0, 1.0, 0.0), -Vec3::Y, 0.3, 0.3),
        false,
        None,
    );
    let mut expected_irradiance = 0.0;
    for (i, radiance) in [0.5f32, 2.0, 8.0, 1.0, 30.0].into_iter().enumerate() {
        let centre = Vec3::new(-2.0 + 0.7 * i as f32, 1.0 + 0.2 * i as f32, -1.0);
        let light = rect_light(radiance, centre, -Vec3::Y, 0.3, 0.2);
        let corners = rect_corners(&light).map(|c| c.as_dvec3());
        expected_irradiance +=
            polygon_irradiance(x.as_dvec3(), DVec3::Y, &corners, radiance as f64);
        scene.lights.push(light);
    }
    // The first rectangle, from the builder, was replaced by the five above.
    scene.lights.remove(0);
    for (i, intensity) in [0.05f32, 0.2, 1.0, 3.0, 0.5, 0.1, 2.0]
        .into_iter()
        .enumerate()
    {
        let position = Vec3::new(-2.5 + 0.6 * i as f32, 0.8 + 0.3 * i as f32, 1.0);
        let to = (position - x).as_dvec3();
        expected_irradiance += intensity as f64 * to.y / to.length().powi(3);
        scene.lights.push(Light::Point {
            intensity: Vec3::splat(intensity),
            position,
        });
    }
    let expected = albedo as f64 / PI * expected_irradiance;
    let ray = ray_towards(Vec3::new(0.5, 1.5, 1.5), x);
    let bvh = accel(&scene);
    let alpha = ALPHA / 4.0;
    for (k, rule) in [LightChoiceRule::ByPower, LightChoiceRule::EveryLight]
        .into_iter()
        .enumerate()
    {
        let options = WorldOptions {
            light_choice: rule,
            ..WorldOptions::default()
        };
        let world = World::with_options(&scene, &bvh, options);
        let by_power = matches!(world.lights.choice(), LightChoice::ByPower(_));
        assert_eq!(by_power, rule == LightChoiceRule::ByPower);
        for (j, mis) in [true, false].into_iter().enumerate() {
            let direct = DirectStrategy::Lights(DirectLights {
                samples_per_light: 2,
                environment_samples: None,
                mis,
            });
            let seed = 500 + 10 * k as u64 + j as u64;
            let est = estimate(&world, &tracer(direct, 1, false), &ray, 100_000, seed);
            assert_mean_matches(&format!("{rule:?}, MIS {mis}"), est, expected, alpha, 0.0);
        }
    }
    let auto = World::new(&scene, &bvh);
    assert!(matches!(auto.lights.choice(), LightChoice::ByPower(_)));
}
