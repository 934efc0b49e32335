//! The course's command line, shared by every binary, and the drivers the
//! binaries call (load the scene, print `--info`, render, write, report).

pub mod args;
pub mod check;
pub mod drivers;
pub mod settings;
pub mod values;

pub use args::CourseArgs;

use std::process::ExitCode;

/// Runs a driver and turns its error into a message on stderr and exit code 1.
pub fn exit_with(result: Result<(), Box<dyn std::error::Error>>) -> ExitCode {
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
