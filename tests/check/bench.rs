//! The checker's test bench, shared by `tests/check.rs` and
//! `tests/check_rates.rs`: stand-in students (this project's own
//! `pathtracer --course-exact=3-1`, with or without `--mistake NAME`,
//! behind a wrapper script), the project's box as the scene, one stage
//! that keeps its renders, and a reader of the report.

#![allow(dead_code)]

use std::os::unix::fs::PermissionsExt;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use std::time::Duration;

use pathtracer::check::{battery, judge, scene_for_checks, Check, CheckResult, Stage, Student};
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

/// A stand-in student: the course's renderer with `mistake`, at `seed`.
pub fn stand_in(dir: &Path, mistake: Option<Mistake>, seed: u64) -> PathBuf {
    let flag = mistake.map_or(String::new(), |m| format!("--mistake {m}"));
    script(
        dir,
        &format!(
            "student-{}-{seed}.sh",
            mistake.map_or("right".into(), |m| m.to_string())
        ),
        &format!("exec {PATHTRACER} --course-exact=3-1 {flag} --seed {seed} \"$@\""),
    )
}

pub struct Bench {
    pub dir: tempfile::TempDir,
    pub scene_file: String,
    pub stage: &'static Stage,
}

/// One stage for every test, keeping its renders: the tests judge the
/// same checks many times (the null images of a check, its suspects'),
/// and each image is rendered once. Every bench exports the same scene.
pub fn shared_stage(scene: Scene) -> &'static Stage {
    static STAGE: OnceLock<Stage> = OnceLock::new();
    STAGE.get_or_init(|| Stage::remembering(scene))
}

impl Bench {
    /// The project's own box, exported where the checker puts it (no
    /// course scenes: `--scenes` names an empty folder).
    pub fn new() -> Self {
        let dir = tempfile::tempdir().unwrap();
        let empty = dir.path().join("no-scenes");
        std::fs::create_dir_all(&empty).unwrap();
        let (file, scene) = scene_for_checks(Some(&empty), dir.path()).unwrap();
        Bench {
            scene_file: file.to_string_lossy().into_owned(),
            stage: shared_stage(scene),
            dir,
        }
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

    /// The checks `checks` for `binary`, at the full battery's rate.
    pub fn run(&self, binary: PathBuf, checks: &[Check]) -> Vec<CheckResult> {
        let student = self.student(binary, Duration::from_secs(120));
        let capabilities = student.capabilities().unwrap();
        let alpha = pathtracer::check::ALPHA / battery(&[]).len() as f64;
        checks
            .iter()
            .map(|c| {
                judge(
                    c,
                    &student,
                    capabilities,
                    &self.scene_file,
                    self.stage,
                    alpha,
                    2,
                )
            })
            .collect()
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
            .output()
            .is_ok()
    });
    let Some(browser) = browser else {
        eprintln!("no headless browser (chromium) here: the report was checked as a file only");
        return;
    };
    let dom = std::process::Command::new(browser)
        .args(["--headless", "--no-sandbox", "--disable-gpu", "--dump-dom"])
        .arg(&path)
        .output()
        .expect("the browser runs");
    let dom = String::from_utf8_lossy(&dom.stdout);
    for r in results {
        assert!(
            dom.contains(r.check.name),
            "{} not in the rendered page",
            r.check.name
        );
    }
    assert!(dom.contains("class=\"pass\""));
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
