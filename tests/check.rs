//! The checker ([`pathtracer::check`]) against stand-in students: this
//! project's own `pathtracer` in the course's mode (`--course-exact=3-1`),
//! correct or with a catalogued mistake (`--mistake NAME`), through a
//! small wrapper script, as a student's binary; and binaries that go wrong
//! in every way a student's can (missing, not executable, crashing,
//! writing nothing, writing the wrong size, hanging).

#![cfg(unix)]

use std::os::unix::fs::PermissionsExt;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use std::time::Duration;

use pathtracer::check::{
    battery, judge, scene_for_checks, Capabilities, Check, CheckResult, Outcome, Stage, Student,
};
use pathtracer::mistakes::Mistake;
use pathtracer::scene::Scene;

const PATHTRACER: &str = env!("CARGO_BIN_EXE_pathtracer");

/// Writes an executable shell script `name` into `dir`.
fn script(dir: &Path, name: &str, body: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, format!("#!/bin/sh\n{body}\n")).unwrap();
    std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o755)).unwrap();
    path
}

/// A stand-in student: the course's renderer with `mistake`, at `seed`.
fn stand_in(dir: &Path, mistake: Option<Mistake>, seed: u64) -> PathBuf {
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

struct Bench {
    dir: tempfile::TempDir,
    scene_file: String,
    stage: &'static Stage,
}

/// One stage for every test, keeping its renders: the tests judge the
/// same checks many times (the null images of a check, its suspects'),
/// and each image is rendered once. Every bench exports the same scene.
fn shared_stage(scene: Scene) -> &'static Stage {
    static STAGE: OnceLock<Stage> = OnceLock::new();
    STAGE.get_or_init(|| Stage::remembering(scene))
}

