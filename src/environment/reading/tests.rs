//! The plain words for what the system and the first bytes say, and the
//! memory check where the memory available is known and where it is not.

use super::*;

/// Each kind of read error in plain words, without the system's code.
#[test]
fn read_errors_are_said_in_plain_words() {
    let file = Path::new("/nonexistent/map.exr");
    let kind = |k: ErrorKind| io_problem(file, &std::io::Error::from(k));
    assert_eq!(
        kind(ErrorKind::NotFound),
        "cannot open it: there is no such file"
    );
    assert_eq!(
        kind(ErrorKind::PermissionDenied),
        "cannot open it: permission denied"
    );
    assert_eq!(
        kind(ErrorKind::OutOfMemory),
        "cannot read it: the file is larger than the memory available"
    );
    for k in [ErrorKind::InvalidInput, ErrorKind::InvalidData] {
        assert_eq!(
            kind(k),
            "cannot read it: it is not a file that can be read from start to end"
        );
    }
    // A directory, whatever the error's kind says.
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    for k in [ErrorKind::Other, ErrorKind::OutOfMemory] {
        assert_eq!(
            io_problem(dir, &std::io::Error::from(k)),
            "cannot open it: it is a directory, not a file"
        );
    }
    // Others with the system's words, less its "(os error 5)".
    let io = std::io::Error::from_raw_os_error(5);
    assert!(io.to_string().contains("(os error 5)"), "{io}");
    let words = io_problem(file, &io);
    assert!(words.starts_with("cannot read it: "), "{words}");
    assert!(!words.contains("os error") && words.len() > 20, "{words}");
    let plain = std::io::Error::other("the disk is on fire");
    assert_eq!(plain_io_message(&plain), "the disk is on fire");
}

/// Text with spaces, tabs and line ends is quoted as text; a byte
/// outside printable ASCII makes it bytes.
#[test]
fn the_start_of_a_file_is_text_or_bytes() {
    assert_eq!(
        describe_start(b"P3\r\n\t1 2"),
        "it begins with the text \"P3\\r\\n\\t1 2\""
    );
    assert_eq!(
        describe_start(b"ab\x01cd"),
        "it begins with the bytes 61 62 01 63 64"
    );
    assert_eq!(describe_start(b"GIF89a"), "it looks like a GIF image");
}

/// Known memory: a shortfall is said with both amounts. Unknown memory:
/// what no allocation can hold is refused, past `isize::MAX` bytes and
/// past `usize::MAX` (where a cast would wrap to a small size).
#[test]
fn memory_is_checked_where_known_and_where_not() {
    let check = |texels: u128, available| check_memory_against("a map", texels, 12, available);
    assert_eq!(check(100, Some(1200)), Ok(()));
    assert_eq!(
        check(101, Some(1200)),
        Err("a map; reading it needs about 1.2 kB of memory and 1.2 kB is available (12 bytes a texel)".into())
    );
    assert_eq!(check(100, None), Ok(()));
    for texels in [(1u128 << 64) / 12 + 1, (1u128 << 63) / 12 + 1] {
        let err = check(texels, None).unwrap_err();
        assert!(err.contains("which cannot be allocated"), "{texels}: {err}");
    }
}

/// An OpenEXR file whose display window is small but whose data window
/// needs more memory than any machine has is refused before decoding,
/// by the data window's size. Its one chunk is whole, so the check is
/// the memory's.
#[test]
fn a_huge_data_window_is_refused_before_decoding() {
    use super::super::exr_layout::tests::{header, ints};
    let mut bytes = header(
        0,
        &[
            ("dataWindow", "box2i", ints(&[0, 0, 1_999_999, 999_999])),
            ("displayWindow", "box2i", ints(&[0, 0, 15, 7])),
            ("compression", "compression", vec![0]),
            ("chunkCount", "int", ints(&[1])),
        ],
    );
    let chunk = bytes.len() as u64 + 8;
    bytes.extend(chunk.to_le_bytes());
    bytes.extend(ints(&[0, 0]));
    let err = read_openexr(&bytes).unwrap_err();
    let what = "its data window is 2000000 x 1000000 texels; reading it needs";
    assert!(err.starts_with(what) && err.contains("24.0 TB"), "{err}");
}

/// The OpenEXR decoder's complaints in plain words where they are known.
#[test]
fn the_decoders_complaints_are_said_in_plain_words() {
    let bytes = [0u8; 42];
    for text in ["failed to fill whole buffer", "Unexpected End of file"] {
        assert_eq!(
            exr_problem(&bytes, text),
            "the file ends early, at byte 42, before its last pixels"
        );
    }
    assert_eq!(
        exr_problem(
            &bytes,
            "Format error OpenExr: non-deep rgb channels missing"
        ),
        "the OpenEXR image has no R, G and B channels (or only deep ones)"
    );
    assert_eq!(
        exr_problem(&bytes, "OpenExr: invalid: chunk offset"),
        "the OpenEXR decoder could not read it, it found invalid chunk offset"
    );
    assert_eq!(
        exr_problem(&bytes, "not supported: deep data"),
        "the OpenEXR decoder could not read it, it does not support deep data"
    );
    assert_eq!(
        exr_problem(&bytes, "something new"),
        "the OpenEXR decoder could not read it: something new"
    );
}
