//! Reading a map file ([`super::EnvironmentMap::load`]) with its problems
//! said in plain words: which file, and what is wrong with it.
//!
//! The file is read whole, then recognised by its first bytes (not by
//! its name): `#?` begins a Radiance picture (read by [`super::radiance`]),
//! `76 2f 31 01` an OpenEXR image (read by the `image` crate). Before
//! texels are allocated, the map's size is checked (2:1) and the memory it
//! needs against what the system has available (`MemAvailable` of
//! `/proc/meminfo`, else whether the allocation succeeds); a file shorter
//! than its header says is reported as truncated at its length, "of" the
//! length it should have where that is known (a flat Radiance picture,
//! an OpenEXR image whose chunk table and last chunk header can be read).
//!
//! OpenEXR windows: the map is the display window (the image's frame in
//! OpenEXR's terms, and what the `image` crate returns), with the data
//! window's texels placed in it at their offset; texels of the display
//! window outside the data window are black, data outside it is cut off.

use std::io::{Cursor, ErrorKind};
use std::path::Path;

use image::codecs::openexr::OpenExrDecoder;
use image::{DynamicImage, ImageDecoder};

use super::radiance::{self, Problem};
use super::{EnvironmentError, EnvironmentMap};
use crate::math::Rgb;
use crate::render::memory;

/// Bytes a texel takes while an OpenEXR map is read: the decoder's RGB
/// `f32` buffer, its copy in the image and the map's texels.
const EXR_BYTES_PER_TEXEL: u64 = 36;
/// Bytes a texel of the map takes (Radiance texels are decoded in place).
const MAP_BYTES_PER_TEXEL: u64 = 12;

pub(super) fn load(path: &Path) -> Result<EnvironmentMap, EnvironmentError> {
    let file = path.display().to_string();
    let error = |problem: String| EnvironmentError {
        file: file.clone(),
        problem,
    };
    let bytes = std::fs::read(path).map_err(|e| error(io_problem(path, &e)))?;
    if bytes.is_empty() {
        return Err(error("the file is empty (0 bytes)".into()));
    }
    let (width, height, texels) = if bytes.starts_with(b"#?") {
        read_radiance(&bytes)
    } else if bytes.starts_with(&[0x76, 0x2f, 0x31, 0x01]) {
        read_openexr(&bytes)
    } else {
        Err(format!(
            "cannot decode it: it is not an OpenEXR (.exr) or Radiance (.hdr) image; {}",
            describe_start(&bytes)
        ))
    }
    .map_err(error)?;
    EnvironmentMap::new(&file, width, height, texels)
}

/// Why the file could not be read, without the system's error codes.
fn io_problem(path: &Path, e: &std::io::Error) -> String {
    match e.kind() {
        ErrorKind::NotFound => "cannot open it: there is no such file".into(),
        ErrorKind::PermissionDenied => "cannot open it: permission denied".into(),
        _ if path.is_dir() => "cannot open it: it is a directory, not a file".into(),
        ErrorKind::OutOfMemory => {
            "cannot read it: the file is larger than the memory available".into()
        }
        ErrorKind::InvalidInput | ErrorKind::InvalidData => {
            "cannot read it: it is not a file that can be read from start to end".into()
        }
        _ => format!("cannot read it: {}", plain_io_message(e)),
    }
}

/// The system's message of `e` without its `(os error N)` suffix.
fn plain_io_message(e: &std::io::Error) -> String {
    let text = e.to_string();
    match text.find(" (os error") {
        Some(k) => text[..k].to_string(),
        None => text,
    }
}

/// What the first bytes look like, for a file that is no map.
fn describe_start(bytes: &[u8]) -> String {
    let known: [(&[u8], &str); 9] = [
        (b"\x89PNG", "a PNG image"),
        (b"\xff\xd8\xff", "a JPEG image"),
        (b"GIF8", "a GIF image"),
        (b"II*\0", "a TIFF image"),
        (b"MM\0*", "a TIFF image"),
        (b"BM", "a BMP image"),
        (b"PF", "a PFM image"),
        (b"Pf", "a PFM image"),
        (b"RIFF", "a RIFF file (such as WebP)"),
    ];
    if let Some((_, name)) = known.iter().find(|(magic, _)| bytes.starts_with(magic)) {
        return format!("it looks like {name}");
    }
    let start = &bytes[..bytes.len().min(16)];
    if start
        .iter()
        .all(|&b| b.is_ascii_graphic() || b == b' ' || b == b'\n' || b == b'\r' || b == b'\t')
    {
        format!(
            "it begins with the text {:?}",
            String::from_utf8_lossy(start)
        )
    } else {
        let hex: Vec<String> = start.iter().take(8).map(|b| format!("{b:02x}")).collect();
        format!("it begins with the bytes {}", hex.join(" "))
    }
}

