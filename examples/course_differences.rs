//! The table of docs/14-course-image.md: what each thing `--course-exact`
//! does differently from the project changes in the image. For each, a
//! course scene is rendered with the course's image settings
//! ([`CourseExact`]) and again with that one thing as the project does it;
//! the table gives the ratio of the two images' mean radiance (course /
//! project), the largest change of an 8 x 6 block's mean, and the noise of
//! the means.
//!
//! ```text
//! cargo run --release --example course_differences [-- -r 480 360 -s 64]
//! ```
//!
//! Needs the course's scenes (`CS184_SCENES`, or `../shared/scenes/cs184`).

use std::error::Error;

use pathtracer::bvh::WideBvhAccel;
use pathtracer::course::pixel::StopRule;
use pathtracer::course::{Assignment, Choices, CourseExact, Lamps, StarterDirect, StarterTracer};
use pathtracer::direct::DirectHemisphere;
use pathtracer::global::{DirectStrategy, PathTracer, Roulette};
use pathtracer::intersect::Primitives;
use pathtracer::lights::LightConvention;
use pathtracer::materials::{EtaScaling, FresnelModel, MicrofacetModel};
use pathtracer::math::{luminance, Rgb};
use pathtracer::mistakes::Mistakes;
use pathtracer::raygen::Camera;
use pathtracer::render::{render_image, tone_map, Quantization, RenderSettings, Rendered};
use pathtracer::scene::course_files;
use pathtracer::world::{World, WorldOptions};

/// How one of the two images of a row is rendered.
#[derive(Clone, Copy)]
enum Renderer {
    /// The course's functions under these options; with the staff's
    /// early-stop factor when `staff`.
    Course {
        options: WorldOptions,
        tracer: StarterTracer,
        staff: bool,
    },
    /// The project's path tracer under these options.
    Project {
        options: WorldOptions,
        tracer: PathTracer,
    },
}

/// One row: the difference, the scene and settings, the two renderers.
struct Row {
    what: &'static str,
    scene: &'static str,
    flags: &'static str,
    adaptive: bool,
    course: Renderer,
    project: Renderer,
}

fn main() -> Result<(), Box<dyn Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let value = |flag: &str, i: usize, default: u32| -> u32 {
        args.iter()
            .position(|a| a == flag)
            .and_then(|p| args.get(p + 1 + i))
            .and_then(|v| v.parse().ok())
            .unwrap_or(default)
    };
    let (width, height, spp) = (value("-r", 0, 480), value("-r", 1, 360), value("-s", 0, 64));
    println!(
        "| what | scene, flags | course / project: image mean | median block | largest block change | noise of a mean |"
    );
    println!("| --- | --- | ---: | ---: | ---: | ---: |");
    for row in rows() {
        let Some(path) = course_files::find(row.scene) else {
            println!("| {} | {} not found | | | | |", row.what, row.scene);
            continue;
        };
        let scene = pathtracer::scene::load(&path)?;
        let primitives = Primitives::from_scene(&scene);
        let camera = Camera::course_placement(&scene.camera, &primitives.bounds(), width, height);
        let accel = WideBvhAccel::new(primitives);
        let settings = RenderSettings {
            width,
            height,
            samples_per_pixel: spp,
            threads: None,
            seed: 1,
            sampler: pathtracer::sampling::SamplerKind::Independent,
            progress: false,
        };
        let adaptive = row.adaptive.then(pathtracer::adaptive::Adaptive::default);
        let render = |renderer: Renderer, seed: u64| -> Rendered {
            let settings = RenderSettings { seed, ..settings };
            match renderer {
                Renderer::Course {
                    options,
                    tracer,
                    staff,
                } => {
                    let world = World::with_options(&scene, &accel, options);
                    let mut rendered = render_image(&camera, &settings, adaptive, |ray, s| {
                        tracer.radiance(&world, ray, s)
                    });
                    if staff {
                        StopRule::StaffOneLate.write_stopped(&mut rendered, spp);
                    }
                    rendered
                }
                Renderer::Project { options, tracer } => {
                    let world = World::with_options(&scene, &accel, options);
                    render_image(&camera, &settings, adaptive, |ray, s| {
                        tracer.radiance(&world, ray, s)
                    })
                }
            }
        };
        let a = render(row.course, 1);
        let b = render(row.project, 2);
        let (ma, mb) = (mean(&a.film.pixels), mean(&b.film.pixels));
        let (median, blocks) = block_changes(&a, &b);
        let noise = (a.relative_error().unwrap_or(0.0) / (a.film.pixels.len() as f64).sqrt())
            .max(b.relative_error().unwrap_or(0.0) / (b.film.pixels.len() as f64).sqrt());
        println!(
            "| {} | `{}` {} | {:.4} | {:.4} | {:+.1} % | {:.2} % |",
            row.what,
            row.scene,
            row.flags,
            ma / mb,
            median,
            100.0 * blocks,
            100.0 * noise
        );
    }
    // The PNG's quantization, on the course's image of the first scene.
    if let Some(path) = course_files::find("CBspheres_lambertian.dae") {
        let scene = pathtracer::scene::load(&path)?;
        let primitives = Primitives::from_scene(&scene);
        let camera = Camera::course_placement(&scene.camera, &primitives.bounds(), width, height);
        let accel = WideBvhAccel::new(primitives);
        let world = World::with_options(&scene, &accel, course().world_options());
        let settings = RenderSettings {
            width,
            height,
            samples_per_pixel: spp,
            threads: None,
            seed: 3,
            sampler: pathtracer::sampling::SamplerKind::Independent,
            progress: false,
        };
        let tracer = starter(5, Lamps::MeshFaces, StarterDirect::Importance);
        let rendered = render_image(&camera, &settings, None, |ray, s| {
            tracer.radiance(&world, ray, s)
        });
        let decoded = |q: Quantization| -> f64 {
            let sum: f64 = rendered
                .film
                .pixels
                .iter()
                .map(|&p| {
                    let d = tone_map(p).to_array().map(|v| {
                        // Back to linear radiance from the 8-bit value, as
                        // a viewer of the PNG would (bin centres).
                        let byte = q.apply(v) as f32;
                        ((byte + 0.5) / 256.0).powf(2.2) / std::f32::consts::SQRT_2
                    });
                    luminance(Rgb::from_array(d)) as f64
                })
                .sum();
            sum / rendered.film.pixels.len() as f64
        };
        println!(
            "| PNG values truncated, not rounded | `CBspheres_lambertian.dae` -m 5, decoded | {:.4} | | | |",
            decoded(Quantization::Truncate) / decoded(Quantization::Round)
        );
    }
    Ok(())
}

