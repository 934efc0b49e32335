//! The gallery of symptoms, docs/13-symptoms.md: for every mistake of the
//! catalogue ([`pathtracer::mistakes`]), the course's correct image beside
//! the mistaken one and the ratio of the two, on a built-in scene, with
//! the starter function to look at.
//!
//! ```text
//! cargo run --release --example symptoms [-- -t THREADS]
//! ```
//!
//! Writes `docs/images/symptom-NAME.png` (three 320 x 240 pictures,
//! labelled) and `docs/13-symptoms.md`. Scenes are framed as the course
//! frames 480 x 360 and rendered at 320 x 240, by the course's renderer
//! ([`pathtracer::course::StarterTracer`], what `--course-exact` runs).

#[path = "gallery31/picture.rs"]
#[allow(dead_code)]
mod picture;

use std::error::Error;
use std::fmt::Write as _;
use std::path::Path;

use pathtracer::adaptive::Adaptive;
use pathtracer::bvh::WideBvhAccel;
use pathtracer::course::{pixel, Assignment, CourseExact, Lamps, StarterDirect, StarterTracer};
use pathtracer::depth_of_field::ThinLens;
use pathtracer::environment::{builtin_sky, EnvironmentLight, EnvironmentSampling};
use pathtracer::intersect::Primitives;
use pathtracer::math::{luminance, Rgb};
use pathtracer::mistakes::{Mistake, Mistakes};
use pathtracer::raygen::Camera;
use pathtracer::render::{RenderSettings, Rendered};
use pathtracer::sampling::SamplerKind;
use pathtracer::scene::{builtin, Light, Material, Scene};
use pathtracer::world::World;
use picture::{grid, Picture};

type Result<T> = std::result::Result<T, Box<dyn Error>>;

const SIZE: (u32, u32) = (320, 240);

/// The built-in scene a mistake is shown on.
#[derive(Clone, Copy)]
enum Stage {
    /// The Cornell box (`part3-direct`, `part4-global` with no scene).
    CornellBox,
    /// The Cornell box with its lamp hung 0.3 lower (made in code).
    LoweredLamp,
    /// The materials box (`part6-materials`).
    MaterialsBox,
    /// Two balls on a floor under the built-in sky (`part7-environment`).
    Sky,
}

/// How a mistake is shown: where, and with which of the course's flags.
struct Showing {
    stage: Stage,
    hemisphere: bool,
    light_samples: u32,
    max_depth: u32,
    accumulate: bool,
    spp: u32,
    /// `-b` and `-d`.
    lens: Option<ThinLens>,
    /// `-a 32 0.05`, and the rate images shown.
    adaptive: bool,
}

fn showing(m: Mistake) -> Showing {
    use Mistake::*;
    let direct = |stage| Showing {
        stage,
        hemisphere: false,
        light_samples: 1,
        max_depth: 1,
        accumulate: true,
        spp: 64,
        lens: None,
        adaptive: false,
    };
    let paths = |stage, max_depth| Showing {
        max_depth,
        ..direct(stage)
    };
    match m {
        NoPdf | HemispherePdfOneOverPi => Showing {
            hemisphere: true,
            spp: 256,
            ..direct(Stage::CornellBox)
        },
        LightFromBehind => direct(Stage::LoweredLamp),
        LightSamplesNotAveraged => Showing {
            light_samples: 4,
            ..direct(Stage::CornellBox)
        },
        FovFullAngle
        | NoCosine
        | BrdfIsAlbedo
        | ShadowAcne
        | ShadowRayReachesLight
        | DepthOffByOne => direct(Stage::CornellBox),
        AdaptiveNotSquareRooted | AdaptiveCountNotUpdated => Showing {
            spp: 128,
            adaptive: true,
            ..direct(Stage::CornellBox)
        },
        LensRadiusUnscaled => Showing {
            lens: Some(ThinLens {
                radius: 0.02,
                focal_distance: 2.0,
            }),
            spp: 128,
            ..direct(Stage::CornellBox)
        },
        FocusOnASphere => Showing {
            lens: Some(ThinLens {
                radius: 0.3,
                focal_distance: 5.0,
            }),
            spp: 128,
            ..direct(Stage::CornellBox)
        },
        NoAccumulationSumsAll => Showing {
            accumulate: false,
            ..paths(Stage::CornellBox, 3)
        },
        RouletteNotDivided | EmissionEveryBounce | ThroughputWithoutCosPdf => {
            paths(Stage::CornellBox, 5)
        }
        ReflectWrongAxis
        | RefractionRatioInverted
        | NoEtaSquared
        | NoTotalInternalReflection
        | SchlickR0NotSquared => Showing {
            spp: 128,
            ..paths(Stage::MaterialsBox, 5)
        },
        EnvPdfNoSin | EnvPdfNoJacobian | EnvMapUFlipped | EnvMapVFlipped => paths(Stage::Sky, 5),
    }
}

