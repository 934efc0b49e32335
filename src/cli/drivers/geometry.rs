//! Parts 1 and 2: normal shading by linear scan and through the BVH, and
//! the BVH benchmarks.

use std::time::Instant;

use super::{describe_or, prepare, report_render, write_film, Result};
use crate::bvh::BvhAccel;
use crate::cli::args::AccelArg;
use crate::cli::CourseArgs;
use crate::intersect::{Intersector, LinearScan, Ray, TriangleTest};
use crate::raygen::{Camera, NormalShading};
use crate::render::{pixel_ray, render_image, RenderSettings, Rendered};

/// Renders normal shading through `intersector`.
pub fn render_normals(
    intersector: impl Intersector,
    camera: &Camera,
    settings: &RenderSettings,
) -> Rendered {
    let shading = NormalShading { intersector };
    render_image(camera, settings, None, |ray, _| shading.radiance(ray))
}

/// `part1-raygen`: normal shading, testing every primitive for every ray.
///
/// Triangles are intersected by Möller-Trumbore, the course's test for
/// part 1 (the later parts use the watertight test; see
/// `docs/02-intersect.md`).
/// The normal-shading binaries render no light, so neither the course's
/// image nor a mistake: refuse the flags rather than ignore them.
fn refuse_course_image(args: &CourseArgs, binary: &str) -> Result<()> {
    if args.course_exact.is_some() || !args.mistakes.is_empty() {
        return Err(format!(
            "{binary} shades normals: --course-exact and --mistake are for the binaries that render light \
             (part3-direct to part8-dof, pathtracer)"
        )
        .into());
    }
    Ok(())
}

pub fn part1(args: &CourseArgs) -> Result<()> {
    refuse_course_image(args, "part1-raygen")?;
    let Some(mut p) = describe_or(prepare(args)?, args)? else {
        return Ok(());
    };
    p.primitives.triangle_test = TriangleTest::MollerTrumbore;
    crate::say!(
        "{}: {} primitives, linear scan, Möller-Trumbore triangles",
        p.scene.source,
        p.primitives.len()
    )?;
    let settings = args.render_settings();
    let rendered = render_normals(LinearScan::new(&p.primitives), &p.camera, &settings);
    report_render(&rendered)?;
    write_film(&rendered, args)
}

/// `part2-bvh`: normal shading through a BVH, with its build time and its
/// speed-up over part 1's linear scan.
pub fn part2(args: &CourseArgs) -> Result<()> {
    refuse_course_image(args, "part2-bvh")?;
    let Some(p) = describe_or(prepare(args)?, args)? else {
        return Ok(());
    };
    let count = p.primitives.len();
    let start = Instant::now();
    let accel = BvhAccel::new(p.primitives);
    let build = start.elapsed().as_secs_f64();
    let (leaves, depth) = accel.bvh.leaf_stats();
    crate::say!(
        "{}: {count} primitives, BVH build {build:.3} s ({} nodes, {leaves} leaves, depth {depth})",
        p.scene.source,
        accel.bvh.nodes.len()
    )?;
    let settings = args.render_settings();
    let rendered = render_normals(&accel, &p.camera, &settings);
    report_render(&rendered)?;
    let speedup = measure_speedup(&accel, &p.camera, &settings);
    crate::say!(
        "speed-up over the linear scan: {:.1}x (one thread, {} of {} pixels, {} disagreements)",
        speedup.ratio,
        speedup.rays,
        speedup.pixels,
        speedup.disagreements
    )?;
    write_film(&rendered, args)
}

/// BVH against linear scan on the same camera rays.
pub struct Speedup {
    /// Linear-scan time over BVH time.
    pub ratio: f64,
    /// Rays traced by each.
    pub rays: usize,
    /// Pixels in the image.
    pub pixels: usize,
    /// Rays whose closest hit differs between the two.
    pub disagreements: usize,
}

/// Ray-primitive tests the linear scan may spend on the measurement
/// (about a second on one core).
const LINEAR_BUDGET: f64 = 3e8;

/// Times both intersectors on one thread over a sample of pixel-centre rays,
/// evenly spread over the image, sized so the linear scan takes about a second.
pub fn measure_speedup(accel: &BvhAccel, camera: &Camera, settings: &RenderSettings) -> Speedup {
    let (w, h) = (settings.width, settings.height);
    let pixels = w as usize * h as usize;
    let wanted = (LINEAR_BUDGET / accel.primitives.len().max(1) as f64) as usize;
    let stride = (pixels / wanted.clamp(1, pixels)).max(1);
    let rays: Vec<Ray> = (0..pixels)
        .step_by(stride)
        .map(|i| {
            let centre = glam::Vec2::splat(0.5);
            let pixel = ((i % w as usize) as u32, (i / w as usize) as u32);
            pixel_ray(camera, (w, h), pixel, centre, centre)
        })
        .collect();
    let time = |intersector: &dyn Intersector| {
        let start = Instant::now();
        let hits: Vec<Option<u32>> = rays
            .iter()
            .map(|r| intersector.intersect(r).map(|h| h.primitive))
            .collect();
        (start.elapsed().as_secs_f64(), hits)
    };
    let (bvh_seconds, bvh_hits) = time(accel);
    let (linear_seconds, linear_hits) = time(&LinearScan::new(&accel.primitives));
    Speedup {
        ratio: linear_seconds / bvh_seconds.max(1e-9),
        rays: rays.len(),
        pixels,
        disagreements: bvh_hits
            .iter()
            .zip(&linear_hits)
            .filter(|(a, b)| a != b)
            .count(),
    }
}

