//! Writes a scene's triangles and two sets of its rays, and times this
//! project's wide BVH on them, one ray at a time
//! ([`throughput::measure`], as `part2-bvh --bench` does), for
//! `benches/compare/packets.sh` (Embree's packets on the same rays).
//!
//! ```text
//! cargo run --release --example render_rays -- SCENE.dae OUT_DIR [WIDTH HEIGHT SAMPLES]
//! ```
//!
//! `OUT_DIR` is made if missing.
//!
//! - `camera.bin`: `SAMPLES` camera rays a pixel (default 480 x 360, 16),
//!   pixel after pixel, a pixel's rays one after another, as a renderer
//!   that traces a pixel's samples together would hand them over;
//! - `bounce.bin`: from each camera ray's hit, a direction uniform on the
//!   hemisphere of the geometric normal on the ray's side
//!   ([`throughput::diffuse_rays`], the bench's diffuse set), in the same
//!   order, cut to a multiple of 16 (made-up rays: on glass a render
//!   would refract, and its rays inside glass always hit);
//! - `triangles.bin`: every triangle's three corners.
//!
//! Rays are eight little-endian `f32`: origin, direction, `t_min`,
//! `t_max`; corners three. Spheres are left out (Embree's side has only
//! triangles), so use a scene of triangles.

use std::error::Error;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;

use glam::Vec2;
use pathtracer::bvh::throughput::{self, Query, RaySet};
use pathtracer::bvh::wide::WideBvhAccel;
use pathtracer::intersect::{Intersector, Primitives, Ray, Shape};
use pathtracer::raygen::Camera;
use rand::{Rng, SeedableRng};

fn write_floats(path: &Path, values: impl Iterator<Item = f32>) -> Result<(), Box<dyn Error>> {
    let named = |e: std::io::Error| format!("{}: {e}", path.display());
    let mut file = BufWriter::new(File::create(path).map_err(named)?);
    for v in values {
        file.write_all(&v.to_le_bytes()).map_err(named)?;
    }
    file.flush().map_err(named)?;
    Ok(())
}

fn ray_floats(rays: &[Ray]) -> impl Iterator<Item = f32> + '_ {
    rays.iter().flat_map(|r| {
        [
            r.origin.x, r.origin.y, r.origin.z, r.dir.x, r.dir.y, r.dir.z, r.t_min, r.t_max,
        ]
    })
}

fn main() -> Result<(), Box<dyn Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [scene_path, out, ..] = args.as_slice() else {
        return Err("usage: render_rays SCENE.dae OUT_DIR [WIDTH HEIGHT SAMPLES]".into());
    };
    let number = |k: usize, default: u32| -> Result<u32, Box<dyn Error>> {
        Ok(args
            .get(k)
            .map(|s| s.parse())
            .transpose()?
            .unwrap_or(default))
    };
    let (width, height, samples) = (number(2, 480)?, number(3, 360)?, number(4, 16)?);
    let scene = pathtracer::scene::load(Path::new(scene_path))?;
    let primitives = Primitives::from_scene(&scene);
    let size = (width, height);
    let camera = Camera::course_placement(&scene.camera, &primitives.bounds(), width, height);
    let out = Path::new(out);
    std::fs::create_dir_all(out).map_err(|e| format!("{}: {e}", out.display()))?;
    write_floats(
        &out.join("triangles.bin"),
        primitives.shapes.iter().flat_map(|shape| match shape {
            Shape::Triangle(t) => [t.p0, t.p1, t.p2]
                .into_iter()
                .flat_map(|p| p.to_array())
                .collect(),
            _ => Vec::new(),
        }),
    )?;
    let accel = WideBvhAccel::new(primitives);
    let mut rng = rand::rngs::StdRng::seed_from_u64(7);
    let mut camera_rays = Vec::new();
    for y in 0..height {
        for x in 0..width {
            for _ in 0..samples {
                let offset = Vec2::new(rng.gen(), rng.gen());
                let ray =
                    pathtracer::render::pixel_ray(&camera, size, (x, y), offset, Vec2::splat(0.5));
                camera_rays.push(ray);
            }
        }
    }
    let hitting: Vec<Ray> = camera_rays
        .iter()
        .filter(|ray| accel.nearest(ray).is_some())
        .copied()
        .collect();
    let mut bounce_rays = throughput::diffuse_rays(&accel, &hitting);
    bounce_rays.truncate(bounce_rays.len() / 16 * 16);
    let sets = [
        RaySet {
            name: "camera",
            rays: camera_rays,
        },
        RaySet {
            name: "bounce",
            rays: bounce_rays,
        },
    ];
    for set in &sets {
        write_floats(
            &out.join(format!("{}.bin", set.name)),
            ray_floats(&set.rays),
        )?;
        let measured = throughput::measure(&accel, set, Query::Nearest, 1);
        println!(
            "this project, {} rays, one a query: {measured}",
            set.rays.len()
        );
    }
    Ok(())
}
