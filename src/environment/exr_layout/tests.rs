//! The layout read from headers built byte by byte: the chunk count for
//! each compression's block of scan lines, for tiles and from
//! `chunkCount`; where the table ends; which chunk ends the file.

use super::*;

/// The magic number and version 2 with `flags`, then `attributes` (name,
/// type, value) and the header's closing NUL.
pub(in crate::environment) fn header(flags: u32, attributes: &[(&str, &str, Vec<u8>)]) -> Vec<u8> {
    let mut bytes = vec![0x76, 0x2f, 0x31, 0x01];
    bytes.extend((2 | flags).to_le_bytes());
    for (name, kind, value) in attributes {
        for text in [name, kind] {
            bytes.extend(text.as_bytes());
            bytes.push(0);
        }
        bytes.extend((value.len() as i32).to_le_bytes());
        bytes.extend(value);
    }
    bytes.push(0);
    bytes
}

/// The little-endian bytes of `values`.
pub(in crate::environment) fn ints(values: &[i32]) -> Vec<u8> {
    values.iter().flat_map(|v| v.to_le_bytes()).collect()
}

/// A data window of `w x h` texels starting at `(3, -2)`.
fn data_window(w: i32, h: i32) -> (&'static str, &'static str, Vec<u8>) {
    ("dataWindow", "box2i", ints(&[3, -2, 3 + w - 1, -2 + h - 1]))
}

fn compression(code: u8) -> (&'static str, &'static str, Vec<u8>) {
    ("compression", "compression", vec![code])
}

/// `(chunks, table_end)` of a header, read back as `truncation` reports
/// them for the header alone.
fn table(bytes: &[u8]) -> (u64, u64) {
    let layout = layout(bytes).unwrap().expect("a layout");
    assert_eq!(layout.table_end, bytes.len() as u64 + 8 * layout.chunks);
    let message = layout.truncation(bytes).expect("the table is missing");
    let expected = format!(
        "the file is truncated at byte {}, inside its table of {} chunks (which alone ends at byte {})",
        bytes.len(),
        layout.chunks,
        layout.table_end
    );
    assert_eq!(message, expected);
    (layout.chunks, layout.table_end)
}

/// Each compression's block of scan lines (none, RLE and ZIPS one line;
/// ZIP and PXR24 16; PIZ, B44, B44A and DWAA 32; DWAB 256), on 1000 rows.
#[test]
fn scan_line_chunks_follow_the_compressions_block_height() {
    let lines = [1, 1, 1, 16, 32, 16, 32, 32, 32, 256];
    for (code, lines) in lines.into_iter().enumerate() {
        let bytes = header(0, &[data_window(7, 1000), compression(code as u8)]);
        let (chunks, _) = table(&bytes);
        assert_eq!(chunks, 1000u64.div_ceil(lines), "compression {code}");
        assert_eq!(layout(&bytes).unwrap().unwrap().data_window, (7, 1000));
    }
    // An unknown compression, or none given: the decoder says what is wrong.
    let unknown = header(0, &[data_window(7, 1000), compression(10)]);
    assert!(layout(&unknown).unwrap().is_none());
    assert!(layout(&header(0, &[data_window(7, 1000)]))
        .unwrap()
        .is_none());
}

/// `chunkCount` wins over the count the compression gives, and tiles of
/// one level number `ceil(w / tw) ceil(h / th)`; mip-mapped tiles, tiles
/// of no width, deep and multi-part files are left to the decoder.
#[test]
fn tiles_and_chunk_count_give_the_chunks() {
    let counted = header(
        0,
        &[
            data_window(7, 1000),
            compression(3),
            ("chunkCount", "int", ints(&[5])),
        ],
    );
    assert_eq!(table(&counted).0, 5);
    let tiles = |tw: i32, th: i32, mode: u8| {
        let mut value = ints(&[tw, th]);
        value.push(mode);
        ("tiles", "tiledesc", value)
    };
    let tiled = header(
        0x200,
        &[data_window(100, 50), compression(0), tiles(32, 16, 0)],
    );
    assert_eq!(table(&tiled).0, 4 * 4);
    // The level mode is the low four bits; the rounding mode above them.
    let rounded = header(0x200, &[data_window(100, 50), tiles(32, 16, 0x10)]);
    assert_eq!(table(&rounded).0, 16);
    for unknown in [
        header(0x200, &[data_window(100, 50), tiles(32, 16, 1)]),
        header(0x200, &[data_window(100, 50), tiles(0, 16, 0)]),
        header(0x200, &[data_window(100, 50), tiles(32, 0, 0)]),
        header(0x200, &[data_window(100, 50), compression(0)]),
        header(0x800, &[data_window(100, 50), compression(0)]),
        header(0x1000, &[data_window(100, 50), compression(0)]),
    ] {
        assert!(layout(&unknown).unwrap().is_none());
    }
}

