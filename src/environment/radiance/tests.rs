//! The reader on pictures built byte by byte: the header's factors and
//! errors, the resolution line's axes, the texel decoding, both kinds of
//! run-length encoding and where each goes wrong.

use super::*;

fn picture(header: &str, texels: &[[u8; 4]]) -> Vec<u8> {
    let mut bytes = header.as_bytes().to_vec();
    bytes.extend(texels.concat());
    bytes
}

fn read(bytes: &[u8]) -> Result<(Header, Vec<Rgb>), Problem> {
    let header = read_header(bytes).map_err(Problem::Other)?;
    let mut texels = Vec::new();
    read_texels(bytes, &header, &mut texels)?;
    Ok((header, texels))
}

#[test]
fn scanlines_may_be_columns_stored_from_the_right() {
    // "-X 4 +Y 2": four columns from the right, each bottom up.
    let texels: Vec<[u8; 4]> = (0..8).map(|k| [k, 0, 0, 136]).collect();
    let (header, rgb) = read(&picture("#?RADIANCE\n\n-X 4 +Y 2\n", &texels)).unwrap();
    assert_eq!((header.width, header.height), (4, 2));
    let red: Vec<f32> = rgb.iter().map(|t| t.x - 0.5).collect();
    assert_eq!(red, [7.0, 5.0, 3.0, 1.0, 6.0, 4.0, 2.0, 0.0]);
}

#[test]
fn runs_past_their_scanline_are_refused() {
    let mut bytes = b"#?RADIANCE\n\n-Y 1 +X 8\n".to_vec();
    bytes.extend([2, 2, 0, 8, 128 + 9, 1]);
    let err = read(&bytes).unwrap_err();
    assert!(
        matches!(&err, Problem::Other(t) if t.contains("past the end of its scanline")),
        "{err:?}"
    );
    let mut bytes = b"#?RADIANCE\n\n-Y 1 +X 8\n".to_vec();
    bytes.extend([2, 2, 0, 9]);
    let err = read(&bytes).unwrap_err();
    assert!(
        matches!(&err, Problem::Other(t) if t.contains("says it has 9 texels")),
        "{err:?}"
    );
}

/// The red channel of each texel, as the mantissa it was written with
/// (texels written with exponent 136, so that `value = m + 1/2`).
fn reds(texels: &[Rgb]) -> Vec<f32> {
    texels.iter().map(|t| t.x - 0.5).collect()
}

/// `EXPOSURE` and `COLORCORR` multiply, repeated or not, and the texels
/// are divided by their product; a bad factor or an overflowing product
/// is an error that quotes it.
#[test]
fn exposure_and_colour_correction_divide_the_texels() {
    let header = "#?RADIANCE\nEXPOSURE=2\nCOLORCORR=1 4 0.5\nEXPOSURE= 3 \n\n-Y 1 +X 1\n";
    let (_, rgb) = read(&picture(header, &[[11, 23, 5, 136]])).unwrap();
    assert_eq!(rgb, [Rgb::new(11.5 / 6.0, 23.5 / 24.0, 5.5 / 3.0)]);
    for (line, quoted) in [
        ("EXPOSURE=0", "EXPOSURE=0 is not a positive number"),
        ("EXPOSURE=-1", "EXPOSURE=-1 is not a positive number"),
        ("EXPOSURE=inf", "EXPOSURE=inf is not a positive number"),
        ("EXPOSURE=x", "EXPOSURE=x is not a positive number"),
        (
            "COLORCORR=1 1",
            "COLORCORR=1 1 is not three positive numbers",
        ),
        ("COLORCORR=1 1 1 1", "COLORCORR=1 1 1 1 is not"),
        ("COLORCORR=1 0 1", "COLORCORR=1 0 1 is not"),
        ("COLORCORR=1 1 nan", "COLORCORR=1 1 nan is not"),
        ("COLORCORR=1 a 1", "COLORCORR=1 a 1 is not"),
        ("FORMAT=32-bit_rle_lab", "its FORMAT is \"32-bit_rle_lab\""),
        ("FORMAT=32-bit_rle_xyze", "it is a Radiance XYZE picture"),
    ] {
        let err = read_header(format!("#?RGBE\n{line}\n\n-Y 1 +X 1\n").as_bytes()).unwrap_err();
        assert!(err.contains(quoted), "{line}: {err}");
    }
    let huge = "#?RGBE\nEXPOSURE=1e30\nEXPOSURE=1e30\n\n-Y 1 +X 1\n";
    let err = read_header(huge.as_bytes()).unwrap_err();
    assert!(err.contains("multiply past the largest float"), "{err}");
    // The format the reader reads, and a carriage return, are accepted.
    let fine = "#?RGBE\r\nFORMAT=32-bit_rle_rgbe\r\n\r\n-Y 2 +X 3\n";
    let header = read_header(fine.as_bytes()).unwrap();
    assert_eq!(
        (header.width, header.height, header.length),
        (3, 2, fine.len())
    );
    assert_eq!(header.scale, Rgb::ONE);
}

