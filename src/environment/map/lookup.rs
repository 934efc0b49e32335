//! Lookup: the radiance at a point `(u, v)` of the map, bilinear between
//! the four nearest texel centres (texel `(i, j)` is centred on
//! `((i + 1/2) / w, (j + 1/2) / h)`; columns wrap around, rows clamp):
//!
//! ```text
//! x = u w - 1/2,  y = v h - 1/2,  i = floor(x),  j = floor(y)
//! L(u, v) = lerp(lerp(t[i, j], t[i+1, j], x - i), lerp(t[i, j+1], t[i+1, j+1], x - i), y - j)
//! ```
//!
//! and the cache hints that start loading those texels before a lookup
//! or a light sample reads them.

use glam::{Vec2, Vec3, Vec4};

use super::{direction_to_uv, EnvironmentMap};
use crate::math::distribution::cell_of;
use crate::math::prefetch::prefetch_lines;
use crate::math::special::floor;
use crate::math::Rgb;

impl EnvironmentMap {
    /// The cell `(column, row)` of `uv` in `[0, 1]^2`, as
    /// [`crate::math::distribution::Distribution2D`] finds it (1 belongs to
    /// the last cell).
    fn cell(&self, uv: Vec2) -> usize {
        cell_of(uv.y, self.height) * self.width + cell_of(uv.x, self.width)
    }

    /// Radiance at `(u, v)`, bilinear between texel centres (columns
    /// wrapped around, rows clamped, as [`Self::texel`]).
    #[doc(alias = "bilerp")]
    pub fn lookup(&self, uv: Vec2) -> Rgb {
        self.bilinear(uv).truncate()
    }

    /// [`Self::lookup`], and the density set for the cell of `uv` by
    /// [`Self::set_cell_densities`] (0 if none was): the cell is one of
    /// the four texels the lookup reads, so its density comes from a
    /// cache line already loaded.
    pub fn lookup_with_density(&self, uv: Vec2) -> (Rgb, f32) {
        (self.lookup(uv), self.cell_density(uv))
    }

    /// The density set for the cell of `uv` by [`Self::set_cell_densities`]
    /// (0 if none was), without the radiance.
    pub fn cell_density(&self, uv: Vec2) -> f32 {
        self.texels[self.cell(uv)].w
    }

    /// The four texels around `uv` interpolated, all four lanes.
    fn bilinear(&self, uv: Vec2) -> Vec4 {
        let (left, right, fx) = self.lookup_columns(uv.x);
        let (top, bottom, fy) = self.lookup_rows(uv.y);
        let t = &self.texels;
        let upper = t[top + left].lerp(t[top + right], fx);
        let lower = t[bottom + left].lerp(t[bottom + right], fx);
        upper.lerp(lower, fy)
    }

    /// The two columns a lookup at `u` reads (wrapped around) and the
    /// weight of the right one.
    #[inline(always)]
    fn lookup_columns(&self, u: f32) -> (usize, usize, f32) {
        let x = u * self.width as f32 - 0.5;
        let x0 = floor(x);
        // Wrapping by comparison, not by a division per texel (a hot path).
        let w = self.width as i64;
        let left = match x0 as i64 {
            i if (0..w).contains(&i) => i,
            i => i.rem_euclid(w),
        } as usize;
        let right = if left + 1 == self.width { 0 } else { left + 1 };
        (left, right, x - x0)
    }

    /// The offsets in [`Self::texels`] of the two rows a lookup at `v`
    /// reads (clamped) and the weight of the lower one.
    #[inline(always)]
    fn lookup_rows(&self, v: f32) -> (usize, usize, f32) {
        let y = v * self.height as f32 - 0.5;
        let y0 = floor(y);
        let (j, last) = (y0 as i64, self.height as i64 - 1);
        let top = j.clamp(0, last) as usize * self.width;
        let bottom = (j + 1).clamp(0, last) as usize * self.width;
        (top, bottom, y - y0)
    }

    /// Starts loading the texels a lookup at `v` reads in the columns
    /// from `column - 1` to about `column + 6` (two cache lines), where
    /// a sample whose importance search starts at `column` ends; changes
    /// nothing else.
    #[inline]
    pub fn prefetch_sampled_texels(&self, column: usize, v: f32) {
        let (top, bottom, _) = self.lookup_rows(v);
        let texels = self.texels.as_ptr().wrapping_add(column.saturating_sub(1));
        for row in [top, bottom] {
            prefetch_lines(texels.wrapping_add(row), 2);
        }
    }

    /// Starts loading the four texels a lookup at `uv` reads; nothing else.
    #[inline]
    pub fn prefetch_uv(&self, uv: Vec2) {
        let (left, right, _) = self.lookup_columns(uv.x);
        let (top, bottom, _) = self.lookup_rows(uv.y);
        let texels = self.texels.as_ptr();
        for texel in [top + left, top + right, bottom + left, bottom + right] {
            prefetch_lines(texels.wrapping_add(texel), 1);
        }
    }

    /// Radiance arriving from the unit direction `d`.
    pub fn radiance(&self, d: Vec3) -> Rgb {
        self.lookup(direction_to_uv(d))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lookup_is_bilinear_wraps_in_u_and_clamps_in_v() {
        let texels = vec![
            Rgb::splat(0.0),
            Rgb::splat(1.0),
            Rgb::splat(2.0),
            Rgb::splat(3.0),
            Rgb::splat(4.0),
            Rgb::splat(5.0),
            Rgb::splat(6.0),
            Rgb::splat(7.0),
        ];
        let map = EnvironmentMap::new("test", 4, 2, texels).unwrap();
        assert_eq!(map.lookup(Vec2::new(0.125, 0.25)), Rgb::splat(0.0));
        assert_eq!(map.lookup(Vec2::new(0.25, 0.25)), Rgb::splat(0.5));
        assert_eq!(map.lookup(Vec2::new(0.25, 0.5)), Rgb::splat(2.5));
        // Across the seam: halfway between texels 3 and 0.
        assert_eq!(map.lookup(Vec2::new(0.0, 0.25)), Rgb::splat(1.5));
        assert_eq!(map.lookup(Vec2::new(0.125, 0.0)), Rgb::splat(0.0));
        assert_eq!(map.lookup(Vec2::new(0.125, 1.0)), Rgb::splat(4.0));
    }
}
