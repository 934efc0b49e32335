//! The latitude-longitude environment image: loading (OpenEXR, Radiance
//! `.hdr`), checks, the course's direction <-> `(u, v)` mapping and
//! bilinear lookup.
//!
//! Mapping (the course's handout, 3-2 part 3, and its starter's
//! `EnvironmentLight::dir_to_theta_phi` / `theta_phi_to_xy`):
//!
//! ```text
//! theta = acos(d.y),  phi = atan2(-d.z, d.x) + pi,
//! u = phi / (2 pi),   v = theta / pi            (row 0 = up, +Y)
//! d = (-sin(theta) cos(phi), cos(theta), sin(theta) sin(phi))
//! ```
//!
//! so `u = 1/2` looks along +X and `u = 1/4` along +Z. Texel `(i, j)` is
//! centred on `((i + 1/2) / w, (j + 1/2) / h)`; the lookup interpolates
//! bilinearly between the four nearest centres, wrapping around in `u`
//! and clamping in `v`.
//!
//! Each texel is stored in 16 bytes, its radiance and beside it the
//! density per unit area `p(u, v)` with which the light's importance
//! sampler draws points of its cell ([`EnvironmentMap::set_cell_densities`]):
//! a ray that escapes reads the radiance and, for its MIS weight, the
//! density from the same cache lines, one or two random misses in a map
//! of tens of megabytes instead of three or four.
//!
//! Texels are radiance: every channel finite, non-negative and at most
//! [`MAX_RADIANCE`]; a map with another texel is refused, naming the
//! first such texel `(x, y)` (column from the left, row from the top) and
//! its value. Negative texels (legal in OpenEXR) are refused too, not
//! clamped: the map has no channel for warnings, and a negative texel
//! usually means a map made by subtraction or a wrong colour conversion.
//! Reading files: the private modules `reading` (what is wrong with a
//! file, in plain words; OpenEXR windows), `radiance` (the Radiance
//! format) and `exr_layout` (how long an OpenEXR file should be); the
//! bilinear lookup and its cache hints are in the child module `lookup`.

use std::f32::consts::PI;
use std::fmt;
use std::path::Path;

use glam::{Vec2, Vec3, Vec4};

use crate::math::float::readable;
use crate::math::huge_pages;
use crate::math::special::atan2;
use crate::math::{Rgb, MAX_RADIANCE};

mod lookup;

/// An environment map that could not be used: the file (or the name of a
/// map made in code) and what was wrong.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct EnvironmentError {
    pub file: String,
    pub problem: String,
}

impl fmt::Display for EnvironmentError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: environment map: {}", self.file, self.problem)
    }
}

impl std::error::Error for EnvironmentError {}

/// A latitude-longitude image of radiance, `width = 2 height`. Two maps
/// are equal when their texels and the densities set beside them are.
#[derive(Clone, PartialEq)]
pub struct EnvironmentMap {
    width: usize,
    height: usize,
    /// Linear RGB radiance in `xyz`, rows from the top (`v = 0`, +Y)
    /// down; in `w`, the cell's sampling density (0 until set).
    texels: Vec<Vec4>,
    /// Where the map came from, for messages.
    source: String,
}

impl fmt::Debug for EnvironmentMap {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "EnvironmentMap({}, {} x {})",
            self.source, self.width, self.height
        )
    }
}

/// `(u, v)` in `[0, 1)^2` of the unit direction `d` (need not be exactly unit).
pub fn direction_to_uv(d: Vec3) -> Vec2 {
    // theta from atan2 keeps its accuracy near the poles, where acos loses it.
    let theta = atan2((d.x * d.x + d.z * d.z).sqrt(), d.y);
    let phi = atan2(-d.z, d.x) + PI;
    let u = (phi / (2.0 * PI)).clamp(0.0, 1.0);
    Vec2::new(if u >= 1.0 { 0.0 } else { u }, (theta / PI).clamp(0.0, 1.0))
}

/// The unit direction of `(u, v)`: the inverse of [`direction_to_uv`].
pub fn uv_to_direction(uv: Vec2) -> Vec3 {
    let (sin_theta, cos_theta) = (PI * uv.y).sin_cos();
    let (sin_phi, cos_phi) = (2.0 * PI * uv.x).sin_cos();
    Vec3::new(-sin_theta * cos_phi, cos_theta, sin_theta * sin_phi)
}

/// The unit direction through the centre of texel `(i, j)` (column, row
/// from the top) of a `width x height` map.
pub fn texel_direction(i: usize, j: usize, width: usize, height: usize) -> Vec3 {
    uv_to_direction(Vec2::new(
        (i as f32 + 0.5) / width as f32,
        (j as f32 + 0.5) / height as f32,
    ))
}

