//! Environment map files (`-e FILE`), written into a temporary directory:
//!
//! - bad files are refused with the file's name and the problem in plain
//!   words (empty, truncated at which byte of how many, not a map and what
//!   it looks like, too large for memory, texels that are not finite,
//!   negative or above `MAX_RADIANCE`), never the decoder's internals;
//! - legal files load with the right size and values (module `legal`): Radiance pictures
//!   headed `#?RGBE`, run-length encoded old and new style, stored bottom
//!   up, with an `EXPOSURE`; an OpenEXR image whose data window is not its
//!   display window; a 16384 x 8192 map; half-float RGBA OpenEXR and
//!   Radiance pictures written by the `image` and `exr` crates;
//! - a bad map given to a part's binary is an error naming the file, and
//!   no image is written.

use std::path::{Path, PathBuf};

use exr::prelude::{
    Encoding, Image, IntegerBounds, Layer, LayerAttributes, SpecificChannels, WritableImage,
};
use pathtracer::environment::EnvironmentMap;
use pathtracer::math::Rgb;

/// Legal files that must load, with the right size and values.
#[path = "environment_files/legal.rs"]
mod legal;

/// The decoders' words that a message must not show.
const INTERNALS: [&str; 5] = [
    "fill whole buffer",
    "missing bytes",
    "os error",
    "Memory limit",
    "Format error",
];

/// The message of loading `path`, checked to name the file and to contain
/// each of `expected`, and none of the decoders' internals.
fn refused(path: &Path, expected: &[&str]) -> String {
    let err = EnvironmentMap::load(path).unwrap_err().to_string();
    eprintln!("{err}");
    let name = path.file_name().unwrap().to_str().unwrap();
    assert!(err.contains(name), "{err} does not name {name}");
    for e in expected {
        assert!(err.contains(e), "{err} (expected {e:?})");
    }
    for internal in INTERNALS {
        assert!(!err.contains(internal), "{err} shows {internal:?}");
    }
    err
}

/// A Radiance picture: `first` line, `extra` header lines (each ending in
/// a newline), the resolution line and the scanline bytes.
fn radiance(first: &str, extra: &str, resolution: &str, pixels: &[u8]) -> Vec<u8> {
    let mut bytes =
        format!("{first}\nFORMAT=32-bit_rle_rgbe\n{extra}\n{resolution}\n").into_bytes();
    bytes.extend_from_slice(pixels);
    bytes
}

/// One new-style run-length encoded scanline of `n` copies of `rgbe`.
fn constant_scanline(n: usize, rgbe: [u8; 4]) -> Vec<u8> {
    let mut line = vec![2, 2, (n >> 8) as u8, n as u8];
    for value in rgbe {
        let mut left = n;
        while left > 0 {
            let run = left.min(127);
            line.extend_from_slice(&[128 + run as u8, value]);
            left -= run;
        }
    }
    line
}

/// `(m + 1/2) 2^(e - 136)`, Ward's RGBE decoding.
fn rgbe(m: [u8; 3], e: u8) -> Rgb {
    (Rgb::new(m[0] as f32, m[1] as f32, m[2] as f32) + 0.5) * (e as f32 - 136.0).exp2()
}

/// An RGB `f32` OpenEXR file whose data window of `size` starts at
/// `position`, in a display window `display`, texel `(x, y)` of the data
/// window holding `f(x, y)`.
fn write_exr(
    path: &Path,
    display: IntegerBounds,
    position: (i32, i32),
    size: (usize, usize),
    f: impl Fn(usize, usize) -> (f32, f32, f32) + Sync,
) {
    let attributes = LayerAttributes {
        layer_position: exr::math::Vec2(position.0, position.1),
        ..Default::default()
    };
    let channels = SpecificChannels::rgb(|p: exr::math::Vec2<usize>| f(p.x(), p.y()));
    let layer = Layer::new(size, attributes, Encoding::UNCOMPRESSED, channels);
    let mut image = Image::from_layer(layer);
    image.attributes.display_window = display;
    image.write().to_file(path).unwrap();
}

