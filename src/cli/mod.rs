//! The course's command line, shared by every binary, and the drivers the
//! binaries call (load the scene, print `--info`, render, write, report).

pub mod args;
pub mod check;
pub mod drivers;
pub mod say;
pub mod settings;
pub mod values;

pub use args::CourseArgs;

use std::process::ExitCode;

/// The exit status of a run whose standard output was closed by its
/// reader: 128 + `SIGPIPE` (13), what a shell reports for a program the
/// signal ended ([`say`]).
pub const CLOSED_PIPE_STATUS: u8 = 141;

/// Runs a driver and turns its error into a message on stderr and exit
/// code 1; a closed standard output ends it quietly with
/// [`CLOSED_PIPE_STATUS`].
pub fn exit_with(result: Result<(), Box<dyn std::error::Error>>) -> ExitCode {
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            if e.downcast_ref::<say::StdoutError>()
                .is_some_and(say::StdoutError::is_closed_pipe)
            {
                return ExitCode::from(CLOSED_PIPE_STATUS);
            }
            crate::say_err!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
