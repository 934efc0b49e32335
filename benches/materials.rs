//! Criterion benchmarks of the rough conductor: what one BSDF sample and
//! one evaluation (`f` and `pdf` at once) cost, per sampling strategy, for
//! a smooth and a rough lobe seen near the normal and near grazing. The
//! visible normals invert their slope CDF by Newton's method
//! (`materials::beckmann`), which these time. The metal is the built-in
//! scenes' copper. See `docs/10-performance.md`.
//!
//! `cargo bench --bench materials`

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use glam::{Vec2, Vec3};
use pathtracer::materials::{Conductor, MicrofacetSampling};
use pathtracer::math::rng::{next_2d, sampler};
use pathtracer::math::warp::sample_cosine_hemisphere;
use pathtracer::scene::builtin::{COPPER_ETA, COPPER_K};

/// Points per timed loop.
const POINTS: usize = 1 << 14;

fn materials(c: &mut Criterion) {
    let mut rng = sampler(11, 0);
    let points: Vec<Vec2> = (0..POINTS).map(|_| next_2d(&mut rng)).collect();
    let incoming: Vec<Vec3> = points
        .iter()
        .map(|&u| sample_cosine_hemisphere(u))
        .collect();
    for alpha in [0.05f32, 0.3] {
        for cos_o in [0.9f32, 0.2] {
            let wo = Vec3::new((1.0 - cos_o * cos_o).sqrt(), 0.0, cos_o);
            let mut group = c.benchmark_group(format!("conductor alpha {alpha} cos_o {cos_o}"));
            group.throughput(Throughput::Elements(POINTS as u64));
            group.sample_size(20);
            for (name, sampling) in [
                ("half vector", MicrofacetSampling::HalfVector),
                ("visible normals", MicrofacetSampling::VisibleNormals),
                ("auto", MicrofacetSampling::Auto),
            ] {
                let conductor = Conductor::new(alpha, COPPER_ETA, COPPER_K, sampling);
                group.bench_function(format!("sample, {name}"), |b| {
                    b.iter(|| {
                        points
                            .iter()
                            .filter_map(|&u| conductor.sample(wo, u))
                            .map(|s| s.wi.z)
                            .sum::<f32>()
                    })
                });
            }
            let conductor = Conductor::new(alpha, COPPER_ETA, COPPER_K, MicrofacetSampling::Auto);
            group.bench_function("eval", |b| {
                b.iter(|| {
                    incoming
                        .iter()
                        .map(|&wi| {
                            let (f, pdf) = conductor.eval(wo, wi);
                            f.x + pdf
                        })
                        .sum::<f32>()
                })
            });
            group.finish();
        }
    }
}

criterion_group!(benches, materials);
criterion_main!(benches);
