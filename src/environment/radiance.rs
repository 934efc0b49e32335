//! A reader for Radiance pictures (`.hdr`, `.pic`): RGBE texels, flat or
//! run-length encoded.
//!
//! The format (Greg Ward, "Real Pixels", Graphics Gems II, 1991, and the
//! Radiance reference manual's "Radiance File Formats"):
//!
//! - a header of text lines: the first is `#?` and the writing program's
//!   name (`#?RADIANCE`, but other writers put `#?RGBE`), then variables
//!   `NAME=value` and comments, ended by an empty line. `FORMAT=` is
//!   `32-bit_rle_rgbe` (or `32-bit_rle_xyze`, CIE XYZ, refused here);
//!   `EXPOSURE=e` and `COLORCORR=r g b` say the texels were multiplied by
//!   `e` (per channel by `r g b`), cumulatively when repeated, so the
//!   radiance is the texel divided by their product;
//! - a resolution line, `-Y H +X W` for the usual `H` rows of `W` texels
//!   from the top left; in general two axes (the first changes slowest),
//!   each `-` or `+` for the direction it is stored in, `-Y` top down;
//! - the scanlines, 4 bytes a texel: mantissas `r g b` and a shared
//!   exponent `e`, value `(m + 1/2) 2^(e - 136)` (the middle of the interval
//!   the encoder's truncation mapped to `m`, as Radiance's `colr_color`;
//!   Bruce Walter's widely copied `rgbe.c`, and the `image` crate, drop
//!   the `1/2`, reading up to 1/256 darker; `e = 0` is black);
//! - a scanline of `8..=32767` texels may be run-length encoded ("new
//!   style"): it starts `2 2 hi lo` with `hi lo` its length, then each of
//!   the four components in turn as runs, a byte `c > 128` followed by a
//!   value repeated `c - 128` times, or `c` in `1..=128` followed by `c`
//!   literal values. Other scanlines are flat, where ("old style") a texel
//!   `1 1 1 n` repeats the previous one `n << s` times, `s` growing by 8
//!   for each repeat texel in a row.

use crate::math::Rgb;

/// A Radiance picture's header: its size and how its scanlines are laid
/// out.
#[derive(Debug, Clone, PartialEq)]
pub struct Header {
    pub width: u64,
    pub height: u64,
    /// Bytes of the header and resolution line: where the scanlines start.
    pub length: usize,
    /// Whether the scanlines are columns (`+X W -Y H`, X first).
    columns: bool,
    /// Whether the columns / rows are stored from the right / bottom.
    flip_x: bool,
    flip_y: bool,
    /// The product of `EXPOSURE` and `COLORCORR` factors.
    scale: Rgb,
}

/// What went wrong reading a picture, in plain words.
#[derive(Debug, Clone, PartialEq)]
pub enum Problem {
    /// The bytes end inside the scanlines; `row` of the picture's `rows`
    /// scanlines was being read, and whether any scanline so far was
    /// run-length encoded (so that the flat size is no guide).
    EndsEarly {
        row: u64,
        encoded: bool,
    },
    Other(String),
}

impl Header {
    /// The bytes a flat (not run-length encoded) picture of this size has.
    pub fn flat_length(&self) -> u128 {
        self.length as u128 + 4 * self.width as u128 * self.height as u128
    }

    /// Scanlines and their length.
    pub fn lines(&self) -> (u64, u64) {
        if self.columns {
            (self.width, self.height)
        } else {
            (self.height, self.width)
        }
    }
}

