//! Part 6: mirror, glass and microfacet materials (assignment 3-2, parts 1
//! and 2); with no scene file, a built-in box with a mirror, a glass and a
//! copper sphere.

use clap::Parser;
use pathtracer::cli::{drivers, exit_with, CourseArgs};

fn main() -> std::process::ExitCode {
    exit_with(drivers::part6(&CourseArgs::parse()))
}
