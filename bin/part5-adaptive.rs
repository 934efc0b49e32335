//! Part 5: adaptive sampling (`-a BATCH TOL`) and the sample-rate image.

use clap::Parser;
use pathtracer::cli::{drivers, exit_with, CourseArgs};

fn main() -> std::process::ExitCode {
    exit_with(drivers::part5(&CourseArgs::parse()))
}
