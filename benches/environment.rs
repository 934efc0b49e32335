//! Criterion benchmarks of the environment light: what one light sample,
//! one density and one escaped ray's lookup cost, per map, at random (the
//! access pattern of a render, where each path's directions are unrelated
//! to the last path's). See `docs/10-performance.md`.
//!
//! `cargo bench --bench environment`
//!
//! Maps (all the project's own, made in code): the built-in sky (512 x 256,
//! 2 degree sun), the same sky at 2k (2048 x 1024), a 2k sky with a sun of
//! the real sun's size (a few texels across), and a 4k one (4096 x 2048)
//! black below the horizon.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use glam::{Vec2, Vec3};
use pathtracer::environment::sky::Sky;
use pathtracer::environment::{EnvironmentLight, EnvironmentSampling};
use pathtracer::math::rng::{next_2d, sampler};
use pathtracer::math::warp::sample_uniform_sphere;

/// Points per timed loop: far more than the caches hold of a 2k map's
/// tables, so that each access lands where the last one did not.
const POINTS: usize = 1 << 16;

fn maps() -> Vec<(&'static str, EnvironmentLight)> {
    let real_sun = 0.27f32.to_radians();
    let black_ground = Sky {
        ground: Vec3::ZERO,
        ..Sky::default()
    };
    [
        ("sky 512", Sky::default(), 256),
        ("sky 2k", Sky::default(), 1024),
        (
            "real sun 2k",
            Sky::default().with_sun_radius(real_sun),
            1024,
        ),
        (
            "real sun 4k, black ground",
            black_ground.with_sun_radius(real_sun),
            2048,
        ),
    ]
    .into_iter()
    .map(|(name, sky, height)| {
        let map = sky.map(name, height).expect("a sky map is valid");
        (
            name,
            EnvironmentLight::new(map, EnvironmentSampling::Importance),
        )
    })
    .collect()
}

fn environment(c: &mut Criterion) {
    let mut rng = sampler(7, 0);
    let points: Vec<Vec2> = (0..POINTS).map(|_| next_2d(&mut rng)).collect();
    let directions: Vec<Vec3> = points.iter().map(|&u| sample_uniform_sphere(u)).collect();
    for (name, light) in maps() {
        let mut group = c.benchmark_group(format!("environment {name}"));
        group.throughput(Throughput::Elements(POINTS as u64));
        group.sample_size(20);
        group.bench_function("sample_li", |b| {
            b.iter(|| {
                points
                    .iter()
                    .filter_map(|&u| light.sample_li(u))
                    .map(|s| s.radiance.x)
                    .sum::<f32>()
            })
        });
        group.bench_function("pdf_li", |b| {
            b.iter(|| directions.iter().map(|&w| light.pdf_li(w)).sum::<f32>())
        });
        // What a ray escaping to the map pays under MIS: the radiance and
        // the density, from one look-up.
        group.bench_function("escaped", |b| {
            b.iter(|| {
                directions
                    .iter()
                    .map(|&w| {
                        let (radiance, pdf) = light.escaped(w, true);
                        radiance.x + pdf
                    })
                    .sum::<f32>()
            })
        });
        group.bench_function("escaped_radiance", |b| {
            b.iter(|| {
                directions
                    .iter()
                    .map(|&w| light.escaped_radiance(w).x)
                    .sum::<f32>()
            })
        });
        group.finish();
    }
}

criterion_group!(benches, environment);
criterion_main!(benches);
