//! The course's starters for the tests that build and run them
//! (`CS184_STARTER_DIR`), and the rows of `check --source`'s table.

use std::path::PathBuf;

/// The starters' folder, or `None` (after a line) outside CI without it;
/// under `CI=true` its absence fails the test.
pub fn starter_dir() -> Option<PathBuf> {
    match std::env::var_os("CS184_STARTER_DIR") {
        Some(dir) => Some(PathBuf::from(dir)),
        None => {
            assert!(
                std::env::var("CI").as_deref() != Ok("true"),
                "CS184_STARTER_DIR is not set: CI must point it at ../shared/course"
            );
            eprintln!("skipped: set CS184_STARTER_DIR to the course's starters");
            None
        }
    }
}

/// A row of `check --source`'s summary table: the function, its verdict
/// word(s) and the likely mistake (`-` for none).
#[derive(Debug, Clone, PartialEq)]
pub struct ProbeRow {
    pub function: String,
    pub verdict: String,
    pub mistake: String,
}

/// The rows of the summary table at the top of `stdout`.
pub fn probe_rows(stdout: &str) -> Vec<ProbeRow> {
    stdout
        .lines()
        .skip(1)
        .take_while(|l| !l.trim().is_empty())
        .map(|l| {
            let w: Vec<&str> = l.split_whitespace().collect();
            let last = w.len() - 1;
            ProbeRow {
                function: w[1].to_owned(),
                verdict: w[2..last].join(" "),
                mistake: w[last].to_owned(),
            }
        })
        .collect()
}
