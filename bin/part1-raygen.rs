//! Part 1: camera rays and intersection. Renders normal shading by testing
//! every primitive for every ray, and reports render time and rays per second.

use clap::Parser;
use pathtracer::cli::{drivers, exit_with, CourseArgs};

fn main() -> std::process::ExitCode {
    exit_with(drivers::part1(&CourseArgs::parse()))
}