fn course() -> CourseExact {
    CourseExact {
        assignment: Assignment::PathTracer1,
    }
}

fn starter(max_depth: u32, lamps: Lamps, direct: StarterDirect) -> StarterTracer {
    StarterTracer {
        direct,
        light_samples: 1,
        max_depth,
        accumulate: true,
        lamps,
        choices: Choices::of(Assignment::PathTracer1),
        mistakes: Mistakes::NONE,
    }
}

/// The course's renderer with `change` applied to its world options.
fn course_with(max_depth: u32, lamps: Lamps, change: impl Fn(&mut WorldOptions)) -> Renderer {
    let mut options = course().world_options();
    change(&mut options);
    Renderer::Course {
        options,
        tracer: starter(max_depth, lamps, StarterDirect::Importance),
        staff: false,
    }
}

fn rows() -> Vec<Row> {
    let plain = |m| course_with(m, Lamps::MeshFaces, |_| {});
    let hemisphere = DirectStrategy::Hemisphere(DirectHemisphere { samples: 1 });
    vec![
        Row {
            what: "light samples by the starter's `sample_L`",
            scene: "CBspheres_lambertian.dae",
            flags: "-m 5",
            adaptive: false,
            course: plain(5),
            project: course_with(5, Lamps::MeshFaces, |o| {
                o.light_convention = LightConvention::Physical
            }),
        },
        Row {
            what: "`-H` sees the lamp mesh, not the area light",
            scene: "CBspheres_lambertian.dae",
            flags: "-H -m 1",
            adaptive: false,
            course: Renderer::Course {
                options: course().world_options(),
                tracer: starter(1, Lamps::MeshFaces, StarterDirect::Hemisphere),
                staff: false,
            },
            project: Renderer::Project {
                options: course().world_options(),
                tracer: PathTracer {
                    direct: hemisphere,
                    max_depth: 1,
                    accumulate: true,
                    roulette: Roulette::Off,
                    glass_splits: 0,
                },
            },
        },
        Row {
            what: "3-2 lamps: the light's own quad, `L / A cos`",
            scene: "CBspheres.dae",
            flags: "-m 8",
            adaptive: false,
            course: course_with(8, Lamps::LightQuads, |_| {}),
            project: plain(8),
        },
        Row {
            what: "glass by Schlick's approximation",
            scene: "CBspheres.dae",
            flags: "-m 8",
            adaptive: false,
            course: plain(8),
            project: course_with(8, Lamps::MeshFaces, |o| {
                o.bsdf.fresnel = FresnelModel::Exact
            }),
        },
        Row {
            what: "radiance across glass by the starter's `eta`",
            scene: "CBspheres.dae",
            flags: "-m 8",
            adaptive: false,
            course: plain(8),
            project: course_with(8, Lamps::MeshFaces, |o| {
                o.bsdf.eta_scaling = EtaScaling::Physical
            }),
        },
        Row {
            what: "the starter's microfacet `Lambda` and `F(wi)`",
            scene: "CBspheres_microfacet_al_ag.dae",
            flags: "-m 5",
            adaptive: false,
            course: plain(5),
            project: course_with(5, Lamps::MeshFaces, |o| {
                o.bsdf.microfacet_model = MicrofacetModel::Physical
            }),
        },
        Row {
            what: "3-2: the staff's mean of a pixel that stops early",
            scene: "CBspheres_lambertian.dae",
            flags: "-m 5 -a 32 0.05",
            adaptive: true,
            course: Renderer::Course {
                options: course().world_options(),
                tracer: starter(5, Lamps::MeshFaces, StarterDirect::Importance),
                staff: true,
            },
            project: plain(5),
        },
    ]
}

fn mean(pixels: &[Rgb]) -> f64 {
    pixels.iter().map(|&p| luminance(p) as f64).sum::<f64>() / pixels.len() as f64
}

/// The median ratio of the 8 x 6 blocks' mean luminance, `a` over `b`,
/// and the largest relative change of one, over the blocks that are not
/// black (the median is blind to the lamp, which dominates the mean).
fn block_changes(a: &Rendered, b: &Rendered) -> (f64, f64) {
    let (ba, bb) = (a.film.block_means(8, 6), b.film.block_means(8, 6));
    let mut ratios: Vec<f64> = ba
        .iter()
        .zip(&bb)
        .map(|(&x, &y)| (luminance(x) as f64, luminance(y) as f64))
        .filter(|&(_, y)| y > 1e-3)
        .map(|(x, y)| x / y)
        .collect();
    let largest = ratios
        .iter()
        .map(|r| r - 1.0)
        .fold(0.0, |m: f64, d| if d.abs() > m.abs() { d } else { m });
    ratios.sort_by(f64::total_cmp);
    let median = ratios.get(ratios.len() / 2).copied().unwrap_or(f64::NAN);
    (median, largest)
}