impl Bench {
    /// The project's own box, exported where the checker puts it (no
    /// course scenes: `--scenes` names an empty folder).
    fn new() -> Self {
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

    fn student(&self, binary: PathBuf, timeout: Duration) -> Student {
        let work = self.dir.path().join("runs");
        std::fs::create_dir_all(&work).unwrap();
        Student {
            binary,
            work,
            timeout,
        }
    }

    /// The checks `checks` for `binary`, at the full battery's rate.
    fn run(&self, binary: PathBuf, checks: &[Check]) -> Vec<CheckResult> {
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
fn report_is_whole(results: &[CheckResult], dir: &Path) {
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
fn decode_base64(text: &str) -> Vec<u8> {
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

/// A correct renderer passes every check (one run cannot measure a rate
/// of 1 %: `the_false_alarm_rate_is_bounded` does, in process).
#[test]
fn a_correct_renderer_passes_every_check() {
    let bench = Bench::new();
    for seed in [1] {
        let binary = stand_in(bench.dir.path(), None, seed);
        let results = bench.run(binary, &battery(&[]));
        assert_eq!(results.len(), 4);
        report_is_whole(&results, bench.dir.path());
        for r in results {
            match r.outcome {
                Outcome::Pass {
                    statistic,
                    threshold,
                } => {
                    eprintln!("{}: {statistic:.1} of {threshold:.1}", r.check.name);
                }
                other => panic!("{}: {other:?}", r.check.name),
            }
        }
    }
}

/// The decision's false-alarm rate, measured: 60 images of a correct
/// solution (in process, independent seeds) against one null model, at
/// `alpha` = 0.05 on the noisiest check (`-H`). A correct rule exceeds
/// its threshold in at most 5 % of them; 13 or more would happen with
/// probability below 1e-4 if the rate were 5 % (binomial tail).
#[test]
fn the_false_alarm_rate_is_bounded() {
    use pathtracer::check::battery::SIZE;
    use pathtracer::check::stats::{cells, chi_square_quantile, statistic, NullModel};
    use pathtracer::mistakes::Mistakes;
    let bench = Bench::new();
    let check = battery(&[3])[0];
    assert!(check.hemisphere);
    let null: Vec<Vec<u8>> = (0..8)
        .map(|seed| bench.stage.render(&check, Mistakes::NONE, 1000 + seed, 2))
        .collect();
    let model = NullModel::new(SIZE.0, SIZE.1, &null);
    let threshold = chi_square_quantile(model.mean.len() as f64, 0.05);
    let alarms = (0..60)
        .filter(|seed| {
            let image = bench.stage.render(&check, Mistakes::NONE, 50_000 + seed, 2);
            let x = cells(SIZE.0, SIZE.1, &image);
            statistic(&model.z_scores(&x)) > threshold
        })
        .count();
    eprintln!("false alarms at alpha 0.05: {alarms} of 60");
    assert!(alarms < 13, "{alarms} of 60");
}

/// A student with a catalogued mistake fails the checks of its part, and
/// the mistake is named among those that fit, first or tied with one whose
/// image cannot be told apart at these settings.
#[test]
fn a_mistake_fails_its_part_and_is_named() {
    let bench = Bench::new();
    // Each with a telling check of its part: light sampling for part 3;
    // all bounces (roulette) or the second alone (-o 0) for part 4.
    let cases = [
        (Mistake::NoCosine, 3, 1),
        (Mistake::LightSamplesNotAveraged, 3, 1),
        (Mistake::ShadowRayReachesLight, 3, 1),
        (Mistake::RouletteNotDivided, 4, 0),
        (Mistake::NoAccumulationSumsAll, 4, 1),
    ];
    for (mistake, part, index) in cases {
        let check = battery(&[part])[index];
        let binary = stand_in(bench.dir.path(), Some(mistake), 3);
        let results = bench.run(binary, &[check]);
        let named = results.iter().any(|r| match &r.outcome {
            Outcome::Fail { suspects, what, .. } => {
                eprintln!("{mistake}: {}: {what}; {:?}", r.check.name, &suspects[..3]);
                let best = suspects[0].misfit;
                suspects
                    .iter()
                    .take_while(|s| s.fits && s.misfit <= 1.2 * best.max(0.05))
                    .any(|s| s.mistake == mistake)
            }
            _ => false,
        });
        assert!(named, "{mistake} was not named: {:?}", results[0].outcome);
    }
}

/// Binaries that go wrong get a clear line each, and the battery goes on.
#[test]
fn a_broken_binary_gets_a_clear_line() {
    let bench = Bench::new();
    let dir = bench.dir.path();
    let not_executable = dir.join("plain.txt");
    std::fs::write(&not_executable, "not a program").unwrap();
    let cases: [(PathBuf, &str); 5] = [
        (dir.join("no-such-binary"), "no such file"),
        (not_executable, "cannot run it"),
        (
            script(dir, "crash.sh", "echo 'segfault!' >&2; exit 3"),
            "crashed",
        ),
        (script(dir, "lazy.sh", "exit 0"), "without writing"),
        (
            script(
                dir,
                "small.sh",
                &format!("exec {PATHTRACER} --course-exact=3-1 -r 64 48 -s 1 -f check.png"),
            ),
            "64x48",
        ),
    ];
    let check = battery(&[3])[1];
    let caps = Capabilities {
        accumulate_flag: true,
    };
    for (binary, says) in cases {
        let student = bench.student(binary.clone(), Duration::from_secs(60));
        let r = judge(
            &check,
            &student,
            caps,
            &bench.scene_file,
            bench.stage,
            1e-3,
            2,
        );
        match r.outcome {
            Outcome::Error(why) => assert!(why.contains(says), "{}: {why}", binary.display()),
            other => panic!("{}: {other:?}", binary.display()),
        }
    }
    let hang = bench.student(
        script(dir, "hang.sh", "sleep 30"),
        Duration::from_millis(300),
    );
    let r = judge(&check, &hang, caps, &bench.scene_file, bench.stage, 1e-3, 2);
    assert!(
        matches!(&r.outcome, Outcome::Error(why) if why.contains("within")),
        "{r:?}"
    );
    // A binary without -o: the check that needs it is skipped, saying so.
    let no_o = battery(&[4])[1];
    let caps = Capabilities {
        accumulate_flag: false,
    };
    let r = judge(&no_o, &hang, caps, &bench.scene_file, bench.stage, 1e-3, 2);
    assert!(matches!(&r.outcome, Outcome::Skipped(why) if why.contains("-o")));
}
