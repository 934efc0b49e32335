//! Glint samples (`pathtracer::glints`): the pixels that may see a small,
//! bright part of an environment map along mirror and glass bounces take
//! more samples. The allocation goes where the sun's glint is and
//! nowhere under a map without one; it changes each pixel's number of
//! samples, never the image's expectation (a two-sample z-test over
//! seeds), and lowers the error where the glint is.
//!
//! The statistical tests use fixed seeds at [`ALPHA`] = 1e-4 per test
//! (the policy is in `tests/common/stats.rs`).

mod common;

use common::{
    accel, assert_means_agree, diffuse, image_mean, tracer, MeanEstimate, SceneBuilder, ALPHA,
    GLASS,
};
use glam::Vec3;
use pathtracer::bvh::BvhAccel;
use pathtracer::cli::drivers::render_lighting_allocated;
use pathtracer::environment::{EnvironmentLight, EnvironmentMap, EnvironmentSampling};
use pathtracer::glints::pilot::chain_leaves;
use pathtracer::glints::{allocate, Allocation, MAX_FACTOR, PILOT_OFFSETS};
use pathtracer::intersect::{Intersector, Ray};
use pathtracer::math::luminance;
use pathtracer::raygen::Camera;
use pathtracer::render::{pixel_ray, RenderSettings, Rendered};
use pathtracer::sampling::SamplerKind;
use pathtracer::scene::{Material, Scene};
use pathtracer::world::World;

use common::LIGHTS;

const SIZE: (u32, u32) = (40, 30);
const SPHERE_CENTER: Vec3 = Vec3::new(0.0, 0.5, 0.0);
const SPHERE_RADIUS: f32 = 0.5;

const MIRROR: Material = Material::Mirror {
    reflectance: Vec3::ONE,
};

/// The sun's direction and angular radius (4 degrees), and its radiance
/// against the sky's 0.5.
const SUN_RADIANCE: f32 = 300.0;
fn sun() -> Vec3 {
    Vec3::new(0.6, 0.5, 0.4).normalize()
}

/// A sky of 0.5 with a sun of 4 degrees' radius.
fn sun_map() -> EnvironmentMap {
    let cos_radius = 4f32.to_radians().cos();
    EnvironmentMap::from_fn("sun", 256, 128, |d| {
        Vec3::splat(if d.dot(sun()) >= cos_radius {
            SUN_RADIANCE
        } else {
            0.5
        })
    })
    .unwrap()
}

/// A mirror ball on a diffuse floor.
fn ball_on_a_floor() -> Scene {
    let mut b = SceneBuilder::new();
    let floor = b.material(diffuse(0.5));
    let mirror = b.material(MIRROR);
    b.floor(floor, 3.0)
        .sphere(SPHERE_CENTER, SPHERE_RADIUS, mirror);
    b.finish()
}

fn camera() -> Camera {
    Camera::look_at(Vec3::new(0.0, 1.0, 2.2), SPHERE_CENTER, Vec3::Y, 40.0, 30.0)
}

fn settings(spp: u32, seed: u64) -> RenderSettings {
    RenderSettings {
        width: SIZE.0,
        height: SIZE.1,
        samples_per_pixel: spp,
        threads: Some(2),
        seed,
        sampler: SamplerKind::ZSobol,
        progress: false,
    }
}

fn world_under<'a>(
    scene: &'a Scene,
    bvh: &'a BvhAccel,
    map: EnvironmentMap,
) -> World<'a, &'a BvhAccel> {
    World::new(scene, bvh).with_environment(Some(EnvironmentLight::new(
        map,
        EnvironmentSampling::Importance,
    )))
}

/// The pixel whose centre sees the sun in the ball: where the ball's
/// normal halves the angle between the eye and the sun.
fn glint_pixel(world: &World<&BvhAccel>) -> (u32, u32) {
    let eye = camera().position;
    let mut best = ((0, 0), f32::MIN);
    for y in 0..SIZE.1 {
        for x in 0..SIZE.0 {
            let ray = pixel_ray(
                &camera(),
                SIZE,
                (x, y),
                glam::Vec2::splat(0.5),
                glam::Vec2::splat(0.5),
            );
            if let Some(hit) = world.intersector.intersect(&ray) {
                let n = (hit.p - SPHERE_CENTER).normalize();
                if (hit.p - SPHERE_CENTER).length() < SPHERE_RADIUS * 1.01 {
                    let half = ((eye - hit.p).normalize() + sun()).normalize();
                    if n.dot(half) > best.1 {
                        best = ((x, y), n.dot(half));
                    }
                }
            }
        }
    }
    best.0
}