/// Reads the header of the picture in `bytes` (which start with `#?`).
pub fn read_header(bytes: &[u8]) -> Result<Header, String> {
    let mut at = 0;
    let next_line = |at: &mut usize| -> Option<&[u8]> {
        let rest = &bytes[*at..];
        let end = rest.iter().position(|&b| b == b'\n')?;
        *at += end + 1;
        Some(&rest[..end])
    };
    let mut scale = Rgb::ONE;
    let mut first = true;
    loop {
        let Some(line) = next_line(&mut at) else {
            return Err(if first {
                "the Radiance header ends before its first line does".into()
            } else {
                format!(
                    "the Radiance header never ends (no empty line in the file's {} bytes)",
                    bytes.len()
                )
            });
        };
        let text = String::from_utf8_lossy(line);
        let text = text.trim_end_matches('\r');
        if first {
            first = false;
            continue;
        }
        if text.is_empty() {
            break;
        }
        if let Some(format) = text.strip_prefix("FORMAT=") {
            match format.trim() {
                "32-bit_rle_rgbe" => {}
                "32-bit_rle_xyze" => return Err(
                    "it is a Radiance XYZE picture (CIE XYZ texels); only RGBE pictures are read"
                        .into(),
                ),
                other => {
                    return Err(format!(
                        "its FORMAT is {other:?}; only 32-bit_rle_rgbe is read"
                    ))
                }
            }
        } else if let Some(value) = text.strip_prefix("EXPOSURE=") {
            match value.trim().parse::<f32>() {
                Ok(e) if e.is_finite() && e > 0.0 => scale *= e,
                _ => {
                    return Err(format!(
                        "its header's EXPOSURE={value} is not a positive number"
                    ))
                }
            }
        } else if let Some(value) = text.strip_prefix("COLORCORR=") {
            let factors: Option<Vec<f32>> =
                value.split_whitespace().map(|f| f.parse().ok()).collect();
            match factors.as_deref().unwrap_or_default() {
                &[r, g, b] if [r, g, b].iter().all(|f| f.is_finite() && *f > 0.0) => {
                    scale *= Rgb::new(r, g, b)
                }
                _ => {
                    return Err(format!(
                        "its header's COLORCORR={value} is not three positive numbers"
                    ))
                }
            }
        }
    }
    if !scale.is_finite() {
        return Err(
            "its header's EXPOSURE and COLORCORR factors multiply past the largest float".into(),
        );
    }
    let Some(line) = next_line(&mut at) else {
        return Err(
            "the Radiance header ends without its resolution line (such as -Y 512 +X 1024)".into(),
        );
    };
    let text = String::from_utf8_lossy(line);
    let bad = || {
        format!(
            "the resolution line {:?} is not of the form -Y 512 +X 1024",
            text.trim_end()
        )
    };
    let words: Vec<&str> = text.split_whitespace().collect();
    let [a, m, b, n] = words[..] else {
        return Err(bad());
    };
    let size = |s: &str| s.parse::<u64>().ok().filter(|&s| s > 0);
    let (Some(m), Some(n)) = (size(m), size(n)) else {
        return Err(bad());
    };
    let axis = |s: &str| match s {
        "-Y" | "+Y" | "-X" | "+X" => Some((s.as_bytes()[1], s.starts_with('+'))),
        _ => None,
    };
    let (Some((first_axis, first_up)), Some((second_axis, second_up))) = (axis(a), axis(b)) else {
        return Err(bad());
    };
    if first_axis == second_axis {
        return Err(bad());
    }
    let columns = first_axis == b'X';
    let (width, height, x_up, y_up) = if columns {
        (m, n, first_up, second_up)
    } else {
        (n, m, second_up, first_up)
    };
    Ok(Header {
        width,
        height,
        length: at,
        columns,
        flip_x: !x_up,
        flip_y: y_up,
        scale,
    })
}

