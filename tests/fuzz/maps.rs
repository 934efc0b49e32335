//! Mutation of environment maps (`.hdr`, `.exr`): truncation, header bit
//! flips and edits, extreme sizes and values. A map whose texels are not
//! finite, negative or brighter than `MAX_RADIANCE` is *nonsense* (refused
//! or warned about); a Radiance file that starts `#?RGBE` is *legal*
//! (rendered).

use std::io::Cursor;

use image::{DynamicImage, ImageFormat, Rgb32FImage};
use rand::seq::SliceRandom;
use rand::Rng;

/// A mutated map and its file extension.
pub struct MapMutant {
    pub bytes: Vec<u8>,
    pub extension: &'static str,
    pub what: String,
    pub nonsense: bool,
    pub legal: bool,
}

const WIDTH: u32 = 32;
const HEIGHT: u32 = 16;

/// A soft sky with a small sun: the base of every map mutation.
fn sky() -> Rgb32FImage {
    Rgb32FImage::from_fn(WIDTH, HEIGHT, |x, y| {
        let sun = if (x, y) == (9, 4) { 200.0 } else { 0.0 };
        let v = 0.2 + 0.8 * (HEIGHT - y) as f32 / HEIGHT as f32 + sun;
        image::Rgb([v, v * 0.9, v * 0.8 + 0.05 * x as f32])
    })
}

/// `image` encoded in `format`.
fn encode(image: Rgb32FImage, format: ImageFormat) -> Vec<u8> {
    let mut bytes = Cursor::new(Vec::new());
    DynamicImage::from(image)
        .write_to(&mut bytes, format)
        .expect("the map encodes");
    bytes.into_inner()
}

/// Values a texel cannot have.
const BAD_TEXELS: [f32; 6] = [
    f32::MAX,
    f32::NAN,
    f32::INFINITY,
    -1.0,
    1e20,
    f32::NEG_INFINITY,
];

/// One mutation of a generated map, chosen by `rng`.
pub fn mutate(rng: &mut impl Rng) -> MapMutant {
    let (extension, format) = *[("hdr", ImageFormat::Hdr), ("exr", ImageFormat::OpenExr)]
        .choose(rng)
        .unwrap();
    let base = encode(sky(), format);
    let plain = |what: String, bytes: Vec<u8>| MapMutant {
        bytes,
        extension,
        what,
        nonsense: false,
        legal: false,
    };
    match rng.gen_range(0..6) {
        0 => {
            let cut = rng.gen_range(0..base.len());
            plain(
                format!("{extension} truncated at byte {cut}"),
                base[..cut].to_vec(),
            )
        }
        1 => {
            let mut bytes = base.clone();
            let header = bytes.len().min(if extension == "hdr" { 80 } else { 400 });
            for _ in 0..rng.gen_range(1..4) {
                bytes[rng.gen_range(0..header)] ^= 1 << rng.gen_range(0..8);
            }
            plain(format!("{extension} with header bits flipped"), bytes)
        }
        2 => {
            let mut bytes = base.clone();
            for _ in 0..rng.gen_range(1..16) {
                let at = rng.gen_range(0..bytes.len());
                bytes[at] = rng.gen();
            }
            plain(format!("{extension} with random bytes"), bytes)
        }
        3 if extension == "hdr" => {
            let size = [
                "-Y 100000 +X 200000",
                "-Y 0 +X 0",
                "-Y -5 +X 32",
                "+Y 16 +X 32",
                "-Y 16 +X 999999999999",
            ]
            .choose(rng)
            .unwrap();
            let text = String::from_utf8_lossy(&base).into_owned();
            let line = format!("-Y {HEIGHT} +X {WIDTH}");
            let edited = replace_bytes(&base, line.as_bytes(), size.as_bytes());
            assert!(text.contains(&line), "the encoder writes the size line");
            plain(format!("hdr with the size line \"{size}\""), edited)
        }
        3 => {
            let width = *[0u32, 1, 65_536, 1 << 20].choose(rng).unwrap();
            let mut bytes = base.clone();
            // The dataWindow's xMax, an int after its name, type and size.
            if let Some(at) = find(&bytes, b"dataWindow\0box2i\0") {
                let x_max = at + 17 + 4 + 8;
                bytes[x_max..x_max + 4].copy_from_slice(&(width as i32).to_le_bytes());
            }
            plain(format!("exr with a data window {width} wide"), bytes)
        }
        4 => {
            let mut image = sky();
            // `image`'s radiance encoder cannot take an infinite texel (its
            // exponent, `floor(log2 inf) + 128`, overflows: a panic where
            // overflow checks are on, as in plain `cargo test`), and a
            // radiance file cannot hold one.
            let texels: Vec<f32> = BAD_TEXELS
                .into_iter()
                .filter(|&v| format != ImageFormat::Hdr || v != f32::INFINITY)
                .collect();
            let bad = *texels.choose(rng).unwrap();
            let (x, y) = (rng.gen_range(0..WIDTH), rng.gen_range(0..HEIGHT));
            image.get_pixel_mut(x, y).0[rng.gen_range(0..3)] = bad;
            // Radiance files hold no NaN, infinite or negative values, and
            // f32::MAX's exponent does not fit in RGBE's byte: what the
            // encoder makes of them is its business. 1e20 it holds.
            let exr = format == ImageFormat::OpenExr;
            MapMutant {
                nonsense: exr || bad == 1e20,
                ..plain(
                    format!("{extension} with texel ({x}, {y}) {bad}"),
                    encode(image, format),
                )
            }
        }
        _ if extension == "hdr" => MapMutant {
            legal: true,
            ..plain(
                "hdr starting #?RGBE".into(),
                replace_bytes(&base, b"#?RADIANCE", b"#?RGBE"),
            )
        },
        _ => {
            let image = Rgb32FImage::from_pixel(WIDTH, HEIGHT, image::Rgb([f32::MAX; 3]));
            MapMutant {
                nonsense: true,
                ..plain("exr of texels all f32::MAX".into(), encode(image, format))
            }
        }
    }
}

/// The first position of `pattern` in `bytes`.
fn find(bytes: &[u8], pattern: &[u8]) -> Option<usize> {
    bytes.windows(pattern.len()).position(|w| w == pattern)
}

/// `bytes` with the first `from` replaced by `to`.
fn replace_bytes(bytes: &[u8], from: &[u8], to: &[u8]) -> Vec<u8> {
    match find(bytes, from) {
        Some(at) => [&bytes[..at], to, &bytes[at + from.len()..]].concat(),
        None => bytes.to_vec(),
    }
}