/// The allocation under the sun: factors are powers of four up to
/// [`MAX_FACTOR`], the extra samples' cost at most half of the render's, the
/// pixel of the sun's glint in the ball among those with more, and every
/// pixel with more sees the ball (the floor and the sky have no chain of
/// mirror bounces). Under the same sky without its sun, and with no map,
/// every pixel takes `-s`.
#[test]
fn samples_go_to_the_glint_and_only_there() {
    let scene = ball_on_a_floor();
    let bvh = accel(&scene);
    let world = world_under(&scene, &bvh, sun_map());
    let a = allocate(&world, &camera(), &settings(16, 0), 5);
    assert_eq!(a.factors.len(), (SIZE.0 * SIZE.1) as usize);
    // Powers of four, to keep ZSobol's nets.
    assert!(a
        .factors
        .iter()
        .all(|k| k.is_power_of_two() && k.trailing_zeros() % 2 == 0 && *k <= MAX_FACTOR));
    assert!(a.extra_cost <= 0.5, "{}", a.extra_cost);
    let (gx, gy) = glint_pixel(&world);
    let at = |x: u32, y: u32| a.factors[(y * SIZE.0 + x) as usize];
    eprintln!(
        "glint pixel ({gx}, {gy}): factor {}; {} pixels above 1, largest {}, extra {:.3}",
        at(gx, gy),
        a.pixels_above_one(),
        a.largest(),
        a.extra_fraction()
    );
    assert!(at(gx, gy) > 1, "the glint's pixel takes {}", at(gx, gy));
    for y in 0..SIZE.1 {
        for x in 0..SIZE.0 {
            if at(x, y) > 1 {
                let sees_ball = PILOT_OFFSETS.iter().any(|&offset| {
                    let ray = pixel_ray(&camera(), SIZE, (x, y), offset, glam::Vec2::splat(0.5));
                    world
                        .intersector
                        .intersect(&ray)
                        .is_some_and(|h| (h.p - SPHERE_CENTER).length() < SPHERE_RADIUS * 1.01)
                });
                assert!(
                    sees_ball,
                    "pixel ({x}, {y}) takes {} but does not see the ball",
                    at(x, y)
                );
            }
        }
    }
    let sky = EnvironmentMap::from_fn("sky", 256, 128, |_| Vec3::splat(0.5)).unwrap();
    let uniform = allocate(
        &world_under(&scene, &bvh, sky),
        &camera(),
        &settings(16, 0),
        5,
    );
    assert_eq!((uniform.largest(), uniform.pixels_above_one()), (1, 0));
    let dark = allocate(&World::new(&scene, &bvh), &camera(), &settings(16, 0), 5);
    assert_eq!((dark.largest(), dark.pixels_above_one()), (1, 0));
}

fn render(world: &World<&BvhAccel>, allocation: Option<&Allocation>, seed: u64) -> Rendered {
    let tracer = tracer(LIGHTS, 5, false);
    render_lighting_allocated(
        world,
        &tracer,
        &camera(),
        &settings(16, seed),
        None,
        allocation,
    )
}

