//! The binaries as a user meets them: errors on bad input name the file and
//! exit non-zero without a panic; an output file is written whole or not at all.

use std::process::Command;

fn run(binary: &str, args: &[&str]) -> (bool, String, String) {
    let out = Command::new(binary)
        .args(args)
        .output()
        .expect("binary runs");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

const PATHTRACER: &str = env!("CARGO_BIN_EXE_pathtracer");
const BINARIES: [&str; 3] = [
    env!("CARGO_BIN_EXE_pathtracer"),
    env!("CARGO_BIN_EXE_part1-raygen"),
    env!("CARGO_BIN_EXE_part2-bvh"),
];

#[test]
fn bad_scene_files_give_a_clear_error_naming_the_file() {
    let dir = tempfile::tempdir().unwrap();
    let truncated = dir.path().join("truncated.dae");
    std::fs::write(
        &truncated,
        "<?xml version=\"1.0\"?><COLLADA><library_geometries>",
    )
    .unwrap();
    let empty = dir.path().join("empty.dae");
    std::fs::write(&empty, "").unwrap();
    let missing = dir.path().join("missing.dae");
    for binary in BINARIES {
        for file in [&truncated, &empty, &missing] {
            let (ok, _, stderr) = run(binary, &[file.to_str().unwrap(), "-r", "8", "6"]);
            assert!(!ok, "{binary} accepted {}", file.display());
            assert!(stderr.starts_with("error: "), "{stderr}");
            assert!(stderr.contains(file.to_str().unwrap()), "{stderr}");
            assert!(!stderr.contains("panicked"), "{stderr}");
        }
    }
}

#[test]
fn info_prints_the_three_fixed_lines() {
    let (ok, stdout, _) = run(PATHTRACER, &["--info", "-r", "480", "360"]);
    assert!(ok);
    assert!(stdout.lines().any(|l| l == "triangles: 12"), "{stdout}");
    assert!(stdout.lines().any(|l| l == "spheres: 2"), "{stdout}");
    let camera = stdout.lines().find(|l| l.starts_with("camera: ")).unwrap();
    assert_eq!(
        camera,
        "camera: position (0.0000, 0.7500, 4.8023) direction (-0.0000, 0.0000, -1.0000) hfov 30.68 vfov 23.25"
    );
    // Without -r or a scene file the built-in render's size applies: 480 x 360.
    let (ok, default_size, _) = run(PATHTRACER, &["--info"]);
    assert!(ok);
    assert!(default_size.lines().any(|l| l == camera), "{default_size}");
}

#[test]
fn default_render_writes_a_png_and_says_where() {
    let dir = tempfile::tempdir().unwrap();
    let out = Command::new(PATHTRACER)
        .args(["-r", "40", "30"])
        .current_dir(dir.path())
        .output()
        .unwrap();
    assert!(out.status.success());
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("wrote cornell-box.png"), "{stdout}");
    let image = image::open(dir.path().join("cornell-box.png")).unwrap();
    assert_eq!((image.width(), image.height()), (40, 30));
}

#[test]
fn a_failed_write_leaves_no_file_and_keeps_an_old_one() {
    let dir = tempfile::tempdir().unwrap();
    // Into a folder that does not exist: an error, and nothing appears.
    let nowhere = dir.path().join("no-such-folder").join("x.png");
    let (ok, _, stderr) = run(
        PATHTRACER,
        &["-r", "8", "6", "-f", nowhere.to_str().unwrap()],
    );
    assert!(!ok && stderr.contains("x.png"), "{stderr}");
    assert!(!nowhere.exists());
    // Over a directory of the same name: an error, and the directory stays.
    let taken = dir.path().join("taken.png");
    std::fs::create_dir(&taken).unwrap();
    let (ok, _, _) = run(PATHTRACER, &["-r", "8", "6", "-f", taken.to_str().unwrap()]);
    assert!(!ok && taken.is_dir());
    // No temporary file is left behind.
    let leftovers: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(leftovers.len(), 1, "{leftovers:?}");
}

#[test]
fn exr_output_holds_linear_radiance() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("n.exr");
    let (ok, _, stderr) = run(
        BINARIES[1],
        &["-r", "48", "36", "-f", path.to_str().unwrap()],
    );
    assert!(ok, "{stderr}");
    let image = image::open(&path).unwrap().to_rgb32f();
    // part1-raygen shades normals: every channel is (n + 1) / 2 in [0, 1], untouched by tone mapping.
    assert!(image
        .pixels()
        .all(|p| p.0.iter().all(|&c| (0.0..=1.0).contains(&c))));
    assert!(
        image.pixels().any(|p| p.0[2] > 0.99),
        "the back wall faces the camera: blue = 1"
    );
}

