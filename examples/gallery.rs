//! Figures of docs/07-materials.md that need a scene changed in code: the
//! microfacet materials of a scene given another roughness or another
//! metal, rendered with the course's flags.
//!
//! ```text
//! cargo run --release --example gallery -- [--alpha A] [--metal NAME] -- COURSE FLAGS
//! ```
//!
//! `--alpha A` sets the Beckmann roughness of every microfacet material,
//! `--metal NAME` its complex index `eta + i k` (`gold`, `silver`,
//! `aluminium`, `copper`; [`METALS`]). Everything after `--` is what
//! `part6-materials` takes (scene, `-r -s -l -m -f -t`, ...); the path
//! tracer is part 4's, with Russian roulette, as the binaries run it.

use std::error::Error;
use std::process::ExitCode;

use clap::Parser;
use pathtracer::bvh::BvhAccel;
use pathtracer::cli::args::Builtin;
use pathtracer::cli::drivers::lighting::direct_strategy;
use pathtracer::cli::drivers::{prepare, render_lighting, Prepared};
use pathtracer::cli::CourseArgs;
use pathtracer::global::{PathTracer, Roulette};
use pathtracer::math::Rgb;
use pathtracer::scene::Material;
use pathtracer::world::World;

/// Complex indices of refraction `(eta, k)` as RGB triples: Mitsuba's
/// conductor presets `Au`, `Ag`, `Al`, `Cu` (measured spectra from Palik,
/// *Handbook of Optical Constants of Solids*, 1985, reduced to RGB), the
/// same numbers as Yocto/GL's `conductor_eta` table.
pub const METALS: [(&str, [f32; 3], [f32; 3]); 4] = [
    (
        "gold",
        [0.143119, 0.374957, 1.442479],
        [3.98316, 2.385721, 1.603215],
    ),
    (
        "silver",
        [0.155265, 0.116723, 0.138381],
        [4.828343, 3.122246, 2.14695],
    ),
    (
        "aluminium",
        [1.65746, 0.880369, 0.521229],
        [9.223869, 6.269523, 4.837001],
    ),
    (
        "copper",
        [0.200438, 0.924033, 1.102212],
        [3.912949, 2.452848, 2.142188],
    ),
];

/// The gallery's own options, then the course's flags.
struct Overrides {
    alpha: Option<f32>,
    metal: Option<(Rgb, Rgb)>,
}

fn parse(args: &[String]) -> Result<(Overrides, CourseArgs), Box<dyn Error>> {
    let mut overrides = Overrides {
        alpha: None,
        metal: None,
    };
    let mut it = args.iter();
    let mut rest = vec!["gallery".to_string()];
    while let Some(arg) = it.next() {
        match arg.as_str() {
            "--alpha" => {
                let a: f32 = it.next().ok_or("--alpha needs a value")?.parse()?;
                if !(a.is_finite() && a > 0.0) {
                    return Err(format!("--alpha {a}: expected a positive roughness").into());
                }
                overrides.alpha = Some(a);
            }
            "--metal" => {
                let name = it.next().ok_or("--metal needs a name")?;
                let (_, eta, k) = METALS
                    .iter()
                    .find(|m| m.0 == name)
                    .ok_or_else(|| format!("unknown metal {name}"))?;
                overrides.metal = Some((Rgb::from_array(*eta), Rgb::from_array(*k)));
            }
            "--" => {
                rest.extend(it.by_ref().cloned());
            }
            other => return Err(format!("unexpected argument {other}").into()),
        }
    }
    let mut course = CourseArgs::try_parse_from(rest)?;
    course.builtin = Builtin::MaterialsBox;
    Ok((overrides, course))
}

/// Gives every microfacet material the overridden roughness and index.
fn apply(overrides: &Overrides, materials: &mut [Material]) -> usize {
    let mut changed = 0;
    for m in materials {
        if let Material::Microfacet { alpha, eta, k } = m {
            if let Some(a) = overrides.alpha {
                *alpha = a;
            }
            if let Some((e, kk)) = overrides.metal {
                (*eta, *k) = (e, kk);
            }
            changed += 1;
        }
    }
    changed
}

fn run(args: &[String]) -> Result<(), Box<dyn Error>> {
    let (overrides, course) = parse(args)?;
    let Prepared {
        mut scene,
        primitives,
        camera,
    } = prepare(&course)?;
    let changed = apply(&overrides, &mut scene.materials);
    println!("{}: {changed} microfacet materials changed", scene.source);
    let accel = BvhAccel::new(primitives);
    let world = World::with_options(&scene, &accel, course.world_options());
    let tracer = PathTracer {
        direct: direct_strategy(&course, &scene),
        max_depth: course.max_depth(),
        accumulate: course.accumulate == 1,
        roulette: Roulette::Fixed,
    };
    let settings = course.render_settings();
    let rendered = render_lighting(&world, &tracer, &camera, &settings, None);
    println!(
        "render: {:.3} s on {} threads, relative standard error {:.2} %",
        rendered.stats.seconds,
        rendered.stats.threads,
        100.0 * rendered.relative_error().unwrap_or(f64::NAN)
    );
    let path = course.output_path();
    pathtracer::render::write_image(&rendered.film, &path)?;
    println!("wrote {}", path.display());
    Ok(())
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
