//! Image output: PNG with the course's tone mapping, OpenEXR in linear
//! radiance. A file is written whole or not at all: the image is encoded
//! in memory, written to a temporary file beside the target, then renamed
//! over it (a rename within one directory is atomic on POSIX).
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

/// The course's tone map of linear radiance to display values in `[0, 1]`.
/// NaN maps to 0.
pub fn tone_map(radiance: Rgb) -> Rgb {
    let exposed = radiance * std::f32::consts::SQRT_2;
    let v = exposed.max(Rgb::ZERO).powf(1.0 / 2.2).min(Rgb::ONE);
    Rgb::select(v.is_nan_mask(), Rgb::ZERO, v)
}

/// Writes `film` to `path`: OpenEXR (linear) for `.exr`, otherwise PNG
/// (tone mapped).
pub fn write_image(film: &Film, path: &Path) -> Result<(), OutputError> {
    let is_exr = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("exr"));
    if !is_exr {
        let display: Vec<Rgb> = film.pixels.iter().map(|&p| tone_map(p)).collect();
        return write_png(film.width, film.height, &display, path);
    }
    let data = film.pixels.iter().flat_map(|p| p.to_array()).collect();
    let image = Rgb32FImage::from_raw(film.width, film.height, data).map(DynamicImage::from);
    encode_and_write(image, ImageFormat::OpenExr, path)
}

/// Writes display values in `[0, 1]` (row 0 at the top) as an 8-bit PNG.
pub fn write_png(width: u32, height: u32, display: &[Rgb], path: &Path) -> Result<(), OutputError> {
    let data = display
        .iter()
        .flat_map(|p| {
            (p.clamp(Rgb::ZERO, Rgb::ONE) * 255.0)
                .round()
                .to_array()
                .map(|v| v as u8)
        })
        .collect();
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
    let name = path
        .file_name()
        .ok_or_else(|| std::io::Error::new(std::io::ErrorKind::InvalidInput, "not a file name"))?;
    let mut temp_name = std::ffi::OsString::from(".");
    temp_name.push(name);
    temp_name.push(format!(".{}.partial", std::process::id()));
    let temp = path.with_file_name(temp_name);
    let result = std::fs::write(&temp, bytes).and_then(|()| std::fs::rename(&temp, path));
    if result.is_err() {
        let _ = std::fs::remove_file(&temp);
    }
    result
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tone_map_matches_the_course_formula() {
        let v = tone_map(Rgb::new(0.0, 0.25, 100.0));
        assert_eq!(v.x, 0.0);
        assert!((v.y - (0.25f32 * 2f32.sqrt()).powf(1.0 / 2.2)).abs() < 1e-6);
        assert_eq!(v.z, 1.0);
        assert_eq!(tone_map(Rgb::splat(f32::NAN)), Rgb::ZERO);
    }
}
