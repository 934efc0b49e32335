//! Part 3: direct lighting, by light sampling or uniform hemisphere sampling (`-H`).

use clap::Parser;
use pathtracer::cli::{drivers, exit_with, CourseArgs};

fn main() -> std::process::ExitCode {
    exit_with(drivers::part3(&CourseArgs::parse()))
}
