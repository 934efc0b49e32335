//! The figures the course's 3-1 write-up asks for, parts 1 to 5, one
//! subcommand per chapter:
//!
//! ```text
//! export CS184_SCENES=/path/to/p3_1-pathtracer/dae
//! cargo run --release --example gallery31 -- part1|part2|part3|part4|part5 [-t N]
//! ```
//!
//! Each subcommand renders its chapter's figures and writes them to
//! `docs/images/` as labelled grids (`w31-*.png`), printing what it did.
//! `-t N` sets the worker threads (default 2).
//!
//! Scenes are framed as the course frames a 480 x 360 render (the whole
//! Cornell box) and rendered at 240 x 180: the course's field of view
//! follows the output size (docs/01-raygen.md), so asking the binaries for
//! 240 x 180 would crop the view instead. Everything else is what the
//! binaries run: the same loader, BVH, plan ([`Plan::specialise`]),
//! path tracer and tone map.

#[path = "support/font.rs"]
mod font;

use std::error::Error;
use std::path::{Path, PathBuf};
use std::time::Instant;

use pathtracer::adaptive::{rate_colour, Adaptive};
use pathtracer::bvh::BvhAccel;
use pathtracer::cli::drivers::render_lighting;
use pathtracer::cli::drivers::render_normals;
use pathtracer::direct::{DirectHemisphere, DirectLights};
use pathtracer::global::{DirectStrategy, PathTracer, Roulette};
use pathtracer::intersect::{Aabb, LinearScan, Primitives, TriangleTest};
use pathtracer::math::{luminance, Rgb};
use pathtracer::plan::Plan;
use pathtracer::raygen::Camera;
use pathtracer::render::{tone_map, write_png, RenderSettings, Rendered};
use pathtracer::sampling::SamplerKind;
use pathtracer::scene::{course_files, Scene};
use pathtracer::world::World;
use plotters::prelude::*;

type Result<T> = std::result::Result<T, Box<dyn Error>>;

/// The course frames scenes for this size...
const FRAME: (u32, u32) = (480, 360);
/// ...and the gallery renders them at this one.
const SIZE: (u32, u32) = (240, 180);

/// Height of the label band above each picture of a grid, pixels.
const LABEL: u32 = 20;

/// A course scene, its BVH and the camera the course places for [`FRAME`].
struct Setup {
    name: String,
    scene: Scene,
    accel: BvhAccel,
    camera: Camera,
    threads: usize,
}

impl Setup {
    fn load(file: &str, threads: usize) -> Result<Self> {
        let path = course_files::find(file).ok_or_else(|| {
            format!(
                "{file} not found ({}); {}",
                course_files::searched(),
                course_files::HOW_TO_ENABLE
            )
        })?;
        let scene = pathtracer::scene::load(&path)?;
        let primitives = Primitives::from_scene(&scene);
        let camera =
            Camera::course_placement(&scene.camera, &primitives.bounds(), FRAME.0, FRAME.1);
        Ok(Setup {
            name: file.to_string(),
            scene,
            accel: BvhAccel::new(primitives),
            camera,
            threads,
        })
    }

    fn settings(&self, samples_per_pixel: u32, seed: u64) -> RenderSettings {
        RenderSettings {
            width: SIZE.0,
            height: SIZE.1,
            samples_per_pixel,
            threads: Some(self.threads),
            seed,
            // The independent sampler the documented studies were measured with.
            sampler: SamplerKind::Independent,
            progress: false,
        }
    }

