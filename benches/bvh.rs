//! Criterion benchmarks of the BVH: build, and closest-hit traversal of the
//! throughput benchmark's ray sets (see `docs/03-bvh.md`).
//!
//! `cargo bench --bench bvh`

use criterion::{criterion_group, criterion_main, BatchSize, Criterion, Throughput};
use pathtracer::bvh::throughput::{primary_rays, random_rays};
use pathtracer::bvh::BvhAccel;
use pathtracer::intersect::{Intersector, Primitives};
use pathtracer::scene::builtin::bumpy_sphere;

fn build(c: &mut Criterion) {
    let mut group = c.benchmark_group("build");
    group.sample_size(10);
    for (phi, theta) in [(256, 128), (1024, 512)] {
        let primitives = Primitives::from_scene(&bumpy_sphere(phi, theta));
        group.throughput(Throughput::Elements(primitives.len() as u64));
        group.bench_function(
            format!("bumpy sphere {} triangles", primitives.len()),
            |b| b.iter_batched(|| primitives.clone(), BvhAccel::new, BatchSize::LargeInput),
        );
    }
    group.finish();
}

fn traverse(c: &mut Criterion) {
    let accel = BvhAccel::new(Primitives::from_scene(&bumpy_sphere(1024, 512)));
    let mut group = c.benchmark_group("closest hit, 1M triangles");
    for (name, rays) in [
        ("primary", primary_rays(256)),
        ("random", random_rays(1 << 16)),
    ] {
        group.throughput(Throughput::Elements(rays.len() as u64));
        group.bench_function(name, |b| {
            b.iter(|| rays.iter().filter(|r| accel.intersect(r).is_some()).count())
        });
    }
    group.finish();
}

criterion_group!(benches, build, traverse);
criterion_main!(benches);
