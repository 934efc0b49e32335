//! What one probe of one function concludes, and the cases it is built
//! from: each case an input, what a correct function gives and what the
//! student's gave; the first case that fails (cases run from the simplest
//! input to the hardest) is the one reported.

use std::fmt;

use super::driver::Stopped;
use crate::mistakes::Mistake;

/// A probe's conclusion about one function.
#[derive(Debug, Clone, PartialEq)]
pub enum Verdict {
    /// Every case passed.
    Pass { cases: usize, note: Option<String> },
    /// The function is still the starter's: it does what the stub does.
    NotWritten(String),
    /// It cannot be told from the starter's until a function it needs is
    /// written (a traversal, until there is a tree to traverse).
    Waits(String),
    /// A case failed.
    Fail(Failure),
    /// The probe could not finish: the driver crashed, hung or could not
    /// be built.
    Broken(String),
}

/// The first failing case of a probe.
#[derive(Debug, Clone, PartialEq)]
pub struct Failure {
    /// What was asked, in the function's own terms.
    pub input: String,
    pub expected: String,
    pub got: String,
    /// What is wrong, in a sentence.
    pub what: String,
    /// The catalogued mistake whose behaviour this is, when one is.
    pub mistake: Option<Mistake>,
    /// How many cases failed, of how many.
    pub failed: usize,
    pub cases: usize,
}

impl Verdict {
    /// The one word of the summary table.
    pub fn word(&self) -> &'static str {
        match self {
            Verdict::Pass { .. } => "pass",
            Verdict::NotWritten(_) => "not yet",
            Verdict::Waits(_) => "waits",
            Verdict::Fail(_) => "FAIL",
            Verdict::Broken(_) => "broken",
        }
    }

    /// Whether the function needs the student's attention.
    pub fn is_pass(&self) -> bool {
        matches!(self, Verdict::Pass { .. })
    }

    /// A driver that stopped at `stop`: the command and why.
    pub fn stopped(stop: &Stopped, command: &str) -> Verdict {
        Verdict::Broken(format!("{} at `{command}`", stop.how))
    }
}

impl fmt::Display for Verdict {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Verdict::Pass { cases, note } => {
                write!(f, "pass ({cases} cases)")?;
                if let Some(note) = note {
                    write!(f, "; {note}")?;
                }
                Ok(())
            }
            Verdict::NotWritten(why) => write!(f, "not written yet: {why}"),
            Verdict::Waits(why) => write!(f, "cannot be probed yet: {why}"),
            Verdict::Fail(fail) => {
                let counts = if fail.cases > 1 {
                    format!(" ({} of {} cases)", fail.failed, fail.cases)
                } else {
                    String::new()
                };
                write!(
                    f,
                    "FAIL{counts}: {}\n    input:    {}\n    expected: {}\n    got:      {}",
                    fail.what, fail.input, fail.expected, fail.got
                )?;
                if let Some(m) = fail.mistake {
                    write!(
                        f,
                        "\n    likely:   {m}, docs/13-symptoms.md#{m} (`pathtracer --mistake {m}` renders it)"
                    )?;
                }
                Ok(())
            }
            Verdict::Broken(why) => write!(f, "could not be probed: {why}"),
        }
    }
}

/// Collects a probe's cases: counts them and keeps the first failure.
#[derive(Debug, Default)]
pub struct Cases {
    cases: usize,
    failed: usize,
    first: Option<Failure>,
}

impl Cases {
    /// Records one case: `None` when it passed, else what failed.
    pub fn record(&mut self, failure: Option<Failure>) {
        self.cases += 1;
        if let Some(f) = failure {
            self.failed += 1;
            self.first.get_or_insert(f);
        }
    }

    /// Whether no case has failed so far.
    pub fn all_pass(&self) -> bool {
        self.failed == 0
    }

    /// The verdict: the first failure with the counts, else a pass.
    pub fn verdict(self, note: Option<String>) -> Verdict {
        match self.first {
            Some(mut f) => {
                f.failed = self.failed;
                f.cases = self.cases;
                Verdict::Fail(f)
            }
            None => Verdict::Pass {
                cases: self.cases,
                note,
            },
        }
    }
}

/// A failure of one case (counts filled in by [`Cases::verdict`]).
pub fn failure(
    input: impl Into<String>,
    expected: impl Into<String>,
    got: impl Into<String>,
    what: impl Into<String>,
    mistake: Option<Mistake>,
) -> Failure {
    Failure {
        input: input.into(),
        expected: expected.into(),
        got: got.into(),
        what: what.into(),
        mistake,
        failed: 1,
        cases: 1,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_first_failure_is_kept_and_all_are_counted() {
        let mut cases = Cases::default();
        cases.record(None);
        cases.record(Some(failure("a", "1", "2", "first", None)));
        cases.record(Some(failure("b", "1", "3", "second", None)));
        let Verdict::Fail(f) = cases.verdict(None) else {
            panic!("a failure")
        };
        assert_eq!((f.input.as_str(), f.failed, f.cases), ("a", 2, 3));
        let mut passing = Cases::default();
        passing.record(None);
        assert_eq!(
            passing.verdict(None),
            Verdict::Pass {
                cases: 1,
                note: None
            }
        );
    }
}
