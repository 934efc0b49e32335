//! `--course-exact`, the image a correct course solution renders
//! ([`pathtracer::course`]): its path tracer written as the starter's
//! functions agrees with the project's path tracer given the course's
//! choices, in every colour channel; what it does differently (the lamp
//! `-H` sees, the 3-2 lamp quads) against closed forms.
//!
//! Fixed seeds; each test's comparisons share [`ALPHA`] = 1e-4
//! (Bonferroni), so a correct renderer fails a test less than once in 10^4
//! seeds.

mod common;

use std::f64::consts::PI;

use common::*;
use glam::{DVec3, Vec3};
use pathtracer::course::{Assignment, Choices, CourseExact, Lamps, StarterDirect, StarterTracer};
use pathtracer::direct::DirectLights;
use pathtracer::global::{DirectStrategy, PathTracer, Roulette};
use pathtracer::intersect::Ray;
use pathtracer::math::Rgb;
use pathtracer::mistakes::Mistakes;
use pathtracer::sampling::IndependentSampler;
use pathtracer::scene::{builtin, Light, Material, Scene};
use pathtracer::world::World;

/// Mean and standard error of each channel of `n` radiance estimates, one
/// random stream seeded by `seed`.
fn channels(
    n: usize,
    seed: u64,
    mut radiance: impl FnMut(&mut IndependentSampler) -> Rgb,
) -> [MeanEstimate; 3] {
    let mut rng = IndependentSampler::from_stream(seed, 0);
    let samples: Vec<Rgb> = (0..n)
        .map(|_| {
            let l = radiance(&mut rng);
            assert!(l.is_finite(), "non-finite radiance {l}");
            l
        })
        .collect();
    [0, 1, 2].map(|c| MeanEstimate::of(samples.iter().map(|l| l[c] as f64)))
}

const THREE_ONE: CourseExact = CourseExact {
    assignment: Assignment::PathTracer1,
};

fn starter(direct: StarterDirect, max_depth: u32, accumulate: bool, lamps: Lamps) -> StarterTracer {
    StarterTracer {
        direct,
        light_samples: 1,
        max_depth,
        accumulate,
        lamps,
        choices: Choices::of(Assignment::PathTracer1),
        mistakes: Mistakes::NONE,
    }
}

/// The built-in Cornell box (red and blue walls, a yellow sphere, an area
/// light with its lamp mesh) under the course's world options: the
/// starter's functions ([`StarterTracer`]) and the project's path tracer
/// with light sampling alone and the course's roulette give the same
/// radiance in each channel, along rays to the floor, the red wall and the
/// yellow sphere, at `-m 5 -o 1`, `-m 3 -o 0` and `-m 1`. Nine two-sample
/// z-tests per setting. Checked with the catalogue's mistakes in the
/// starter's functions: `roulette-not-divided` fails (`-m 5`, ray 0, red,
/// by 45 standard errors), and so does `o0-accumulates` (`-m 3 -o 0`, by
/// 870).
#[test]
fn the_starters_functions_agree_with_the_project_given_the_courses_choices() {
    let scene = builtin::cornell_box();
    let bvh = accel(&scene);
    let world = World::with_options(&scene, &bvh, THREE_ONE.world_options());
    let eye = Vec3::new(0.0, 0.75, 4.8);
    let rays = [
        ray_towards(eye, Vec3::new(0.1, 0.0, 0.2)),
        ray_towards(eye, Vec3::new(-1.0, 0.9, -0.5)),
        ray_towards(eye, Vec3::new(-0.45, 0.35, -0.05)),
    ];
    let settings = [(5, true), (3, false), (1, true)];
    let alpha = ALPHA / (settings.len() * rays.len() * 3) as f64;
    for (s, &(max_depth, accumulate)) in settings.iter().enumerate() {
        let ours = PathTracer {
            direct: DirectStrategy::Lights(DirectLights {
                samples_per_light: 1,
                environment_samples: None,
                mis: false,
            }),
            max_depth,
            accumulate,
            roulette: Roulette::Fixed,
            glass_splits: 0,
        };
        let theirs = starter(
            StarterDirect::Importance,
            max_depth,
            accumulate,
            Lamps::MeshFaces,
        );
        for (r, ray) in rays.iter().enumerate() {
            let seed = 1000 * s as u64 + 10 * r as u64;
            let a = channels(60_000, seed, |rng| ours.radiance(&world, ray, rng));
            let b = channels(60_000, seed + 1, |rng| theirs.radiance(&world, ray, rng));
            for c in 0..3 {
                let label = format!(
                    "-m {max_depth} -o {}, ray {r}, channel {c}",
                    u8::from(accumulate)
                );
                assert_means_agree(&label, a[c], b[c], alpha);
            }
        }
    }
}