/// Where the header stops short, and resolution lines that are not two
/// different signed axes with positive sizes, quoted.
#[test]
fn short_headers_and_bad_resolution_lines_are_refused() {
    let err = read_header(b"#?RGBE").unwrap_err();
    assert_eq!(err, "the Radiance header ends before its first line does");
    let err = read_header(b"#?RGBE\nEXPOSURE=1\n").unwrap_err();
    assert!(
        err.contains("never ends (no empty line in the file's 18 bytes)"),
        "{err}"
    );
    let err = read_header(b"#?RGBE\n\n-Y 1 +X 1").unwrap_err();
    assert!(err.contains("ends without its resolution line"), "{err}");
    for line in [
        "-Y 2 +Y 3",
        "+X 2 -X 3",
        "-Y 0 +X 3",
        "-Y 2 +X 0",
        "-Y 2 +X",
        "-Y 2 +X 3 4",
        "Y 2 +X 3",
        "-Y 2 +Z 3",
        "-Y -2 +X 3",
        "-Y 1 X 2",
    ] {
        let err = read_header(format!("#?RGBE\n\n{line}\n").as_bytes()).unwrap_err();
        assert!(
            err.contains(&format!("{line:?} is not of the form")),
            "{line}: {err}"
        );
    }
}

/// The four orders of rows: `-Y H +X W` top down left to right, and the
/// other three flips, on a 3 x 2 picture whose texel `k` in the file has
/// mantissa `k`.
#[test]
fn rows_may_be_stored_from_either_side() {
    let texels: Vec<[u8; 4]> = (0..6).map(|k| [k, 0, 0, 136]).collect();
    for (resolution, expected, lines) in [
        ("-Y 2 +X 3", [0.0, 1.0, 2.0, 3.0, 4.0, 5.0], (2, 3)),
        ("+Y 2 +X 3", [3.0, 4.0, 5.0, 0.0, 1.0, 2.0], (2, 3)),
        ("-Y 2 -X 3", [2.0, 1.0, 0.0, 5.0, 4.0, 3.0], (2, 3)),
        ("+Y 2 -X 3", [5.0, 4.0, 3.0, 2.0, 1.0, 0.0], (2, 3)),
        ("+X 3 -Y 2", [0.0, 2.0, 4.0, 1.0, 3.0, 5.0], (3, 2)),
    ] {
        let bytes = picture(&format!("#?RADIANCE\n\n{resolution}\n"), &texels);
        let (header, rgb) = read(&bytes).unwrap();
        assert_eq!((header.width, header.height), (3, 2), "{resolution}");
        assert_eq!(reds(&rgb), expected, "{resolution}");
        assert_eq!(header.flat_length(), bytes.len() as u128, "{resolution}");
        assert_eq!(header.lines(), lines, "{resolution}");
    }
}

/// `(m + 1/2) 2^(e - 136)`, and black at `e = 0` whatever the mantissas.
#[test]
fn texels_decode_to_the_middle_of_their_interval() {
    assert_eq!(rgbe_to_rgb([0, 1, 255, 0]), Rgb::ZERO);
    assert_eq!(rgbe_to_rgb([0, 1, 255, 136]), Rgb::new(0.5, 1.5, 255.5));
    assert_eq!(rgbe_to_rgb([2, 0, 7, 128]), Rgb::new(2.5, 0.5, 7.5) / 256.0);
    assert_eq!(rgbe_to_rgb([2, 0, 7, 139]), Rgb::new(20.0, 4.0, 60.0));
}

/// New-style scanlines: runs (`c > 128`: the next byte `c - 128` times)
/// and literals (`c <= 128` bytes as they are, 128 included), one channel
/// after the other; a run of 0 is refused.
#[test]
fn new_style_scanlines_mix_runs_and_literals() {
    let n = 130;
    let mut bytes = b"#?RADIANCE\n\n-Y 1 +X 130\n".to_vec();
    bytes.extend([2, 2, 0, n as u8]);
    // Red: a literal of 128 values 0..128, then a run of two 200s.
    bytes.push(128);
    bytes.extend(0..128u8);
    bytes.extend([128 + 2, 200]);
    // Green, blue and the exponent: runs.
    for value in [9, 4, 136] {
        bytes.extend([128 + 127, value, 128 + 3, value]);
    }
    let (_, rgb) = read(&bytes).unwrap();
    let mut expected: Vec<f32> = (0..128).map(|k| k as f32).collect();
    expected.extend([200.0, 200.0]);
    assert_eq!(reds(&rgb), expected);
    assert!(rgb.iter().all(|t| t.y == 9.5 && t.z == 4.5));
    // A count of 0 would never move on.
    let mut bytes = b"#?RADIANCE\n\n-Y 1 +X 8\n".to_vec();
    bytes.extend([2, 2, 0, 8, 0, 1]);
    let err = read(&bytes).unwrap_err();
    let expected = format!(
        "a run at byte {} goes past the end of its scanline",
        bytes.len() - 2
    );
    assert_eq!(err, Problem::Other(expected));
}

