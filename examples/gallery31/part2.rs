//! Part 2 (BVH): large meshes, BVH against linear scan, and the BVH's
//! boxes drawn over a mesh.

use std::time::Instant;

use pathtracer::bvh::BvhAccel;
use pathtracer::cli::drivers::render_normals;
use pathtracer::intersect::{Aabb, LinearScan};
use pathtracer::math::Rgb;
use pathtracer::raygen::Camera;

use crate::picture::{grid, Picture};
use crate::setup::Setup;
use crate::Result;

/// Part 2: large meshes through the BVH, the time of the same render by
/// linear scan, and the BVH's boxes at chosen depths over a mesh.
pub fn part2(threads: usize) -> Result<()> {
    let mut pictures = Vec::new();
    println!("| scene | triangles | BVH build | render, BVH | render, linear scan | speed-up |");
    println!("| --- | ---: | ---: | ---: | ---: | ---: |");
    for file in ["teapot.dae", "bunny.dae", "CBbunny.dae"] {
        let setup = Setup::load(file, threads)?;
        let start = Instant::now();
        let accel = BvhAccel::new(setup.accel.primitives.clone());
        let build = start.elapsed().as_secs_f64();
        let settings = setup.settings(1, 0);
        let fast = render_normals(&accel, &setup.camera, &settings);
        let slow = render_normals(LinearScan::new(&accel.primitives), &setup.camera, &settings);
        let (t_bvh, t_lin) = (fast.stats.seconds, slow.stats.seconds);
        println!(
            "| {file} | {} | {:.1} ms | {:.1} ms | {:.0} ms | {:.0}x |",
            accel.primitives.len(),
            1e3 * build,
            1e3 * t_bvh,
            1e3 * t_lin,
            t_lin / t_bvh
        );
        pictures.push(Picture::of(file, &fast));
    }
    grid("w31-part2-meshes.png", 3, &pictures)?;

    let setup = Setup::load("bunny.dae", threads)?;
    let shaded = render_normals(&setup.accel, &setup.camera, &setup.settings(1, 0));
    let mut pictures = Vec::new();
    for depth in [1, 3, 5, 8] {
        let boxes = boxes_at_depth(&setup.accel, depth);
        let mut picture = Picture::of(format!("depth {depth}: {} boxes", boxes.len()), &shaded);
        // Dim the mesh so the boxes stand out.
        picture.display.iter_mut().for_each(|p| *p *= 0.6);
        for (i, b) in boxes.iter().enumerate() {
            draw_box(&mut picture, &setup.camera, b, PALETTE[i % PALETTE.len()]);
        }
        pictures.push(picture);
    }
    grid("w31-part2-bvh.png", 4, &pictures)
}

/// Colours of the boxes of [`part2`]'s BVH picture.
const PALETTE: [Rgb; 6] = [
    Rgb::new(1.0, 0.2, 0.2),
    Rgb::new(1.0, 1.0, 0.2),
    Rgb::new(0.2, 1.0, 1.0),
    Rgb::new(1.0, 0.5, 1.0),
    Rgb::new(1.0, 0.6, 0.0),
    Rgb::new(1.0, 1.0, 1.0),
];

/// The boxes of the BVH's nodes at `depth` (root 1), and of the leaves
/// that end above it, so together they cover every primitive.
fn boxes_at_depth(accel: &BvhAccel, depth: usize) -> Vec<Aabb> {
    let bvh = &accel.bvh;
    let Some(root) = bvh.root else {
        return Vec::new();
    };
    let mut out = Vec::new();
    let mut stack = vec![(root, bvh.bounds, 1)];
    while let Some((link, bounds, d)) = stack.pop() {
        if d == depth || link.is_leaf() {
            out.push(bounds);
            continue;
        }
        let node = &bvh.nodes[link.first as usize];
        for i in 0..2 {
            stack.push((node.children[i], node.child_bounds(i), d + 1));
        }
    }
    out
}

/// The pixel where `camera` sees world point `p`, `None` behind it.
fn project(camera: &Camera, (w, h): (u32, u32), p: glam::Vec3) -> Option<glam::Vec2> {
    let q = camera.c2w.transpose() * (p - camera.position);
    if q.z >= -1e-4 {
        return None;
    }
    let tan_h = (0.5 * camera.hfov_deg.to_radians()).tan();
    let tan_v = (0.5 * camera.vfov_deg.to_radians()).tan();
    let x = 0.5 * (q.x / -q.z / tan_h + 1.0);
    let y = 0.5 * (q.y / -q.z / tan_v + 1.0);
    Some(glam::Vec2::new(x * w as f32, (1.0 - y) * h as f32))
}

/// Draws the 12 edges of `b` into `picture` (no depth test: the course's
/// viewer also draws boxes over the mesh).
fn draw_box(picture: &mut Picture, camera: &Camera, b: &Aabb, colour: Rgb) {
    let corner = |i: usize| {
        glam::Vec3::new(
            if i & 1 == 0 { b.min.x } else { b.max.x },
            if i & 2 == 0 { b.min.y } else { b.max.y },
            if i & 4 == 0 { b.min.z } else { b.max.z },
        )
    };
    let size = (picture.width, picture.height);
    for i in 0..8 {
        for bit in [1, 2, 4] {
            if i & bit != 0 {
                continue;
            }
            let (Some(a), Some(c)) = (
                project(camera, size, corner(i)),
                project(camera, size, corner(i | bit)),
            ) else {
                continue;
            };
            let steps = (c - a).abs().max_element().ceil().clamp(1.0, 4096.0) as u32;
            for s in 0..=steps {
                let p = a.lerp(c, s as f32 / steps as f32);
                let (x, y) = (p.x.floor(), p.y.floor());
                if x >= 0.0 && y >= 0.0 && (x as u32) < size.0 && (y as u32) < size.1 {
                    picture.display[(y as u32 * size.0 + x as u32) as usize] = colour;
                }
            }
        }
    }
}
