//! The scale benchmark (`cargo bench --bench scale`): build time, memory
//! per triangle and ray rate of the BVH over the benchmark's bumpy sphere
//! ([`crate::scene::builtin::bumpy_sphere`]) from about 10 thousand to
//! 10 million triangles.
//!
//! Each size is measured for the binary BVH (Part 2's) and for the wide
//! one the renderers use ([`super::wide`], collapsed from the same binary
//! tree: its collapse time, bytes and ray rates).
//!
//! Memory is counted exactly from the vectors' capacities (heap bytes,
//! not what the allocator rounds them to), split into the accelerator
//! (nodes and leaf order), the primitives (shapes by id
//! and each triangle's shading record) and the scene's mesh, which a
//! render keeps. The peak resident memory of the whole process is read
//! from the kernel (`VmHWM` in `/proc/self/status`, Linux only); the
//! sizes run in increasing order and everything is freed between them,
//! so the peak after a size is that size's peak.

use std::io::Write;
use std::mem::size_of;
use std::path::Path;
use std::time::Instant;

use glam::Vec3;

use super::throughput::{primary_rays, random_rays, RUNS};
use super::wide::{TrianglePack, WideBvhAccel, WideNode};
use super::{BuildOptions, BvhAccel, Node};
use crate::intersect::{Intersector, Primitives, Ray, Shape};
use crate::scene::builtin::bumpy_sphere;
use crate::scene::export::{write_dae, ExportView};
use crate::scene::{MaterialId, TriangleMesh};

/// Grid sizes `(phi_steps, theta_steps)` of the bumpy sphere for about
/// 10k, 100k, 1M and 10M triangles (`2 phi (theta - 1)` triangles).
pub const SIZES: [(u32, u32); 4] = [(100, 51), (316, 159), (1024, 512), (3236, 1619)];

/// Bytes of a triangle's shading record in [`Primitives`]: three vertex
/// normals and a material id.
pub const SHADING_BYTES: usize = 3 * size_of::<Vec3>() + size_of::<MaterialId>();

/// Heap bytes of one part of the data, and how many triangles they serve.
#[derive(Clone, Copy, Debug, Default)]
pub struct Footprint {
    /// Interior nodes and leaf order.
    pub accel: usize,
    /// Shapes by id and the triangles' shading records.
    pub primitives: usize,
    /// The scene's mesh: positions, normals, vertex indices, materials.
    pub mesh: usize,
}

impl Footprint {
    pub fn of(accel: &BvhAccel, mesh: &TriangleMesh) -> Self {
        let bytes = |capacity: usize, size: usize| capacity * size;
        let triangles = accel
            .primitives
            .shapes
            .iter()
            .filter(|s| matches!(s, Shape::Triangle(_)))
            .count();
        Footprint {
            accel: accel.heap_bytes(),
            primitives: bytes(accel.primitives.shapes.capacity(), size_of::<Shape>())
                + triangles * SHADING_BYTES,
            mesh: bytes(mesh.positions.capacity(), size_of::<Vec3>())
                + bytes(mesh.normals.capacity(), size_of::<Vec3>())
                + bytes(mesh.triangles.capacity(), size_of::<[u32; 3]>())
                + bytes(mesh.materials.capacity(), size_of::<MaterialId>()),
        }
    }
}

impl BvhAccel {
    /// Heap bytes of the accelerator's own vectors (nodes and leaf
    /// order), from their capacities.
    pub fn heap_bytes(&self) -> usize {
        self.bvh.nodes.capacity() * size_of::<Node>() + self.bvh.order.capacity() * size_of::<u32>()
    }
}

impl WideBvhAccel {
    /// Heap bytes of the wide tree's own vectors (nodes and triangle
    /// packs, which hold the triangles' vertices), from their capacities.
    pub fn heap_bytes(&self) -> usize {
        self.wide.nodes.capacity() * size_of::<WideNode>()
            + self.wide.packs.capacity() * size_of::<TrianglePack>()
    }
}

/// The process's peak resident memory in bytes (`VmHWM`), or `None` where
/// the kernel does not say (not Linux).
pub fn peak_resident_bytes() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
}

/// One row of the scale table.
#[derive(Clone, Debug)]
pub struct ScaleRow {
    pub triangles: usize,
    pub build_seconds: f64,
    /// CPU time of the build on the calling thread, where known.
    pub build_cpu_seconds: Option<f64>,
    pub sah_cost: f64,
    pub footprint: Footprint,
    pub peak_bytes: Option<u64>,
    /// Closest-hit rays per second of CPU time on one thread (millions):
    /// 256 x 256 primary rays ([`closest_hit_rate`]).
    pub primary_mrays: f64,
    /// The same for 2^16 random rays.
    pub random_mrays: f64,
    /// The wide BVH collapsed from the same tree: seconds of the collapse,
    /// heap bytes, and the two ray rates.
    pub wide_collapse_seconds: f64,
    pub wide_bytes: usize,
    pub wide_primary_mrays: f64,
    pub wide_random_mrays: f64,
}

impl ScaleRow {
    pub const HEADER: &'static str = "| triangles | build (s) | build CPU (s) | SAH cost | accel B/tri | primitives B/tri | mesh B/tri | peak RSS (MB) | primary (Mrays/s, 1 core) | random (Mrays/s, 1 core) | wide: collapse (s) | wide B/tri | wide primary | wide random |\n| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |";
}