impl Showing {
    /// The flags that render it with a binary (its built-in scene), and a
    /// note where the figure's scene differs.
    fn command(&self, m: Mistake) -> String {
        let binary = match self.stage {
            _ if self.lens.is_some() => "part8-dof",
            _ if self.adaptive => "part5-adaptive",
            Stage::CornellBox | Stage::LoweredLamp if self.max_depth == 1 => "part3-direct",
            Stage::CornellBox | Stage::LoweredLamp => "part4-global",
            Stage::MaterialsBox => "part6-materials",
            Stage::Sky => "part7-environment",
        };
        let mut flags = format!("-r 480 360 -s {} -l {}", self.spp, self.light_samples);
        if binary != "part3-direct" {
            write!(flags, " -m {}", self.max_depth).unwrap();
        }
        if !self.accumulate {
            flags += " -o 0";
        }
        if self.hemisphere {
            flags += " -H";
        }
        if let Some(lens) = self.lens {
            write!(flags, " -b {} -d {}", lens.radius, lens.focal_distance).unwrap();
        }
        if self.adaptive {
            flags += " -a 32 0.05";
        }
        let lowered = match self.stage {
            Stage::LoweredLamp => " (the figure lowers the lamp by 0.3, in code)",
            _ => "",
        };
        format!(
            "`cargo run --release --bin {binary} -- {flags} --mistake {}`{lowered}",
            m.info().name
        )
    }
}

/// A built-in scene with its camera, BVH and light.
struct Staged {
    scene: Scene,
    camera: Camera,
    accel: WideBvhAccel,
    environment: Option<EnvironmentLight>,
}

fn stage(how: &Showing) -> Result<Staged> {
    let stage = how.stage;
    let mut scene = match stage {
        Stage::CornellBox | Stage::LoweredLamp => builtin::cornell_box(),
        Stage::MaterialsBox => builtin::materials_box(),
        Stage::Sky => builtin::environment_spheres(),
    };
    if let Stage::LoweredLamp = stage {
        lower_lamp(&mut scene, 0.3);
    }
    let environment = match stage {
        Stage::Sky => Some(EnvironmentLight::new(
            builtin_sky()?,
            EnvironmentSampling::Importance,
        )),
        _ => None,
    };
    let primitives = Primitives::from_scene(&scene);
    let camera = Camera::course_placement(&scene.camera, &primitives.bounds(), 480, 360);
    let camera = match how.lens {
        Some(lens) => camera.with_lens(lens),
        None => camera,
    };
    Ok(Staged {
        accel: WideBvhAccel::new(primitives),
        scene,
        camera,
        environment,
    })
}

/// Moves the area lights and the emissive triangles down by `drop`.
fn lower_lamp(scene: &mut Scene, drop: f32) {
    for light in &mut scene.lights {
        if let Light::Area { center, .. } = light {
            center.y -= drop;
        }
    }
    let mut moved = vec![false; scene.mesh.positions.len()];
    for (t, &m) in scene.mesh.triangles.iter().zip(&scene.mesh.materials) {
        if matches!(scene.materials[m as usize], Material::Emission { .. }) {
            for &v in t {
                if !std::mem::replace(&mut moved[v as usize], true) {
                    scene.mesh.positions[v as usize].y -= drop;
                }
            }
        }
    }
}

fn render(staged: &Staged, how: &Showing, mistakes: Mistakes, threads: usize) -> Rendered {
    let exact = CourseExact {
        assignment: Assignment::PathTracer1,
    };
    let world = World::with_options(&staged.scene, &staged.accel, exact.world_options())
        .with_environment(staged.environment.clone());
    let tracer = StarterTracer {
        direct: if how.hemisphere {
            StarterDirect::Hemisphere
        } else {
            StarterDirect::Importance
        },
        light_samples: how.light_samples,
        max_depth: how.max_depth,
        accumulate: how.accumulate,
        lamps: Lamps::MeshFaces,
        mistakes,
    };
    let settings = RenderSettings {
        width: SIZE.0,
        height: SIZE.1,
        samples_per_pixel: how.spp,
        threads: Some(threads),
        seed: 1,
        sampler: SamplerKind::Independent,
        progress: false,
    };
    let adaptive = how.adaptive.then(Adaptive::default);
    pixel::render(&staged.camera, &settings, adaptive, mistakes, |ray, s| {
        tracer.radiance(&world, ray, s)
    })
}