impl EnvironmentMap {
    /// A map of `width x height` texels (rows from the top), checked: 2:1,
    /// at least 2 x 1, every channel of every texel finite, non-negative
    /// and at most [`MAX_RADIANCE`]. `source` names the map in errors.
    pub fn new(
        source: &str,
        width: usize,
        height: usize,
        texels: Vec<Rgb>,
    ) -> Result<Self, EnvironmentError> {
        let error = |problem: String| EnvironmentError {
            file: source.to_string(),
            problem,
        };
        if height == 0 || width != 2 * height {
            return Err(error(shape_problem(width as u64, height as u64)));
        }
        if texels.len() != width * height {
            return Err(error(format!(
                "{} texels for {width} x {height}",
                texels.len()
            )));
        }
        if let Some((k, why)) = texels
            .iter()
            .enumerate()
            .find_map(|(k, &t)| texel_problem(t).map(|why| (k, why)))
        {
            return Err(error(format!(
                "texel ({}, {}) is {}: {why} (a texel's radiance must be finite, \
                 between 0 and {MAX_RADIANCE:e})",
                k % width,
                k / width,
                texel_text(texels[k])
            )));
        }
        // Backed by 2 MiB pages: a 2k map's 33 MB are read at random.
        let mut backed = Vec::with_capacity(texels.len());
        huge_pages::advise(&backed);
        backed.extend(texels.iter().map(|t| t.extend(0.0)));
        Ok(EnvironmentMap {
            width,
            height,
            texels: backed,
            source: source.to_string(),
        })
    }

    /// The map whose texel `(i, j)` holds `radiance` of the direction
    /// through its centre.
    pub fn from_fn(
        source: &str,
        width: usize,
        height: usize,
        radiance: impl Fn(Vec3) -> Rgb,
    ) -> Result<Self, EnvironmentError> {
        let texels = (0..width * height)
            .map(|k| radiance(texel_direction(k % width, k / width, width, height)))
            .collect();
        Self::new(source, width, height, texels)
    }

    /// Reads an OpenEXR (half or full float, RGB or RGBA; alpha is
    /// ignored; the display window with the data window's texels placed
    /// in it, black elsewhere) or Radiance
    /// (`#?RADIANCE` or `#?RGBE`, flat or run-length encoded) map,
    /// recognised by its first bytes. The error names the file and says
    /// what is wrong: empty, truncated (at which byte, of how many where
    /// known), not one of those formats (and what it begins with), too
    /// large for memory (the size and the memory it needs), not 2:1, or
    /// its first texel that is not finite, negative or above
    /// [`MAX_RADIANCE`].
    pub fn load(path: &Path) -> Result<Self, EnvironmentError> {
        super::reading::load(path)
    }

    pub fn width(&self) -> usize {
        self.width
    }

    pub fn height(&self) -> usize {
        self.height
    }

    /// Where the map came from.
    pub fn source(&self) -> &str {
        &self.source
    }

    /// Texel `(i, j)`, column `i` wrapped around, row `j` clamped.
    pub fn texel(&self, i: i64, j: i64) -> Rgb {
        let i = i.rem_euclid(self.width as i64) as usize;
        let j = j.clamp(0, self.height as i64 - 1) as usize;
        self.texels[j * self.width + i].truncate()
    }

    /// Sets each cell's density per unit area `p(u, v)` (`width x height`
    /// values, rows from the top), which [`Self::lookup_with_density`]
    /// returns with the radiance.
    ///
    /// # Panics
    ///
    /// If `densities` has not one value a texel.
    pub fn set_cell_densities(&mut self, densities: impl ExactSizeIterator<Item = f32>) {
        assert_eq!(densities.len(), self.texels.len());
        for (t, p) in self.texels.iter_mut().zip(densities) {
            t.w = p;
        }
    }

    /// Average over texel `(i, j)`'s cell of the bilinear interpolant:
    /// the kernel `[1 6 1] / 8` in each direction (on each half of the cell
    /// the interpolant runs linearly from a neighbour's mean with the texel
    /// to the texel). Positive wherever [`Self::lookup`] is somewhere
    /// positive in the cell.
    pub fn cell_average(&self, i: usize, j: usize) -> Rgb {
        let (i, j) = (i as i64, j as i64);
        let weights = [(-1, 1.0), (0, 6.0), (1, 1.0)];
        let mut sum = Rgb::ZERO;
        for (dj, wj) in weights {
            for (di, wi) in weights {
                sum += wi * wj * self.texel(i + di, j + dj);
            }
        }
        sum / 64.0
    }
}

/// Why a map of `width x height` texels is not latitude-longitude.
pub(super) fn shape_problem(width: u64, height: u64) -> String {
    format!("a latitude-longitude map is twice as wide as high, this one is {width} x {height}")
}

/// Texel `t` as `(r, g, b)`, large values in scientific notation.
fn texel_text(t: Rgb) -> String {
    format!("({}, {}, {})", readable(t.x), readable(t.y), readable(t.z))
}