fn plain_exr(path: &Path, f: impl Fn(usize, usize) -> (f32, f32, f32) + Sync) {
    write_exr(path, IntegerBounds::new((0, 0), (8, 4)), (0, 0), (8, 4), f);
}

struct Dir(tempfile::TempDir);

impl Dir {
    fn new() -> Self {
        Dir(tempfile::tempdir().unwrap())
    }

    fn file(&self, name: &str, bytes: &[u8]) -> PathBuf {
        let path = self.0.path().join(name);
        std::fs::write(&path, bytes).unwrap();
        path
    }
}

#[test]
fn an_empty_file_is_called_empty() {
    let dir = Dir::new();
    refused(&dir.file("empty.exr", b""), &["empty"]);
    refused(&dir.file("empty.hdr", b""), &["empty"]);
}

#[test]
fn a_truncated_flat_radiance_picture_says_at_which_byte_of_how_many() {
    let dir = Dir::new();
    let full = radiance(
        "#?RADIANCE",
        "",
        "-Y 4 +X 8",
        &[[128, 64, 32, 129]; 32].concat(),
    );
    let cut = full.len() - 50;
    let path = dir.file("cut.hdr", &full[..cut]);
    refused(
        &path,
        &[&format!("truncated at byte {cut} of {}", full.len())],
    );
    // The whole file loads.
    let map = EnvironmentMap::load(&dir.file("whole.hdr", &full)).unwrap();
    assert_eq!(map.texel(7, 3), rgbe([128, 64, 32], 129));
}

#[test]
fn a_truncated_run_length_encoded_picture_ends_early() {
    let dir = Dir::new();
    let lines = constant_scanline(16, [128, 128, 128, 129]).repeat(8);
    let full = radiance("#?RADIANCE", "", "-Y 8 +X 16", &lines);
    let path = dir.file("cut.hdr", &full[..full.len() - 3]);
    refused(&path, &["ends early", "scanline 8 of 8"]);
}

#[test]
fn a_truncated_openexr_file_says_at_which_byte_of_how_many() {
    let dir = Dir::new();
    let path = dir.0.path().join("whole.exr");
    plain_exr(&path, |x, y| (x as f32, y as f32, 1.0));
    let full = std::fs::read(&path).unwrap();
    let cut = full.len() - 10;
    refused(
        &dir.file("cut.exr", &full[..cut]),
        &[&format!("truncated at byte {cut} of {}", full.len())],
    );
    // Cut inside the chunk table (four 8-byte offsets, one per row).
    let table_end = full.len() - 4 * (8 + 8 * 12);
    let cut = table_end - 5;
    refused(
        &dir.file("table.exr", &full[..cut]),
        &[&format!("truncated at byte {cut}"), "table"],
    );
}

#[test]
fn a_file_that_is_no_map_says_what_it_looks_like() {
    let dir = Dir::new();
    let err = refused(
        &dir.file("text.hdr", b"P3 not an image at all"),
        &["not an OpenEXR (.exr) or Radiance (.hdr)"],
    );
    assert!(err.contains("\"P3 not an image"), "{err}");
    let png = dir.0.path().join("picture.exr");
    image::RgbImage::new(8, 4)
        .save_with_format(&png, image::ImageFormat::Png)
        .unwrap();
    refused(&png, &["looks like a PNG image"]);
    refused(
        &dir.file("binary.exr", &[0, 1, 2, 3, 250, 251]),
        &["00 01 02 03 fa fb"],
    );
}

#[test]
fn a_map_too_large_for_memory_says_its_size_and_the_memory_it_needs() {
    let dir = Dir::new();
    let huge = radiance("#?RADIANCE", "", "-Y 1000000000 +X 2000000000", &[0; 64]);
    refused(
        &dir.file("huge.hdr", &huge),
        &["2000000000 x 1000000000", "24.0 EB of memory"],
    );
    // An OpenEXR file whose display window is made huge.
    let path = dir.0.path().join("small.exr");
    plain_exr(&path, |_, _| (1.0, 1.0, 1.0));
    let mut bytes = std::fs::read(&path).unwrap();
    let key = b"displayWindow\0box2i\0";
    let at = bytes.windows(key.len()).position(|w| w == key).unwrap() + key.len() + 4;
    bytes[at + 8..at + 12].copy_from_slice(&1_999_999i32.to_le_bytes());
    bytes[at + 12..at + 16].copy_from_slice(&999_999i32.to_le_bytes());
    refused(
        &dir.file("huge.exr", &bytes),
        &["2000000 x 1000000", "72.0 TB of memory"],
    );
}

