//! Legal map files load with the right size and values: Radiance
//! pictures headed `#?RGBE`, run-length encoded old and new style, stored
//! bottom up, with an `EXPOSURE`; an OpenEXR image whose data window is
//! not its display window; a 16384 x 8192 map; half-float RGBA OpenEXR
//! and Radiance pictures written by the `image` and `exr` crates.

use super::*;

#[test]
fn radiance_pictures_headed_rgbe_encoded_either_way_or_bottom_up_load() {
    let dir = Dir::new();
    // #?RGBE, new-style run-length encoding, rows of 16 texels.
    let mut lines = Vec::new();
    for row in 0..8u8 {
        lines.extend(constant_scanline(16, [100 + row, 50, 25, 130]));
    }
    let map =
        EnvironmentMap::load(&dir.file("rgbe.hdr", &radiance("#?RGBE", "", "-Y 8 +X 16", &lines)))
            .unwrap();
    assert_eq!((map.width(), map.height()), (16, 8));
    assert_eq!(map.texel(11, 5), rgbe([105, 50, 25], 130));
    // Rows stored bottom up (+Y), an exposure of 2 (texels halved), and
    // old-style repeats: texel 1 1 1 n repeats the previous n times.
    let mut pixels = Vec::new();
    for row in 0..4u8 {
        pixels.extend_from_slice(&[10 + row, 20, 30, 128, 1, 1, 1, 7]);
    }
    let path = dir.file(
        "old.hdr",
        &radiance("#?RADIANCE", "EXPOSURE=2\n", "+Y 4 +X 8", &pixels),
    );
    let map = EnvironmentMap::load(&path).unwrap();
    assert_eq!((map.width(), map.height()), (8, 4));
    assert_eq!(map.texel(6, 0), rgbe([13, 20, 30], 128) / 2.0);
    assert_eq!(map.texel(0, 3), rgbe([10, 20, 30], 128) / 2.0);
}

#[test]
fn an_openexr_map_is_its_display_window_with_the_data_window_placed_in_it() {
    let dir = Dir::new();
    let path = dir.0.path().join("window.exr");
    // Display window (-2, -1) .. (5, 2), 8 x 4; data 3 x 2 at (0, 0),
    // which is texel (2, 1) of the map.
    let display = IntegerBounds::new((-2, -1), (8, 4));
    write_exr(&path, display, (0, 0), (3, 2), |x, y| {
        (x as f32 + 1.0, y as f32 + 1.0, 0.5)
    });
    let map = EnvironmentMap::load(&path).unwrap();
    assert_eq!((map.width(), map.height()), (8, 4));
    assert_eq!(map.texel(2, 1), Rgb::new(1.0, 1.0, 0.5));
    assert_eq!(map.texel(4, 2), Rgb::new(3.0, 2.0, 0.5));
    assert_eq!(map.texel(1, 1), Rgb::ZERO);
    assert_eq!(map.texel(5, 2), Rgb::ZERO);
    assert_eq!(map.texel(2, 3), Rgb::ZERO);
}

#[test]
fn a_16384_by_8192_map_loads() {
    let dir = Dir::new();
    let lines = constant_scanline(16384, [128, 64, 192, 131]).repeat(8192);
    let path = dir.file(
        "big.hdr",
        &radiance("#?RADIANCE", "", "-Y 8192 +X 16384", &lines),
    );
    let map = EnvironmentMap::load(&path).unwrap();
    assert_eq!((map.width(), map.height()), (16384, 8192));
    let value = rgbe([128, 64, 192], 131);
    assert_eq!(map.texel(16383, 8191), value);
    assert_eq!(map.texel(8000, 4000), value);
}

// --- Through the image crate's encoders, and a binary's driver ---

#[test]
fn half_float_rgba_exr_and_radiance_hdr_maps_are_read() {
    let dir = tempfile::tempdir().unwrap();
    let exr = dir.path().join("half.exr");
    exr::prelude::write_rgba_file(&exr, 8, 4, |x, y| {
        let v = exr::prelude::f16::from_f32((x + 8 * y) as f32 / 4.0);
        (
            v,
            v,
            exr::prelude::f16::from_f32(0.5),
            exr::prelude::f16::ONE,
        )
    })
    .unwrap();
    let map = EnvironmentMap::load(&exr).unwrap();
    assert_eq!((map.width(), map.height()), (8, 4));
    assert_eq!(map.texel(3, 2), Rgb::new(4.75, 4.75, 0.5));

    let hdr = dir.path().join("sky.hdr");
    let pixels: Vec<image::Rgb<f32>> = (0..32).map(|k| image::Rgb([k as f32, 1.0, 0.25])).collect();
    let file = std::fs::File::create(&hdr).unwrap();
    image::codecs::hdr::HdrEncoder::new(file)
        .encode(&pixels, 8, 4)
        .unwrap();
    let map = EnvironmentMap::load(&hdr).unwrap();
    assert_eq!((map.width(), map.height()), (8, 4));
    // RGBE keeps 8 bits of mantissa per channel.
    let t = map.texel(5, 1);
    assert!(
        (t - Rgb::new(13.0, 1.0, 0.25)).abs().max_element() < 0.1,
        "{t}"
    );
}