impl std::fmt::Display for ScaleRow {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let per = |bytes: usize| bytes as f64 / self.triangles as f64;
        let peak = match self.peak_bytes {
            Some(b) => format!("{:.0}", b as f64 / 1e6),
            None => "n/a".into(),
        };
        let cpu = match self.build_cpu_seconds {
            Some(s) => format!("{s:.3}"),
            None => "n/a".into(),
        };
        write!(
            f,
            "| {} | {:.3} | {cpu} | {:.2} | {:.1} | {:.1} | {:.1} | {peak} | {:.2} | {:.2} | {:.3} | {:.1} | {:.2} | {:.2} |",
            self.triangles,
            self.build_seconds,
            self.sah_cost,
            per(self.footprint.accel),
            per(self.footprint.primitives),
            per(self.footprint.mesh),
            self.primary_mrays,
            self.random_mrays,
            self.wide_collapse_seconds,
            per(self.wide_bytes),
            self.wide_primary_mrays,
            self.wide_random_mrays,
        )
    }
}

/// Builds the sphere of `phi x theta` steps on the current thread pool and
/// measures one row.
pub fn scale_row(phi_steps: u32, theta_steps: u32) -> ScaleRow {
    let scene = bumpy_sphere(phi_steps, theta_steps);
    let primitives = Primitives::from_scene(&scene);
    let (start, cpu_start) = (Instant::now(), thread_cpu_seconds());
    let accel = BvhAccel::new(primitives);
    let build_seconds = start.elapsed().as_secs_f64();
    let build_cpu_seconds = thread_cpu_seconds().zip(cpu_start).map(|(b, a)| b - a);
    let (primary, random) = (primary_rays(256), random_rays(1 << 16));
    let triangles = accel.primitives.len();
    let sah_cost = accel.bvh.sah_cost(&BuildOptions::default());
    let footprint = Footprint::of(&accel, &scene.mesh);
    let primary_mrays = closest_hit_rate(&accel, &primary);
    let random_mrays = closest_hit_rate(&accel, &random);
    // The wide tree takes the primitives over, as a render's would.
    let BvhAccel { bvh, primitives } = accel;
    let start = Instant::now();
    let wide = WideBvhAccel::from_binary(&bvh, primitives);
    let wide_collapse_seconds = start.elapsed().as_secs_f64();
    drop(bvh);
    ScaleRow {
        triangles,
        build_seconds,
        build_cpu_seconds,
        sah_cost,
        footprint,
        primary_mrays,
        random_mrays,
        wide_collapse_seconds,
        wide_bytes: wide.heap_bytes(),
        wide_primary_mrays: closest_hit_rate(&wide, &primary),
        wide_random_mrays: closest_hit_rate(&wide, &random),
        peak_bytes: peak_resident_bytes(),
    }
}

/// CPU time of the calling thread in seconds (`/proc/thread-self/schedstat`,
/// Linux only): unlike wall-clock time, it does not count the time other
/// processes on a shared machine hold the core.
pub fn thread_cpu_seconds() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    let nanos: u64 = stat.split_whitespace().next()?.parse().ok()?;
    Some(nanos as f64 * 1e-9)
}

/// One timed build: wall-clock seconds and, where known, the CPU seconds
/// of the calling thread.
#[derive(Clone, Copy, Debug)]
pub struct BuildTime {
    pub wall: f64,
    pub cpu: Option<f64>,
}

/// Times of `BvhAccel::new` (the primitives' boxes and the tree)
/// over the sphere of `phi x theta` steps, `runs` times on the current
/// thread pool, and the tree's SAH cost: for profiling the build.
pub fn build_times(phi_steps: u32, theta_steps: u32, runs: usize) -> (Vec<BuildTime>, f64) {
    let primitives = Primitives::from_scene(&bumpy_sphere(phi_steps, theta_steps));
    let mut cost = 0.0;
    let times = (0..runs)
        .map(|_| {
            let input = primitives.clone();
            let (start, cpu_start) = (Instant::now(), thread_cpu_seconds());
            let accel = BvhAccel::new(input);
            let wall = start.elapsed().as_secs_f64();
            let cpu = thread_cpu_seconds().zip(cpu_start).map(|(b, a)| b - a);
            cost = accel.bvh.sah_cost(&BuildOptions::default());
            BuildTime { wall, cpu }
        })
        .collect();
    (times, cost)
}

/// Writes the sphere of `phi x theta` steps as a `.dae` file for
/// `pathtracer` ([`crate::scene::export`]): seen from the benchmark
/// camera's direction, lit by a point light above and to the right.
pub fn write_bumpy_sphere(phi_steps: u32, theta_steps: u32, path: &Path) -> std::io::Result<()> {
    let scene = bumpy_sphere(phi_steps, theta_steps);
    let view = ExportView {
        dir_to_camera: Vec3::new(0.0, 0.3, 3.2).normalize(),
        hfov_deg: 45.0,
        light_position: Vec3::new(2.0, 3.0, 4.0),
        light_intensity: 30.0,
        albedo: 0.6,
    };
    let mut out = std::io::BufWriter::new(std::fs::File::create(path)?);
    write_dae(&scene.mesh, &view, &mut out)?;
    out.flush()
}

/// Millions of closest hits (full hit records) per second, traced on the
/// calling thread, the best of [`RUNS`] runs, timed in CPU time where the
/// kernel gives it (so other work on a shared machine does not count),
/// else in wall-clock time.
pub fn closest_hit_rate(accel: &impl Intersector, rays: &[Ray]) -> f64 {
    let mut best = f64::INFINITY;
    for _ in 0..RUNS {
        let (start, cpu_start) = (Instant::now(), thread_cpu_seconds());
        let hits = rays.iter().filter(|r| accel.intersect(r).is_some()).count();
        std::hint::black_box(hits);
        let wall = start.elapsed().as_secs_f64();
        let cpu = thread_cpu_seconds().zip(cpu_start).map(|(b, a)| b - a);
        best = best.min(cpu.unwrap_or(wall));
    }
    rays.len() as f64 / best / 1e6
}
