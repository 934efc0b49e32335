//! Convergence studies of parts 3 to 7: error against time, as PNG charts
//! and Markdown tables (docs/04-direct.md, 05-global.md, 06-adaptive.md,
//! 07-materials.md, 08-environment.md).
//!
//! ```text
//! cargo run --release --example convergence -- STUDY [--out DIR] [--scenes DIR] [-t N] [-r W H]
//! ```
//!
//! STUDY is `direct` (hemisphere vs light sampling), `samples` (`-s` vs
//! `-l`), `global` (max depth, Russian roulette), `adaptive` (adaptive vs
//! uniform sampling), `course` (the course's area and point light
//! factors), `materials` (MIS against light or BSDF sampling alone, and
//! the microfacet samplers, on glossy spheres), `environment` (importance
//! against uniform sampling of the built-in sky, with and without MIS, on
//! `bunny_unlit.dae`), `sampling` (independent against ZSobol sampler,
//! fixed against throughput roulette, at equal samples; run it with
//! `-r 480 360 -t 2`) or `all`. Charts go to `--out` (default `docs/images`), tables
//! to stdout, progress to stderr. The course's scenes are found by name
//! under `--scenes DIR`, by default under `$CS184_SCENES` (the course
//! starter's `dae/` folder; see `pathtracer::scene::course_files`). Images are 160 x 120 (`-r`) with
//! the camera of a 480 x 360 render, so they show the whole Cornell box.
//!
//! Error: the RMS luminance error against a reference render of many
//! samples, less the reference's own noise, over the reference's mean
//! luminance (see `measure.rs`). Times are wall clock.

mod course;
mod measure;
mod plot;
mod sampling;
mod setup;
mod studies;

use std::error::Error;
use std::path::PathBuf;
use std::process::ExitCode;

use studies::Options;

const USAGE: &str =
    "usage: convergence direct|samples|global|adaptive|course|materials|environment|sampling|all \
                     [--out DIR] [--scenes DIR] [-t N] [-r W H]";

fn parse(args: &[String]) -> Result<(String, Options), Box<dyn Error>> {
    let mut study = None;
    let mut options = Options {
        scenes: None,
        out: PathBuf::from("docs/images"),
        threads: None,
        size: (160, 120),
    };
    let mut it = args.iter();
    let value = |it: &mut std::slice::Iter<String>, flag: &str| {
        it.next()
            .cloned()
            .ok_or_else(|| format!("{flag} needs a value\n{USAGE}"))
    };
    while let Some(arg) = it.next() {
        match arg.as_str() {
            "--out" => options.out = value(&mut it, "--out")?.into(),
            "--scenes" => options.scenes = Some(value(&mut it, "--scenes")?.into()),
            "-t" => options.threads = Some(value(&mut it, "-t")?.parse()?),
            "-r" => {
                options.size = (
                    value(&mut it, "-r")?.parse()?,
                    value(&mut it, "-r")?.parse()?,
                )
            }
            s if !s.starts_with('-') && study.is_none() => study = Some(s.to_string()),
            other => return Err(format!("unexpected argument {other}\n{USAGE}").into()),
        }
    }
    Ok((study.ok_or(USAGE)?, options))
}

fn run(study: &str, options: &Options) -> Result<(), Box<dyn Error>> {
    std::fs::create_dir_all(&options.out)?;
    match study {
        "direct" => studies::direct(options),
        "samples" => studies::samples(options),
        "global" => studies::global(options),
        "adaptive" => studies::adaptive(options),
        "course" => studies::course(options),
        "materials" => studies::materials(options),
        "environment" => studies::environment(options),
        "sampling" => sampling::sampling(options),
        "all" => [
            "direct",
            "samples",
            "global",
            "adaptive",
            "course",
            "materials",
            "environment",
        ]
        .iter()
        .try_for_each(|s| run(s, options)),
        other => Err(format!("unknown study {other}\n{USAGE}").into()),
    }
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let result = parse(&args).and_then(|(study, options)| {
        let start = std::time::Instant::now();
        run(&study, &options)?;
        eprintln!("{study}: {:.0} s in all", start.elapsed().as_secs_f64());
        Ok(())
    });
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
