//! The `check` binary's command line and what it does: the battery of
//! [`crate::check`] against a student's binary, a summary table on stdout.

use std::error::Error;
use std::path::PathBuf;
use std::time::Duration;

use clap::Parser;
use indicatif::{ProgressBar, ProgressStyle};

use super::values::{whole, Number};
use crate::check::{
    battery, judge, report, scene_for_checks, table, CheckResult, Outcome, Stage, Student, ALPHA,
};

/// Check your own course renderer: runs it through the course's command
/// line and compares each image with what a correct solution renders.
#[derive(Parser, Debug)]
#[command(name = "check")]
pub struct CheckArgs {
    /// Your `pathtracer` binary, built from the course's starter.
    #[arg(long)]
    pub student: PathBuf,
    /// Only the checks of these parts (repeatable; all by default).
    #[arg(long = "part", allow_hyphen_values = true, value_parser = Number(whole(1u8, 8)))]
    pub parts: Vec<u8>,
    /// The course's scene folder (default: `CS184_SCENES`, else a scene of
    /// this project's, written into `--out`).
    #[arg(long)]
    pub scenes: Option<PathBuf>,
    /// Where the scene, the images and the report go.
    #[arg(long, default_value = "check-out")]
    pub out: PathBuf,
    /// Threads for your binary (`-t`) and for the reference.
    #[arg(short = 't', long, default_value_t = 2, allow_hyphen_values = true,
          value_parser = Number(whole(1u16, 256)))]
    pub threads: u16,
    /// Seconds one run of your binary may take.
    #[arg(long, default_value_t = 300, allow_hyphen_values = true,
          value_parser = Number(whole(1u64, 86_400)))]
    pub timeout: u64,
}

/// Runs the battery and prints the table; an error only where nothing can
/// be checked (no output folder, no scene).
pub fn check(args: &CheckArgs) -> Result<(), Box<dyn Error>> {
    let work = args.out.join("runs");
    std::fs::create_dir_all(&work).map_err(|e| format!("{}: {e}", work.display()))?;
    let student = Student {
        binary: std::path::absolute(&args.student)?,
        work,
        timeout: Duration::from_secs(args.timeout),
    };
    let (scene_file, scene) = scene_for_checks(args.scenes.as_deref(), &args.out)?;
    let scene_file = std::path::absolute(&scene_file)?;
    let stage = Stage::new(scene);
    let checks = battery(&args.parts);
    // A binary that cannot even print its usage fails every check with
    // the reason, in the table and the report alike.
    let capabilities = student.capabilities();
    let alpha = ALPHA / checks.len().max(1) as f64;
    let bar = ProgressBar::new(checks.len() as u64).with_style(
        ProgressStyle::with_template("{bar:30} {pos}/{len} {msg}").expect("a valid template"),
    );
    let mut results = Vec::new();
    for check in &checks {
        bar.set_message(check.name);
        let file = scene_file.to_string_lossy();
        results.push(match &capabilities {
            Ok(caps) => judge(
                check,
                &student,
                *caps,
                &file,
                &stage,
                alpha,
                args.threads.into(),
            ),
            Err(e) => CheckResult {
                check: *check,
                outcome: Outcome::Error(e.to_string()),
                images: None,
            },
        });
        bar.inc(1);
    }
    bar.finish_and_clear();
    crate::cli::say::text(&table(&results))?;
    let page = report::html(
        &student.binary.to_string_lossy(),
        &scene_file.to_string_lossy(),
        &results,
    );
    let path = report::write_report(&args.out, &page)
        .map_err(|e| format!("{}: {e}", args.out.join("report.html").display()))?;
    for r in &results {
        if let Outcome::Fail { what, suspects, .. } = &r.outcome {
            crate::say!("\npart {}, {}: {what}", r.check.part, r.check.name)?;
            for s in suspects.iter().take(3) {
                let fit = if s.fits { "fits" } else { "does not fit" };
                crate::say!("  {} ({fit}; misfit {:.2} per cell)", s.mistake, s.misfit)?;
            }
        }
    }
    crate::say!("\nwrote {}", path.display())?;
    Ok(())
}