/// A window whose corner lies before its origin has no texels.
#[test]
fn a_backwards_window_is_an_error_naming_it() {
    let display = |x1: i32, y1: i32| ("displayWindow", "box2i", ints(&[0, 0, x1, y1]));
    for (window, name) in [
        (("dataWindow", "box2i", ints(&[5, 0, 4, 9])), "data window"),
        (("dataWindow", "box2i", ints(&[0, 5, 9, 4])), "data window"),
        (display(-1, 9), "display window"),
        (display(9, -1), "display window"),
    ] {
        let bytes = header(0, &[window, compression(0)]);
        let error = layout(&bytes).err().expect("an error");
        assert!(
            error.starts_with(&format!("its header's {name} runs from")),
            "{error}"
        );
        assert!(error.ends_with("backwards: it has no texels"), "{error}");
    }
    // One row and one column are texels.
    let single = header(
        0,
        &[("dataWindow", "box2i", ints(&[4, 4, 4, 4])), display(0, 0)],
    );
    assert!(layout(&single).is_ok());
}

/// A file of two scan-line chunks whose table lists the later one first:
/// it must reach the end of the chunk that starts last, its offset plus
/// 8 bytes of `y` and size plus the size; tiles have 20 bytes before
/// their data.
#[test]
fn the_chunk_that_starts_last_must_end_in_the_file() {
    for (flags, before_size, extra) in [(0, 4, vec![]), (0x200, 16, ints(&[32, 16]))] {
        let mut attributes = vec![data_window(20, 20), compression(3)];
        if flags != 0 {
            let mut value = extra.clone();
            value.push(0);
            attributes.push(("tiles", "tiledesc", value));
        }
        let mut bytes = header(flags, &attributes);
        let layout = layout(&bytes).unwrap().unwrap();
        assert_eq!(layout.chunks, 2, "flags {flags:#x}");
        let table_at = bytes.len();
        bytes.extend([0; 16]);
        let first = bytes.len();
        let header_len = before_size + 4;
        // The first chunk: its header and 3 bytes of data.
        bytes.extend(vec![0; before_size]);
        bytes.extend(3i32.to_le_bytes());
        bytes.extend([1, 2, 3]);
        let last = bytes.len();
        bytes.extend(vec![0; before_size]);
        bytes.extend(10i32.to_le_bytes());
        bytes.extend([7; 10]);
        bytes[table_at..table_at + 8].copy_from_slice(&(last as u64).to_le_bytes());
        bytes[table_at + 8..table_at + 16].copy_from_slice(&(first as u64).to_le_bytes());
        assert_eq!(bytes.len(), last + header_len + 10);
        assert_eq!(layout.truncation(&bytes), None, "flags {flags:#x}");
        let short = &bytes[..bytes.len() - 1];
        assert_eq!(
            layout.truncation(short).as_deref(),
            Some(
                format!(
                    "the file is truncated at byte {} of {}",
                    short.len(),
                    bytes.len()
                )
                .as_str()
            )
        );
        // Cut right after the table: whole, but no chunk follows it.
        let table_only = &bytes[..table_at + 16];
        assert_eq!(
            layout.truncation(table_only),
            Some(format!(
                "the file ends early, at byte {}, before its last chunk of pixels (which starts at byte {last})",
                table_only.len()
            ))
        );
        // Cut inside the last chunk's size: its end cannot be read.
        let early = &bytes[..last + before_size + 2];
        assert_eq!(
            layout.truncation(early),
            Some(format!(
                "the file ends early, at byte {}, before its last chunk of pixels (which starts at byte {last})",
                early.len()
            ))
        );
    }
}
