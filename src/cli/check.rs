//! The `check` binary's command line and what it does: the battery of
//! [`crate::check`] against a student's binary, a summary table on stdout.

use std::error::Error;
use std::path::PathBuf;
use std::time::Duration;

use clap::Parser;
use indicatif::{ProgressBar, ProgressStyle};

use super::values::{whole, AssignmentArg, Number};
use crate::check::battery::{assignment_of, battery_of};
use crate::check::{
    battery, judge, report, table, CheckResult, CheckScene, Outcome, Stage, Student, ALPHA,
};
use crate::course::Assignment;

/// Check your own course renderer: runs it through the course's command
/// line and compares each image with what a correct solution renders.
#[derive(Parser, Debug)]
#[command(name = "check")]
pub struct CheckArgs {
    /// Your `pathtracer` binary, built from the course's starter.
    #[arg(long)]
    pub student: PathBuf,
    /// Only the checks of these parts (repeatable; all of the
    /// assignment's by default). Parts 6 to 8 are 3-2's: naming them
    /// checks a 3-2 binary.
    #[arg(long = "part", allow_hyphen_values = true, value_parser = Number(whole(1u8, 8)))]
    pub parts: Vec<u8>,
    /// Which assignment your binary is of (default: 3-2 when every
    /// `--part` is 6 or more, else 3-1). A 3-2 binary renders parts 1 to
    /// 5 with the staff's library and its lamps as the lights' own quads.
    #[arg(long, value_enum)]
    pub assignment: Option<AssignmentArg>,
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
    let checks = checks_for(args)?;
    // The scenes the checks render, each written once.
    let mut stages: Vec<(CheckScene, String, Stage)> = Vec::new();
    for which in CheckScene::ALL {
        if checks.iter().any(|c| c.scene == which) {
            let (file, scene) = which.file(args.scenes.as_deref(), &args.out)?;
            let file = std::path::absolute(&file)?;
            let stage = which.stage(&file, scene, false)?;
            stages.push((which, file.to_string_lossy().into_owned(), stage));
        }
    }
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
        let (_, file, stage) = stages
            .iter()
            .find(|(which, ..)| *which == check.scene)
            .expect("a stage for every check's scene");
        results.push(match &capabilities {
            Ok(caps) => judge(
                check,
                &student,
                *caps,
                file,
                stage,
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
    let files: Vec<&str> = stages.iter().map(|(_, file, _)| file.as_str()).collect();
    let page = report::html(
        &student.binary.to_string_lossy(),
        &files.join(", "),
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

/// The checks the flags ask for: those of `--part`, or every check of the
/// binary's assignment (`--assignment`, else as the parts imply); an
/// error when the parts and the assignment disagree.
fn checks_for(args: &CheckArgs) -> Result<Vec<crate::check::Check>, Box<dyn Error>> {
    let implied = assignment_of(&args.parts).ok_or(
        "--part names parts of both assignments (6 to 8 are 3-2's): check each binary on its own",
    )?;
    let assignment: Assignment = args.assignment.map_or(implied, Into::into);
    if args.parts.is_empty() {
        return Ok(battery_of(assignment));
    }
    if assignment != implied {
        return Err(format!(
            "--assignment {}: the parts named are {}'s",
            assignment.name(),
            implied.name()
        )
        .into());
    }
    Ok(battery(&args.parts))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(words: &str) -> CheckArgs {
        let words = std::iter::once("check").chain(words.split_whitespace());
        CheckArgs::try_parse_from(words).unwrap()
    }

    /// `--part` and `--assignment` pick the checks: 3-1's by default,
    /// 3-2's for parts 6 to 8 or `--assignment 3-2`; parts of both, or an
    /// assignment the parts contradict, are refused with a reason.
    #[test]
    fn parts_and_assignment_pick_the_checks() {
        let parts = |words: &str| -> Result<Vec<u8>, String> {
            checks_for(&parse(words))
                .map(|c| c.iter().map(|c| c.part).collect())
                .map_err(|e| e.to_string())
        };
        assert_eq!(parts("--student s"), Ok(vec![2, 3, 3, 4, 4, 5]));
        assert_eq!(parts("--student s --assignment 3-2"), Ok(vec![6, 6, 7, 8]));
        assert_eq!(parts("--student s --part 8"), Ok(vec![8]));
        assert_eq!(
            parts("--student s --part 3 --assignment 3-1"),
            Ok(vec![3, 3])
        );
        assert!(parts("--student s --part 5 --part 6")
            .unwrap_err()
            .contains("both assignments"));
        assert!(parts("--student s --part 6 --assignment 3-1")
            .unwrap_err()
            .contains("3-2's"));
    }
}
