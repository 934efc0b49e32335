//! Writes a scene's triangles and two sets of its rays, and times this
//! project's wide BVH on them, one ray at a time, for
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
//! - `bounce.bin`: from each camera ray's hit, a cosine-distributed
//!   direction about the geometric normal on the ray's side, in the same
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
use std::time::Instant;

use glam::Vec2;
use pathtracer::bvh::wide::WideBvhAccel;
use pathtracer::intersect::{Intersector, Primitives, Ray, Shape};
use pathtracer::math::warp::sample_cosine_hemisphere;
use pathtracer::math::Frame;
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

/// Rays a second through `accel`, one at a time (median of five passes),
/// how many hit and the sum of their hit distances.
fn rate(accel: &WideBvhAccel, rays: &[Ray]) -> (f64, usize, f64) {
    let mut rates = Vec::new();
    let (mut hits, mut distances) = (0, 0.0);
    for _ in 0..5 {
        let start = Instant::now();
        (hits, distances) = (0, 0.0);
        for hit in rays.iter().filter_map(|r| accel.nearest(r)) {
            hits += 1;
            distances += f64::from(hit.hit.t);
        }
        rates.push(rays.len() as f64 / start.elapsed().as_secs_f64());
    }
    rates.sort_by(f64::total_cmp);
    (rates[2], hits, distances)
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
    let (mut camera_rays, mut bounce_rays) = (Vec::new(), Vec::new());
    for y in 0..height {
        for x in 0..width {
            for _ in 0..samples {
                let offset = Vec2::new(rng.gen(), rng.gen());
                let ray =
                    pathtracer::render::pixel_ray(&camera, size, (x, y), offset, Vec2::splat(0.5));
                camera_rays.push(ray);
                if let Some(hit) = accel.intersect(&ray) {
                    let normal = if hit.ng.dot(ray.dir) < 0.0 {
                        hit.ng
                    } else {
                        -hit.ng
                    };
                    let u = Vec2::new(rng.gen(), rng.gen());
                    let dir = Frame::from_z(normal).to_world(sample_cosine_hemisphere(u));
                    bounce_rays.push(hit.spawn_ray(dir));
                }
            }
        }
    }
    bounce_rays.truncate(bounce_rays.len() / 16 * 16);
    write_floats(&out.join("camera.bin"), ray_floats(&camera_rays))?;
    write_floats(&out.join("bounce.bin"), ray_floats(&bounce_rays))?;
    for (name, rays) in [("camera", &camera_rays), ("bounce", &bounce_rays)] {
        let (rays_per_second, hits, distances) = rate(&accel, rays);
        println!(
            "this project {name}: {} rays, {hits} hits, sum of t {distances:.1}, {:.2} Mrays/s (one at a time, median of 5)",
            rays.len(),
            rays_per_second / 1e6
        );
    }
    Ok(())
}
