//! Part 4: global illumination, paths up to `-m` bounces with Russian roulette.

use clap::Parser;
use pathtracer::cli::{drivers, exit_with, CourseArgs};

fn main() -> std::process::ExitCode {
    exit_with(drivers::part4(&CourseArgs::parse()))
}
