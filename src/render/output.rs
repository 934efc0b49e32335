//! Image output: PNG with the course's tone mapping, OpenEXR in linear
//! radiance; the file name's extension chooses ([`OutputFormat`]), and any
//! other name is refused rather than given bytes it does not announce. A
//! file is written whole or not at all: the image is encoded in memory,
//! written to a temporary file beside the target, then renamed over it (a
//! rename within one directory is atomic on POSIX). [`check_output_path`]
//! finds a name or a folder that cannot be written before a render spends
//! its time.
//!
//! Tone mapping (the course's, exposure level 1), per channel:
//!
//! ```text
//! v = clamp((L * sqrt(2))^(1 / 2.2), 0, 1),   byte = round(255 v)
//! ```

use std::io::Cursor;
use std::path::{Path, PathBuf};

use image::{DynamicImage, ImageFormat, Rgb32FImage, RgbImage};

use super::Film;
use crate::math::Rgb;

/// An image that could not be written.
#[derive(Debug, thiserror::Error)]
#[error("{path}: {problem}")]
pub struct OutputError {
    pub path: PathBuf,
    pub problem: String,
}

/// The image formats an output file's name can ask for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutputFormat {
    /// `.png`: 8-bit, tone mapped ([`tone_map`]).
    Png,
    /// `.exr`: OpenEXR, 32-bit float linear radiance.
    Exr,
}

/// The formats [`OutputFormat::from_path`] accepts, for messages.
pub const OUTPUT_FORMATS: &str = ".png (8-bit, tone mapped) or .exr (linear radiance)";

impl OutputFormat {
    /// The format `path`'s extension names (case-insensitive), or an error
    /// naming the file and listing the formats.
    pub fn from_path(path: &Path) -> Result<Self, OutputError> {
        let extension = path.extension().map(|e| e.to_string_lossy().to_lowercase());
        match extension.as_deref() {
            Some("png") => Ok(Self::Png),
            Some("exr") => Ok(Self::Exr),
            other => Err(OutputError {
                path: path.to_path_buf(),
                problem: format!(
                    "cannot write {}: the image formats are {OUTPUT_FORMATS}",
                    other.map_or("a file without an extension".into(), |e| format!(
                        ".{e} files"
                    ))
                ),
            }),
        }
    }
}

/// Checks, before rendering, that an image can be written to `path`: its
/// extension names a format ([`OutputFormat::from_path`]), it is not a
/// folder, and its folder exists and takes a new file (tried by creating
/// and removing an empty temporary file there). Gives the format.
///
/// Other files written beside `path` (the rate image `NAME_rate.png`) go
/// to the same folder, so this checks them too. The write can still fail
/// later (a full disk, a folder removed meanwhile); it then fails as
/// [`write_image`] says.
pub fn check_output_path(path: &Path) -> Result<OutputFormat, OutputError> {
    let fail = |problem: String| OutputError {
        path: path.to_path_buf(),
        problem,
    };
    let format = OutputFormat::from_path(path)?;
    if path.is_dir() {
        return Err(fail("is a folder, not an image file".into()));
    }
    let folder = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    if !folder.is_dir() {
        return Err(fail(format!(
            "cannot write there: the folder {} does not exist",
            folder.display()
        )));
    }
    let probe =
        temporary_path(path, "probe").map_err(|e| fail(format!("cannot write there: {e}")))?;
    std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&probe)
        .map_err(|e| {
            fail(format!(
                "cannot write in the folder {}: {e}",
                folder.display()
            ))
        })?;
    let _ = std::fs::remove_file(&probe);
    Ok(format)
}

/// The course's tone map of linear radiance to display values in `[0, 1]`.
/// NaN maps to 0.
pub fn tone_map(radiance: Rgb) -> Rgb {
    let exposed = radiance * std::f32::consts::SQRT_2;
    let v = exposed.max(Rgb::ZERO).powf(1.0 / 2.2).min(Rgb::ONE);
    Rgb::select(v.is_nan_mask(), Rgb::ZERO, v)
}

/// How display values in `[0, 1]` become 8-bit values.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Quantization {
    /// `round(255 v)`: the nearest 8-bit value.
    #[default]
    Round,
    /// `floor(255 v)`: the course's (`HDRImageBuffer::toColor` casts to an
    /// integer), on average half a step darker, 0.7 % on the course's boxes.
    Truncate,
}

