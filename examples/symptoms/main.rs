//! The gallery of symptoms, docs/13-symptoms.md: for every mistake of the
//! catalogue ([`pathtracer::mistakes`]), the course's correct image beside
//! the mistaken one and the ratio of the two, on a built-in scene, with
//! the starter function to look at.
//!
//! ```text
//! cargo run --release --example symptoms [-- -t THREADS] [--only NAME]...
//! ```
//!
//! `--only NAME` renders the pictures of the mistakes named, prints their
//! sections of docs/13-symptoms.md and leaves the file as it is.
//!
//! Writes `docs/images/symptom-NAME.png` (three 320 x 240 pictures,
//! labelled) and `docs/13-symptoms.md`. Scenes are framed as the course
//! frames 480 x 360 and rendered at 320 x 240, by the course's renderer
//! ([`pathtracer::course::StarterTracer`], what `--course-exact` runs).

#[path = "../gallery31/picture.rs"]
#[allow(dead_code)]
mod picture;
mod showing;

use std::error::Error;
use std::fmt::Write as _;
use std::path::Path;

use pathtracer::adaptive::Adaptive;
use pathtracer::course::{
    Assignment, Choices, CourseExact, CourseSampling, CourseView, Lamps, StarterDirect,
    StarterTracer,
};
use pathtracer::math::{luminance, ratio_colour, Rgb};
use pathtracer::mistakes::{Mistake, Mistakes};
use pathtracer::render::{RenderSettings, Rendered};
use pathtracer::sampling::SamplerKind;
use picture::{grid, Picture};
use showing::{showing, stage, Showing, Staged};

type Result<T> = std::result::Result<T, Box<dyn Error>>;

/// The size of each picture.
pub const SIZE: (u32, u32) = (320, 240);

fn render(staged: &Staged, how: &Showing, mistakes: Mistakes, threads: usize) -> Rendered {
    let exact = CourseExact {
        assignment: Assignment::PathTracer1,
    };
    let tracer = StarterTracer {
        direct: StarterDirect::from_hemisphere(how.hemisphere),
        light_samples: how.light_samples,
        max_depth: how.max_depth,
        accumulate: how.accumulate,
        lamps: Lamps::MeshFaces,
        choices: Choices::of(Assignment::PathTracer1),
        mistakes,
    };
    let view = CourseView {
        scene: &staged.scene,
        camera: &staged.camera,
        environment: staged.environment.as_ref(),
    };
    let sampling = CourseSampling {
        settings: RenderSettings {
            width: SIZE.0,
            height: SIZE.1,
            samples_per_pixel: how.spp,
            threads: Some(threads),
            seed: 1,
            sampler: SamplerKind::Independent,
            progress: false,
        },
        adaptive: how.adaptive.then(Adaptive::default),
    };
    exact.render(view, &staged.accel, &tracer, &sampling)
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
    let mut out = Vec::with_capacity((w * h) as usize);
    for y in 0..h {
        for x in 0..w {
            if y >= h - 12 {
                out.push(ratio_colour(2.0 * x as f32 / (w - 1) as f32 - 1.0));
                continue;
            }
            let (a, b) = (
                block(&wrong.film, x / 4, y / 4),
                block(&right.film, x / 4, y / 4),
            );
            out.push(if a <= 1e-6 && b <= 1e-6 {
                Rgb::splat(0.6)
            } else {
                ratio_colour(((a + 1e-6) / (b + 1e-6)).log2() / 2.0)
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
    let only: Vec<Mistake> = args
        .iter()
        .enumerate()
        .filter(|(_, a)| *a == "--only")
        .map(|(i, _)| {
            let name = args.get(i + 1).ok_or("--only needs a mistake's name")?;
            Mistake::from_name(name).ok_or_else(|| format!("no mistake is named {name}"))
        })
        .collect::<std::result::Result<_, _>>()?;
    let mut doc = String::from(HEADER);
    let mut part = 0;
    for m in Mistake::ALL {
        if !only.is_empty() && !only.contains(&m) {
            continue;
        }
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
             Means, mistaken over correct: {:.3}. {}\n",
            info.name,
            info.function,
            info.what,
            info.symptom,
            info.name,
            w / r,
            how.command(m)
        )?;
    }
    if !only.is_empty() {
        // The sections alone, to paste: docs/13 is written whole or not.
        print!("{}", &doc[HEADER.len()..]);
        return Ok(());
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
catalogue (src/mistakes/catalogue.rs) or the example, not this file. -->

Each section shows one mistake of the catalogue (`--mistake list`): the
image a correct course solution renders (`--course-exact`, left), the
image with the mistake (middle) and their ratio (right, 4 x 4 pixel
blocks: blue where the mistake darkens, red where it brightens, grey where
both are black; the bar runs from a quarter to four times). It names the
starter function to look at, what is wrong in it and what to look for,
then the ratio of the two images' means (the lamp included) and a command
that renders the mistake at 480 x 360 with a binary.

The pictures are this project's built-in scenes, framed as the course
frames 480 x 360 and rendered at 320 x 240 by the course's renderer with
independent random numbers, noisy as a student's are
(`cargo run --release --example symptoms`). Each symptom is tested
(`tests/mistakes_1_2.rs`, `tests/mistakes.rs`, `tests/mistakes_3_2.rs`).

Two mistakes often named do not show in a course image. The light's
cosine cannot be left out: the starter's `AreaLight::sample_L` puts it in
the pdf it returns. A ray direction left unnormalised changes no 3-1
image: the triangle's and the box's `t` scale with `|d|` while the hit
point `o + t d` does not, so only the clipping distances move, and the
spheres' test, `a = d . d`, is exact for any length.
";
