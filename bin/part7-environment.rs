//! Part 7: the environment light (assignment 3-2, part 3): the path tracer
//! lit by a latitude-longitude map, `-e FILE` or the built-in sky with a
//! sun; with no scene file, a diffuse and a copper sphere on a floor.

use clap::Parser;
use pathtracer::cli::{drivers, exit_with, CourseArgs};

fn main() -> std::process::ExitCode {
    exit_with(drivers::part7(&CourseArgs::parse()))
}
