//! Stand-in trees for `check --source`: a copy of one of the course's
//! starters (`CS184_STARTER_DIR`) whose functions are replaced by short,
//! correct C++ kept in the tests (a file of definitions, each after a
//! marker line `//== FILE :: FIRST LINE`), each catalogued mistake one
//! macro of the header `src/standin_mistake.h` written before each build.
//! The copy and `check`'s output folder stay the same from build to
//! build, so a build recompiles only what changed.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::Mutex;

use super::{probe_rows, starter_dir};
use pathtracer::check::probe::PROBES;

const CHECK: &str = env!("CARGO_BIN_EXE_check");

/// The header that switches the mistakes, in the tree.
const HEADER: &str = "src/standin_mistake.h";

/// One set of stand-ins.
pub struct Standins {
    /// The starter's folder name.
    pub starter: &'static str,
    /// The definitions, each after its marker line.
    pub functions: &'static str,
    /// The parts whose probes run.
    pub parts: &'static [u8],
    /// Lines put at the top of every changed file, before the header.
    pub prelude: &'static str,
    /// The samplers among the functions: with no mistake, the report
    /// shows each one's warptest picture.
    pub samplers: &'static [&'static str],
}

/// One row of the summary table: function, verdict, likely mistake.
pub type Row = (String, String, String);

impl Standins {
    /// The stand-ins: file, the starter's first line of the definition
    /// (indentation aside), and the text that replaces the definition.
    fn definitions(&self) -> Vec<(&'static str, &'static str, String)> {
        let mut out: Vec<(&str, &str, String)> = Vec::new();
        for line in self.functions.lines() {
            if let Some(marker) = line.strip_prefix("//== ") {
                let (file, first) = marker.split_once(" :: ").expect("FILE :: LINE");
                out.push((file, first, String::new()));
            } else if let Some((.., text)) = out.last_mut() {
                text.push_str(line);
                text.push('\n');
            }
        }
        out
    }

