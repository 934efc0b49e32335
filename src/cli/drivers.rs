//! What each binary does, so that `bin/` holds no logic and the tests run
//! exactly what the binaries run.

use std::error::Error;
use std::time::Instant;

use crate::bvh::BvhAccel;
use crate::intersect::{Intersector, LinearScan, Primitives, Ray};
use crate::raygen::{Camera, NormalShading};
use crate::render::{
    pixel_ray, render_tiles, sample_pixel, write_image, Film, RenderSettings, RenderStats,
};
use crate::scene::info::describe;
use crate::scene::Scene;

use super::CourseArgs;

type Result<T> = std::result::Result<T, Box<dyn Error>>;

/// A loaded scene with its primitives and the course's camera for the
/// requested size; prints the loader's warnings.
pub struct Prepared {
    pub scene: Scene,
    pub primitives: Primitives,
    pub camera: Camera,
}

/// Loads the scene named by `args` and places the camera.
pub fn prepare(args: &CourseArgs) -> Result<Prepared> {
    let scene = args.load_scene()?;
    for warning in &scene.warnings {
        eprintln!("warning: {}: {warning}", scene.source);
    }
    let primitives = Primitives::from_scene(&scene);
    let camera = Camera::course_placement(
        &scene.camera,
        &primitives.bounds(),
        args.width(),
        args.height(),
    );
    Ok(Prepared {
        scene,
        primitives,
        camera,
    })
}

/// Renders normal shading through `intersector`.
pub fn render_normals(
    intersector: impl Intersector,
    camera: &Camera,
    settings: &RenderSettings,
) -> (Film, RenderStats) {
    let shading = NormalShading { intersector };
    let (w, h, spp) = (settings.width, settings.height, settings.samples_per_pixel);
    render_tiles(settings, |x, y, rng| {
        sample_pixel(camera, w, h, (x, y), spp, rng, |ray, _| {
            shading.radiance(ray)
        })
    })
}

fn report_render(stats: &RenderStats, settings: &RenderSettings) {
    let rays = settings.width as f64 * settings.height as f64 * settings.samples_per_pixel as f64;
    println!(
        "render: {:.3} s on {} threads, {} camera rays/s",
        stats.seconds,
        stats.threads,
        si(rays / stats.seconds)
    );
}

/// `x` with three significant digits and an SI prefix: `4.74 k`, `14.9 M`.
pub fn si(x: f64) -> String {
    let (value, prefix) = [(1e9, "G"), (1e6, "M"), (1e3, "k")]
        .into_iter()
        .find(|(scale, _)| x.abs() >= *scale)
        .map_or((x, ""), |(scale, p)| (x / scale, p));
    let decimals = if value.abs() >= 100.0 {
        0
    } else if value.abs() >= 10.0 {
        1
    } else {
        2
    };
    format!("{value:.decimals$} {prefix}")
}

fn write(film: &Film, args: &CourseArgs) -> Result<()> {
    let path = args.output_path();
    write_image(film, &path)?;
    println!("wrote {}", path.display());
    Ok(())
}

/// `part1-raygen`: normal shading, testing every primitive for every ray.
pub fn part1(args: &CourseArgs) -> Result<()> {
    let p = prepare(args)?;
    if args.info {
        print!("{}", describe(&p.scene, &p.camera));
        return Ok(());
    }
    println!(
        "{}: {} primitives, linear scan",
        p.scene.source,
        p.primitives.len()
    );
    let settings = args.render_settings();
    let (film, stats) = render_normals(LinearScan::new(&p.primitives), &p.camera, &settings);
    report_render(&stats, &settings);
    write(&film, args)
}