    /// Renders as the binaries do: the tracer specialised by the scene's
    /// plan, `spp` camera rays per pixel, adaptive sampling if asked.
    fn render(
        &self,
        tracer: &PathTracer,
        spp: u32,
        adaptive: Option<Adaptive>,
        seed: u64,
    ) -> Rendered {
        let world = World::new(&self.scene, &self.accel);
        let plan = Plan::new(&self.scene, &world.lights, tracer, &self.camera.lens);
        let tracer = plan.specialise(tracer);
        let rendered = render_lighting(
            &world,
            &tracer,
            &self.camera,
            &self.settings(spp, seed),
            adaptive,
        );
        println!(
            "  {}: -s {spp} -m {} -o {}: {:.1} s, mean {:.0} spp",
            self.name,
            tracer.max_depth,
            tracer.accumulate as u8,
            rendered.stats.seconds,
            rendered.mean_samples_per_pixel()
        );
        rendered
    }
}

/// Light sampling with `l` samples per light and MIS (the default flags).
fn lights(l: u32) -> DirectStrategy {
    DirectStrategy::Lights(DirectLights {
        samples_per_light: l,
        mis: true,
    })
}

/// The path tracer of `part4-global`: `-l l -m m -o o`, Russian roulette.
fn paths(l: u32, m: u32, accumulate: bool) -> PathTracer {
    PathTracer {
        direct: lights(l),
        max_depth: m,
        accumulate,
        roulette: Roulette::Fixed,
    }
}

/// The direct-only tracer of `part3-direct`.
fn direct(strategy: DirectStrategy) -> PathTracer {
    PathTracer {
        direct: strategy,
        max_depth: 1,
        accumulate: true,
        roulette: Roulette::Off,
    }
}

/// Display values (tone mapped, in `[0, 1]`) of one picture of a grid.
struct Picture {
    label: String,
    width: u32,
    height: u32,
    display: Vec<Rgb>,
}

impl Picture {
    fn radiance(label: impl Into<String>, width: u32, height: u32, radiance: &[Rgb]) -> Self {
        Picture {
            label: label.into(),
            width,
            height,
            display: radiance.iter().map(|&l| tone_map(l)).collect(),
        }
    }

    fn of(label: impl Into<String>, rendered: &Rendered) -> Self {
        let film = &rendered.film;
        Picture::radiance(label, film.width, film.height, &film.pixels)
    }

    /// The course's sample-rate image of an adaptive render.
    fn rate(label: impl Into<String>, rendered: &Rendered, max_samples: u32) -> Self {
        Picture {
            label: label.into(),
            width: rendered.film.width,
            height: rendered.film.height,
            display: rendered
                .estimates
                .iter()
                .map(|e| rate_colour(e.samples, max_samples))
                .collect(),
        }
    }
}

/// Writes `pictures` (all one size) as a grid of `columns`, each with its
/// label above it, to `docs/images/NAME`.
fn grid(name: &str, columns: usize, pictures: &[Picture]) -> Result<()> {
    font::register_font()?;
    let (w, h) = (pictures[0].width, pictures[0].height);
    let gap = 4;
    let cols = columns.min(pictures.len()) as u32;
    let rows = pictures.len().div_ceil(columns) as u32;
    let (cell_w, cell_h) = (w + gap, h + LABEL + gap);
    let (width, height) = (cols * cell_w - gap, rows * cell_h - gap);
    let mut buffer = vec![255u8; (width * height * 3) as usize];
    for (i, picture) in pictures.iter().enumerate() {
        let (x0, y0) = (
            (i as u32 % cols) * cell_w,
            (i as u32 / cols) * cell_h + LABEL,
        );
        for y in 0..h {
            for x in 0..w {
                let v = picture.display[(y * w + x) as usize].clamp(Rgb::ZERO, Rgb::ONE) * 255.0;
                let at = (((y0 + y) * width + x0 + x) * 3) as usize;
                buffer[at..at + 3].copy_from_slice(&v.round().to_array().map(|c| c as u8));
            }
        }
    }
    {
        let root = BitMapBackend::with_buffer(&mut buffer, (width, height)).into_drawing_area();
        let style = TextStyle::from(("sans-serif", 15).into_font()).color(&BLACK);
        for (i, picture) in pictures.iter().enumerate() {
            let (x0, y0) = ((i as u32 % cols) * cell_w, (i as u32 / cols) * cell_h);
            root.draw_text(&picture.label, &style, (x0 as i32 + 2, y0 as i32 + 2))?;
        }
        root.present()?;
    }
    let display: Vec<Rgb> = buffer
        .chunks(3)
        .map(|c| Rgb::new(c[0] as f32, c[1] as f32, c[2] as f32) / 255.0)
        .collect();
    let path = images().join(name);
    write_png(width, height, &display, &path)?;
    println!("wrote {}", path.display());
    Ok(())
}

