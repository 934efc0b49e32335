//! The ray-throughput benchmark of `part2-bvh --bench`: three ray sets
//! traced through a BVH (binary or wide: any [`Intersector`]) over the
//! 1,046,528-triangle bumpy sphere
//! ([`crate::scene::builtin::bumpy_sphere`]).
//!
//! - `primary`: a 1024 x 1024 pinhole camera at (0, 0.3, 3.2) looking at
//!   the origin, vertical fov 45 degrees, through pixel centres, in 8 x 8 tiles
//!   (coherent rays).
//! - `random`: 2^20 rays with origins uniform in `[-1.5, 1.5]^3` and
//!   directions uniform on the sphere (incoherent).
//! - `diffuse`: from each primary hit, a direction uniform on the
//!   hemisphere of the normal facing the camera; a primary miss restarts
//!   at `origin + 5 d` with a direction uniform on the sphere.
//!
//! Rate = rays / wall-clock seconds of tracing only (the ray sets are
//! made beforehand). `hit` and `tsum` are checksums that must agree
//! between thread counts.
//!
//! Two queries ([`Query`]): the search for the closest primitive alone
//! ([`Intersector::nearest`]: which primitive, `t` and barycentrics, what
//! Embree's `rtcIntersect1` computes), and the full hit record the
//! renderer asks for ([`Intersector::intersect`]: the search, then the
//! point, its error bound and both normals, which reads the shading
//! record, a second array).

use std::time::Instant;

use glam::Vec3;
use rand::Rng;
use rayon::prelude::*;

use super::{BvhAccel, WideBvhAccel};
use crate::intersect::{Intersector, Primitives, Ray, Shape};
use crate::math::rng::{next_2d, sampler};
use crate::math::warp::{sample_uniform_hemisphere, sample_uniform_sphere};
use crate::math::Frame;
use crate::raygen::Camera;
use crate::scene::builtin::bumpy_sphere;

/// Seed of the benchmark's random ray sets.
const SEED: u64 = 184;

/// One named set of rays.
pub struct RaySet {
    pub name: &'static str,
    pub rays: Vec<Ray>,
}

/// What is asked of each ray.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Query {
    /// [`Intersector::nearest`]: the closest primitive, `t`, `u`, `v`.
    Nearest,
    /// [`Intersector::intersect`]: the same and the full hit record.
    Record,
}

/// The result of tracing one set with one thread count.
#[derive(Clone, Debug)]
pub struct Measurement {
    pub set: &'static str,
    pub query: Query,
    pub threads: usize,
    pub mrays_per_second: f64,
    pub hit_fraction: f64,
    pub t_sum: f64,
}

impl std::fmt::Display for Measurement {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let query = match self.query {
            Query::Nearest => "",
            Query::Record => " with records",
        };
        write!(
            f,
            "{}{query} {}T {:.2} Mrays/s hit {:.4} tsum {:.6e}",
            self.set, self.threads, self.mrays_per_second, self.hit_fraction, self.t_sum
        )
    }
}

/// Builds the benchmark BVH; returns it with the build time in seconds.
pub fn build_benchmark_bvh(phi_steps: u32, theta_steps: u32) -> (BvhAccel, f64) {
    let primitives = Primitives::from_scene(&bumpy_sphere(phi_steps, theta_steps));
    let start = Instant::now();
    let accel = BvhAccel::new(primitives);
    (accel, start.elapsed().as_secs_f64())
}

/// Builds the benchmark's wide BVH ([`WideBvhAccel`]: the binary build,
/// then its collapse); returns it with the times of both, in seconds.
pub fn build_benchmark_wide(phi_steps: u32, theta_steps: u32) -> (WideBvhAccel, [f64; 2]) {
    let primitives = Primitives::from_scene(&bumpy_sphere(phi_steps, theta_steps));
    let start = Instant::now();
    let bvh = super::build::build_from(
        primitives.shapes.iter().map(Shape::bounds),
        &super::wide::accel::binary_options(&primitives),
    );
    let binary = start.elapsed().as_secs_f64();
    let accel = WideBvhAccel::from_binary(&bvh, primitives);
    (accel, [binary, start.elapsed().as_secs_f64() - binary])
}

