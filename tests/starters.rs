//! The checker against the course's own binaries: the three starters of
//! `CS184_STARTER_DIR` (the 2023 and 2025 3-1 starters, the 2023 3-2
//! starter with the staff's precompiled 3-1 library), built here with
//! CMake as their README says, into `target/course-starters/`. Without
//! the variable the tests skip with a line, except under `CI=true`, where
//! they fail: CI points it at `../shared/course`.
//!
//! - every scene the checker exports loads in every starter, whole;
//! - a bare 3-1 starter gets "not written yet" for every check, without a
//!   crash, and `check` exits with 1;
//! - the 3-2 starter's parts 2 to 5, the staff's library, pass, and its
//!   parts 6 to 8, still the starter's, are "not written yet";
//! - a binary that does not exist makes `check` exit with 2;
//! - every starter file the checker names is in every starter.

#![cfg(unix)]

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

use pathtracer::check::scenes::CheckScene;
use pathtracer::scene::{self, Light};

const CHECK: &str = env!("CARGO_BIN_EXE_check");

/// The starters, by folder name.
const STARTERS: [&str; 3] = ["p3_1-sp23", "p3_1-2025", "p3_2-sp23"];

/// The built starters' binaries, in [`STARTERS`]' order; `None` (after a
/// line saying so) when `CS184_STARTER_DIR` is not set outside CI.
fn starters() -> Option<&'static [PathBuf]> {
    static BUILT: OnceLock<Option<Vec<PathBuf>>> = OnceLock::new();
    BUILT
        .get_or_init(|| {
            let Some(dir) = std::env::var_os("CS184_STARTER_DIR") else {
                assert!(
                    std::env::var("CI").as_deref() != Ok("true"),
                    "CS184_STARTER_DIR is not set: CI must point it at ../shared/course"
                );
                eprintln!("skipped: set CS184_STARTER_DIR to the course's starters");
                return None;
            };
            Some(
                STARTERS
                    .iter()
                    .map(|s| build(&PathBuf::from(&dir).join(s)))
                    .collect(),
            )
        })
        .as_deref()
}