/// `part2-bvh --bench [-t N] [--accel A]`: the ray-throughput benchmark
/// ([`crate::bvh::throughput`]) on BVH `accel`: one thread, then `threads`
/// (default: all cores).
pub fn bvh_benchmark(threads: Option<usize>, accel: AccelArg) -> Result<()> {
    use crate::bvh::throughput::{build_benchmark_bvh, build_benchmark_wide};
    match accel {
        AccelArg::Binary => {
            let (accel, times) = best_of_builds(|| {
                let (accel, build) = build_benchmark_bvh(1024, 512);
                (accel, [build])
            });
            let (leaves, depth) = accel.bvh.leaf_stats();
            crate::say!("binary BVH: build {}", times[0])?;
            crate::say!(
                "triangles {} nodes {} leaves {leaves} depth {depth}",
                accel.primitives.len(),
                accel.bvh.nodes.len()
            )?;
            trace_benchmark_sets(&accel, threads)?;
        }
        AccelArg::Wide => {
            let (accel, [total, binary, collapse]) = best_of_builds(|| {
                let (accel, [binary, collapse]) = build_benchmark_wide(1024, 512);
                (accel, [binary + collapse, binary, collapse])
            });
            let (leaves, depth, lanes) = accel.wide.leaf_stats();
            let (nodes, packs) = accel.wide.sizes();
            crate::say!(
                "wide BVH: build {total} (binary SAH build {binary}, collapse {collapse})"
            )?;
            crate::say!(
                "triangles {} nodes {nodes} leaves {leaves} depth {depth} packs {packs} lanes used {:.1} %",
                accel.primitives.len(),
                100.0 * lanes as f64 / (4 * packs).max(1) as f64
            )?;
            trace_benchmark_sets(&accel, threads)?;
        }
    }
    Ok(())
}

/// Builds of the benchmark: each is timed this many times, as Embree's
/// bench script does, since a build's first touch of fresh memory is
/// sometimes slowed by the kernel (seen as one build in five taking 0.1 s
/// longer in the collapse).
const BUILDS: usize = 3;

/// Runs `build` [`BUILDS`] times; returns the last result and, for each
/// of its `N` timings, "min X s median Y s".
fn best_of_builds<A, const N: usize>(build: impl Fn() -> (A, [f64; N])) -> (A, [String; N]) {
    let mut runs = Vec::with_capacity(BUILDS);
    let mut accel = None;
    for _ in 0..BUILDS {
        // Free the previous tree before the next build.
        drop(accel.take());
        let (a, times) = build();
        accel = Some(a);
        runs.push(times);
    }
    let summary = std::array::from_fn(|i| {
        let mut t: Vec<f64> = runs.iter().map(|r| r[i]).collect();
        t.sort_by(f64::total_cmp);
        format!("min {:.3} s median {:.3} s", t[0], t[t.len() / 2])
    });
    (accel.expect("at least one build"), summary)
}

/// The benchmark's ray sets through `accel`, one thread, then `threads`,
/// for the closest primitive; then, on one thread, for full hit records.
fn trace_benchmark_sets(accel: &impl Intersector, threads: Option<usize>) -> Result<()> {
    use crate::bvh::throughput::{measure, ray_sets, Query};
    let all = threads.unwrap_or_else(rayon::current_num_threads);
    let counts = if all > 1 { vec![1, all] } else { vec![1] };
    for set in &ray_sets(accel, 1024, 1 << 20) {
        for &t in &counts {
            crate::say!("{}", measure(accel, set, Query::Nearest, t))?;
        }
        crate::say!("{}", measure(accel, set, Query::Record, 1))?;
    }
    Ok(())
}

/// `part2-bvh --scaling`: build time and one-thread ray rates of the
/// benchmark's sphere at growing triangle counts, as a Markdown table.
pub fn bvh_scaling() -> Result<()> {
    use crate::bvh::throughput::{
        build_benchmark_bvh, measure, primary_rays, random_rays, Query, RaySet,
    };
    crate::say!("| triangles | build (s) | primary 1T (Mrays/s) | random 1T (Mrays/s) |")?;
    crate::say!("| ---: | ---: | ---: | ---: |")?;
    for k in 0..6 {
        let (phi, theta) = (32 << k, 16 << k);
        let (accel, build) = build_benchmark_bvh(phi, theta);
        let rate = |name, rays| {
            measure(&accel, &RaySet { name, rays }, Query::Nearest, 1).mrays_per_second
        };
        let primary = rate("primary", primary_rays(512));
        let random = rate("random", random_rays(1 << 18));
        crate::say!(
            "| {} | {build:.4} | {primary:.2} | {random:.2} |",
            accel.primitives.len()
        )?;
    }
    Ok(())
}
