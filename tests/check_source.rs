//! `check --source` against the course's own trees (`CS184_STARTER_DIR`,
//! read-only: the probe builds in its output folder): the driver builds
//! through each starter's own CMake, and
//!
//! - the 2023 3-2 starter, whose 3-1 functions are the staff's compiled
//!   library, passes every probe of parts 1 to 3, and its own functions
//!   (parts 6 to 8, the 3-2 TODOs) are "not written yet";
//! - the bare 3-1 starters (which hold the 3-2 stubs too) are "not written
//!   yet" for every function (a traversal "waits" for a tree), without a
//!   crash, and `check` exits with 1;
//! - a folder that is no starter is refused with a reason, exit 2.
//!
//! Without the variable the tests skip with a line, except under
//! `CI=true`, where they fail.

#![cfg(unix)]

mod common;

use common::{probe_rows, starter_dir};
use std::path::PathBuf;
use std::process::Command;
use std::sync::OnceLock;

const CHECK: &str = env!("CARGO_BIN_EXE_check");

/// What one `check` run gave: its exit code and standard output.
type Run = (Option<i32>, String);

/// `check --source STARTER`, run once per starter (the first build takes
/// a minute or two).
fn probe(starter: &'static str) -> Option<&'static Run> {
    static RUNS: OnceLock<std::sync::Mutex<Vec<(&'static str, &'static Run)>>> = OnceLock::new();
    let dir = starter_dir()?;
    let runs = RUNS.get_or_init(Default::default);
    let mut runs = runs.lock().unwrap();
    if let Some((_, run)) = runs.iter().find(|(s, _)| *s == starter) {
        return Some(run);
    }
    let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("check-source-{starter}"));
    let run = Command::new(CHECK)
        .arg("--source")
        .arg(dir.join(starter))
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&run.stdout).into_owned();
    assert!(
        run.status.code() != Some(2),
        "{starter}: {}\n{stdout}",
        String::from_utf8_lossy(&run.stderr)
    );
    let leaked: &'static Run = Box::leak(Box::new((run.status.code(), stdout)));
    runs.push((starter, leaked));
    Some(leaked)
}

/// The part of the probe of `function`.
fn part(function: &str) -> u8 {
    pathtracer::check::probe::PROBES
        .iter()
        .find(|p| p.function == function)
        .unwrap_or_else(|| panic!("no probe of {function}"))
        .part
}

#[test]
fn the_staffs_functions_pass_every_probe() {
    let Some((code, stdout)) = probe("p3_2-sp23") else {
        return;
    };
    let rows = probe_rows(stdout);
    assert_eq!(
        rows.len(),
        pathtracer::check::probe::PROBES.len(),
        "{stdout}"
    );
    for row in &rows {
        let (function, verdict) = (&row.function, &row.verdict);
        // The staff's library holds parts 1 to 5; parts 6 to 8 are the
        // 3-2 starter's own TODOs.
        let want = if part(function) <= 5 {
            "pass"
        } else {
            "not yet"
        };
        assert_eq!(verdict, want, "{function}:\n{stdout}");
    }
    assert_eq!(*code, Some(1), "{stdout}");
}

#[test]
fn a_bare_starter_is_not_written_yet_everywhere() {
    for starter in ["p3_1-sp23", "p3_1-2025"] {
        let Some((code, stdout)) = probe(starter) else {
            return;
        };
        let rows = probe_rows(stdout);
        assert_eq!(
            rows.len(),
            pathtracer::check::probe::PROBES.len(),
            "{stdout}"
        );
        for row in &rows {
            let (function, verdict) = (&row.function, &row.verdict);
            let waits = function.starts_with("BVHAccel::") && function != "BVHAccel::construct_bvh";
            let want = if waits { "waits" } else { "not yet" };
            assert_eq!(verdict, want, "{starter}, {function}:\n{stdout}");
        }
        assert!(
            stdout.contains("not written yet: it answers true for every ray"),
            "{stdout}"
        );
        assert_eq!(*code, Some(1), "{starter}:\n{stdout}");
    }
}

#[test]
fn a_folder_that_is_no_starter_is_refused_with_a_reason() {
    let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("check-source-none");
    let run = Command::new(CHECK)
        .arg("--source")
        .arg(env!("CARGO_MANIFEST_DIR"))
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("no CMakeLists.txt"), "{stderr}");
}