/// Builds the starter at `source` (copied to a writable place first) and
/// returns its `pathtracer`, reusing an earlier build.
fn build(source: &Path) -> PathBuf {
    let name = source.file_name().unwrap().to_string_lossy().into_owned();
    let root = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("course-starters")
        .join(&name);
    let binary = root.join("build").join("pathtracer");
    if binary.exists() {
        return binary;
    }
    let tree = root.join("src");
    let _ = std::fs::remove_dir_all(&root);
    std::fs::create_dir_all(&root).unwrap();
    let copied = Command::new("cp")
        .arg("-r")
        .arg(source)
        .arg(&tree)
        .status()
        .unwrap();
    assert!(copied.success(), "copying {}", source.display());
    let _ = Command::new("chmod")
        .args(["-R", "u+w"])
        .arg(&tree)
        .status();
    let build = root.join("build");
    let run = |args: &[&str]| {
        let out = Command::new("cmake").args(args).output().expect("cmake");
        assert!(
            out.status.success(),
            "cmake {args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    };
    let (tree_s, build_s) = (tree.to_string_lossy(), build.to_string_lossy());
    run(&[
        "-S",
        &tree_s,
        "-B",
        &build_s,
        "-DCMAKE_BUILD_TYPE=Release",
        "-DCMAKE_C_FLAGS=-fcommon -w",
        "-DCMAKE_CXX_FLAGS=-w",
        "-DCMAKE_BUILD_RPATH=$ORIGIN",
        "-DCMAKE_POLICY_VERSION_MINIMUM=3.5",
    ]);
    run(&["--build", &build_s, "--target", "pathtracer", "-j", "2"]);
    let staff = tree.join("libs/x64_linux/libpt31.so");
    if staff.exists() {
        std::fs::copy(&staff, build.join("libpt31.so")).unwrap();
    }
    assert!(binary.exists(), "{} was not built", binary.display());
    binary
}

/// Every file a check or a "not written yet" names is a file of each
/// starter (the 3-1 starters hold 3-2's files too).
#[test]
fn every_file_the_checker_names_is_in_the_starters() {
    let Some(dir) = std::env::var_os("CS184_STARTER_DIR") else {
        assert!(std::env::var("CI").as_deref() != Ok("true"));
        return;
    };
    let mut checks =
        pathtracer::check::battery::battery_of(pathtracer::course::Assignment::PathTracer2);
    checks.extend(pathtracer::check::battery(&[1]));
    let named = checks.iter().flat_map(|c| c.file.split(", ")).chain(
        pathtracer::check::unwritten::FILES
            .iter()
            .flat_map(|f| f.split(", ")),
    );
    for file in named {
        for starter in STARTERS {
            let path = PathBuf::from(&dir).join(starter).join(file);
            assert!(path.is_file(), "{} is not a file", path.display());
        }
    }
}

/// Runs `check` with `args`: its exit code and its standard output.
fn check(args: &[&str]) -> (Option<i32>, String) {
    let out = Command::new(CHECK).args(args).output().unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
    )
}

/// Every scene the checker writes loads whole in every starter: it exits
/// 0, writes its image, and builds its BVH over every triangle and
/// sphere (a 3-2 starter adds each area light's two triangles).
#[test]
fn every_exported_scene_loads_in_every_starter() {
    let Some(binaries) = starters() else { return };
    let dir = tempfile::tempdir().unwrap();
    let empty = dir.path().join("no-scenes");
    std::fs::create_dir_all(&empty).unwrap();
    let files: Vec<PathBuf> = CheckScene::ALL
        .iter()
        .map(|which| which.file(Some(&empty), dir.path()).unwrap().path)
        .collect();
    for (name, binary) in STARTERS.iter().zip(binaries) {
        for file in &files {
            let scene = scene::load(file).unwrap();
            let areas = scene
                .lights
                .iter()
                .filter(|l| matches!(l, Light::Area { .. }))
                .count();
            let extra = if name.starts_with("p3_2") {
                2 * areas
            } else {
                0
            };
            let expected = scene.mesh.triangles.len() + scene.spheres.len() + extra;
            let image = dir.path().join("probe.png");
            let _ = std::fs::remove_file(&image);
            let mut args: Vec<String> = "-t 1 -s 1 -l 1 -m 0 -r 8 6 -f"
                .split(' ')
                .map(String::from)
                .collect();
            args.push(image.to_string_lossy().into_owned());
            if let Some(map) = CheckScene::Sky
                .environment_file(file)
                .filter(|m| m.exists())
            {
                args.extend(["-e".to_string(), map.to_string_lossy().into_owned()]);
            }
            args.push(file.to_string_lossy().into_owned());
            let out = Command::new(binary)
                .args(&args)
                .current_dir(dir.path())
                .output()
                .unwrap();
            let log = String::from_utf8_lossy(&out.stdout);
            assert!(
                out.status.success(),
                "{name} on {}: {:?}",
                file.display(),
                out.status
            );
            assert!(
                image.exists(),
                "{name} wrote no image of {}",
                file.display()
            );
            let said = format!("Building BVH from {expected} primitives");
            assert!(log.contains(&said), "{name} on {}: {log}", file.display());
        }
    }
}

/// A bare 3-1 starter: every check that runs says "not written yet" and
/// names `raytrace_pixel`, none crashes, and `check` exits with 1.
#[test]
fn a_bare_3_1_starter_is_not_written_yet_everywhere() {
    let Some(binaries) = starters() else { return };
    for binary in &binaries[..2] {
        let out = tempfile::tempdir().unwrap();
        let (code, table) = check(&[
            "--student",
            &binary.to_string_lossy(),
            "--out",
            &out.path().to_string_lossy(),
        ]);
        assert_eq!(code, Some(1), "{table}");
        let rows: Vec<&str> = table
            .lines()
            .skip(1)
            .take_while(|l| !l.is_empty())
            .collect();
        assert_eq!(rows.len(), 7, "{table}");
        for row in rows {
            assert!(
                row.contains("not written") && row.contains("raytrace_pixel")
                    || row.contains("skipped"),
                "{row}"
            );
        }
    }
}

/// The 3-2 starter's parts 2 to 5 are the staff's library: a correct
/// course solution, which passes. With `-t 1` the starter's random
/// numbers repeat run to run (one static engine, default seed), and the
/// reference's are seeded, so the verdict is the same in every run.
#[test]
fn the_3_2_starter_passes_parts_2_to_5() {
    let Some(binaries) = starters() else { return };
    let out = tempfile::tempdir().unwrap();
    let out = out.path().to_string_lossy().into_owned();
    let student = binaries[2].to_string_lossy().into_owned();
    let mut args = vec!["--student", &student, "--out", &out, "-t", "1"];
    args.extend(["--part", "2", "--part", "3", "--part", "4", "--part", "5"]);
    let (code, table) = check(&args);
    assert_eq!(code, Some(0), "{table}");
    let rows: Vec<&str> = table
        .lines()
        .filter(|l| l.starts_with(['2', '3', '4', '5']))
        .collect();
    assert_eq!(rows.len(), 6, "{table}");
    assert!(
        rows.iter()
            .all(|r| r.contains(" pass") || r.contains("skipped")),
        "{table}"
    );
}

/// The 3-2 starter's parts 6 to 8 are the starter's: "not written yet",
/// each naming its functions, on the project's own scenes (written so that
/// the course shades them as this project does); a binary that does not
/// exist is a usage error (2).
#[test]
fn the_3_2_starter_has_parts_6_to_8_not_written_yet() {
    let Some(binaries) = starters() else { return };
    let out = tempfile::tempdir().unwrap();
    let out = out.path().to_string_lossy().into_owned();
    let student = binaries[2].to_string_lossy().into_owned();
    let parts = ["--part", "6", "--part", "7", "--part", "8"];
    let mut args = vec!["--student", &student, "--out", &out];
    args.extend(parts);
    let (code, table) = check(&args);
    assert_eq!(code, Some(1), "{table}");
    let rows: Vec<&str> = table
        .lines()
        .filter(|l| l.starts_with(['6', '7', '8']))
        .collect();
    assert_eq!(rows.len(), 4, "{table}");
    for (row, function) in rows.iter().zip([
        "GlassBSDF",
        "MicrofacetBSDF",
        "EnvironmentLight",
        "thin_lens",
    ]) {
        assert!(
            row.contains("not written") && row.contains(function),
            "{table}"
        );
    }
    let (code, _) = check(&["--student", "/no/such/binary", "--out", &out, "--part", "3"]);
    assert_eq!(code, Some(2));
}