impl Quantization {
    /// The 8-bit value of the display value `v` in `[0, 1]`.
    pub fn apply(self, v: f32) -> u8 {
        let scaled = v.clamp(0.0, 1.0) * 255.0;
        match self {
            Quantization::Round => scaled.round() as u8,
            Quantization::Truncate => scaled as u8,
        }
    }
}

/// The 8-bit values of display values in `[0, 1]`, three bytes a pixel,
/// as a PNG holds them.
pub fn quantize_display(display: &[Rgb], quantization: Quantization) -> Vec<u8> {
    display
        .iter()
        .flat_map(|p| p.to_array().map(|v| quantization.apply(v)))
        .collect()
}

/// Writes `film` to `path` in the format its name asks for: PNG (tone
/// mapped) for `.png`, OpenEXR (linear) for `.exr`; any other name is an
/// error and nothing is written.
pub fn write_image(film: &Film, path: &Path) -> Result<(), OutputError> {
    write_image_quantized(film, path, Quantization::Round)
}

/// [`write_image`], with a PNG's values made by `quantization`.
pub fn write_image_quantized(
    film: &Film,
    path: &Path,
    quantization: Quantization,
) -> Result<(), OutputError> {
    if OutputFormat::from_path(path)? == OutputFormat::Png {
        let display: Vec<Rgb> = film.pixels.iter().map(|&p| tone_map(p)).collect();
        return write_png_quantized(film.width, film.height, &display, path, quantization);
    }
    let data = film
        .pixels
        .iter()
        .flat_map(|p| p.to_array().map(finite_non_negative))
        .collect();
    let image = Rgb32FImage::from_raw(film.width, film.height, data).map(DynamicImage::from);
    encode_and_write(image, ImageFormat::OpenExr, path)
}

/// `v` as an EXR holds it: a render's pixels are finite and non-negative
/// (non-finite samples are left out, the rest summed in f64, scene values
/// checked on loading), and this makes sure of it whatever made the film:
/// NaN and negative values become 0, infinity the largest `f32`.
fn finite_non_negative(v: f32) -> f32 {
    if v.is_nan() {
        0.0
    } else {
        v.clamp(0.0, f32::MAX)
    }
}

/// Writes display values in `[0, 1]` (row 0 at the top) as an 8-bit PNG,
/// whatever `path`'s extension (callers name it `.png`).
pub fn write_png(width: u32, height: u32, display: &[Rgb], path: &Path) -> Result<(), OutputError> {
    write_png_quantized(width, height, display, path, Quantization::Round)
}

/// [`write_png`], with its values made by `quantization`.
pub fn write_png_quantized(
    width: u32,
    height: u32,
    display: &[Rgb],
    path: &Path,
    quantization: Quantization,
) -> Result<(), OutputError> {
    let data = quantize_display(display, quantization);
    let image = RgbImage::from_raw(width, height, data).map(DynamicImage::from);
    encode_and_write(image, ImageFormat::Png, path)
}

/// Encodes `image` (`None`: its size did not match its pixels) in memory
/// and writes it atomically to `path`.
fn encode_and_write(
    image: Option<DynamicImage>,
    format: ImageFormat,
    path: &Path,
) -> Result<(), OutputError> {
    let fail = |problem: String| OutputError {
        path: path.to_path_buf(),
        problem,
    };
    let image = image.ok_or_else(|| fail("image size does not match its pixels".into()))?;
    let mut bytes = Cursor::new(Vec::new());
    image
        .write_to(&mut bytes, format)
        .map_err(|e| fail(format!("cannot encode {format:?}: {e}")))?;
    write_atomically(path, bytes.get_ref()).map_err(|e| fail(e.to_string()))
}

/// Writes `bytes` to a temporary file in `path`'s directory and renames it
/// to `path`; on any failure the temporary file is removed and `path` is
/// left as it was.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let temp = temporary_path(path, "partial")?;
    let result = std::fs::write(&temp, bytes).and_then(|()| std::fs::rename(&temp, path));
    if result.is_err() {
        let _ = std::fs::remove_file(&temp);
    }
    result
}

