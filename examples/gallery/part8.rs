//! Part 8 (depth of field), the figures of docs/09-depth-of-field.md:
//!
//! ```text
//! cargo run --release --example gallery -- part8
//! ```
//!
//! The scene is made here ([`depth_scene`]): the built-in Cornell box
//! with a checkerboard floor and four spheres in a diagonal row from the
//! front left to the back right, so that every depth of the box has
//! something sharp-edged in it.
//!
//! - `w32-part8-focus.png`: a focus stack, lens radius `-b` [`STACK_RADIUS`]
//!   focused (`-d`) on each sphere in turn;
//! - `w32-part8-aperture.png`: an aperture sweep, focus on the front
//!   sphere, lens radius 0.05, 0.1, 0.2 and 0.4;
//!
//! both at `-s 128 -l 1 -m 5`.

use glam::Vec3;
use pathtracer::depth_of_field::ThinLens;
use pathtracer::scene::{builtin, Material, Scene, Sphere};

use crate::picture::{grid, Picture};
use crate::setup::{paths, Setup};
use crate::{Result, SIZE};

/// Camera rays per pixel.
const SPP: u32 = 128;

/// The lens radius of the focus stack.
pub const STACK_RADIUS: f32 = 0.3;

/// The spheres: name, centre and albedo; all of radius [`RADIUS`].
const SPHERES: [(&str, [f32; 3], [f32; 3]); 4] = [
    ("red", [-0.55, 0.2, 0.6], [0.75, 0.2, 0.15]),
    ("yellow", [-0.2, 0.2, 0.15], [0.75, 0.65, 0.2]),
    ("green", [0.2, 0.2, -0.3], [0.2, 0.6, 0.25]),
    ("blue", [0.55, 0.2, -0.75], [0.2, 0.3, 0.75]),
];
const RADIUS: f32 = 0.2;

/// Tiles of the checkerboard along each side of the floor.
const TILES: usize = 8;

/// The built-in Cornell box (`scene::builtin::cornell_box`), its balls
/// replaced by [`SPHERES`] and its floor by a checkerboard of [`TILES`] x
/// [`TILES`] squares of albedo 0.75 and 0.15.
pub fn depth_scene() -> Scene {
    let mut scene = builtin::cornell_box();
    scene.source = "built-in: cornell-box, depth of field".to_string();
    let add = |scene: &mut Scene, m: Material| {
        scene.materials.push(m);
        (scene.materials.len() - 1) as u32
    };
    scene.spheres.clear();
    for (_, centre, albedo) in SPHERES {
        let material = add(
            &mut scene,
            Material::Diffuse {
                albedo: Vec3::from_array(albedo),
            },
        );
        scene.spheres.push(Sphere {
            center: Vec3::from_array(centre),
            radius: RADIUS,
            material,
        });
    }
    // The floor: the triangles with every vertex at y = 0.
    let mesh = &mut scene.mesh;
    let keep: Vec<bool> = mesh
        .triangles
        .iter()
        .map(|t| t.iter().any(|&v| mesh.positions[v as usize].y != 0.0))
        .collect();
    let mut kept = keep.iter();
    mesh.triangles.retain(|_| *kept.next().unwrap_or(&true));
    let mut kept = keep.iter();
    mesh.materials.retain(|_| *kept.next().unwrap_or(&true));
    let light = add(
        &mut scene,
        Material::Diffuse {
            albedo: Vec3::splat(0.75),
        },
    );
    let dark = add(
        &mut scene,
        Material::Diffuse {
            albedo: Vec3::splat(0.15),
        },
    );
    let mesh = &mut scene.mesh;
    let side = 2.0 / TILES as f32;
    for i in 0..TILES {
        for j in 0..TILES {
            let (x0, z0) = (-1.0 + side * i as f32, -1.0 + side * j as f32);
            let (x1, z1) = (x0 + side, z0 + side);
            let base = mesh.positions.len() as u32;
            // Counter-clockwise seen from above: the normal is +Y.
            mesh.positions.extend([
                Vec3::new(x0, 0.0, z0),
                Vec3::new(x0, 0.0, z1),
                Vec3::new(x1, 0.0, z1),
                Vec3::new(x1, 0.0, z0),
            ]);
            mesh.normals.extend([Vec3::Y; 4]);
            let material = if (i + j) % 2 == 0 { light } else { dark };
            mesh.triangles.push([base, base + 1, base + 2]);
            mesh.triangles.push([base, base + 2, base + 3]);
            mesh.materials.extend([material; 2]);
        }
    }
    scene
}

/// Part 8: the focus stack and the aperture sweep.
pub fn part8(threads: usize) -> Result<()> {
    let mut setup = Setup::of("depth-of-field box", depth_scene(), threads);
    let pinhole = setup.camera;
    // The distance along the view axis of each sphere's centre: where
    // `-d` puts the plane of focus through it.
    let depth =
        |c: [f32; 3]| (Vec3::from_array(c) - pinhole.position).dot(pinhole.view_direction());
    // The circle of confusion of a point at depth z, in pixels across:
    // the lens's cone, of radius b |d - z| / d at depth z, seen from the
    // lens, against the film's half width tan(hfov / 2) = SIZE.0 / 2.
    let pixels = SIZE.0 as f32 / (0.5 * pinhole.hfov_deg.to_radians()).tan();
    let mut render = |radius: f32, focal_distance: f32, label: String| {
        let blur: Vec<String> = SPHERES
            .iter()
            .map(|&(name, c, _)| {
                let z = depth(c);
                let across = pixels * radius * (1.0 / z - 1.0 / focal_distance).abs();
                format!("{name} {across:.1}")
            })
            .collect();
        println!(
            "  {label}: circles of confusion (pixels across) {}",
            blur.join(", ")
        );
        setup.camera = pinhole.with_lens(ThinLens {
            radius,
            focal_distance,
        });
        let r = setup.render(&paths(1, 5, true), SPP, None, 800);
        Picture::of(label, &r)
    };
    let stack: Vec<Picture> = SPHERES
        .iter()
        .map(|&(name, centre, _)| {
            let d = depth(centre);
            render(
                STACK_RADIUS,
                d,
                format!("-b {STACK_RADIUS} -d {d:.2}: {name} sphere"),
            )
        })
        .collect();
    grid("w32-part8-focus.png", 4, &stack)?;
    let (front, centre, _) = SPHERES[0];
    let d = depth(centre);
    let sweep: Vec<Picture> = [0.05, 0.1, 0.2, 0.4]
        .into_iter()
        .map(|b| render(b, d, format!("-b {b} -d {d:.2}: {front} sphere")))
        .collect();
    grid("w32-part8-aperture.png", 4, &sweep)
}