#[test]
fn course_lights_brighten_the_area_lit_box() {
    let dir = tempfile::tempdir().unwrap();
    let mean_radiance = |extra: &[&str]| {
        let path = dir.path().join("m.exr");
        let mut args = vec!["-r", "96", "72", "-s", "4", "-f", path.to_str().unwrap()];
        args.extend(extra);
        let (ok, _, stderr) = run(PATHTRACER, &args);
        assert!(ok, "{stderr}");
        let image = image::open(&path).unwrap().to_rgb32f();
        image.pixels().map(|p| p.0[1] as f64).sum::<f64>() / image.pixels().len() as f64
    };
    let physical = mean_radiance(&[]);
    let course = mean_radiance(&["--course-lights"]);
    // The course's area-light weighting is r times too bright, and most of
    // the box is more than one unit from the light.
    assert!(
        course > 1.1 * physical,
        "course {course}, physical {physical}"
    );
}

#[test]
fn an_output_name_of_another_format_is_refused_before_rendering() {
    let dir = tempfile::tempdir().unwrap();
    for name in ["out.jpg", "out"] {
        let path = dir.path().join(name);
        for binary in BINARIES {
            let (ok, stdout, stderr) = run(binary, &["-r", "8", "6", "-f", path.to_str().unwrap()]);
            assert!(!ok, "{binary} accepted {name}");
            assert!(stderr.starts_with("error: "), "{stderr}");
            assert!(stderr.contains(path.to_str().unwrap()), "{stderr}");
            assert!(
                stderr.contains(".png") && stderr.contains(".exr"),
                "{stderr}"
            );
            assert!(!stdout.contains("render:"), "rendered first: {stdout}");
            assert!(!path.exists(), "{name} was written");
        }
    }
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
}

#[test]
fn an_unwritable_output_fails_before_rendering() {
    let dir = tempfile::tempdir().unwrap();
    let nowhere = dir.path().join("no-such-folder").join("x.png");
    let taken = dir.path().join("taken.png");
    std::fs::create_dir(&taken).unwrap();
    for binary in BINARIES {
        for (path, problem) in [(&nowhere, "does not exist"), (&taken, "is a folder")] {
            // Sizes that would take a while to render: the error must come first.
            let (ok, stdout, stderr) = run(
                binary,
                &["-r", "800", "600", "-s", "64", "-f", path.to_str().unwrap()],
            );
            assert!(!ok, "{binary} accepted {}", path.display());
            assert!(
                stderr.starts_with("error: ")
                    && stderr.contains(path.to_str().unwrap())
                    && stderr.contains(problem),
                "{stderr}"
            );
            assert!(!stdout.contains("render:"), "rendered first: {stdout}");
        }
    }
    assert!(!nowhere.exists() && taken.is_dir());
}

#[test]
fn info_needs_no_writable_output() {
    let (ok, stdout, stderr) = run(PATHTRACER, &["--info", "-f", "/no-such-folder/x.jpg"]);
    assert!(ok, "{stderr}");
    assert!(stdout.lines().any(|l| l == "triangles: 12"), "{stdout}");
}

#[test]
fn info_names_the_sampler_the_roulette_and_the_glass_splits() {
    let materials = env!("CARGO_BIN_EXE_part6-materials");
    let plan = |flags: &[&str]| {
        let mut args = vec!["--info"];
        args.extend(flags);
        let (ok, stdout, _) = run(materials, &args);
        assert!(ok, "{stdout}");
        let line = |what: &str| {
            let prefix = format!("plan: {what}: ");
            stdout
                .lines()
                .find_map(|l| l.strip_prefix(&prefix))
                .unwrap_or_else(|| panic!("no plan: {what} line in {stdout}"))
                .split(' ')
                .next()
                .unwrap()
                .to_string()
        };
        (line("sampler"), line("roulette"), line("glass splits"))
    };
    let triple = |a: &str, b: &str, c: &str| (a.to_string(), b.to_string(), c.to_string());
    // The built-in materials box has a glass sphere; the default scene none.
    assert_eq!(plan(&[]), triple("zsobol", "throughput", "2"));
    let (ok, stdout, _) = run(PATHTRACER, &["--info"]);
    assert!(
        ok && stdout.contains("plan: glass splits: none (no glass)"),
        "{stdout}"
    );
    assert_eq!(plan(&["--course"]), triple("independent", "fixed", "none"));
    assert_eq!(
        plan(&["--sampler", "independent"]),
        triple("independent", "throughput", "2")
    );
    assert_eq!(
        plan(&["--roulette", "fixed", "--glass-splits", "3"]),
        triple("zsobol", "fixed", "3")
    );
    for refused in [
        &["--course", "--glass-splits", "1"][..],
        &["--glass-splits", "9"],
    ] {
        let mut args = vec!["--info"];
        args.extend(refused);
        let (ok, _, stderr) = run(materials, &args);
        assert!(
            !ok && stderr.contains("--glass-splits"),
            "{refused:?}: {stderr}"
        );
    }
}

