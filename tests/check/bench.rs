//! The checker's test bench, shared by `tests/check.rs`,
//! `tests/check_rates.rs` and `tests/check_32.rs`: stand-in students
//! (this project's own `pathtracer --course-exact=3-1` or `=3-2`, with or
//! without `--mistake NAME`, behind a wrapper script), the project's
//! scenes ([`CheckScene`]) with one stage each that keeps its renders, and
//! a reader of the report.

#![allow(dead_code)]

use std::os::unix::fs::PermissionsExt;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use std::time::Duration;

use pathtracer::check::battery::battery_of;
use pathtracer::check::{
    judge, wait_at_most, Check, CheckResult, CheckScene, Outcome, Stage, Student,
};
use pathtracer::course::Assignment;
use pathtracer::mistakes::Mistake;
use pathtracer::scene::Scene;

pub const PATHTRACER: &str = env!("CARGO_BIN_EXE_pathtracer");

/// Writes an executable shell script `name` into `dir`.
pub fn script(dir: &Path, name: &str, body: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, format!("#!/bin/sh\n{body}\n")).unwrap();
    std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o755)).unwrap();
    path
}

/// A script that refuses the flags `refused` as the course's getopt does
/// a flag it does not know (the usage, exit status 1) and otherwise runs
/// `body`.
pub fn refusing(dir: &Path, name: &str, refused: &[&str], body: &str) -> PathBuf {
    let cases = refused.join("|");
    let guard = format!(
        "for a in \"$@\"; do case \"$a\" in {cases}) echo 'Usage: pathtracer [options] <scenefile>'; exit 1;; esac; done"
    );
    script(dir, name, &format!("{guard}\n{body}"))
}

/// A stand-in student of assignment 3-1: the course's renderer with
/// `mistake`, at `seed`.
pub fn stand_in(dir: &Path, mistake: Option<Mistake>, seed: u64) -> PathBuf {
    stand_in_of(Assignment::PathTracer1, dir, mistake, seed)
}

/// A stand-in student's binary of `assignment`, with `mistake`, at `seed`.
pub fn stand_in_of(
    assignment: Assignment,
    dir: &Path,
    mistake: Option<Mistake>,
    seed: u64,
) -> PathBuf {
    let flag = mistake.map_or(String::new(), |m| format!("--mistake {m}"));
    let year = assignment.name();
    script(
        dir,
        &format!(
            "student-{year}-{}-{seed}.sh",
            mistake.map_or("right".into(), |m| m.to_string())
        ),
        &format!("exec {PATHTRACER} --course-exact={year} {flag} --seed {seed} \"$@\""),
    )
}

/// A stand-in student of assignment 3-1 whose correct solution made the
/// handout's `choices` (`--course-choice KEY=VALUE` each), at `seed`.
pub fn stand_in_choosing(dir: &Path, choices: &[&str], seed: u64) -> PathBuf {
    let flags: Vec<String> = choices
        .iter()
        .map(|c| format!("--course-choice {c}"))
        .collect();
    script(
        dir,
        &format!("student-3-1-{}-{seed}.sh", choices.join("-")),
        &format!(
            "exec {PATHTRACER} --course-exact=3-1 {} --seed {seed} \"$@\"",
            flags.join(" ")
        ),
    )
}

pub struct Bench {
    pub dir: tempfile::TempDir,
    /// The diffuse box's file and stage ([`CheckScene::Lambertian`]).
    pub scene_file: String,
    pub stage: &'static Stage,
    /// Every scene's file and stage.
    pub scenes: Vec<(CheckScene, String, &'static Stage)>,
}

/// One stage per scene for every test, keeping its renders: the tests
/// judge the same checks many times (the null images of a check, its
/// suspects'), and each image is rendered once. Every bench exports the
/// same scenes.
pub fn shared_stage(which: CheckScene, file: &Path, scene: Scene) -> &'static Stage {
    static STAGES: [OnceLock<Stage>; CheckScene::ALL.len()] =
        [const { OnceLock::new() }; CheckScene::ALL.len()];
    let index = CheckScene::ALL.iter().position(|&s| s == which).unwrap();
    STAGES[index].get_or_init(|| which.stage(file, scene, true).unwrap())
}

