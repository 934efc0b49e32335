//! Part 7's environment map: a small latitude-longitude sky of the
//! project's own, written as an OpenEXR file the course's loader reads.
//!
//! The course's loader (the starter's `load_exr` in
//! `src/application/main.cpp`, with its bundled `tinyexr.h`) refuses tiled
//! files and takes the file's channels 2, 1 and 0 as red,
//! green and blue. OpenEXR stores channels sorted by name, so an RGB file
//! holds `B, G, R` and loads right, while an RGBA file (`A, B, G, R`)
//! loads with its colours shifted. [`write_exr`] therefore writes three
//! half-float channels (as the course's maps are) in scan lines,
//! uncompressed; `image`'s own OpenEXR encoder writes tiles and cannot.
//!
//! The sky ([`radiance`]) is made so that every mistake of part 7 shows:
//! blue above the horizon and brown below (a map read upside down,
//! `env-map-v-flipped`, lights the scene from below), redder towards
//! `-z`, where the camera looks, than behind it, and a sun of radiance 30
//! and angular radius 12 degrees up and to the right, in front (a map read
//! mirrored, `env-map-u-flipped`, puts it behind the camera, and turns the
//! shadows). The sun is most of the light, so a density of direction
//! without its `1 / sin(theta)` or its `1 / (2 pi^2)` (`env-pdf-no-sin`,
//! `env-pdf-no-jacobian`) shows in the direct light of every diffuse
//! surface.

use std::path::Path;

use exr::prelude::{f16, Encoding, Image, Layer, LayerAttributes, SpecificChannels, WritableImage};
use glam::Vec3;

use crate::environment::EnvironmentMap;
use crate::math::Rgb;

/// The map's width and height in texels (2:1).
pub const MAP_SIZE: (usize, usize) = (64, 32);

/// The sun's direction (towards it; world space, `y` up, the camera on `+z`).
pub fn sun() -> Vec3 {
    Vec3::new(0.6, 0.55, -0.58).normalize()
}

/// The cosine of the sun's angular radius (12 degrees).
const SUN_COS: f32 = 0.978;

/// The sky's radiance towards the unit direction `d` (see the module docs).
pub fn radiance(d: Vec3) -> Rgb {
    if d.dot(sun()) > SUN_COS {
        return Rgb::new(30.0, 27.0, 21.0);
    }
    if d.y < 0.0 {
        return Rgb::new(0.30, 0.22, 0.14);
    }
    let red = 0.35 * (-d.z).max(0.0);
    Rgb::new(0.25 + red, 0.45, 0.85) * (0.6 + 0.4 * d.y)
}

/// The map as [`write_exr`] writes it: each texel [`radiance`] at its
/// centre, rounded to half floats.
pub fn map() -> EnvironmentMap {
    let half = |v: f32| f16::from_f32(v).to_f32();
    EnvironmentMap::from_fn("check: sky", MAP_SIZE.0, MAP_SIZE.1, |d| {
        radiance(d).map(half)
    })
    .expect("the sky is finite, non-negative and 2:1")
}

/// Writes [`map`] to `path`: RGB half floats in scan lines, uncompressed.
pub fn write_exr(path: &Path) -> Result<(), String> {
    let map = map();
    let texel = |p: exr::math::Vec2<usize>| {
        let t = map.texel(p.x() as i64, p.y() as i64);
        (f16::from_f32(t.x), f16::from_f32(t.y), f16::from_f32(t.z))
    };
    let layer = Layer::new(
        MAP_SIZE,
        LayerAttributes::default(),
        Encoding::UNCOMPRESSED,
        SpecificChannels::rgb(texel),
    );
    Image::from_layer(layer)
        .write()
        .to_file(path)
        .map_err(|e| format!("{}: {e}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The file is what the course's loader takes: not tiled (bit 0x200
    /// of the version field clear), channels `B, G, R` in that order (its
    /// 2, 1, 0 are red, green, blue) and no alpha, half floats; the
    /// project's loader reads back the map's texels exactly.
    #[test]
    fn the_sky_is_written_as_the_course_reads_it() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("sky.exr");
        write_exr(&path).unwrap();
        let bytes = std::fs::read(&path).unwrap();
        assert_eq!(bytes[..4], [0x76, 0x2f, 0x31, 0x01]);
        let flags = u32::from_le_bytes(bytes[4..8].try_into().unwrap());
        assert_eq!(flags & 0x200, 0, "tiled");
        let meta = exr::meta::MetaData::read_from_file(&path, false).unwrap();
        let header = &meta.headers[0];
        let names: Vec<String> = header
            .channels
            .list
            .iter()
            .map(|c| c.name.to_string())
            .collect();
        assert_eq!(names, ["B", "G", "R"]);
        assert!(header
            .channels
            .list
            .iter()
            .all(|c| c.sample_type == exr::meta::attribute::SampleType::F16));
        assert!(matches!(
            header.blocks,
            exr::meta::BlockDescription::ScanLines
        ));
        let loaded = EnvironmentMap::load(&path).unwrap();
        let expected = map();
        assert_eq!((loaded.width(), loaded.height()), MAP_SIZE);
        for j in 0..MAP_SIZE.1 as i64 {
            for i in 0..MAP_SIZE.0 as i64 {
                assert_eq!(loaded.texel(i, j), expected.texel(i, j), "({i}, {j})");
            }
        }
        // Not a uniform sky: the sun's texel is far the brightest, up and
        // in front (v < 1/2; u where phi = atan2(-z, x) + pi puts it).
        let brightest = (0..MAP_SIZE.0 * MAP_SIZE.1)
            .max_by(|&a, &b| {
                let t = |k: usize| expected.texel((k % 64) as i64, (k / 64) as i64).x;
                t(a).total_cmp(&t(b))
            })
            .unwrap();
        assert!(brightest / MAP_SIZE.0 < MAP_SIZE.1 / 2);
    }
}