/// Which scanlines are new-style: 8 to 32767 texels, starting `2 2` and a
/// length byte below 128. Others are read flat, their first texel as it
/// is.
#[test]
fn only_scanlines_of_8_to_32767_texels_are_new_style() {
    for width in [7u8, 8] {
        let mut first = vec![[2, 2, 0, width]];
        first.extend(vec![[5, 5, 5, 136]; width as usize - 1]);
        let bytes = picture(&format!("#?RADIANCE\n\n-Y 1 +X {width}\n"), &first);
        let result = read(&bytes);
        if width == 7 {
            let (_, rgb) = result.unwrap();
            assert_eq!(rgb[0], rgbe_to_rgb([2, 2, 0, 7]));
            assert_eq!(rgb[6], Rgb::splat(5.5));
        } else {
            // Read as encoded, the byte 5 is a literal of the five bytes
            // 5 5 136 5 5 after it, and the next 5 (5 + 5 > 8) runs past
            // the eighth texel.
            let err = result.unwrap_err();
            assert!(
                matches!(&err, Problem::Other(t) if t.contains("past the end of its scanline")),
                "{err:?}"
            );
        }
    }
    // A third byte of 128 or more is a flat texel.
    let texels = [
        [2, 2, 128, 136],
        [1, 0, 0, 136],
        [1, 0, 0, 136],
        [1, 0, 0, 136],
    ];
    let flat: Vec<[u8; 4]> = texels.iter().cycle().take(8).copied().collect();
    let (_, rgb) = read(&picture("#?RADIANCE\n\n-Y 1 +X 8\n", &flat)).unwrap();
    assert_eq!(rgb[0], Rgb::new(2.5, 2.5, 128.5));
    assert_eq!(rgb[1], Rgb::new(1.5, 0.5, 0.5));
    // A second byte other than 2 too.
    let flat = [[2, 3, 0, 8]; 8];
    let (_, rgb) = read(&picture("#?RADIANCE\n\n-Y 1 +X 8\n", &flat)).unwrap();
    assert_eq!(rgb[7], rgbe_to_rgb([2, 3, 0, 8]));
}

/// Old-style repeats: `1 1 1 n` copies the texel before it `n` times, and
/// each further repeat code in a row counts 256 times more; a repeat with
/// nothing before it, or past the scanline's end, is refused with its
/// byte.
#[test]
fn old_style_repeats_grow_by_256_when_they_follow_each_other() {
    let width = 2 + 3 + 256 + 1;
    let texels = [
        [7, 0, 0, 136],
        [8, 0, 0, 136],
        [1, 1, 1, 3],
        [1, 1, 1, 1],
        [9, 0, 0, 136],
    ];
    let bytes = picture(&format!("#?RADIANCE\n\n-Y 1 +X {width}\n"), &texels);
    let (_, rgb) = read(&bytes).unwrap();
    let mut expected = vec![7.0, 8.0];
    expected.extend(vec![8.0; 3 + 256]);
    expected.push(9.0);
    assert_eq!(reds(&rgb), expected);
    // A repeat code after a texel starts counting from 1 again.
    let texels = [[7, 0, 0, 136], [1, 1, 1, 2], [8, 0, 0, 136], [1, 1, 1, 2]];
    let (_, rgb) = read(&picture("#?RADIANCE\n\n-Y 1 +X 6\n", &texels)).unwrap();
    assert_eq!(reds(&rgb), [7.0, 7.0, 7.0, 8.0, 8.0, 8.0]);
    let header = "#?RADIANCE\n\n-Y 1 +X 4\n";
    for (texels, at) in [
        (vec![[1, 1, 1, 2], [7, 0, 0, 136]], 0),
        (vec![[7, 0, 0, 136], [1, 1, 1, 4]], 4),
        (vec![[7, 0, 0, 136], [1, 1, 1, 2], [1, 1, 1, 1]], 8),
    ] {
        let err = read(&picture(header, &texels)).unwrap_err();
        let expected = format!(
            "a repeat code at byte {} goes outside its scanline",
            header.len() + at
        );
        assert_eq!(err, Problem::Other(expected));
    }
    // A repeat that exactly fills the line ends it.
    let texels = [[7, 0, 0, 136], [1, 1, 1, 3]];
    let (_, rgb) = read(&picture(header, &texels)).unwrap();
    assert_eq!(reds(&rgb), [7.0; 4]);
}

/// A picture that ends early says which scanline and whether any so far
/// was encoded.
#[test]
fn a_picture_that_ends_early_names_its_scanline() {
    let flat = [[7, 0, 0, 136]; 5];
    let err = read(&picture("#?RADIANCE\n\n-Y 2 +X 4\n", &flat)).unwrap_err();
    assert_eq!(
        err,
        Problem::EndsEarly {
            row: 1,
            encoded: false
        }
    );
    let repeated = [[7, 0, 0, 136], [1, 1, 1, 3], [7, 0, 0, 136]];
    let err = read(&picture("#?RADIANCE\n\n-Y 2 +X 4\n", &repeated)).unwrap_err();
    assert_eq!(
        err,
        Problem::EndsEarly {
            row: 1,
            encoded: true
        }
    );
}
