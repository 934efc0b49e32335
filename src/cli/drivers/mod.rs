//! What each binary does, so that `bin/` holds no logic and the tests run
//! exactly what the binaries run.

pub mod course;
pub mod geometry;
pub mod lighting;

pub use geometry::{
    bvh_benchmark, bvh_scaling, measure_speedup, part1, part2, render_normals, Speedup,
};
pub use lighting::{
    environment_light, part3, part4, part5, part6, part7, part8, pathtracer, render_lighting,
    render_lighting_allocated,
};

use std::error::Error;

use super::CourseArgs;
use crate::intersect::{Intersector, LinearScan, Primitives};
use crate::raygen::Camera;
use crate::render::Rendered;
use crate::scene::info::describe;
use crate::scene::Scene;

type Result<T> = std::result::Result<T, Box<dyn Error>>;

/// A loaded scene with its primitives and the course's camera for the
/// requested size.
pub struct Prepared {
    pub scene: Scene,
    pub primitives: Primitives,
    pub camera: Camera,
}

/// Checks that the output image can be written ([`check_output`]), loads
/// the scene named by `args` (printing the loader's warnings) and places
/// the camera.
pub fn prepare(args: &CourseArgs) -> Result<Prepared> {
    check_output(args)?;
    let scene = args.load_scene()?;
    // The loader's warnings name the file and the element themselves.
    for warning in &scene.warnings {
        crate::say_err!("warning: {warning}");
    }
    let primitives = Primitives::from_scene(&scene);
    let pinhole = Camera::course_placement(
        &scene.camera,
        &primitives.bounds(),
        args.width(),
        args.height(),
    );
    let mut lens = args.lens();
    if let Some(pixel) = &args.focus_at {
        let (x, y) = (pixel[0], pixel[1]);
        let size = (args.width(), args.height());
        let distance = focus_distance(&pinhole, &primitives, size, (x, y))?;
        if args.info {
            crate::say!("focus: pixel ({x}, {y}) sees a surface at distance {distance:.4} (-d {distance:.4})")?;
        }
        lens.focal_distance = distance;
    }
    let camera = pinhole.with_lens(lens);
    check_lens(&camera)?;
    Ok(Prepared {
        scene,
        primitives,
        camera,
    })
}

/// Refuses a lens whose camera rays are not finite numbers: a radius or
/// focal distance so large (`-b 1e20`) that a ray's direction overflows
/// when it is normalised. The rays through the film's corners and centre
/// from the lens's rim and centre are the extremes.
fn check_lens(camera: &Camera) -> Result<()> {
    let points = [0.0, 0.5, 1.0];
    for film in points
        .iter()
        .flat_map(|&x| points.map(|y| glam::Vec2::new(x, y)))
    {
        for lens in points
            .iter()
            .flat_map(|&x| points.map(|y| glam::Vec2::new(x, y)))
        {
            let ray = camera.generate_ray(&crate::raygen::CameraSample { film, lens });
            if !(ray.origin.is_finite() && ray.dir.is_finite() && ray.dir.length() > 0.5) {
                return Err(format!(
                    "the lens (-b {:?} -d {:?}) makes camera rays that are not finite numbers; \
                     use a smaller lens radius or focal distance",
                    camera.lens.radius, camera.lens.focal_distance
                )
                .into());
            }
        }
    }
    Ok(())
}

/// The distance along the view axis from `camera` to the surface seen
/// through the centre of pixel `(x, y)` of a `size` image: the `-d` that
/// puts that surface in focus (`--focus-at X Y`).
pub fn focus_distance(
    camera: &Camera,
    primitives: &Primitives,
    size: (u32, u32),
    (x, y): (u32, u32),
) -> Result<f32> {
    if x >= size.0 || y >= size.1 {
        return Err(format!(
            "--focus-at {x} {y}: the pixel is outside the {}x{} image",
            size.0, size.1
        )
        .into());
    }
    let centre = glam::Vec2::splat(0.5);
    let ray = crate::render::pixel_ray(camera, size, (x, y), centre, centre);
    let hit = LinearScan::new(primitives)
        .intersect(&ray)
        .ok_or_else(|| format!("--focus-at {x} {y}: the pixel sees no surface"))?;
    Ok((hit.p - camera.position).dot(camera.view_direction()))
}

/// Fails, before any render, when the image `-f` (or the default name)
/// asks for cannot be written: a name that is neither `.png` nor `.exr`, a
/// folder that does not exist or does not take a new file
/// ([`crate::render::check_output_path`]), or a size that does not fit in
/// the memory available ([`crate::render::memory`]). Nothing to check with `--info`,
/// which writes no image. [`prepare`] calls it first, so every driver does.
pub fn check_output(args: &CourseArgs) -> Result<()> {
    if !args.info {
        crate::render::check_output_path(&args.output_path())?;
        let available = crate::render::memory::available_bytes();
        crate::render::memory::check_image_memory(args.width(), args.height(), available)?;
    }
    Ok(())
}

/// With `--info`, prints the scene's summary and gives `None`.
fn describe_or(prepared: Prepared, args: &CourseArgs) -> Result<Option<Prepared>> {
    if args.info {
        crate::cli::say::text(&describe(&prepared.scene, &prepared.camera))?;
        Ok(None)
    } else {
        Ok(Some(prepared))
    }
}

/// What the warning about pixels that no image should hold says of them.
pub const OUT_OF_RANGE_PIXELS: &str = "pixels hold a NaN, infinite or negative value";

/// Prints render time, ray rate and rejected samples; warns about
/// rejected samples and about pixels no image should hold.
fn report_render(rendered: &Rendered) -> Result<()> {
    let stats = &rendered.stats;
    crate::say!(
        "render: {:.3} s on {} threads, {} camera rays/s",
        stats.seconds,
        stats.threads,
        si(rendered.samples() as f64 / stats.seconds)
    )?;
    crate::say!(
        "samples: {} camera rays, {} rejected (NaN or infinite radiance, left out of the mean)",
        rendered.samples(),
        rendered.rejected()
    )?;
    let out_of_range = rendered
        .film
        .pixels
        .iter()
        .filter(|p| !p.is_finite() || p.min_element() < 0.0)
        .count();
    if out_of_range > 0 {
        crate::say_err!(
            "warning: {out_of_range} {OUT_OF_RANGE_PIXELS}; the image holds 0 for NaN and negative values, the largest float for infinity"
        );
    }
    if rendered.rejected() > 0 {
        crate::say_err!(
            "warning: {} of {} samples ({:.3} %) had a NaN or infinite radiance and were left out of their pixels' means",
            rendered.rejected(),
            rendered.samples(),
            100.0 * rendered.rejected() as f64 / rendered.samples().max(1) as f64
        );
    }
    Ok(())
}

/// The wide SIMD BVH over `primitives` (the binary one's hits, faster:
/// docs/03-bvh.md), timed and reported under `source`.
fn build_wide_bvh(source: &str, primitives: Primitives) -> Result<crate::bvh::WideBvhAccel> {
    let start = std::time::Instant::now();
    let accel = crate::bvh::WideBvhAccel::new(primitives);
    crate::say!("{source}: BVH build {:.3} s", start.elapsed().as_secs_f64())?;
    Ok(accel)
}

/// Writes the film where `-f` (or the default) says and tells where.
fn write_film(rendered: &Rendered, args: &CourseArgs) -> Result<()> {
    let path = args.output_path();
    crate::render::write_image(&rendered.film, &path)?;
    crate::say!("wrote {}", path.display())?;
    Ok(())
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