/// Each pixel takes its factor times `-s` samples; over 40 seeds the
/// mean luminance with and without glint samples agrees, over the image
/// and over the pixels that take more (two-sample z-tests); and the variance over the seeds of the pixels
/// that take more is less than half without (233 against 0.56 when
/// written, with factors of two and eight then allowed).
#[test]
fn glint_samples_change_the_variance_not_the_mean() {
    let scene = ball_on_a_floor();
    let bvh = accel(&scene);
    let world = world_under(&scene, &bvh, sun_map());
    let a = allocate(&world, &camera(), &settings(16, 0), 5);
    let seeds = 40;
    let (mut plain, mut allocated) = (Vec::new(), Vec::new());
    for seed in 0..seeds {
        plain.push(render(&world, None, 1000 + seed));
        allocated.push(render(&world, Some(&a), 2000 + seed));
    }
    for (e, k) in allocated[0].estimates.iter().zip(&a.factors) {
        assert_eq!(e.samples, 16 * k);
    }
    assert!(plain[0].estimates.iter().all(|e| e.samples == 16));
    let means = |renders: &[Rendered]| MeanEstimate::of(renders.iter().map(image_mean));
    // The mean over the pixels that take more alone: a bias there would
    // not be diluted by the rest of the image.
    let more: Vec<usize> = (0..a.factors.len()).filter(|&i| a.factors[i] > 1).collect();
    let where_more = |renders: &[Rendered]| {
        MeanEstimate::of(renders.iter().map(|r| {
            more.iter()
                .map(|&i| luminance(r.film.pixels[i]) as f64)
                .sum::<f64>()
                / more.len() as f64
        }))
    };
    for (what, without, with) in [
        ("the image", means(&plain), means(&allocated)),
        (
            "the pixels with more samples",
            where_more(&plain),
            where_more(&allocated),
        ),
    ] {
        eprintln!(
            "mean over {what}: without {:.5} +- {:.5}, with {:.5} +- {:.5}",
            without.mean, without.se, with.mean, with.se
        );
        let label = format!("mean over {what}, without and with glint samples");
        assert_means_agree(&label, without, with, ALPHA / 3.0);
    }
    let variance_where_more = |renders: &[Rendered]| -> f64 {
        let mut total = 0.0;
        for (i, k) in a.factors.iter().enumerate() {
            if *k > 1 {
                let values = renders.iter().map(|r| luminance(r.film.pixels[i]) as f64);
                total += MeanEstimate::of(values).se.powi(2) * seeds as f64;
            }
        }
        total
    };
    let (v0, v1) = (variance_where_more(&plain), variance_where_more(&allocated));
    eprintln!("variance over the pixels with more samples: without {v0:.4}, with {v1:.4}");
    assert!(v1 < 0.5 * v0, "{v1} against {v0}");
}

/// The render's time counts the pilot's: a render given an allocation
/// whose pilot took an hour reports at least the hour and the render
/// besides, and without one only the render.
#[test]
fn the_render_time_counts_the_pilot() {
    let scene = ball_on_a_floor();
    let bvh = accel(&scene);
    let world = world_under(&scene, &bvh, sun_map());
    let mut a = allocate(&world, &camera(), &settings(16, 0), 5);
    let hour = 3600.0;
    a.seconds = hour;
    let alone = render(&world, None, 0).stats.seconds;
    let with_pilot = render(&world, Some(&a), 0).stats.seconds;
    assert!(alone < hour, "{alone}");
    assert!(with_pilot > hour && with_pilot < 2.0 * hour, "{with_pilot}");
}

