//! The thin lens through the drivers: a pinhole render does not change
//! when the lens code is there (`-b 0`), `--focus-at` measures the
//! distance of the surface a pixel sees, and renders through a lens stay
//! finite.

use clap::Parser;
use pathtracer::cli::drivers::{focus_distance, prepare};
use pathtracer::cli::{drivers, CourseArgs};

fn render(flags: &[&str]) -> Vec<[f32; 3]> {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("render.exr");
    let mut argv = vec![
        "test",
        "-r",
        "64",
        "48",
        "-t",
        "2",
        "-f",
        out.to_str().unwrap(),
    ];
    argv.extend(flags);
    drivers::part8(&CourseArgs::parse_from(argv)).unwrap();
    let image = image::open(&out).unwrap().to_rgb32f();
    image.pixels().map(|p| p.0).collect()
}

#[test]
fn a_lens_of_radius_zero_is_the_pinhole() {
    let pinhole = render(&["-s", "4", "-m", "2"]);
    let zero = render(&["-s", "4", "-m", "2", "-b", "0", "-d", "3"]);
    assert_eq!(
        pinhole, zero,
        "-b 0 renders the pinhole image, sample for sample"
    );
    let lens = render(&["-s", "4", "-m", "2", "-b", "0.2", "-d", "3"]);
    assert_ne!(pinhole, lens, "a lens changes the image");
    assert!(lens.iter().flatten().all(|c| c.is_finite()));
}

#[test]
fn focus_at_measures_the_distance_along_the_view_axis() {
    // The built-in box: the camera looks down -Z from z = 4.8023 (the
    // course's placement), and the back wall is the plane z = -1.
    let args = CourseArgs::parse_from(["test", "-r", "160", "120"]);
    let prepared = prepare(&args).unwrap();
    let d = focus_distance(&prepared.camera, &prepared.primitives, (160, 120), (80, 40)).unwrap();
    let expected = prepared.camera.position.z + 1.0;
    assert!((d - expected).abs() < 1e-3, "{d} vs {expected}");
    // A pixel outside the image is an error, not a panic.
    assert!(focus_distance(&prepared.camera, &prepared.primitives, (160, 120), (160, 0)).is_err());
    let with_focus = CourseArgs::parse_from(["test", "-r", "160", "120", "--focus-at", "80", "40"]);
    let focused = prepare(&with_focus).unwrap();
    assert!((focused.camera.lens.focal_distance - expected).abs() < 1e-3);
}
