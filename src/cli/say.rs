//! Printing to the terminal without panicking when it cannot be written.
//!
//! `println!` panics when standard output is a closed pipe
//! (`pathtracer ... | head -c 1`) or a full device (`> /dev/full`). The
//! drivers print through [`say!`](crate::say) instead, which returns a
//! [`StdoutError`]; [`super::exit_with`] turns a closed pipe into a quiet
//! exit with status 141 (what a shell reports for a program ended by
//! `SIGPIPE`, as the course's C++ binary would be) and any other failure
//! into a clear error. An image is written whole or not at all either way
//! ([`crate::render::write_image`]): a run stopped by a closed pipe before
//! it writes the image writes none.
//!
//! Warnings go to standard error through [`say_err!`](crate::say_err): if that cannot be
//! written there is nowhere left to say so, and the run goes on.

use std::fmt;
use std::io::{self, Write};

/// Standard output could not be written.
#[derive(Debug)]
pub struct StdoutError(pub io::Error);

impl StdoutError {
    /// Whether the reader went away (a closed pipe): the quiet case.
    pub fn is_closed_pipe(&self) -> bool {
        self.0.kind() == io::ErrorKind::BrokenPipe
    }
}

impl fmt::Display for StdoutError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "cannot write to standard output: {}", self.0)
    }
}

impl std::error::Error for StdoutError {}

/// Writes `text` to standard output and flushes it.
pub fn text(text: &str) -> Result<(), StdoutError> {
    let mut out = io::stdout().lock();
    out.write_all(text.as_bytes())
        .and_then(|()| out.flush())
        .map_err(StdoutError)
}

/// Writes one formatted line to standard output ([`say!`](crate::say)).
pub fn line(args: fmt::Arguments) -> Result<(), StdoutError> {
    text(&format!("{args}\n"))
}

/// Writes one line to standard error, ignoring a failure to do so.
pub fn stderr_line(args: fmt::Arguments) {
    let _ = writeln!(io::stderr().lock(), "{args}");
}

/// `println!` that returns a [`StdoutError`] instead of panicking.
#[macro_export]
macro_rules! say {
    ($($arg:tt)*) => {
        $crate::cli::say::line(format_args!($($arg)*))
    };
}

/// `eprintln!` that never panics.
#[macro_export]
macro_rules! say_err {
    ($($arg:tt)*) => {
        $crate::cli::say::stderr_line(format_args!($($arg)*))
    };
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_a_broken_pipe_is_quiet() {
        let closed = StdoutError(io::Error::from(io::ErrorKind::BrokenPipe));
        assert!(closed.is_closed_pipe());
        let full = StdoutError(io::Error::from_raw_os_error(28));
        assert!(!full.is_closed_pipe());
        assert!(full
            .to_string()
            .starts_with("cannot write to standard output"));
    }
}
