//! The furnace test: inside a closed box whose walls reflect diffusely with
//! albedo `a` and emit `Le`, radiance is the same everywhere and in every
//! direction. Each bounce adds the walls' emission attenuated once more by
//! `a`, so a path tracer with at most `m` bounces must give
//!
//! ```text
//! L_m = Le (1 + a + a^2 + ... + a^m) = Le (1 - a^(m+1)) / (1 - a)  ->  Le / (1 - a)
//! ```
//!
//! With cosine-weighted sampling of a diffuse BSDF, `f cos / pdf = a`
//! exactly; the noise comes from sampling the glowing walls (as lights, or
//! by hemisphere rays) and from Russian roulette, and a confidence interval
//! absorbs it.

use glam::Vec3;
use pathtracer::bvh::BvhAccel;
use pathtracer::direct::{DirectHemisphere, DirectLights, SceneTracer};
use pathtracer::global::{DirectStrategy, PathTracer};
use pathtracer::intersect::{Primitives, Ray};
use pathtracer::math::rng::{next_2d, sampler};
use pathtracer::math::warp::sample_uniform_sphere;
use pathtracer::scene::normals::area_weighted_vertex_normals;
use pathtracer::scene::{Material, Scene, TriangleMesh};

/// Half-width multiplier of the confidence intervals: two-sided p = 6.8e-6
/// per comparison; the file makes 8 comparisons with noise, so a correct
/// path tracer fails it with probability below 6e-5.
const Z: f64 = 4.5;

/// A closed unit cube of 12 triangles with one material. Each face has its
/// own four vertices, so the course's rebuilt vertex normals are the face
/// normals: shared corners would average three faces' normals, and a
/// direction sampled around such a smoothed normal can leave through the
/// wall, which is not what a Lambertian box does.
fn furnace(albedo: f32, radiance: f32) -> Scene {
    let corner = |i: u32| Vec3::new((i & 1) as f32, ((i >> 1) & 1) as f32, ((i >> 2) & 1) as f32);
    let faces = [
        [0, 1, 3, 2],
        [4, 6, 7, 5],
        [0, 4, 5, 1],
        [2, 3, 7, 6],
        [0, 2, 6, 4],
        [1, 5, 7, 3],
    ];
    let corners: Vec<Vec3> = faces.iter().flatten().map(|&i| corner(i)).collect();
    let triangles: Vec<[u32; 3]> = (0..6u32)
        .flat_map(|f| [[4 * f, 4 * f + 1, 4 * f + 2], [4 * f, 4 * f + 2, 4 * f + 3]])
        .collect();
    let normals = area_weighted_vertex_normals(&corners, &triangles);
    Scene {
        source: "furnace".into(),
        mesh: TriangleMesh {
            materials: vec![0; triangles.len()],
            positions: corners,
            normals,
            triangles,
        },
        materials: vec![Material::EmissiveDiffuse {
            albedo: Vec3::splat(albedo),
            radiance: Vec3::splat(radiance),
        }],
        ..Scene::default()
    }
}

/// Mean and standard error of `n` camera rays from inside the box.
fn estimate(scene: &Scene, tracer: &PathTracer, n: usize, seed: u64) -> (f64, f64) {
    let accel = BvhAccel::new(Primitives::from_scene(scene));
    let view = SceneTracer::new(scene, &accel);
    let mut rng = sampler(seed, 0);
    let (mut s1, mut s2) = (0.0f64, 0.0f64);
    for _ in 0..n {
        let origin = Vec3::new(0.3, 0.6, 0.45);
        let ray = Ray::new(origin, sample_uniform_sphere(next_2d(&mut rng)));
        let x = tracer.radiance(&view, &ray, &mut rng).x as f64;
        s1 += x;
        s2 += x * x;
    }
    let mean = s1 / n as f64;
    let variance = ((s2 - s1 * s1 / n as f64) / (n as f64 - 1.0)).max(0.0);
    (mean, (variance / n as f64).sqrt())
}

fn geometric_sum(albedo: f64, radiance: f64, max_depth: u32) -> f64 {
    radiance * (1.0 - albedo.powi(max_depth as i32 + 1)) / (1.0 - albedo)
}

fn strategies() -> [(&'static str, DirectStrategy); 2] {
    [
        (
            "light sampling",
            DirectStrategy::Lights(DirectLights {
                samples_per_light: 1,
            }),
        ),
        (
            "hemisphere sampling",
            DirectStrategy::Hemisphere(DirectHemisphere { samples: 1 }),
        ),
    ]
}

#[test]
fn furnace_without_russian_roulette_sums_m_bounces() {
    for (albedo, max_depth) in [(0.5, 12), (0.8, 30)] {
        let scene = furnace(albedo as f32, 1.0);
        let expected = geometric_sum(albedo, 1.0, max_depth);
        for (name, direct) in strategies() {
            let tracer = PathTracer {
                direct,
                max_depth,
                accumulate: true,
                russian_roulette: false,
            };
            let (mean, se) = estimate(&scene, &tracer, 4000, 7);
            let tolerance = Z * se + 1e-4 * expected;
            assert!(
                (mean - expected).abs() <= tolerance,
                "{name}, a = {albedo}, m = {max_depth}: {mean} ± {se}, expected {expected}"
            );
        }
    }
}

#[test]
fn furnace_with_russian_roulette_reaches_le_over_one_minus_a() {
    for albedo in [0.5, 0.8] {
        let scene = furnace(albedo as f32, 1.0);
        // a^(m+1) is below 1e-19 at m = 200: the sum is the infinite one.
        let expected = 1.0 / (1.0 - albedo);
        for (name, direct) in strategies() {
            let tracer = PathTracer {
                direct,
                max_depth: 200,
                accumulate: true,
                russian_roulette: true,
            };
            let (mean, se) = estimate(&scene, &tracer, 20_000, 11);
            assert!(se > 0.0, "Russian roulette adds noise");
            assert!(
                (mean - expected).abs() <= Z * se,
                "{name}, a = {albedo}: {mean} ± {se}, expected {expected}"
            );
        }
    }
}

#[test]
fn only_the_m_th_bounce_with_o_0() {
    let (albedo, max_depth) = (0.8f64, 5);
    let scene = furnace(albedo as f32, 1.0);
    let expected = albedo.powi(max_depth as i32);
    for (name, direct) in strategies() {
        let tracer = PathTracer {
            direct,
            max_depth,
            accumulate: false,
            russian_roulette: false,
        };
        let (mean, se) = estimate(&scene, &tracer, 4000, 13);
        assert!(
            (mean - expected).abs() <= Z * se + 1e-4 * expected,
            "{name}: {mean} ± {se}, expected {expected}"
        );
    }
}