/// `part2-bvh`: normal shading through a BVH, with its build time and its
/// speed-up over part 1's linear scan.
pub fn part2(args: &CourseArgs) -> Result<()> {
    let p = prepare(args)?;
    if args.info {
        print!("{}", describe(&p.scene, &p.camera));
        return Ok(());
    }
    let count = p.primitives.len();
    let start = Instant::now();
    let accel = BvhAccel::new(p.primitives);
    let build = start.elapsed().as_secs_f64();
    let (leaves, depth) = accel.bvh.leaf_stats();
    println!(
        "{}: {count} primitives, BVH build {build:.3} s ({} nodes, {leaves} leaves, depth {depth})",
        p.scene.source,
        accel.bvh.nodes.len()
    );
    let settings = args.render_settings();
    let (film, stats) = render_normals(&accel, &p.camera, &settings);
    report_render(&stats, &settings);
    let speedup = measure_speedup(&accel, &p.camera, &settings);
    println!(
        "speed-up over the linear scan: {:.1}x (one thread, {} of {} pixels, {} disagreements)",
        speedup.ratio, speedup.rays, speedup.pixels, speedup.disagreements
    );
    write(&film, args)
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
            pixel_ray(
                camera,
                w,
                h,
                (i % w as usize) as u32,
                (i / w as usize) as u32,
                glam::Vec2::splat(0.5),
            )
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

/// `pathtracer`: for now parts 1 and 2 (normal shading through the BVH);
/// the lighting parts plug in here.
pub fn pathtracer(args: &CourseArgs) -> Result<()> {
    let p = prepare(args)?;
    if args.info {
        print!("{}", describe(&p.scene, &p.camera));
        return Ok(());
    }
    let accel = BvhAccel::new(p.primitives);
    let settings = args.render_settings();
    let (film, stats) = render_normals(&accel, &p.camera, &settings);
    report_render(&stats, &settings);
    let bad = film.non_finite_count();
    if bad > 0 {
        eprintln!("warning: {bad} pixels are NaN or infinite");
    }
    write(&film, args)
}

/// `part2-bvh --bench [-t N]`: the ray-throughput benchmark
/// ([`crate::bvh::throughput`]): one thread, then `threads` (default: all cores).
pub fn bvh_benchmark(threads: Option<usize>) -> Result<()> {
    use crate::bvh::throughput::{build_benchmark_bvh, measure, ray_sets};
    let (accel, build) = build_benchmark_bvh(1024, 512);
    let (leaves, depth) = accel.bvh.leaf_stats();
    println!("build {build:.3} s");
    println!(
        "triangles {} nodes {} leaves {leaves} depth {depth}",
        accel.primitives.len(),
        accel.bvh.nodes.len()
    );
    let all = threads.unwrap_or_else(rayon::current_num_threads);
    let counts = if all > 1 { vec![1, all] } else { vec![1] };
    for set in &ray_sets(&accel, 1024, 1 << 20) {
        for &t in &counts {
            println!("{}", measure(&accel, set, t));
        }
    }
    Ok(())
}

/// `part2-bvh --scaling`: build time and one-thread ray rates of the
/// benchmark's sphere at growing triangle counts, as a Markdown table.
pub fn bvh_scaling() -> Result<()> {
    use crate::bvh::throughput::{build_benchmark_bvh, measure, primary_rays, random_rays, RaySet};
    println!("| triangles | build (s) | primary 1T (Mrays/s) | random 1T (Mrays/s) |");
    println!("| ---: | ---: | ---: | ---: |");
    for k in 0..6 {
        let (phi, theta) = (32 << k, 16 << k);
        let (accel, build) = build_benchmark_bvh(phi, theta);
        let rate = |name, rays| measure(&accel, &RaySet { name, rays }, 1).mrays_per_second;
        let primary = rate("primary", primary_rays(512));
        let random = rate("random", random_rays(1 << 18));
        println!(
            "| {} | {build:.4} | {primary:.2} | {random:.2} |",
            accel.primitives.len()
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::si;

    #[test]
    fn si_prefixes_keep_three_digits() {
        assert_eq!(si(4737.0), "4.74 k");
        assert_eq!(si(14.89e6), "14.9 M");
        assert_eq!(si(123.4), "123 ");
        assert_eq!(si(0.5), "0.50 ");
    }
}
