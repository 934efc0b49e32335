//! Checks a student's own course renderer (`--student PATH`): runs it
//! through the course's command line, compares each image with what a
//! correct solution renders, and names the likely mistake.

use clap::Parser;
use pathtracer::cli::check::{check, CheckArgs};
use pathtracer::cli::exit_with;
use std::process::ExitCode;

/// 0 when every check that ran passed, 1 when one did not, 2 for a usage
/// error (clap's own), a binary that cannot be run, or nothing to check.
fn main() -> ExitCode {
    match check(&CheckArgs::parse()) {
        Ok(status) => status,
        Err(e) => match exit_with(Err(e)) {
            ExitCode::FAILURE => ExitCode::from(2),
            other => other,
        },
    }
}
