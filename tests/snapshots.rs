//! Snapshot tests: a small render of the built-in scene by each binary's
//! driver, summarised as the mean linear radiance of 12 x 9 blocks and
//! compared with the snapshot under `golden/` within a tolerance, so a
//! harmless change of floating-point order does not fail them.
//!
//! A new or changed snapshot is reviewed with `cargo insta review`
//! (or accepted with `INSTA_UPDATE=always cargo test --profile quick --test snapshots`).

use std::path::Path;

use clap::Parser;
use pathtracer::cli::{drivers, CourseArgs};
use pathtracer::math::Rgb;
use pathtracer::render::Film;

const COLS: u32 = 12;
const ROWS: u32 = 9;
/// Largest accepted difference of a block mean, per channel, relative to
/// the block's value: a change of floating-point order moves a block mean
/// by a few parts in a million, a real change by far more, in a dark
/// block as in a bright one.
const RELATIVE_TOLERANCE: f32 = 1e-3;
/// The difference accepted in a block whose value is (near) zero, where
/// a relative tolerance means nothing; far below a block mean of the
/// darkest lit block of these renders (about 1e-3).
const ABSOLUTE_FLOOR: f32 = 1e-6;

/// Renders with `driver` into a temporary EXR and reads it back.
fn render_with(
    driver: fn(&CourseArgs) -> Result<(), Box<dyn std::error::Error>>,
    flags: &[&str],
) -> Film {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("render.exr");
    let mut argv = vec![
        "test",
        "-r",
        "480",
        "360",
        "-t",
        "2",
        "-f",
        out.to_str().unwrap(),
    ];
    argv.extend(flags);
    driver(&CourseArgs::parse_from(argv)).unwrap();
    let image = image::open(&out).unwrap().to_rgb32f();
    Film {
        width: image.width(),
        height: image.height(),
        pixels: image.pixels().map(|p| Rgb::from_array(p.0)).collect(),
    }
}

/// The block means, six significant digits each (the comparison is
/// relative, so a dark block needs as many digits as a bright one).
fn summary(film: &Film) -> String {
    film.block_means(COLS, ROWS)
        .chunks(COLS as usize)
        .map(|row| {
            row.iter()
                .map(|c| format!("{:.5e} {:.5e} {:.5e}", c.x, c.y, c.z))
                .collect::<Vec<_>>()
                .join(" | ")
        })
        .collect::<Vec<_>>()
        .join("\n")
}

fn numbers(text: &str) -> Vec<f32> {
    text.split(|c: char| c.is_whitespace() || c == '|')
        .filter_map(|t| t.parse().ok())
        .collect()
}

/// Whether every block mean of `new` is within the tolerance of `old`'s.
fn agrees(old: &[f32], new: &[f32]) -> bool {
    old.len() == new.len()
        && old.iter().zip(new).all(|(a, b)| {
            (a - b).abs() <= (RELATIVE_TOLERANCE * a.abs().max(b.abs())).max(ABSOLUTE_FLOOR)
        })
}

/// Passes when the stored snapshot agrees ([`agrees`]); otherwise lets
/// insta fail and record the new snapshot for review.
fn assert_close_to_snapshot(name: &str, film: &Film) {
    assert_eq!(film.non_finite_count(), 0, "NaN or infinite pixels");
    let golden = Path::new(env!("CARGO_MANIFEST_DIR")).join("golden");
    let text = summary(film);
    if let Ok(stored) = std::fs::read_to_string(golden.join(format!("{name}.snap"))) {
        let body = stored.splitn(3, "---").nth(2).unwrap_or("");
        if agrees(&numbers(body), &numbers(&text)) {
            return;
        }
    }
    insta::with_settings!({ snapshot_path => golden, prepend_module_to_snapshot => false }, {
        insta::assert_snapshot!(name, text);
    });
}

/// The comparison fails a 5 % error in a dark block (an absolute
/// tolerance of 2e-3 let it through where the block's mean is 0.01) and
/// passes a change of floating-point order; the stored digits are enough
/// for it.
#[test]
fn a_dark_blocks_error_fails_and_rounding_passes() {
    let old = [0.5, 0.01, 2e-3, 0.0];
    assert!(agrees(&old, &old));
    assert!(agrees(
        &old,
        &[0.5 * (1.0 + 3e-6), 0.01, 2e-3 * (1.0 - 3e-6), 0.0]
    ));
    assert!(!agrees(&old, &[0.5, 0.0105, 2e-3, 0.0]));
    assert!(!agrees(&old, &[0.5, 0.01, 2.1e-3, 0.0]));
    assert!(!agrees(&old, &[0.5, 0.01, 2e-3, 1e-4]));
    assert!(!agrees(&old, &old[..3]));
    let film = Film {
        width: 1,
        height: 1,
        pixels: vec![Rgb::new(0.0123456, 1.0, 0.0)],
    };
    let text = format!("{:.5e}", film.pixels[0].x);
    assert!(agrees(&[0.0123456], &numbers(&text)), "{text}");
}

#[test]
fn part1_raygen_normal_shading() {
    assert_close_to_snapshot("part1-raygen", &render_with(drivers::part1, &[]));
}

#[test]
fn part2_bvh_normal_shading() {
    assert_close_to_snapshot("part2-bvh", &render_with(drivers::part2, &[]));
}

#[test]
fn pathtracer_default_render() {
    assert_close_to_snapshot(
        "pathtracer",
        &render_with(drivers::pathtracer, &["-s", "4", "-m", "2"]),
    );
}

#[test]
fn part3_direct_light_sampling() {
    assert_close_to_snapshot(
        "part3-direct",
        &render_with(drivers::part3, &["-s", "4", "-l", "2"]),
    );
}

#[test]
fn part3_direct_hemisphere_sampling() {
    assert_close_to_snapshot(
        "part3-direct-hemisphere",
        &render_with(drivers::part3, &["-s", "4", "-l", "2", "-H"]),
    );
}

#[test]
fn part4_global_illumination() {
    assert_close_to_snapshot(
        "part4-global",
        &render_with(drivers::part4, &["-s", "4", "-m", "4"]),
    );
}

#[test]
fn part5_adaptive_sampling() {
    assert_close_to_snapshot(
        "part5-adaptive",
        &render_with(drivers::part5, &["-s", "16", "-m", "3", "-a", "8", "0.1"]),
    );
}

#[test]
fn part6_materials() {
    assert_close_to_snapshot(
        "part6-materials",
        &render_with(drivers::part6, &["-s", "8", "-m", "6"]),
    );
}

#[test]
fn part8_depth_of_field() {
    assert_close_to_snapshot(
        "part8-dof",
        &render_with(
            drivers::part8,
            &["-s", "8", "-m", "3", "-b", "0.15", "-d", "4.5"],
        ),
    );
}

#[test]
fn part7_environment() {
    assert_close_to_snapshot(
        "part7-environment",
        &render_with(drivers::part7, &["-s", "8", "-m", "4"]),
    );
}

#[test]
fn renders_do_not_depend_on_the_thread_count() {
    let one = render_with(drivers::pathtracer, &["-s", "4", "-t", "1"]);
    let two = render_with(drivers::pathtracer, &["-s", "4", "-t", "2"]);
    assert_eq!(one, two);
}