/// A floor under an area light whose lamp mesh is the light's rectangle
/// turned by 90 degrees (as in the course's boxes), both of radiance 3.
fn floor_under_a_turned_lamp(with_mesh: bool) -> (Scene, Light, [Vec3; 4]) {
    let centre = Vec3::new(-0.2, 0.5, 0.1);
    let light = rect_light(3.0, centre, -Vec3::Y, 1.2, 0.2);
    let corners = rect_corners(&light);
    // The same rectangle turned a quarter turn about the vertical.
    let turned = corners.map(|c| {
        let d = c - centre;
        centre + Vec3::new(-d.z, d.y, d.x)
    });
    let mut b = SceneBuilder::new();
    let floor = b.material(diffuse(0.6));
    b.floor(floor, 3.0);
    if with_mesh {
        let lamp = b.material(Material::Emission {
            radiance: Vec3::splat(3.0),
        });
        b.quad(lamp, turned);
    }
    b.light(light);
    (b.finish(), light, turned)
}

/// The course's `-H` sees what geometry emits, not the area light, which
/// is no geometry in the course: at a floor point under a lamp mesh turned
/// against its light, the starter's hemisphere estimate is `a / pi E` with
/// `E` the turned mesh's irradiance (Lambert's polygon formula), not the
/// light's; without the mesh it is black. The project's `-H` sees the
/// light itself: the two closed forms differ by 60 % here, over 100
/// standard errors of either estimate, so an estimator that saw the
/// light instead of the mesh would fail.
#[test]
fn the_courses_hemisphere_estimator_sees_the_lamp_mesh() {
    let x = Vec3::new(0.4, 0.0, 0.1);
    let ray = ray_towards(Vec3::new(0.5, 0.6, 0.8), x);
    let hemisphere = starter(StarterDirect::Hemisphere, 1, true, Lamps::MeshFaces);
    let (scene, light, turned) = floor_under_a_turned_lamp(true);
    let bvh = accel(&scene);
    let world = World::with_options(&scene, &bvh, THREE_ONE.world_options());
    let irradiance = |corners: [Vec3; 4]| {
        polygon_irradiance(x.as_dvec3(), DVec3::Y, &corners.map(|c| c.as_dvec3()), 3.0)
    };
    let mesh = 0.6 / PI * irradiance(turned);
    let rect = 0.6 / PI * irradiance(rect_corners(&light));
    eprintln!("mesh {mesh:.5}, light {rect:.5}");
    assert!(
        (mesh - rect).abs() > 0.05 * rect,
        "the test cannot tell them apart"
    );
    let seen = channels(200_000, 7, |rng| hemisphere.radiance(&world, &ray, rng));
    assert_mean_matches("-H, the course's", seen[1], mesh, ALPHA / 3.0, 0.0);

    let ours = PathTracer {
        direct: DirectStrategy::Hemisphere(pathtracer::direct::DirectHemisphere { samples: 1 }),
        max_depth: 1,
        accumulate: true,
        roulette: Roulette::Off,
        glass_splits: 0,
    };
    let project = channels(200_000, 8, |rng| ours.radiance(&world, &ray, rng));
    assert_mean_matches("-H, the project's", project[1], rect, ALPHA / 3.0, 0.0);

    let (dark, _, _) = floor_under_a_turned_lamp(false);
    let bvh = accel(&dark);
    let world = World::with_options(&dark, &bvh, THREE_ONE.world_options());
    let black = channels(1_000, 9, |rng| hemisphere.radiance(&world, &ray, rng));
    assert_eq!(black[1].mean, 0.0, "-H without a lamp mesh");
}

/// Assignment 3-2's lamps: the camera sees each area light as its own quad
/// emitting `L / A max(0, n . wo)`, and the lamp mesh emits nothing (the
/// 3-2 starter's `AreaLight` constructor, measured on the built starter);
/// 3-1's camera sees the mesh.
#[test]
fn the_3_2_lamps_are_the_lights_own_quads() {
    let (scene, light, _) = floor_under_a_turned_lamp(true);
    let Light::Area { dim_x, dim_y, .. } = light else {
        unreachable!()
    };
    let area = dim_x.length() * dim_y.length();
    let bvh = accel(&scene);
    let exact = CourseExact {
        assignment: Assignment::PathTracer2,
    };
    let world = World::with_options(&scene, &bvh, exact.world_options());
    // From below, through the middle of the lamp, 40 degrees off vertical.
    let target = Vec3::new(-0.2, 0.5, 0.1);
    let dir = Vec3::new(40f32.to_radians().sin(), 40f32.to_radians().cos(), 0.0);
    let ray = Ray::new(target - 0.5 * dir, dir);
    let camera_only = |lamps| starter(StarterDirect::Importance, 0, true, lamps);
    let quad = channels(10, 1, |rng| {
        camera_only(Lamps::LightQuads).radiance(&world, &ray, rng)
    });
    let expected = 3.0 / area as f64 * 40f64.to_radians().cos();
    assert!(
        (quad[0].mean - expected).abs() < 1e-4 * expected,
        "3-2 lamp: {} against L / A cos = {expected}",
        quad[0].mean
    );
    let mesh = channels(10, 2, |rng| {
        camera_only(Lamps::MeshFaces).radiance(&world, &ray, rng)
    });
    assert_eq!(mesh[0].mean, 3.0, "3-1 lamp: the mesh's radiance");
    // From above the quad emits nothing, and the mesh is dark in 3-2.
    let above = Ray::new(target + 0.5 * dir, -dir);
    let back = channels(10, 3, |rng| {
        camera_only(Lamps::LightQuads).radiance(&world, &above, rng)
    });
    assert_eq!(back[0].mean, 0.0, "3-2 lamp from behind");
}