fn images() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/images")
}

/// Part 1: normal shading of small scenes by linear scan and
/// Möller-Trumbore, as `part1-raygen` renders it.
fn part1(threads: usize) -> Result<()> {
    let mut pictures = Vec::new();
    for file in [
        "CBempty.dae",
        "CBspheres_lambertian.dae",
        "cube.dae",
        "plane.dae",
    ] {
        let setup = Setup::load(file, threads)?;
        let mut primitives = setup.accel.primitives.clone();
        primitives.triangle_test = TriangleTest::MollerTrumbore;
        let rendered = render_normals(
            LinearScan::new(&primitives),
            &setup.camera,
            &setup.settings(1, 0),
        );
        println!(
            "  {file}: {} primitives, {:.2} s",
            primitives.len(),
            rendered.stats.seconds
        );
        pictures.push(Picture::of(file, &rendered));
    }
    grid("w31-part1-normals.png", 4, &pictures)
}

/// Part 2: large meshes through the BVH, the time of the same render by
/// linear scan, and the BVH's boxes at chosen depths over a mesh.
fn part2(threads: usize) -> Result<()> {
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

/// Part 3: hemisphere against light sampling at equal samples, and soft
/// shadows at one sample per pixel against samples per light.
fn part3(threads: usize) -> Result<()> {
    let mut pictures = Vec::new();
    for file in ["CBspheres_lambertian.dae", "CBbunny.dae"] {
        let setup = Setup::load(file, threads)?;
        let lamps = setup.scene.lights.len().max(1) as u32;
        let hemisphere = direct(DirectStrategy::Hemisphere(DirectHemisphere {
            samples: lamps * 8,
        }));
        let short = file.trim_end_matches(".dae");
        let r = setup.render(&hemisphere, 16, None, 1);
        pictures.push(Picture::of(format!("{short}, -H"), &r));
        let r = setup.render(&direct(lights(8)), 16, None, 1);
        pictures.push(Picture::of(format!("{short}, lights"), &r));
    }
    grid("w31-part3-hemisphere-lights.png", 4, &pictures)?;

    let setup = Setup::load("CBbunny.dae", threads)?;
    let mut pictures = Vec::new();
    for l in [1, 4, 16, 64] {
        let r = setup.render(&direct(lights(l)), 1, None, 2);
        pictures.push(Picture::of(format!("-s 1 -l {l}"), &r));
    }
    grid("w31-part3-soft-shadows.png", 4, &pictures)
}

/// Part 4: direct against indirect light, each bounce alone and
/// accumulated, Russian roulette at several depths, samples per pixel.
fn part4(threads: usize) -> Result<()> {
    let setup = Setup::load("CBbunny.dae", threads)?;
    let spp = 256;
    // The m-th bounce alone (-o 0) for m = 0..5: unbiased estimates of
    // disjoint parts of the image, so bounces 0 + 1 are the direct light
    // and 2 to 5 the indirect light of `-m 5`, exactly as defined.
    let bounces: Vec<Rendered> = (0..=5)
        .map(|m| setup.render(&paths(4, m, false), spp, None, 10 + m as u64))
        .collect();
    let (w, h) = SIZE;
    let sum = |range: std::ops::RangeInclusive<usize>| -> Vec<Rgb> {
        (0..(w * h) as usize)
            .map(|i| range.clone().map(|m| bounces[m].film.pixels[i]).sum())
            .collect()
    };
    let direct_light = sum(0..=1);
    let indirect = sum(2..=5);
    let total = setup.render(&paths(4, 5, true), spp, None, 20);
    let mean = |v: &[Rgb]| v.iter().map(|&l| luminance(l) as f64).sum::<f64>() / v.len() as f64;
    println!(
        "  mean luminance: direct {:.4} + indirect {:.4} = {:.4}; -m 5 -o 1 renders {:.4}",
        mean(&direct_light),
        mean(&indirect),
        mean(&direct_light) + mean(&indirect),
        mean(&total.film.pixels)
    );
    grid(
        "w31-part4-direct-indirect.png",
        3,
        &[
            Picture::radiance("direct (bounces 0, 1)", w, h, &direct_light),
            Picture::radiance("indirect (bounces 2-5)", w, h, &indirect),
            Picture::of("both: -m 5", &total),
        ],
    )?;

    let mut pictures: Vec<Picture> = bounces
        .iter()
        .enumerate()
        .map(|(m, r)| Picture::of(format!("-m {m} -o 0"), r))
        .collect();
    for m in 0..=5 {
        let r = setup.render(&paths(4, m, true), spp, None, 30 + m as u64);
        pictures.push(Picture::of(format!("-m {m} -o 1"), &r));
    }
    grid("w31-part4-bounces.png", 6, &pictures)?;

    let mut pictures = Vec::new();
    for m in [0, 1, 2, 3, 4, 100] {
        let r = setup.render(&paths(4, m, true), spp, None, 40 + m as u64);
        pictures.push(Picture::of(format!("-m {m}"), &r));
    }
    grid("w31-part4-roulette.png", 6, &pictures)?;

    let mut pictures = Vec::new();
    for s in [1, 2, 4, 8, 16, 64, 1024] {
        let r = setup.render(&paths(4, 5, true), s, None, 50 + s as u64);
        pictures.push(Picture::of(format!("-s {s}"), &r));
    }
    grid("w31-part4-samples.png", 4, &pictures)
}

/// Part 5: two scenes at 2048 samples per pixel with adaptive sampling
/// (the course's default `-a 32 0.05`), with their rate images.
fn part5(threads: usize) -> Result<()> {
    let spp = 2048;
    let mut pictures = Vec::new();
    for file in ["CBbunny.dae", "CBspheres_lambertian.dae"] {
        let setup = Setup::load(file, threads)?;
        let r = setup.render(&paths(4, 5, true), spp, Some(Adaptive::default()), 60);
        let short = file.trim_end_matches(".dae");
        pictures.push(Picture::of(short, &r));
        let mean = r.mean_samples_per_pixel();
        pictures.push(Picture::rate(format!("rate: mean {mean:.0} spp"), &r, spp));
    }
    grid("w31-part5-adaptive.png", 4, &pictures)
}

fn run(args: &[String]) -> Result<()> {
    let mut threads = 2;
    let mut parts = Vec::new();
    let mut it = args.iter();
    while let Some(arg) = it.next() {
        match arg.as_str() {
            "-t" => threads = it.next().ok_or("-t needs a value")?.parse()?,
            "part1" | "part2" | "part3" | "part4" | "part5" => parts.push(arg.clone()),
            other => {
                return Err(
                    format!("unexpected argument {other}; expected part1 .. part5 [-t N]").into(),
                )
            }
        }
    }
    if parts.is_empty() {
        return Err("which part? part1 .. part5".into());
    }
    for part in parts {
        println!("{part}:");
        match part.as_str() {
            "part1" => part1(threads)?,
            "part2" => part2(threads)?,
            "part3" => part3(threads)?,
            "part4" => part4(threads)?,
            _ => part5(threads)?,
        }
    }
    Ok(())
}

fn main() -> std::process::ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::ExitCode::FAILURE
        }
    }
}
