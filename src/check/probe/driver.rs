//! Running the probe driver: a script of commands in, one response line
//! per command back (the protocol is `PROTOCOL.md` beside this file).
//!
//! The driver writes its answers to a file of their own, flushed line by
//! line, so a student's debug printing cannot mix in and the first
//! command without an answer is the one that crashed or hung.

use std::path::PathBuf;
use std::process::{Command, Stdio};
use std::time::Duration;

use crate::check::student::wait_at_most;

/// The first line the driver writes: its protocol's version.
pub const HELLO: &str = "cs184-probe 1";

/// A built driver and the folder its runs work in.
#[derive(Debug, Clone)]
pub struct Driver {
    pub binary: PathBuf,
    pub work: PathBuf,
    /// How long one script may run.
    pub timeout: Duration,
    /// The folders searched for the course's scenes: the BVH probes race
    /// on its bunny ([`bvh_race`](super::bvh_race)).
    pub scenes: Vec<PathBuf>,
}

/// How a run ended early, at the command [`Transcript::commands`]`[at]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Stopped {
    pub at: usize,
    pub how: String,
}

/// A script's commands and the answers they got.
#[derive(Debug, Clone)]
pub struct Transcript {
    pub commands: Vec<String>,
    answers: Vec<String>,
    /// Why the answers end before the commands do, if they do.
    ending: Option<String>,
}

impl Transcript {
    /// The numbers command `i` answered, or why it has none: the driver
    /// stopped there (crash, time-out) or answered `error ...`.
    pub fn numbers(&self, i: usize) -> Result<Vec<f64>, Stopped> {
        let line = self.line(i)?;
        line.split_ascii_whitespace()
            .map(parse_number)
            .collect::<Option<Vec<f64>>>()
            .ok_or_else(|| Stopped {
                at: i,
                how: format!("an answer that is not numbers: {line:.80}"),
            })
    }

    /// The line command `i` answered, or why it has none (as
    /// [`Transcript::numbers`]).
    pub fn line(&self, i: usize) -> Result<&str, Stopped> {
        let line = self.answers.get(i).ok_or_else(|| Stopped {
            at: i,
            how: self
                .ending
                .clone()
                .unwrap_or_else(|| "the driver gave no answer".into()),
        })?;
        if let Some(error) = line.strip_prefix("error") {
            return Err(Stopped {
                at: i,
                how: format!("the driver could not run it:{error}"),
            });
        }
        Ok(line)
    }

    /// [`Transcript::numbers`], checked to be `n` numbers.
    pub fn exactly(&self, i: usize, n: usize) -> Result<Vec<f64>, Stopped> {
        let v = self.numbers(i)?;
        if v.len() == n {
            Ok(v)
        } else {
            Err(Stopped {
                at: i,
                how: format!("{} numbers in the answer, {n} expected", v.len()),
            })
        }
    }

    /// Command `i` as the student would type it.
    pub fn command(&self, i: usize) -> &str {
        self.commands.get(i).map_or("", String::as_str)
    }
}

/// A number as `printf("%.17g")` writes it (`nan`, `-nan`, `inf` too).
fn parse_number(token: &str) -> Option<f64> {
    match token.trim_start_matches('-') {
        "nan" | "NaN" => Some(f64::NAN),
        _ => token.parse().ok(),
    }
}

impl Driver {
    /// Runs `commands` (one a line) and reads back the answers. Errors
    /// only when the driver cannot be started or its files written.
    pub fn run(&self, name: &str, commands: Vec<String>) -> Result<Transcript, String> {
        std::fs::create_dir_all(&self.work).map_err(|e| format!("{}: {e}", self.work.display()))?;
        let script = self.work.join(format!("{name}.in"));
        let answers = self.work.join(format!("{name}.out"));
        let mut text = commands.join("\n");
        text.push('\n');
        std::fs::write(&script, text).map_err(|e| format!("{}: {e}", script.display()))?;
        let _ = std::fs::remove_file(&answers);
        let printed = std::fs::File::create(self.work.join(format!("{name}.stdout")))
            .map_err(|e| format!("{}: {e}", self.work.display()))?;
        let mut child = Command::new(&self.binary)
            .arg(&script)
            .arg(&answers)
            .current_dir(&self.work)
            .stdin(Stdio::null())
            .stdout(printed.try_clone().map_err(|e| e.to_string())?)
            .stderr(printed)
            .spawn()
            .map_err(|e| format!("{}: {e}", self.binary.display()))?;
        let status = wait_at_most(&mut child, self.timeout);
        let written = std::fs::read_to_string(&answers).unwrap_or_default();
        let mut lines = written.lines().map(str::to_owned);
        let hello = lines.next();
        let answers: Vec<String> = lines.collect();
        let ending = match status {
            None => Some(format!(
                "it ran longer than {} s (an endless loop?)",
                self.timeout.as_secs()
            )),
            Some(s) if !s.success() => Some(crash(s)),
            Some(_) if hello.as_deref() != Some(HELLO) => {
                Some(format!("the driver did not start: {:?}", hello))
            }
            Some(_) => None,
        };
        Ok(Transcript {
            commands,
            answers,
            ending,
        })
    }
}

/// What a failed exit status says, the signal named where there is one.
fn crash(status: std::process::ExitStatus) -> String {
    #[cfg(unix)]
    {
        use std::os::unix::process::ExitStatusExt;
        if let Some(signal) = status.signal() {
            let name = match signal {
                11 => "a segmentation fault (a null or dangling pointer?)",
                6 => "an abort (an assert or an uncaught exception)",
                8 => "a floating-point exception (an integer divided by zero?)",
                _ => "a signal",
            };
            return format!("it crashed: {name}, signal {signal}");
        }
    }
    format!("it exited with {status}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn printf_numbers_parse() {
        assert_eq!(parse_number("0.5"), Some(0.5));
        assert_eq!(parse_number("-1e-05"), Some(-1e-5));
        assert!(parse_number("-nan").unwrap().is_nan());
        assert_eq!(parse_number("inf"), Some(f64::INFINITY));
        assert_eq!(parse_number("-inf"), Some(f64::NEG_INFINITY));
        assert_eq!(parse_number("ok"), None);
    }

    #[test]
    fn a_missing_answer_names_the_command_and_why() {
        let t = Transcript {
            commands: vec!["a".into(), "b".into()],
            answers: vec!["1 2".into()],
            ending: Some("it crashed".into()),
        };
        assert_eq!(t.exactly(0, 2), Ok(vec![1.0, 2.0]));
        assert_eq!(t.exactly(0, 3).unwrap_err().at, 0);
        let stop = t.numbers(1).unwrap_err();
        assert_eq!((stop.at, stop.how.as_str()), (1, "it crashed"));
        assert_eq!(t.command(1), "b");
    }
}