/// `.NAME.PID.SUFFIX` beside `path`: hidden, and unique to this process.
fn temporary_path(path: &Path, suffix: &str) -> std::io::Result<PathBuf> {
    let name = path
        .file_name()
        .ok_or_else(|| std::io::Error::new(std::io::ErrorKind::InvalidInput, "not a file name"))?;
    let mut temp_name = std::ffi::OsString::from(".");
    temp_name.push(name);
    temp_name.push(format!(".{}.{suffix}", std::process::id()));
    Ok(path.with_file_name(temp_name))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quantization_rounds_or_truncates() {
        for (v, round, truncate) in [
            (0.0, 0, 0),
            (0.999, 255, 254),
            (0.5, 128, 127),
            (1.0, 255, 255),
        ] {
            assert_eq!(Quantization::Round.apply(v), round, "{v}");
            assert_eq!(Quantization::Truncate.apply(v), truncate, "{v}");
        }
        assert_eq!(Quantization::Truncate.apply(f32::NAN), 0);
        assert_eq!(Quantization::Round.apply(2.0), 255);
    }

    #[test]
    fn tone_map_matches_the_course_formula() {
        let v = tone_map(Rgb::new(0.0, 0.25, 100.0));
        assert_eq!(v.x, 0.0);
        assert!((v.y - (0.25f32 * 2f32.sqrt()).powf(1.0 / 2.2)).abs() < 1e-6);
        assert_eq!(v.z, 1.0);
        assert_eq!(tone_map(Rgb::splat(f32::NAN)), Rgb::ZERO);
    }

    #[test]
    fn the_extension_chooses_the_format_and_others_are_refused() {
        let format = |name: &str| OutputFormat::from_path(Path::new(name));
        assert_eq!(format("a.png").unwrap(), OutputFormat::Png);
        assert_eq!(format("dir/a.PNG").unwrap(), OutputFormat::Png);
        assert_eq!(format("a.exr").unwrap(), OutputFormat::Exr);
        for bad in ["a.jpg", "a.jpeg", "a", "a.png.tmp"] {
            let e = format(bad).unwrap_err().to_string();
            assert!(
                e.starts_with(bad) && e.contains(".png") && e.contains(".exr"),
                "{e}"
            );
        }
        assert!(format("a.jpg")
            .unwrap_err()
            .to_string()
            .contains(".jpg files"));
    }

    #[test]
    fn an_exr_never_holds_a_non_finite_or_negative_value() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("odd.exr");
        let film = Film {
            width: 4,
            height: 1,
            pixels: vec![
                Rgb::new(f32::NAN, -1.0, f32::INFINITY),
                Rgb::new(f32::NEG_INFINITY, 0.5, 2.0),
                Rgb::ZERO,
                Rgb::ONE,
            ],
        };
        write_image(&film, &path).unwrap();
        let back = image::open(&path).unwrap().into_rgb32f();
        let values: Vec<f32> = back.into_raw();
        assert_eq!(
            values,
            [
                0.0,
                0.0,
                f32::MAX,
                0.0,
                0.5,
                2.0,
                0.0,
                0.0,
                0.0,
                1.0,
                1.0,
                1.0
            ]
        );
    }

    #[test]
    fn unwritable_outputs_are_found_before_rendering() {
        let dir = tempfile::tempdir().unwrap();
        let ok = dir.path().join("x.exr");
        assert_eq!(check_output_path(&ok).unwrap(), OutputFormat::Exr);
        // The check leaves nothing behind.
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
        let missing = dir.path().join("no-such-folder").join("x.png");
        let e = check_output_path(&missing).unwrap_err().to_string();
        assert!(
            e.contains("no-such-folder") && e.contains("does not exist"),
            "{e}"
        );
        let folder = dir.path().join("taken.png");
        std::fs::create_dir(&folder).unwrap();
        let e = check_output_path(&folder).unwrap_err().to_string();
        assert!(e.contains("is a folder"), "{e}");
        let wrong = dir.path().join("x.jpg");
        assert!(check_output_path(&wrong).is_err());
        // write_image refuses the same name and writes nothing.
        let film = Film {
            width: 1,
            height: 1,
            pixels: vec![Rgb::ONE],
        };
        assert!(write_image(&film, &wrong).is_err());
        assert!(!wrong.exists());
    }
}
