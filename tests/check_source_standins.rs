//! `check --source` on real C++ that is wrong in one catalogued way: a
//! copy of the course's 2025 3-1 starter (`CS184_STARTER_DIR`, copied
//! under the test's temporary folder) whose functions of parts 1 to 3 are
//! replaced by short, correct stand-ins (`check_source_standins/
//! functions.cpp`), each catalogued mistake one macro of the header
//! `src/standin_mistake.h` that the test writes before each build (the
//! same build folder each time, so a build recompiles only the changed
//! files). It proves that
//!
//! - with no mistake, every probe of parts 1 to 3 passes and `check`
//!   exits with 0;
//! - with each mistake, the function it is in fails, the table's "likely
//!   mistake" column names it, every function it does not touch (and that
//!   does not call a function it is in) still passes, and `check` exits
//!   with 1.
//!
//! Without the variable the tests skip with a line, except under
//! `CI=true`, where they fail.

#![cfg(unix)]

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::{Mutex, OnceLock};

use common::{probe_rows, starter_dir};
use pathtracer::check::probe::PROBES;

const CHECK: &str = env!("CARGO_BIN_EXE_check");

/// The stand-ins, each after a marker line `//== FILE :: FIRST LINE`.
const FUNCTIONS: &str = include_str!("check_source_standins/functions.cpp");

/// The header that switches the mistakes, in the tree.
const HEADER: &str = "src/standin_mistake.h";

/// The stand-ins: file, the starter's first line of the definition, and
/// the text that replaces the definition.
fn standins() -> Vec<(&'static str, &'static str, String)> {
    let mut out: Vec<(&str, &str, String)> = Vec::new();
    for line in FUNCTIONS.lines() {
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

/// `text` with the definition that starts with the line `first` (and
/// ends at the next `}` in column 0) replaced by `with`.
fn replace(text: &str, first: &str, with: &str) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let start = lines
        .iter()
        .position(|l| l.trim_end() == first)
        .unwrap_or_else(|| panic!("the starter has no line `{first}`"));
    let end = start
        + lines[start..]
            .iter()
            .position(|l| l.starts_with('}'))
            .unwrap();
    let mut out = lines[..start].join("\n");
    out.push('\n');
    out.push_str(with.trim_end());
    out.push('\n');
    out.push_str(&lines[end + 1..].join("\n"));
    out.push('\n');
    out
}

/// A fresh writable copy of the 2025 starter with the stand-ins in it
/// (timestamps kept, so an earlier run's build folder rebuilds only the
/// changed files).
fn tree(starters: &Path) -> PathBuf {
    let tree = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("standins-p3_1-2025");
    if tree.exists() {
        std::fs::remove_dir_all(&tree).unwrap();
    }
    let ok = |c: &mut Command| assert!(c.status().unwrap().success(), "{c:?}");
    ok(Command::new("cp")
        .arg("-rp")
        .arg(starters.join("p3_1-2025"))
        .arg(&tree));
    ok(Command::new("chmod").args(["-R", "u+w"]).arg(&tree));
    let mut files: Vec<&str> = standins().iter().map(|s| s.0).collect();
    files.sort_unstable();
    files.dedup();
    for file in files {
        let path = tree.join(file);
        let mut text = std::fs::read_to_string(&path).unwrap();
        for (_, first, with) in standins().iter().filter(|s| s.0 == file) {
            text = replace(&text, first, with);
        }
        // Every file is src/DIR/NAME.cpp.
        let text = format!("#include \"../standin_mistake.h\"\n{text}");
        std::fs::write(&path, text).unwrap();
    }
    tree
}

/// One row of the summary table: function, verdict, likely mistake.
type Row = (String, String, String);

/// `check --source` on the stand-ins with `mistake` switched on (none:
/// all correct): the exit code, the table's rows and standard output.
fn check(mistake: Option<&str>) -> Option<(Option<i32>, Vec<Row>, String)> {
    static LOCK: Mutex<()> = Mutex::new(());
    static TREE: OnceLock<PathBuf> = OnceLock::new();
    let dir = starter_dir()?;
    let _one_build_at_a_time = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let tree = TREE.get_or_init(|| tree(&dir));
    let define = mistake.map_or(String::new(), |m| {
        format!("#define STANDIN_{}\n", m.to_uppercase().replace('-', "_"))
    });
    std::fs::write(tree.join(HEADER), format!("#pragma once\n{define}")).unwrap();
    let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("check-source-standins");
    let run = Command::new(CHECK)
        .arg("--source")
        .arg(tree)
        .arg("--out")
        .arg(&out)
        .args(["--part", "1", "--part", "2", "--part", "3"])
        .output()
        .unwrap();
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
    Some((run.status.code(), rows, stdout))
}

/// How many probes parts 1 to 3 have.
fn probes() -> usize {
    PROBES.iter().filter(|p| p.part <= 3).count()
}

#[test]
fn the_correct_stand_ins_pass_every_probe() {
    let Some((code, rows, stdout)) = check(None) else {
        return;
    };
    assert_eq!(rows.len(), probes(), "{stdout}");
    for (function, verdict, _) in &rows {
        assert_eq!(verdict, "pass", "{function}:\n{stdout}");
    }
    assert_eq!(code, Some(0), "{stdout}");
}

/// With `mistake` in the functions `wrong`: those fail naming it, those
/// that call none of them pass.
fn a_mistake_is_named(mistake: &str, wrong: &[&str]) {
    let Some((code, rows, stdout)) = check(Some(mistake)) else {
        return;
    };
    assert_eq!(rows.len(), probes(), "{mistake}:\n{stdout}");
    // The functions that call a wrong one, directly or not, may fail.
    let mut touched: Vec<&str> = wrong.to_vec();
    for p in PROBES {
        if p.needs.iter().any(|n| touched.contains(n)) {
            touched.push(p.function);
        }
    }
    for (function, verdict, named) in &rows {
        if wrong.contains(&function.as_str()) {
            assert_eq!(
                (verdict.as_str(), named.as_str()),
                ("FAIL", mistake),
                "{mistake}, {function}:\n{stdout}"
            );
        } else if !touched.contains(&function.as_str()) {
            assert_eq!(verdict, "pass", "{mistake}, {function}:\n{stdout}");
        }
    }
    assert_eq!(code, Some(1), "{mistake}:\n{stdout}");
}

/// One test a mistake: `name: "mistake" in "Function", ...;`.
macro_rules! mistakes {
    ($($test:ident: $mistake:literal in $($function:literal),+;)*) => {
        $(
            #[test]
            fn $test() {
                a_mistake_is_named($mistake, &[$($function),+]);
            }
        )*
    };
}

mistakes! {
    fov_in_degrees: "fov-in-degrees" in "Camera::generate_ray";
    ray_in_camera_space: "ray-in-camera-space" in "Camera::generate_ray";
    fov_full_angle: "fov-full-angle" in "Camera::generate_ray";
    triangle_chained_comparison: "triangle-chained-comparison"
        in "Triangle::has_intersection", "Triangle::intersect";
    barycentric_normals_permuted: "barycentric-normals-permuted" in "Triangle::intersect";
    max_t_not_shrunk: "max-t-not-shrunk" in "Triangle::intersect";
    sphere_far_root: "sphere-far-root" in "Sphere::intersect";
    bbox_misses_rays_from_inside: "bbox-misses-rays-from-inside" in "BBox::intersect";
    bvh_first_hit: "bvh-first-hit" in "BVHAccel::intersect";
    brdf_is_albedo: "brdf-is-albedo" in "DiffuseBSDF::f";
}