/// Refuses a map that is not 2:1 or whose texels do not fit in memory,
/// before anything is allocated for it.
fn check_size(width: u64, height: u64, bytes_per_texel: u64) -> Result<(), String> {
    if height.checked_mul(2) != Some(width) {
        return Err(super::map::shape_problem(width, height));
    }
    let what = format!("it is {width} x {height} texels");
    check_memory(&what, width as u128 * height as u128, bytes_per_texel)
}

/// Refuses `texels` (`what` they are) at `bytes_per_texel` that do not
/// fit in the memory available.
fn check_memory(what: &str, texels: u128, bytes_per_texel: u64) -> Result<(), String> {
    check_memory_against(what, texels, bytes_per_texel, memory::available_bytes())
}

/// [`check_memory`] with `available` bytes, where known; where not,
/// whether the allocation would succeed.
fn check_memory_against(
    what: &str,
    texels: u128,
    bytes_per_texel: u64,
    available: Option<u64>,
) -> Result<(), String> {
    let needed = texels * bytes_per_texel as u128;
    let words = memory::shortfall(needed, available).or_else(|| {
        let cannot = needed > isize::MAX as u128
            || Vec::<u8>::new().try_reserve_exact(needed as usize).is_err();
        cannot.then(|| {
            format!(
                "needs {} of memory, which cannot be allocated",
                memory::amount(needed)
            )
        })
    });
    match words {
        Some(words) => Err(format!(
            "{what}; reading it {words} ({bytes_per_texel} bytes a texel)"
        )),
        None => Ok(()),
    }
}

fn read_radiance(bytes: &[u8]) -> Result<(usize, usize, Vec<Rgb>), String> {
    let header = radiance::read_header(bytes)?;
    check_size(header.width, header.height, MAP_BYTES_PER_TEXEL)?;
    let (width, height) = (header.width as usize, header.height as usize);
    let mut texels = Vec::new();
    texels.reserve_exact(width * height);
    radiance::read_texels(bytes, &header, &mut texels).map_err(|problem| match problem {
        Problem::EndsEarly { encoded: false, .. } => format!(
            "the file is truncated at byte {} of {} (its header says {width} x {height} texels, stored flat)",
            bytes.len(),
            header.flat_length()
        ),
        Problem::EndsEarly { row, encoded: true } => format!(
            "the file ends early, at byte {}, in scanline {} of {}",
            bytes.len(),
            row + 1,
            header.lines().0
        ),
        Problem::Other(text) => format!("the Radiance picture is damaged: {text}"),
    })?;
    Ok((width, height, texels))
}

fn read_openexr(bytes: &[u8]) -> Result<(usize, usize, Vec<Rgb>), String> {
    if let Some(layout) = super::exr_layout::layout(bytes)? {
        if let Some(problem) = layout.truncation(bytes) {
            return Err(problem);
        }
        // The decoder's buffers follow the data window, not the map.
        let (w, h) = layout.data_window;
        check_memory(
            &format!("its data window is {w} x {h} texels"),
            w as u128 * h as u128,
            MAP_BYTES_PER_TEXEL,
        )?;
    }
    let decoder = OpenExrDecoder::with_alpha_preference(Cursor::new(bytes), Some(false))
        .map_err(|e| exr_problem(bytes, &e.to_string()))?;
    let (width, height) = decoder.dimensions();
    check_size(width as u64, height as u64, EXR_BYTES_PER_TEXEL)?;
    let image = DynamicImage::from_decoder(decoder)
        .map_err(|e| exr_problem(bytes, &e.to_string()))?
        .into_rgb32f();
    let texels = image.pixels().map(|p| Rgb::from_array(p.0)).collect();
    Ok((width as usize, height as usize, texels))
}

/// The OpenEXR decoder's complaint `text`, in plain words where it is
/// known: truncation, no colour channels, or else "could not read it"
/// with the decoder's words.
fn exr_problem(bytes: &[u8], text: &str) -> String {
    let ends = [
        "fill whole buffer",
        "missing bytes",
        "unexpected end",
        "end of file",
    ];
    if ends.iter().any(|e| text.to_lowercase().contains(e)) {
        return format!(
            "the file ends early, at byte {}, before its last pixels",
            bytes.len()
        );
    }
    let text = text.split_once("OpenExr: ").map_or(text, |(_, rest)| rest);
    if text.contains("non-deep rgb channels") {
        return "the OpenEXR image has no R, G and B channels (or only deep ones)".into();
    }
    if let Some(what) = text.strip_prefix("invalid: ") {
        return format!("the OpenEXR decoder could not read it, it found invalid {what}");
    }
    if let Some(what) = text.strip_prefix("not supported: ") {
        return format!("the OpenEXR decoder could not read it, it does not support {what}");
    }
    format!("the OpenEXR decoder could not read it: {text}")
}

#[cfg(test)]
mod tests;