    /// A fresh writable copy of the starter with the stand-ins in it
    /// (timestamps kept, so an earlier run's build folder rebuilds only
    /// the changed files).
    fn tree(&self, starters: &Path) -> PathBuf {
        let tree =
            PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("standins-{}", self.starter));
        if tree.exists() {
            std::fs::remove_dir_all(&tree).unwrap();
        }
        let ok = |c: &mut Command| assert!(c.status().unwrap().success(), "{c:?}");
        ok(Command::new("cp")
            .arg("-rp")
            .arg(starters.join(self.starter))
            .arg(&tree));
        ok(Command::new("chmod").args(["-R", "u+w"]).arg(&tree));
        let definitions = self.definitions();
        let mut files: Vec<&str> = definitions.iter().map(|s| s.0).collect();
        files.sort_unstable();
        files.dedup();
        for file in files {
            let path = tree.join(file);
            let mut text = std::fs::read_to_string(&path).unwrap();
            for (_, first, with) in definitions.iter().filter(|s| s.0 == file) {
                text = replace(&text, first, with);
            }
            // Every file is src/DIR/NAME.cpp.
            let text = format!("{}#include \"../standin_mistake.h\"\n{text}", self.prelude);
            std::fs::write(&path, text).unwrap();
        }
        tree
    }

    /// `check --source` on the stand-ins with `mistake` switched on
    /// (none: all correct): the exit code, the table's rows and standard
    /// output; `None` without the starters.
    pub fn check(&self, mistake: Option<&str>) -> Option<(Option<i32>, Vec<Row>, String)> {
        self.check_in(mistake).map(|(run, _)| run)
    }

    /// [`Standins::check`] and `check`'s output folder.
    #[allow(clippy::type_complexity)]
    fn check_in(
        &self,
        mistake: Option<&str>,
    ) -> Option<((Option<i32>, Vec<Row>, String), PathBuf)> {
        static TREES: Mutex<Vec<(&'static str, PathBuf)>> = Mutex::new(Vec::new());
        let dir = starter_dir()?;
        // One build at a time: the lock is held to the end.
        let mut trees = TREES.lock().unwrap_or_else(|e| e.into_inner());
        if !trees.iter().any(|(s, _)| *s == self.starter) {
            let tree = self.tree(&dir);
            trees.push((self.starter, tree));
        }
        let tree = &trees.iter().find(|(s, _)| *s == self.starter).unwrap().1;
        let define = mistake.map_or(String::new(), |m| {
            format!("#define STANDIN_{}\n", m.to_uppercase().replace('-', "_"))
        });
        std::fs::write(tree.join(HEADER), format!("#pragma once\n{define}")).unwrap();
        let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
            .join(format!("check-source-standins-{}", self.starter));
        let mut command = Command::new(CHECK);
        command.arg("--source").arg(tree).arg("--out").arg(&out);
        for part in self.parts {
            command.arg("--part").arg(part.to_string());
        }
        let run = command.output().unwrap();
        let stdout = String::from_utf8_lossy(&run.stdout).into_owned();
        assert!(
            run.status.code() != Some(2),
            "{mistake:?}: {}\n{stdout}",
            String::from_utf8_lossy(&run.stderr)
        );
        let rows = probe_rows(&stdout)
            .into_iter()
            .map(|r| (r.function, r.verdict, r.mistake))
            .collect();
        Some(((run.status.code(), rows, stdout), out))
    }

    /// How many probes the parts have.
    fn probes(&self) -> usize {
        PROBES
            .iter()
            .filter(|p| self.parts.contains(&p.part))
            .count()
    }

    /// With no mistake every probe passes, `check` exits with 0, and the
    /// report shows the warptest picture of each sampler in its section.
    pub fn all_pass(&self) {
        let Some(((code, rows, stdout), out)) = self.check_in(None) else {
            return;
        };
        assert_eq!(rows.len(), self.probes(), "{stdout}");
        for (function, verdict, _) in &rows {
            assert_eq!(verdict, "pass", "{function}:\n{stdout}");
        }
        assert_eq!(code, Some(0), "{stdout}");
        let report = std::fs::read_to_string(out.join("report.html")).unwrap();
        let sections: Vec<&str> = report.split("<section").skip(1).collect();
        assert_eq!(sections.len(), self.probes());
        for (probe, section) in PROBES
            .iter()
            .filter(|p| self.parts.contains(&p.part))
            .zip(&sections)
        {
            assert!(section.contains(probe.function), "{section}");
            let pictured = section.contains(r#"alt="warptest" src="data:image/png;base64,"#);
            let sampler = self.samplers.contains(&probe.function);
            assert_eq!(pictured, sampler, "{}", probe.function);
        }
    }

    /// With `mistake` in the functions `wrong`: those fail naming it,
    /// those that call none of them pass, and `check` exits with 1.
    pub fn a_mistake_is_named(&self, mistake: &str, wrong: &[&str]) {
        self.fails(mistake, mistake, wrong);
    }

    /// As [`Standins::a_mistake_is_named`] for a slip the catalogue does
    /// not hold: the functions `wrong` fail, name no mistake, and the
    /// first one's failure `says` what is wrong.
    pub fn a_slip_fails(&self, slip: &str, wrong: &[&str], says: &str) {
        if let Some(stdout) = self.fails(slip, "-", wrong) {
            let first = format!("{} (", wrong[0]);
            let details = stdout.split_once(&first).map_or("", |(_, d)| d);
            let line = details.lines().next().unwrap_or("");
            assert!(line.contains(says), "{slip}: {line}\n{stdout}");
        }
    }

    /// With the stand-ins' switch `define` on, the functions `wrong` fail
    /// with `named` in the "likely mistake" column, those that call none
    /// of them pass, and `check` exits with 1; its standard output (`None`
    /// without the starters).
    fn fails(&self, define: &str, named: &str, wrong: &[&str]) -> Option<String> {
        let mistake = define;
        let (code, rows, stdout) = self.check(Some(define))?;
        assert_eq!(rows.len(), self.probes(), "{mistake}:\n{stdout}");
        // The functions that call a wrong one, directly or not, may fail
        // (PROBES lists a function after those it needs).
        let mut touched: Vec<&str> = wrong.to_vec();
        for p in PROBES {
            if p.needs.iter().any(|n| touched.contains(n)) {
                touched.push(p.function);
            }
        }
        for (function, verdict, found) in &rows {
            if wrong.contains(&function.as_str()) {
                assert_eq!(
                    (verdict.as_str(), found.as_str()),
                    ("FAIL", named),
                    "{mistake}, {function}:\n{stdout}"
                );
            } else if !touched.contains(&function.as_str()) {
                assert_eq!(verdict, "pass", "{mistake}, {function}:\n{stdout}");
            }
        }
        assert_eq!(code, Some(1), "{mistake}:\n{stdout}");
        Some(stdout)
    }
}

/// `text` with the definition that starts with the line `first` (leading
/// spaces aside) and ends at the next `}` indented as that line is,
/// replaced by `with`.
fn replace(text: &str, first: &str, with: &str) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let start = lines
        .iter()
        .position(|l| l.trim() == first)
        .unwrap_or_else(|| panic!("the starter has no line `{first}`"));
    let indent = &lines[start][..lines[start].len() - lines[start].trim_start().len()];
    let close = format!("{indent}}}");
    let end = start
        + lines[start..]
            .iter()
            .position(|l| l.trim_end() == close)
            .unwrap_or_else(|| panic!("`{first}` has no `{close}`"));
    let mut out = lines[..start].join("\n");
    out.push('\n');
    out.push_str(with.trim_end());
    out.push('\n');
    out.push_str(&lines[end + 1..].join("\n"));
    out.push('\n');
    out
}

/// One test a mistake, for the stand-ins `$set`:
/// `name: "mistake" in "Function", ...;`.
#[macro_export]
macro_rules! standin_mistakes {
    ($set:expr; $($test:ident: $mistake:literal in $($function:literal),+;)*) => {
        $(
            #[test]
            fn $test() {
                $set.a_mistake_is_named($mistake, &[$($function),+]);
            }
        )*
    };
}