/// Reads the scanlines of a picture with `header` from `bytes` (the whole
/// file), pushing its radiance onto `texels` (empty, with room for the
/// picture) in rows from the top.
pub fn read_texels(bytes: &[u8], header: &Header, texels: &mut Vec<Rgb>) -> Result<(), Problem> {
    let (lines, length) = header.lines();
    let (width, height) = (header.width as usize, header.height as usize);
    texels.resize(width * height, Rgb::ZERO);
    let mut line = vec![[0u8; 4]; length as usize];
    let mut at = header.length;
    let mut encoded = false;
    for l in 0..lines {
        let ends_early = |encoded| Problem::EndsEarly { row: l, encoded };
        read_scanline(bytes, &mut at, &mut line, &mut encoded)
            .map_err(|e| e.unwrap_or_else(|| ends_early(encoded)))?;
        for (k, rgbe) in line.iter().enumerate() {
            let (major, minor) = (l as usize, k);
            let (x, y) = if header.columns {
                (major, minor)
            } else {
                (minor, major)
            };
            let x = if header.flip_x { width - 1 - x } else { x };
            let y = if header.flip_y { height - 1 - y } else { y };
            texels[y * width + x] = rgbe_to_rgb(*rgbe) / header.scale;
        }
    }
    Ok(())
}

/// `(m + 1/2) 2^(e - 136)` per channel, black for `e = 0`.
fn rgbe_to_rgb([r, g, b, e]: [u8; 4]) -> Rgb {
    if e == 0 {
        return Rgb::ZERO;
    }
    let f = (e as f32 - 136.0).exp2();
    (Rgb::new(r as f32, g as f32, b as f32) + 0.5) * f
}

/// Reads one scanline at `bytes[*at..]` into `line`. `Err(None)`: the
/// bytes ended.
fn read_scanline(
    bytes: &[u8],
    at: &mut usize,
    line: &mut [[u8; 4]],
    encoded: &mut bool,
) -> Result<(), Option<Problem>> {
    let n = line.len();
    let byte = |at: &mut usize| -> Result<u8, Option<Problem>> {
        let b = *bytes.get(*at).ok_or(None)?;
        *at += 1;
        Ok(b)
    };
    let start = [byte(at)?, byte(at)?, byte(at)?, byte(at)?];
    if (8..=0x7fff).contains(&n) && start[0] == 2 && start[1] == 2 && start[2] < 128 {
        *encoded = true;
        let said = (start[2] as usize) << 8 | start[3] as usize;
        if said != n {
            return Err(Some(Problem::Other(format!(
                "a run-length encoded scanline says it has {said} texels, the picture's have {n}"
            ))));
        }
        let bad_run = |at: usize| {
            Some(Problem::Other(format!(
                "a run at byte {at} goes past the end of its scanline"
            )))
        };
        for c in 0..4 {
            let mut k = 0;
            while k < n {
                let code = byte(at)? as usize;
                let (count, run) = if code > 128 {
                    (code - 128, true)
                } else {
                    (code, false)
                };
                if count == 0 || k + count > n {
                    return Err(bad_run(*at - 1));
                }
                if run {
                    let value = byte(at)?;
                    line[k..k + count].iter_mut().for_each(|t| t[c] = value);
                } else {
                    for t in &mut line[k..k + count] {
                        t[c] = byte(at)?;
                    }
                }
                k += count;
            }
        }
        return Ok(());
    }
    // Flat, with old-style repeats.
    let mut k = 0;
    let mut shift = 0;
    let mut texel = start;
    loop {
        if texel[..3] == [1, 1, 1] {
            let count = (texel[3] as usize).checked_shl(shift).unwrap_or(usize::MAX);
            if k == 0 || count > n - k {
                return Err(Some(Problem::Other(format!(
                    "a repeat code at byte {} goes outside its scanline",
                    *at - 4
                ))));
            }
            *encoded = true;
            let previous = line[k - 1];
            line[k..k + count].fill(previous);
            k += count;
            shift += 8;
        } else {
            line[k] = texel;
            k += 1;
            shift = 0;
        }
        if k == n {
            return Ok(());
        }
        texel = [byte(at)?, byte(at)?, byte(at)?, byte(at)?];
    }
}

#[cfg(test)]
mod tests;