impl Bench {
    /// The project's own scenes, exported where the checker puts them (no
    /// course scenes: `--scenes` names an empty folder).
    pub fn new() -> Self {
        let dir = tempfile::tempdir().unwrap();
        let empty = dir.path().join("no-scenes");
        std::fs::create_dir_all(&empty).unwrap();
        let scenes: Vec<(CheckScene, String, &'static Stage)> = CheckScene::ALL
            .into_iter()
            .map(|which| {
                let found = which.file(Some(&empty), dir.path()).unwrap();
                let stage = shared_stage(which, &found.path, found.scene);
                (which, found.path.to_string_lossy().into_owned(), stage)
            })
            .collect();
        let lambertian = scenes
            .iter()
            .find(|s| s.0 == CheckScene::Lambertian)
            .unwrap()
            .clone();
        Bench {
            scene_file: lambertian.1.clone(),
            stage: lambertian.2,
            scenes,
            dir,
        }
    }

    /// The sky scene's environment map, to try `-e` with.
    pub fn map(&self) -> Option<PathBuf> {
        let (_, file, _) = self.scenes.iter().find(|s| s.0 == CheckScene::Sky)?;
        CheckScene::Sky.environment_file(Path::new(file))
    }

    /// The file and stage of `check`'s scene.
    pub fn scene_of(&self, check: &Check) -> (&str, &'static Stage) {
        let (_, file, stage) = self.scenes.iter().find(|s| s.0 == check.scene).unwrap();
        (file, stage)
    }

    pub fn student(&self, binary: PathBuf, timeout: Duration) -> Student {
        let work = self.dir.path().join("runs");
        std::fs::create_dir_all(&work).unwrap();
        Student {
            binary,
            work,
            timeout,
        }
    }

    /// The checks `checks` for `binary`, each at its assignment's full
    /// battery's rate.
    pub fn run(&self, binary: PathBuf, checks: &[Check]) -> Vec<CheckResult> {
        let student = self.student(binary, Duration::from_secs(120));
        let capabilities = student
            .capabilities(&self.scene_file, self.map().as_deref())
            .unwrap();
        checks
            .iter()
            .map(|c| {
                let alpha = pathtracer::check::ALPHA / battery_of(c.assignment).len() as f64;
                let (file, stage) = self.scene_of(c);
                judge(c, &student, capabilities, file, stage, alpha, 2)
            })
            .collect()
    }
}

/// Every check of `results` passed; prints each statistic and its
/// threshold.
pub fn all_pass(results: Vec<CheckResult>) {
    for r in results {
        match r.outcome {
            Outcome::Pass {
                statistic,
                threshold,
                region,
                region_threshold,
                variant,
            } => eprintln!(
                "{}: {statistic:.1} of {threshold:.1}, region {region:.1} of {region_threshold:.1}{}",
                r.check.name,
                variant.map(|v| format!(", as a solution that {v}")).unwrap_or_default()
            ),
            other => panic!("{}: {other:?}", r.check.name),
        }
    }
}

/// The report of `results`, written into `dir`: well-formed (read as
/// XML), a section per check with its verdict, and every image a PNG that
/// decodes; in a headless browser where one is installed, the verdicts
/// are in the page it renders.
pub fn report_is_whole(results: &[CheckResult], dir: &Path) {
    use pathtracer::check::report;
    let page = report::html("student", "scene.dae", results);
    let path = report::write_report(dir, &page).unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    let xml = text.replacen("<!DOCTYPE html>", "", 1);
    let doc = roxmltree::Document::parse(&xml).expect("the report is well-formed");
    let sections = doc
        .descendants()
        .filter(|n| n.has_tag_name("section"))
        .count();
    assert_eq!(sections, results.len());
    // Each judged check shows both tests' values against their thresholds.
    let sections = doc.descendants().filter(|n| n.has_tag_name("section"));
    for (section, r) in sections.zip(results) {
        let text: String = section.descendants().filter_map(|n| n.text()).collect();
        if let Outcome::Pass {
            statistic,
            threshold,
            region,
            region_threshold,
            ..
        }
        | Outcome::Fail {
            statistic,
            threshold,
            region,
            region_threshold,
            ..
        } = r.outcome
        {
            for shown in [
                format!("as a whole: {statistic:.1} (threshold {threshold:.1})"),
                format!("region: {region:.1} (threshold {region_threshold:.1})"),
            ] {
                assert!(
                    text.contains(&shown),
                    "{}: no '{shown}' in {text}",
                    r.check.name
                );
            }
        }
    }
    let images: Vec<_> = doc
        .descendants()
        .filter(|n| n.has_tag_name("img"))
        .collect();
    assert!(images.len() >= 3 * results.len());
    for img in images {
        let src = img.attribute("src").unwrap();
        let data = src
            .strip_prefix("data:image/png;base64,")
            .expect("an inlined PNG");
        let bytes = decode_base64(data);
        image::load_from_memory(&bytes).expect("the image decodes");
    }
    let browser = ["chromium", "chromium-browser"].into_iter().find(|b| {
        std::process::Command::new(b)
            .arg("--version")
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .status()
            .is_ok_and(|s| s.success())
    });
    let Some(browser) = browser else {
        eprintln!("no headless browser (chromium) here: the report was checked as a file only");
        return;
    };
    let Some(dom) = dump_dom(browser, &path) else {
        eprintln!("the browser failed or hung: the report was checked as a file only");
        return;
    };
    for r in results {
        assert!(
            dom.contains(r.check.name),
            "{} not in the rendered page",
            r.check.name
        );
    }
    assert!(dom.contains("class=\"pass\""));
}

/// The page at `path` as headless `browser` renders it, or `None` if the
/// browser exits with an error or takes more than a minute (a browser
/// that crashes or hangs in a container says nothing about the page).
fn dump_dom(browser: &str, path: &Path) -> Option<String> {
    let scratch = tempfile::tempdir().unwrap();
    let dom_file = scratch.path().join("dom.html");
    let mut child = std::process::Command::new(browser)
        .args(["--headless", "--no-sandbox", "--disable-gpu"])
        .args(["--disable-dev-shm-usage", "--dump-dom"])
        .arg(format!("--user-data-dir={}", scratch.path().display()))
        .arg(path)
        .stdout(std::fs::File::create(&dom_file).unwrap())
        .stderr(std::process::Stdio::null())
        .spawn()
        .ok()?;
    wait_at_most(&mut child, Duration::from_secs(60))?
        .success()
        .then(|| std::fs::read_to_string(&dom_file).unwrap())
}

/// Standard base64 back to bytes (the test's own decoder).
pub fn decode_base64(text: &str) -> Vec<u8> {
    let value = |c: u8| match c {
        b'A'..=b'Z' => c - b'A',
        b'a'..=b'z' => c - b'a' + 26,
        b'0'..=b'9' => c - b'0' + 52,
        b'+' => 62,
        b'/' => 63,
        _ => panic!("not base64: {c}"),
    } as u32;
    let mut bytes = Vec::new();
    for chunk in text.as_bytes().chunks(4) {
        let pad = chunk.iter().filter(|&&c| c == b'=').count();
        let n = chunk
            .iter()
            .map(|&c| if c == b'=' { 0 } else { value(c) })
            .fold(0u32, |n, v| n << 6 | v);
        bytes.extend_from_slice(&n.to_be_bytes()[1..4 - pad]);
    }
    bytes
}

/// The mistakes other than `culprit` that fit a failed image: what the
/// checker would name if `culprit` were not in its catalogue (a bug held
/// out from it).
pub fn others_that_fit(suspects: &[pathtracer::check::Suspect], culprit: Mistake) -> Vec<Mistake> {
    suspects
        .iter()
        .filter(|s| s.fits && s.mistake != culprit)
        .map(|s| s.mistake)
        .collect()
}