/// What is wrong with texel `t` as radiance, if anything.
fn texel_problem(t: Rgb) -> Option<&'static str> {
    if t.is_nan() {
        Some("not a number (NaN)")
    } else if !t.is_finite() {
        Some("infinite")
    } else if t.min_element() < 0.0 {
        Some("negative")
    } else if t.max_element() > MAX_RADIANCE {
        Some("too bright")
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_course_mapping_and_its_inverse() {
        let close = |a: Vec3, b: Vec3| (a - b).length() < 1e-5;
        assert!(close(uv_to_direction(Vec2::new(0.5, 0.5)), Vec3::X));
        assert!(close(uv_to_direction(Vec2::new(0.25, 0.5)), Vec3::Z));
        assert!(close(uv_to_direction(Vec2::new(0.75, 0.5)), -Vec3::Z));
        assert!(close(uv_to_direction(Vec2::new(0.3, 0.0)), Vec3::Y));
        for k in 0..200 {
            let uv = Vec2::new(
                (k % 20) as f32 / 20.0 + 0.013,
                (k / 20) as f32 / 10.0 + 0.021,
            );
            let back = direction_to_uv(uv_to_direction(uv));
            assert!((back - uv).length() < 1e-5, "{uv} -> {back}");
        }
    }

    /// `from_fn`'s texel `(i, j)` is the radiance of the direction
    /// through its cell's centre, computed as `uv_to_direction` computes
    /// it (compared exactly); the map keeps its name for messages.
    #[test]
    fn a_map_from_a_function_samples_it_at_the_cells_centres() {
        let radiance = |d: Vec3| Rgb::new(d.x + 1.0, d.y + 1.0, d.z + 1.0);
        let map = EnvironmentMap::from_fn("gradient", 16, 8, radiance).unwrap();
        for j in 0..8 {
            for i in 0..16 {
                let centre = Vec2::new((i as f32 + 0.5) / 16.0, (j as f32 + 0.5) / 8.0);
                let expected = radiance(uv_to_direction(centre));
                assert_eq!(map.texel(i, j), expected, "texel ({i}, {j})");
            }
        }
        assert_eq!(map.source(), "gradient");
        assert_eq!(format!("{map:?}"), "EnvironmentMap(gradient, 16 x 8)");
    }

    /// The cell average is the texels under the kernel `[1 6 1] / 8` in
    /// each direction: a texel of 64 gives its own cell 36, its side
    /// neighbours 6, its diagonal ones 1; columns wrap around, rows clamp
    /// (the row above the top is the top row again).
    #[test]
    fn the_cell_average_is_the_bilinear_lookups_kernel() {
        let mut texels = vec![Rgb::ZERO; 16 * 8];
        texels[3 * 16] = Rgb::new(64.0, 128.0, 0.0);
        texels[5] = Rgb::splat(64.0);
        let map = EnvironmentMap::new("two texels", 16, 8, texels).unwrap();
        let red = |i: usize, j: usize| map.cell_average(i, j).x;
        assert_eq!(map.cell_average(0, 3), Rgb::new(36.0, 72.0, 0.0));
        assert_eq!([red(1, 3), red(15, 3), red(0, 2), red(0, 4)], [6.0; 4]);
        assert_eq!([red(1, 2), red(15, 4)], [1.0; 2]);
        assert_eq!([red(2, 3), red(0, 5), red(14, 3)], [0.0; 3]);
        // Texel (5, 0) on the top row: the row above is the top row again,
        // so its own cell weighs it (6 + 1) 6 = 42, the cell beside it
        // (6 + 1) 1 = 7, the cell below 6.
        assert_eq!([red(5, 0), red(4, 0), red(5, 1)], [42.0, 7.0, 6.0]);
    }

    #[test]
    fn bad_maps_are_refused_with_the_reason() {
        let err = EnvironmentMap::new("m.exr", 3, 2, vec![Rgb::ONE; 6]).unwrap_err();
        assert!(err.to_string().contains("m.exr") && err.to_string().contains("3 x 2"));
        let mut texels = vec![Rgb::ONE; 8];
        texels[5] = Rgb::new(1.0, f32::NAN, 0.0);
        let err = EnvironmentMap::new("m.exr", 4, 2, texels.clone()).unwrap_err();
        assert!(err.problem.contains("(1, 1)"), "{err}");
        texels[5] = Rgb::new(1.0, -0.5, 0.0);
        assert!(EnvironmentMap::new("m.exr", 4, 2, texels.clone()).is_err());
        // MAX_RADIANCE itself is radiance; the next float up is not.
        texels[5] = Rgb::new(1.0, MAX_RADIANCE, 0.0);
        assert!(EnvironmentMap::new("m.exr", 4, 2, texels.clone()).is_ok());
        texels[5].y = f32::from_bits(MAX_RADIANCE.to_bits() + 1);
        let err = EnvironmentMap::new("m.exr", 4, 2, texels).unwrap_err();
        assert!(
            err.problem.contains("(1, 1)") && err.problem.contains("too bright"),
            "{err}"
        );
    }
}