/// The pilot's chains: a camera ray straight at the mirror ball's top
/// escapes once, reflected, with the mirror's weight; one at the floor
/// ends there (a diffuse surface) without a leaf, and one at the sky
/// has no bounce and no leaf; a glass ball forks: its leaves' weights
/// sum to at most 1, and more than one leaf escapes.
#[test]
fn the_pilot_follows_mirror_and_glass_chains_to_the_sky() {
    let scene = ball_on_a_floor();
    let bvh = accel(&scene);
    let world = world_under(&scene, &bvh, sun_map());
    let from = Vec3::new(0.3, 3.0, 0.2);
    let top = SPHERE_CENTER + Vec3::Y * SPHERE_RADIUS;
    let ray = Ray::new(from, (top - from).normalize());
    let leaves: Vec<_> = chain_leaves(&world, &ray, 5).iter().copied().collect();
    assert_eq!(leaves.len(), 1, "{leaves:?}");
    let n = Vec3::Y;
    let reflected = ray.dir - 2.0 * ray.dir.dot(n) * n;
    assert!(leaves[0].dir.dot(reflected) > 0.9999, "{:?}", leaves[0]);
    assert!((leaves[0].weight - 1.0).abs() < 1e-5 && leaves[0].key == 0b10);
    let floor = Ray::new(from, (Vec3::new(2.0, 0.0, 2.0) - from).normalize());
    let on_floor = chain_leaves(&world, &floor, 5);
    assert_eq!((on_floor.iter().count(), on_floor.scattered), (0, 1));
    let sky = chain_leaves(&world, &Ray::new(from, Vec3::Y), 5);
    assert_eq!((sky.iter().count(), sky.rays), (0, 1));

    let mut b = SceneBuilder::new();
    let glass = b.material(GLASS);
    b.sphere(SPHERE_CENTER, SPHERE_RADIUS, glass);
    let glass_scene = b.finish();
    let glass_bvh = accel(&glass_scene);
    let glass_world = world_under(&glass_scene, &glass_bvh, sun_map());
    let off_centre = SPHERE_CENTER + Vec3::new(0.2, 0.1, 0.0);
    let ray = Ray::new(from, (off_centre - from).normalize());
    let leaves = chain_leaves(&glass_world, &ray, 8);
    let total: f32 = leaves.iter().map(|l| l.weight).sum();
    eprintln!(
        "glass: {} leaves, weights summing to {total}",
        leaves.iter().count()
    );
    assert!(leaves.iter().count() > 1 && total <= 1.0 + 1e-4 && total > 0.5);
}

/// Runs `binary` with `args`: whether it succeeded, its stdout and stderr.
fn run(binary: &str, args: &[&str]) -> (bool, String, String) {
    let out = std::process::Command::new(binary)
        .args(args)
        .output()
        .unwrap();
    let text = |b: &[u8]| String::from_utf8_lossy(b).into_owned();
    (out.status.success(), text(&out.stdout), text(&out.stderr))
}

/// `--info` says whether glint samples are on: on for a mirror ball under
/// the built-in sky (`part7-environment` with a scene of the project's
/// own) at `-s 16`, off at the default `-s 1`, with `--glints off` or
/// `--course`, and for the default box (no map) (`-a` is the plan's
/// test's: `part7-environment` has no adaptive sampling); `--course --glints off` is refused as a conflict.
#[test]
fn info_names_the_glint_samples() {
    let part7 = env!("CARGO_BIN_EXE_part7-environment");
    let (dir, name) = (tempfile::tempdir().unwrap(), "mirror_ball.dae");
    let scene = dir.path().join(name);
    // The test scene with its red material (the ball's) a mirror.
    let mirror = common::corrupt(
        "<technique sid=\"common\"><phong>\n      <diffuse><color>0.7 0.1 0.1 1</color></diffuse></phong></technique></profile_COMMON>",
        "</profile_COMMON><extra><technique profile=\"CGL\"><mirror><reflectance>1 1 1</reflectance></mirror></technique></extra>",
    );
    std::fs::write(&scene, mirror).unwrap();
    let scene = scene.to_str().unwrap();
    let glints = |binary: &str, flags: &[&str]| {
        let mut args = vec!["--info"];
        args.extend(flags);
        let (ok, stdout, stderr) = run(binary, &args);
        assert!(ok, "{flags:?}: {stderr}");
        let line = stdout
            .lines()
            .find_map(|l| l.strip_prefix("plan: glint samples: "));
        line.expect("a glint samples line")
            .split(' ')
            .next()
            .unwrap()
            .to_string()
    };
    assert_eq!(glints(part7, &["-s", "16", scene]), "on:");
    // The default -s 1: off, the pilot would cost more than it buys.
    assert_eq!(glints(part7, &[scene]), "off");
    assert_eq!(
        glints(part7, &["-s", "16", "--glints", "off", scene]),
        "off"
    );
    assert_eq!(glints(part7, &["-s", "16", "--course", scene]), "off");
    assert_eq!(glints(env!("CARGO_BIN_EXE_pathtracer"), &[]), "off");
    let (ok, _, stderr) = run(part7, &["--info", "--course", "--glints", "off", scene]);
    assert!(!ok && stderr.contains("--glints"), "{stderr}");
}
