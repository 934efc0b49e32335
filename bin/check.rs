//! Checks a student's own course renderer (`--student PATH`): runs it
//! through the course's command line, compares each image with what a
//! correct solution renders, and names the likely mistake.

use clap::Parser;
use pathtracer::cli::check::{check, CheckArgs};
use pathtracer::cli::exit_with;

fn main() -> std::process::ExitCode {
    exit_with(check(&CheckArgs::parse()))
}
