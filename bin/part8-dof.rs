//! Part 8: depth of field with a thin lens (`-b` lens radius, `-d` focal
//! distance, `--focus-at X Y`).

use clap::Parser;
use pathtracer::cli::{drivers, exit_with, CourseArgs};

fn main() -> std::process::ExitCode {
    exit_with(drivers::part8(&CourseArgs::parse()))
}
