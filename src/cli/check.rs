//! The `check` binary's command line and what it does: the battery of
//! [`crate::check`] against a student's binary, a summary table on stdout.

use std::error::Error;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Duration;

use clap::Parser;
use indicatif::{ProgressBar, ProgressStyle};

use super::values::{whole, AssignmentArg, Number};
use crate::check::battery::{assignment_of, battery_for};
use crate::check::{
    judge, probe, report, table, CheckResult, CheckScene, Outcome, Stage, Student, ALPHA,
};
use crate::course::Assignment;

/// Check your own course renderer: runs it through the course's command
/// line and compares each image with what a correct solution renders.
#[derive(Parser, Debug)]
#[command(name = "check")]
pub struct CheckArgs {
    /// Your `pathtracer` binary, built from the course's starter: its
    /// images are checked.
    #[arg(long, required_unless_present = "source")]
    pub student: Option<PathBuf>,
    /// Your starter tree (the folder with `CMakeLists.txt`): each function
    /// you wrote is compiled with a probe of this project's and tested on
    /// its own.
    #[arg(long)]
    pub source: Option<PathBuf>,
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

/// What `check` exits with: 0 when every check that ran passed, 1 when
/// one did not (failed, not written yet, or no image), 2 when the binary
/// cannot be run at all (and, through clap, for a usage error).
pub fn status(results: &[CheckResult], binary_runs: bool) -> ExitCode {
    let failed = results.iter().any(|r| {
        matches!(
            r.outcome,
            Outcome::Fail { .. } | Outcome::NotWritten(_) | Outcome::Error(_)
        )
    });
    match (binary_runs, failed) {
        (false, _) => ExitCode::from(2),
        (true, true) => ExitCode::from(1),
        (true, false) => ExitCode::SUCCESS,
    }
}

/// Probes the functions of `--source` and checks the images of
/// `--student`, whichever are given, and says how it went: 0 when all
/// passed, 1 when one did not; an error where nothing can be checked (the
/// probe does not build, no output folder, no scene).
pub fn check(args: &CheckArgs) -> Result<ExitCode, Box<dyn Error>> {
    let mut probed = Vec::new();
    if let Some(source) = &args.source {
        crate::say_err!(
            "building the probe against {} (its first build takes a few minutes)",
            source.display()
        );
        probed = probe::run(
            source,
            args.scenes.as_deref(),
            &args.out,
            &args.parts,
            args.threads,
        )?;
        crate::cli::say::text(&probe::table(&probed))?;
        crate::cli::say::text(&probe::details(&probed))?;
    }
    let source = args.source.as_ref().map(|s| s.display().to_string());
    let runs = args.out.join("probe").join("runs");
    let functions = source.as_deref().map(|s| (s, &probed[..], runs.as_path()));
    let images = match &args.student {
        Some(binary) => check_images(args, binary, functions)?,
        None => {
            let page = report::page(None, functions);
            let path = report::write_report(&args.out, &page)
                .map_err(|e| format!("{}: {e}", args.out.join("report.html").display()))?;
            crate::say!("\nwrote {}", path.display())?;
            ExitCode::SUCCESS
        }
    };
    Ok(match (probe::all_pass(&probed), images) {
        (false, ExitCode::SUCCESS) => ExitCode::from(1),
        (_, code) => code,
    })
}

/// Runs the battery on `binary`, prints the table and says how it went
/// ([`status`]).
fn check_images(
    args: &CheckArgs,
    binary: &std::path::Path,
    functions: Option<report::Functions>,
) -> Result<ExitCode, Box<dyn Error>> {
    let work = args.out.join("runs");
    std::fs::create_dir_all(&work).map_err(|e| format!("{}: {e}", work.display()))?;
    let student = Student {
        binary: std::path::absolute(binary)?,
        work,
        timeout: Duration::from_secs(args.timeout),
    };
    let course_scenes = args
        .scenes
        .clone()
        .or_else(crate::scene::course_files::env_root);
    let (assignment, why) = assignment_for(args, course_scenes.as_deref(), &student)?;
    let checks = battery_for(assignment, &args.parts);
    if checks.is_empty() {
        return Err(format!(
            "no check of part {:?} for a {} binary (part 1 has none of its own yet)",
            args.parts,
            assignment.name()
        )
        .into());
    }
    crate::say_err!("checking a {} binary ({why})", assignment.name());
    // A 3-2 binary's lamp is a quad of its own, which the course's boxes
    // tie with their lamp mesh to 1e-7 (measured on the 3-2 starter:
    // which one a ray meets turns on f32 against f64): its checks use
    // the project's scenes, whose lamp mesh lies behind the light.
    let course_scenes = match assignment {
        Assignment::PathTracer1 => course_scenes,
        Assignment::PathTracer2 => {
            if course_scenes.is_some() {
                crate::say_err!("a 3-2 binary is checked on this project's scenes, not the course's: the course's boxes tie their lamp mesh with the light's own quad (docs/maintainers/checker.md)");
            }
            None
        }
    };
    // The scenes the checks render, each written once.
    let mut stages: Vec<(CheckScene, String, Stage)> = Vec::new();
    for which in CheckScene::ALL {
        if checks.iter().any(|c| c.scene == which) {
            let found = which.file(course_scenes.as_deref(), &args.out)?;
            // A 3-2 binary's are the project's on purpose (above).
            if let Some(warning) = found
                .warning
                .as_ref()
                .filter(|_| assignment == Assignment::PathTracer1)
            {
                crate::say_err!("warning: {warning}");
            }
            let file = std::path::absolute(&found.path)?;
            let stage = which.stage(&file, found.scene, false)?;
            stages.push((which, file.to_string_lossy().into_owned(), stage));
        }
    }
    // What the binary supports, by trying each flag in a tiny render of
    // the first scene; a binary that cannot even run fails every check
    // with the reason, in the table and the report alike.
    let map = stages
        .iter()
        .find_map(|(which, file, _)| which.environment_file(std::path::Path::new(file)));
    let (_, first, _) = &stages[0];
    let capabilities = student.capabilities(first, map.as_deref());
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
                command: Vec::new(),
            },
        });
        bar.inc(1);
    }
    bar.finish_and_clear();
    crate::cli::say::text(&table(&results))?;
    let files: Vec<&str> = stages.iter().map(|(_, file, _)| file.as_str()).collect();
    let page = report::page(
        Some((
            &student.binary.to_string_lossy(),
            &files.join(", "),
            &results,
        )),
        functions,
    );
    let path = report::write_report(&args.out, &page)
        .map_err(|e| format!("{}: {e}", args.out.join("report.html").display()))?;
    for r in &results {
        match &r.outcome {
            Outcome::Fail { what, suspects, .. } => {
                crate::say!("\npart {}, {}: {what}", r.check.part, r.check.name)?;
                for s in suspects.iter().take(3) {
                    let fit = if s.fits { "fits" } else { "does not fit" };
                    crate::say!(
                        "  {} ({fit}; misfit {:.2} per cell): docs/13-symptoms.md#{}",
                        s.mistake,
                        s.misfit,
                        s.mistake
                    )?;
                }
                crate::say!(
                    "  to run it again, in {}: {}",
                    student.work.display(),
                    r.command.join(" ")
                )?;
            }
            Outcome::NotWritten(u) => crate::say!(
                "\npart {}, {}: not written yet: {} in {} (part {}): {}",
                r.check.part,
                r.check.name,
                u.function,
                u.file,
                u.part,
                u.shows
            )?,
            _ => {}
        }
    }
    crate::say!("\nwrote {}", path.display())?;
    Ok(status(&results, capabilities.is_ok()))
}