/// `--info` reports the light choice the render makes: by power with
/// `--light-choice power`, every light by default in a scene of one light.
#[test]
fn info_reports_the_light_choice_the_render_makes() {
    let samples_line = |flags: &[&str]| info_line(PATHTRACER, flags, "plan: light sampling: on");
    let by_power = samples_line(&["--light-choice", "power"]);
    assert!(by_power.contains("by power"), "{by_power}");
    let default = samples_line(&[]);
    assert!(default.contains("every light"), "{default}");
}

/// The line of `binary --info FLAGS` that starts with `prefix`.
fn info_line(binary: &str, flags: &[&str], prefix: &str) -> String {
    let mut args = vec!["--info"];
    args.extend(flags);
    let (ok, stdout, stderr) = run(binary, &args);
    assert!(ok, "{stderr}");
    stdout
        .lines()
        .find(|l| l.starts_with(prefix))
        .unwrap_or_else(|| panic!("no line {prefix:?} in {stdout}"))
        .to_string()
}

/// `--course-exact` names its assignment and its adaptive sampling: 3-2
/// (adaptive on by default) for `pathtracer`, 3-1 without part 5 for
/// `part4-global`, whatever `=3-1` or `=3-2` says otherwise; `--mistake`
/// implies it. It refuses the project's own estimator choices.
#[test]
fn course_exact_names_its_assignment_and_defaults() {
    let part4 = env!("CARGO_BIN_EXE_part4-global");
    let line = |binary: &str, flags: &[&str]| info_line(binary, flags, "course-exact: ");
    let full = line(PATHTRACER, &["--course-exact"]);
    assert!(
        full.contains("assignment 3-2") && full.contains("adaptive 32 0.05"),
        "{full}"
    );
    let part4_line = line(part4, &["--course-exact"]);
    assert!(
        part4_line.contains("assignment 3-1") && part4_line.contains("adaptive off"),
        "{part4_line}"
    );
    let named = line(PATHTRACER, &["--course-exact=3-1", "-a", "16", "0.1"]);
    assert!(
        named.contains("assignment 3-1") && named.contains("adaptive 16 0.1"),
        "{named}"
    );
    let mistaken = line(part4, &["--mistake", "no-cosine", "--mistake", "no-pdf"]);
    assert!(
        mistaken.contains("mistakes: no-cosine, no-pdf"),
        "{mistaken}"
    );
    assert!(line(part4, &["--course-exact"]).contains("mistakes: none"));
    for conflicting in ["--no-mis", "--course", "--schlick"] {
        let (ok, _, stderr) = run(PATHTRACER, &["--info", "--course-exact", conflicting]);
        assert!(
            !ok && stderr.contains("cannot be used with"),
            "{conflicting}: {stderr}"
        );
    }
}

/// `--mistake list` prints the catalogue; an unknown name is refused with
/// the catalogue's names.
#[test]
fn mistake_list_and_unknown_mistakes() {
    let (ok, stdout, _) = run(PATHTRACER, &["--mistake", "list"]);
    assert!(ok);
    for m in pathtracer::mistakes::Mistake::ALL {
        assert!(stdout.contains(m.info().name), "{m} missing from {stdout}");
    }
    let (ok, _, stderr) = run(PATHTRACER, &["--info", "--mistake", "no-such-thing"]);
    assert!(!ok, "{stderr}");
    assert!(
        stderr.starts_with("error: --mistake no-such-thing: no such mistake")
            && stderr.contains("no-cosine"),
        "{stderr}"
    );
    assert!(!stderr.contains("panicked"), "{stderr}");
}

/// The normal-shading binaries refuse `--course-exact` and `--mistake`
/// rather than ignore them.
#[test]
fn normal_shading_refuses_the_course_image_flags() {
    for binary in [
        env!("CARGO_BIN_EXE_part1-raygen"),
        env!("CARGO_BIN_EXE_part2-bvh"),
    ] {
        for flags in [&["--course-exact"][..], &["--mistake", "no-cosine"][..]] {
            let mut args = vec!["--info"];
            args.extend(flags);
            let (ok, _, stderr) = run(binary, &args);
            assert!(
                !ok && stderr.contains("shades normals"),
                "{binary} {flags:?}: {stderr}"
            );
        }
    }
}

/// A lens so large that camera rays overflow (`-b 1e20`, or `-d 1e20`)
/// is refused with a message naming the flags, not a panic, and nothing
/// is written.
#[test]
fn a_lens_that_overflows_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("lens.png");
    let part8 = env!("CARGO_BIN_EXE_part8-dof");
    for lens in [["-b", "1e20", "-d", "4.7"], ["-b", "0.05", "-d", "1e20"]] {
        let mut args = vec!["-r", "16", "12", "-s", "1", "-f", out.to_str().unwrap()];
        args.extend(lens);
        for binary in [part8, PATHTRACER] {
            let (ok, _, stderr) = run(binary, &args);
            assert!(
                !ok && !stderr.contains("panicked"),
                "{binary} {lens:?}: {stderr}"
            );
            assert!(
                stderr.contains("the lens (-b"),
                "{binary} {lens:?}: {stderr}"
            );
            assert!(!out.exists());
        }
    }
}