/// The benchmark camera's rays, `size x size` pixels in 8 x 8 tiles.
pub fn primary_rays(size: u32) -> Vec<Ray> {
    let camera = Camera::look_at(Vec3::new(0.0, 0.3, 3.2), Vec3::ZERO, Vec3::Y, 45.0, 45.0);
    let mut rays = Vec::with_capacity((size * size) as usize);
    for tile_y in (0..size).step_by(8) {
        for tile_x in (0..size).step_by(8) {
            for y in tile_y..(tile_y + 8).min(size) {
                for x in tile_x..(tile_x + 8).min(size) {
                    let u = (x as f32 + 0.5) / size as f32;
                    let v = 1.0 - (y as f32 + 0.5) / size as f32;
                    rays.push(camera.ray(u, v));
                }
            }
        }
    }
    rays
}

/// `count` rays with origins uniform in `[-1.5, 1.5]^3`, directions uniform.
pub fn random_rays(count: usize) -> Vec<Ray> {
    let mut rng = sampler(SEED, 1);
    (0..count)
        .map(|_| {
            let origin = Vec3::new(rng.gen(), rng.gen(), rng.gen()) * 3.0 - 1.5;
            Ray::new(origin, sample_uniform_sphere(next_2d(&mut rng)))
        })
        .collect()
}

/// One diffuse bounce from each primary ray's hit.
pub fn diffuse_rays(accel: &impl Intersector, primary: &[Ray]) -> Vec<Ray> {
    primary
        .par_iter()
        .enumerate()
        .map(|(i, ray)| {
            let mut rng = sampler(SEED, 2 + i as u64);
            let u = next_2d(&mut rng);
            match accel.intersect(ray) {
                Some(hit) => {
                    let n = if hit.ng.dot(ray.dir) < 0.0 {
                        hit.ng
                    } else {
                        -hit.ng
                    };
                    hit.spawn_ray(Frame::from_z(n).to_world(sample_uniform_hemisphere(u)))
                }
                None => Ray::new(ray.at(5.0), sample_uniform_sphere(u)),
            }
        })
        .collect()
}

/// Times of one set are the best of this many runs, so that a brief
/// disturbance by another process does not count.
pub const RUNS: usize = 3;

/// Traces `set` for `query` on a pool of `threads` threads, [`RUNS`]
/// times; reports the fastest run.
pub fn measure(
    accel: &impl Intersector,
    set: &RaySet,
    query: Query,
    threads: usize,
) -> Measurement {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a rayon pool");
    let mut best = f64::INFINITY;
    let mut result = (0, 0.0);
    for _ in 0..RUNS {
        let start = Instant::now();
        result = pool.install(|| trace_all(accel, &set.rays, query));
        best = best.min(start.elapsed().as_secs_f64());
    }
    let (hits, t_sum) = result;
    Measurement {
        set: set.name,
        query,
        threads,
        mrays_per_second: set.rays.len() as f64 / best / 1e6,
        hit_fraction: hits as f64 / set.rays.len() as f64,
        t_sum,
    }
}

/// Number of hits and the sum of their distances.
fn trace_all(accel: &impl Intersector, rays: &[Ray], query: Query) -> (usize, f64) {
    let t = |ray: &Ray| match query {
        Query::Nearest => accel.nearest(ray).map(|found| found.hit.t),
        Query::Record => accel.intersect(ray).map(|hit| hit.t),
    };
    rays.par_chunks(4096)
        .map(|chunk| {
            chunk
                .iter()
                .fold((0usize, 0.0f64), |(n, sum), ray| match t(ray) {
                    Some(t) => (n + 1, sum + t as f64),
                    None => (n, sum),
                })
        })
        .reduce(|| (0, 0.0), |a, b| (a.0 + b.0, a.1 + b.1))
}

/// The three ray sets of the benchmark for `accel`.
pub fn ray_sets(accel: &impl Intersector, primary_size: u32, random_count: usize) -> Vec<RaySet> {
    let primary = primary_rays(primary_size);
    let diffuse = diffuse_rays(accel, &primary);
    vec![
        RaySet {
            name: "primary",
            rays: primary,
        },
        RaySet {
            name: "random",
            rays: random_rays(random_count),
        },
        RaySet {
            name: "diffuse",
            rays: diffuse,
        },
    ]
}