/// The ratio of `wrong` to `right` luminance over 4 x 4 pixel blocks (less
/// noise), as colours: `log2` of the ratio from -2 (blue, a quarter) through
/// 0 (white) to 2 (red, four times), grey where both are black; a colour
/// bar along the bottom 12 rows.
fn ratio_map(wrong: &Rendered, right: &Rendered) -> Vec<Rgb> {
    let (w, h) = SIZE;
    let block = |film: &pathtracer::render::Film, bx: u32, by: u32| -> f32 {
        let mut sum = 0.0;
        for y in by * 4..(by * 4 + 4).min(h) {
            for x in bx * 4..(bx * 4 + 4).min(w) {
                sum += luminance(film.get(x, y));
            }
        }
        sum
    };
    let colour = |t: f32| {
        // t in [-1, 1]: blue to white to red.
        let t = t.clamp(-1.0, 1.0);
        if t < 0.0 {
            Rgb::new(1.0 + t, 1.0 + t, 1.0)
        } else {
            Rgb::new(1.0, 1.0 - t, 1.0 - t)
        }
    };
    let mut out = Vec::with_capacity((w * h) as usize);
    for y in 0..h {
        for x in 0..w {
            if y >= h - 12 {
                out.push(colour(2.0 * x as f32 / (w - 1) as f32 - 1.0));
                continue;
            }
            let (a, b) = (
                block(&wrong.film, x / 4, y / 4),
                block(&right.film, x / 4, y / 4),
            );
            out.push(if a <= 1e-6 && b <= 1e-6 {
                Rgb::splat(0.6)
            } else {
                colour(((a + 1e-6) / (b + 1e-6)).log2() / 2.0)
            });
        }
    }
    out
}

fn main() -> std::process::ExitCode {
    match run() {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::ExitCode::FAILURE
        }
    }
}

fn run() -> Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let threads = match args.iter().position(|a| a == "-t") {
        Some(i) => args.get(i + 1).ok_or("-t needs a value")?.parse()?,
        None => 2,
    };
    let mut doc = String::from(HEADER);
    let mut part = 0;
    for m in Mistake::ALL {
        let info = m.info();
        let how = showing(m);
        let staged = stage(&how)?;
        let right = render(&staged, &how, Mistakes::NONE, threads);
        let wrong = render(&staged, &how, Mistakes::of(&[m]), threads);
        let name = format!("symptom-{}.png", info.name);
        let mut pictures = vec![
            Picture::of("the course's image (--course-exact)", &right),
            Picture::of(format!("--mistake {}", info.name), &wrong),
            Picture::display(
                "mistaken / correct: blue 1/4, white 1, red 4",
                SIZE.0,
                SIZE.1,
                ratio_map(&wrong, &right),
            ),
        ];
        if how.adaptive {
            pictures.push(Picture::rate("its sample rates", &right, how.spp));
            pictures.push(Picture::rate("the mistake's sample rates", &wrong, how.spp));
        }
        grid(&name, 3, &pictures)?;
        if info.part != part {
            part = info.part;
            writeln!(doc, "\n## Part {part}\n")?;
        }
        let (r, w) = (mean(&right), mean(&wrong));
        writeln!(
            doc,
            "### `{}`\n\n**Look at** `{}`. **Wrong:** {}. **Shows:** {}.\n\n\
             ![{} beside the course's image](images/{name})\n\n\
             Image mean (the lamp included), mistaken over correct: {:.3}. {}\n",
            info.name,
            info.function,
            info.what,
            info.symptom,
            info.name,
            w / r,
            how.command(m)
        )?;
    }
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/13-symptoms.md");
    std::fs::write(&path, doc)?;
    println!("wrote {}", path.display());
    Ok(())
}

fn mean(rendered: &Rendered) -> f64 {
    let pixels = &rendered.film.pixels;
    pixels.iter().map(|&p| luminance(p) as f64).sum::<f64>() / pixels.len() as f64
}

const HEADER: &str = "# Symptoms: what each mistake looks like

<!-- Written by `cargo run --release --example symptoms`; edit the
catalogue (src/mistakes/mod.rs) or the example, not this file. -->

Each section shows one mistake of the catalogue (`--mistake list`): the
image a correct course solution renders (`--course-exact`, left), the
image with the mistake (middle), and the ratio of the two (right: 4 x 4
pixel blocks, blue where the mistake darkens, red where it brightens, grey
where both are black; the bar along the bottom runs from a quarter to four
times). It names the starter function to look at, what is wrong in it,
and what to look for. Every mistake renders with any lighting binary
(`--mistake NAME`, repeatable) and is tested for its symptom
(`tests/mistakes.rs`, `tests/mistakes_3_2.rs`).

Made by one command, on this project's built-in scenes, framed as the
course frames 480 x 360 and rendered at 320 x 240 by the course's renderer
(the command under each picture renders it at 480 x 360 with a binary):

```sh
cargo run --release --example symptoms
```

The renders are noisy the way a student's are: independent random
numbers, the course's light sampling, no multiple importance sampling.
What a mistake changes is what the ratio shows, beyond that noise.

Not in the catalogue yet: the intersection and BVH mistakes of parts 1
and 2 (a hit accepted outside `[min_t, max_t]`, the sphere's far root,
permuted barycentric weights, a box test that misses rays starting
inside, traversal that returns the first hit, `max_t` not shrunk), which
need a student's intersector, and a few of parts 1, 3 and 5 (the field of
view in degrees, directions not normalised or left in camera space, the
light's cosine left out, the population variance).
";