#[test]
fn texels_too_bright_not_finite_or_negative_are_refused_with_position_and_value() {
    let dir = Dir::new();
    let with = |name: &str, at: (usize, usize), value: f32| {
        let path = dir.0.path().join(name);
        plain_exr(&path, |x, y| {
            if (x, y) == at {
                (1.0, value, 1.0)
            } else {
                (1.0, 1.0, 1.0)
            }
        });
        path
    };
    refused(
        &with("bright.exr", (5, 2), 2e15),
        &["texel (5, 2)", "(1, 2e15, 1)", "too bright", "1e15"],
    );
    refused(
        &with("nan.exr", (0, 3), f32::NAN),
        &["texel (0, 3)", "NaN", "not a number"],
    );
    refused(
        &with("inf.exr", (7, 0), f32::INFINITY),
        &["texel (7, 0)", "inf", "infinite"],
    );
    refused(
        &with("negative.exr", (2, 1), -0.25),
        &["texel (2, 1)", "-0.25", "negative"],
    );
    // RGBE can hold up to about 1.7e38: a texel past 1e15 is refused too.
    let mut pixels = [[128, 128, 128, 129]; 32];
    pixels[9] = [200, 10, 10, 200];
    let path = dir.file(
        "bright.hdr",
        &radiance("#?RADIANCE", "", "-Y 4 +X 8", &pixels.concat()),
    );
    refused(&path, &["texel (1, 1)", "too bright"]);
}

fn write_exr_f32(path: &Path, width: u32, height: u32, texels: &[f32]) {
    image::Rgb32FImage::from_raw(width, height, texels.to_vec())
        .unwrap()
        .save(path)
        .unwrap();
}

#[test]
fn bad_map_files_give_errors_naming_the_file() {
    let dir = tempfile::tempdir().unwrap();
    let path = |name: &str| dir.path().join(name);
    std::fs::write(path("text.exr"), "not an image").unwrap();
    image::RgbImage::new(8, 4).save(path("ldr.png")).unwrap();
    write_exr_f32(&path("square.exr"), 4, 4, &[1.0; 48]);
    let mut nan = vec![1.0; 8 * 4 * 3];
    nan[7] = f32::NAN;
    write_exr_f32(&path("nan.exr"), 8, 4, &nan);
    let mut negative = vec![1.0; 8 * 4 * 3];
    negative[40] = -2.0;
    write_exr_f32(&path("negative.exr"), 8, 4, &negative);
    let mut infinite = vec![1.0; 8 * 4 * 3];
    infinite[3] = f32::INFINITY;
    write_exr_f32(&path("infinite.exr"), 8, 4, &infinite);
    for (name, expect) in [
        ("missing.exr", "cannot open"),
        ("text.exr", "cannot decode"),
        ("ldr.png", "OpenEXR"),
        ("square.exr", "4 x 4"),
        ("nan.exr", "texel (2, 0)"),
        ("negative.exr", "texel (5, 1)"),
        ("infinite.exr", "texel (1, 0)"),
    ] {
        let err = EnvironmentMap::load(&path(name)).unwrap_err().to_string();
        eprintln!("{err}");
        assert!(
            err.contains(name) && err.contains(expect),
            "{name}: {err} (expected {expect:?})"
        );
    }
    // Through a binary's driver: an error, not a panic, and no image.
    let out = path("out.png");
    let args = <pathtracer::cli::CourseArgs as clap::Parser>::parse_from([
        "part7",
        "-r",
        "8",
        "6",
        "-e",
        path("nan.exr").to_str().unwrap(),
        "-f",
        out.to_str().unwrap(),
    ]);
    let err = pathtracer::cli::drivers::part7(&args)
        .unwrap_err()
        .to_string();
    assert!(err.contains("nan.exr"), "{err}");
    assert!(!out.exists());
}