/// The assignment whose battery runs, and why: `--assignment`, else 3-2
/// when a `--part` is 6 or more, else as the binary shows (a 3-2 binary
/// renders emissive surfaces without light black at `-m 0`, and a lit
/// box not, [`Student::renders_lamps_as_quads`]); an error when `--assignment 3-1`
/// names parts of 3-2.
fn assignment_for(
    args: &CheckArgs,
    scenes: Option<&std::path::Path>,
    student: &Student,
) -> Result<(Assignment, &'static str), Box<dyn Error>> {
    let implied = assignment_of(&args.parts);
    let three_two = || -> Result<bool, Box<dyn Error>> {
        let glowing = crate::check::scenes::write_lamp_probe(&args.out)?;
        let lit = CheckScene::Lambertian.file(scenes, &args.out)?.path;
        Ok(student.renders_lamps_as_quads(&glowing, &lit) == Some(true))
    };
    match (args.assignment.map(Assignment::from), implied) {
        (Some(Assignment::PathTracer1), Some(_)) => {
            Err("--assignment 3-1: parts 6 to 8 are 3-2's (a 3-2 binary has every part)".into())
        }
        (Some(a), _) => Ok((a, "--assignment")),
        (None, Some(a)) => Ok((a, "--part names a part of 3-2")),
        (None, None) if three_two()? => Ok((
            Assignment::PathTracer2,
            "its emissive meshes emit nothing, as in the 3-2 starter; --assignment 3-1 to say otherwise",
        )),
        (None, None) => Ok((
            Assignment::PathTracer1,
            "its emissive meshes glow, as in the 3-1 starter; --assignment 3-2 to say otherwise",
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(words: &str) -> CheckArgs {
        let out = std::env::temp_dir().join("check-args-test");
        let out = out.to_string_lossy().into_owned();
        let words = std::iter::once("check")
            .chain(words.split_whitespace())
            .chain(["--out", out.as_str()]);
        CheckArgs::try_parse_from(words).unwrap()
    }

    /// `--part` and `--assignment` pick the checks: the binary's own
    /// assignment by default (this test's `s` does not run: 3-1), 3-2's
    /// for parts 6 to 8 or `--assignment 3-2` (every part, the first five
    /// as a 3-2 binary renders them); parts of 3-2 with `--assignment 3-1`
    /// are refused with a reason.
    #[test]
    fn parts_and_assignment_pick_the_checks() {
        let parts = |words: &str| -> Result<(Assignment, Vec<u8>), String> {
            let args = parse(words);
            let student = Student {
                binary: args.student.clone().unwrap(),
                work: std::env::temp_dir(),
                timeout: Duration::from_secs(1),
            };
            assignment_for(&args, None, &student)
                .map(|(a, _)| {
                    (
                        a,
                        battery_for(a, &args.parts).iter().map(|c| c.part).collect(),
                    )
                })
                .map_err(|e| e.to_string())
        };
        use Assignment::{PathTracer1 as A1, PathTracer2 as A2};
        assert_eq!(parts("--student s"), Ok((A1, vec![1, 2, 3, 3, 4, 4, 5])));
        assert_eq!(
            parts("--student s --assignment 3-2"),
            Ok((A2, vec![2, 3, 3, 4, 4, 5, 6, 6, 7, 8]))
        );
        assert_eq!(parts("--student s --part 8"), Ok((A2, vec![8])));
        assert_eq!(
            parts("--student s --part 5 --part 6"),
            Ok((A2, vec![5, 6, 6]))
        );
        assert_eq!(
            parts("--student s --part 3 --assignment 3-1"),
            Ok((A1, vec![3, 3]))
        );
        assert!(parts("--student s --part 6 --assignment 3-1")
            .unwrap_err()
            .contains("3-2's"));
    }

    /// 0 when every check that ran passed (skipped ones aside), 1 when one
    /// failed, was not written or gave no image, 2 when the binary does
    /// not run.
    #[test]
    fn the_exit_status_says_how_the_battery_went() {
        let check = crate::check::battery(&[3])[0];
        let result = |outcome| CheckResult {
            check,
            outcome,
            images: None,
            command: Vec::new(),
        };
        let pass = result(Outcome::Pass {
            statistic: 1.0,
            threshold: 2.0,
            region: 1.0,
            region_threshold: 2.0,
            variant: None,
        });
        let skipped = result(Outcome::Skipped("no -o".into()));
        let error = result(Outcome::Error("it crashed".into()));
        assert_eq!(
            status(&[pass.clone(), skipped.clone()], true),
            ExitCode::SUCCESS
        );
        assert_eq!(
            status(&[pass.clone(), error.clone()], true),
            ExitCode::from(1)
        );
        assert_eq!(status(&[pass, skipped], false), ExitCode::from(2));
    }
}
