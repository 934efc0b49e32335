//! The full renderer with the course's command line.

use clap::Parser;
use pathtracer::cli::{drivers, exit_with, CourseArgs};

fn main() -> std::process::ExitCode {
    exit_with(drivers::pathtracer(&CourseArgs::parse()))
}
