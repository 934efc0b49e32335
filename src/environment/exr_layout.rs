//! How long an OpenEXR file should be, read from its header and chunk
//! table, so that a truncated file is reported as such ("truncated at byte
//! N of M") before its pixels are decoded.
//!
//! The layout (OpenEXR's "File Layout" document): the magic number
//! `76 2f 31 01`, a version field (flags: `0x200` tiled, `0x800` deep,
//! `0x1000` multi-part), the header's attributes (name and type as
//! NUL-terminated strings, an `i32` size, the value) ended by a NUL byte,
//! then the chunk table: one `u64` file offset per chunk. A chunk of scan
//! lines starts with its `y` and its data's size (two `i32`), a tile with
//! its four coordinates and its size (five `i32`). The chunks number
//! `chunkCount` if the header says so, else `ceil(h / lines)` scan line
//! blocks (`lines` by compression: 1 none, RLE and ZIPS; 16 ZIP and PXR24;
//! 32 PIZ, B44, B44A and DWAA; 256 DWAB) or, for tiles of one level,
//! `ceil(w / tw) ceil(h / th)`. Multi-part, deep and mip-mapped files
//! are left to the decoder.

/// Where an OpenEXR file's chunk table ends and how many chunks it lists.
pub struct Layout {
    /// The data window's width and height: the decoder allocates for
    /// blocks of its rows whatever the display window.
    pub data_window: (u64, u64),
    table_end: u64,
    chunks: u64,
    /// Bytes before a chunk's data: 8 for scan lines, 20 for tiles.
    chunk_header: u64,
}

/// The layout of the single-part OpenEXR file `bytes`, or `None` where the
/// header cannot be followed (the decoder then says what is wrong); an
/// error for a data or display window without texels (`max < min`), which
/// the decoder takes for a huge one.
pub fn layout(bytes: &[u8]) -> Result<Option<Layout>, String> {
    let Some((layout, windows)) = parse(bytes) else {
        return Ok(None);
    };
    for (name, [x0, y0, x1, y1]) in windows {
        if x1 < x0 || y1 < y0 {
            return Err(format!(
                "its header's {name} runs from ({x0}, {y0}) to ({x1}, {y1}), backwards: it has no texels"
            ));
        }
    }
    Ok(layout)
}

type Window = (&'static str, [i64; 4]);

/// The layout (where it can be worked out) and the windows of `bytes`.
fn parse(bytes: &[u8]) -> Option<(Option<Layout>, Vec<Window>)> {
    let flags = u32::from_le_bytes(bytes.get(4..8)?.try_into().ok()?);
    if flags & (0x800 | 0x1000) != 0 {
        return Some((None, Vec::new()));
    }
    let tiled = flags & 0x200 != 0;
    let mut at = 8;
    let mut windows = Vec::new();
    let mut compression = None;
    let mut tiles = None;
    let mut chunk_count = None;
    let string = |at: &mut usize| -> Option<&[u8]> {
        let end = bytes.get(*at..)?.iter().position(|&b| b == 0)?;
        let s = &bytes[*at..*at + end];
        *at += end + 1;
        Some(s)
    };
    loop {
        let name = string(&mut at)?;
        if name.is_empty() {
            break;
        }
        string(&mut at)?;
        let size = i32::from_le_bytes(bytes.get(at..at + 4)?.try_into().ok()?);
        let value = bytes.get(at + 4..at + 4 + usize::try_from(size).ok()?)?;
        at += 4 + value.len();
        let int = |k: usize| {
            Some(i32::from_le_bytes(value.get(4 * k..4 * k + 4)?.try_into().ok()?) as i64)
        };
        match name {
            b"dataWindow" => windows.push(("data window", [int(0)?, int(1)?, int(2)?, int(3)?])),
            b"displayWindow" => {
                windows.push(("display window", [int(0)?, int(1)?, int(2)?, int(3)?]))
            }
            b"compression" => compression = Some(*value.first()?),
            b"tiles" => {
                tiles = Some((
                    int(0)? as u32 as u64,
                    int(1)? as u32 as u64,
                    *value.get(8)? & 0xf,
                ))
            }
            b"chunkCount" => chunk_count = Some(int(0)?),
            _ => {}
        }
    }
    let layout = (|| {
        let [x0, y0, x1, y1] = windows.iter().find(|w| w.0 == "data window")?.1;
        let (w, h) = (
            u64::try_from(x1 - x0 + 1).ok()?,
            u64::try_from(y1 - y0 + 1).ok()?,
        );
        let chunks = match (chunk_count, tiled, tiles) {
            (Some(n), _, _) => u64::try_from(n).ok()?,
            (None, false, _) => {
                let lines = match compression? {
                    0..=2 => 1,
                    3 | 5 => 16,
                    4 | 6..=8 => 32,
                    9 => 256,
                    _ => return None,
                };
                h.div_ceil(lines)
            }
            (None, true, Some((tw, th, 0))) if tw > 0 && th > 0 => {
                w.div_ceil(tw).checked_mul(h.div_ceil(th))?
            }
            _ => return None,
        };
        Some(Layout {
            data_window: (w, h),
            table_end: (at as u64).checked_add(chunks.checked_mul(8)?)?,
            chunks,
            chunk_header: if tiled { 20 } else { 8 },
        })
    })();
    Some((layout, windows))
}

impl Layout {
    /// What is missing from the file `bytes` with this layout, if
    /// anything: "truncated at byte N of M" where `M` can be read (the
    /// chunk that starts last must end within the file).
    pub fn truncation(&self, bytes: &[u8]) -> Option<String> {
        let len = bytes.len() as u64;
        if len < self.table_end {
            return Some(format!(
                "the file is truncated at byte {len}, inside its table of {} chunks (which alone ends at byte {})",
                self.chunks, self.table_end
            ));
        }
        let start = (self.table_end - 8 * self.chunks) as usize;
        let last = bytes[start..self.table_end as usize]
            .chunks_exact(8)
            .map(|o| u64::from_le_bytes(o.try_into().unwrap()))
            .max()?;
        let size_at = last.saturating_add(self.chunk_header - 4).min(u64::MAX - 4);
        let Some(size) = bytes
            .get(size_at as usize..(size_at + 4) as usize)
            .map(|s| i32::from_le_bytes(s.try_into().unwrap()))
        else {
            return Some(format!(
                "the file ends early, at byte {len}, before its last chunk of pixels (which starts at byte {last})"
            ));
        };
        let end = last.saturating_add(self.chunk_header + u64::try_from(size).ok()?);
        (len < end).then(|| format!("the file is truncated at byte {len} of {end}"))
    }
}

#[cfg(test)]
pub(super) mod tests;
