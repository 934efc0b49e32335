//! What an environment map's radiance can do over a small disk of
//! directions: its largest, smallest and mean luminance there, from a
//! pyramid of the map's luminance (each level's texel the max, min and
//! mean of the four below it), and the bound they give on the variance of
//! the radiance seen by a direction drawn from the disk (Bhatia and Davis
//! 2000, "A better bound on the variance", *Amer. Math. Monthly* 107):
//!
//! ```text
//! Var[L] <= (M - mu) (mu - m)      M = max, m = min, mu = mean of L over the disk
//! ```
//!
//! A disk of radius `r` around `(theta, phi)` is covered by the texels of
//! the first level whose rows are at least `r` high, one row above and
//! below, and the columns within `asin(sin r / sin theta)` of `phi` (the
//! whole row where the disk holds a pole). The mean is the texels' plain mean (not weighted by
//! solid angle): a bound for choosing where samples go, not an estimate.

use glam::Vec3;
use rayon::prelude::*;
use std::f32::consts::PI;

use crate::environment::map::direction_to_uv;
use crate::environment::EnvironmentMap;
use crate::math::color::luminance;

/// Max, min and mean luminance of a set of texels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Range {
    pub max: f32,
    pub min: f32,
    pub mean: f32,
}

impl Range {
    /// The range of no values, which any value widens.
    const EMPTY: Range = Range {
        max: f32::NEG_INFINITY,
        min: f32::INFINITY,
        mean: 0.0,
    };

    /// The Bhatia–Davis bound on the variance of a quantity in
    /// `[min, max]` with mean `mean`.
    pub fn variance_bound(&self) -> f32 {
        ((self.max - self.mean) * (self.mean - self.min)).max(0.0)
    }

    fn of(values: impl Iterator<Item = Range>) -> Range {
        let mut out = Range::EMPTY;
        let mut n = 0u32;
        for v in values {
            out.max = out.max.max(v.max);
            out.min = out.min.min(v.min);
            out.mean += v.mean;
            n += 1;
        }
        out.mean /= n.max(1) as f32;
        out
    }
}

/// One level of the pyramid: `width x height` ranges, rows from the top.
struct Level {
    width: usize,
    height: usize,
    ranges: Vec<Range>,
}

impl Level {
    fn at(&self, i: i64, j: i64) -> Range {
        let i = i.rem_euclid(self.width as i64) as usize;
        let j = j.clamp(0, self.height as i64 - 1) as usize;
        self.ranges[j * self.width + i]
    }
}

/// The widest base level kept: the map's texels in blocks so that it is
/// at most this many columns wide (a 0.18 degree texel), so that an 8k
/// map's pyramid takes 34 MB, not 0.5 GB, beside the map's own 0.5 GB
/// (a 2k map keeps its texels, and the pyramid its 34 MB while the
/// pilot runs). A coarser base only widens the ranges.
pub const BASE_WIDTH: usize = 2048;

/// The luminance pyramid of a map: level 0 the map in blocks of
/// `block x block` texels, each level above of the 2 x 2 blocks below
/// (rounded up: a last odd column or row is taken with its neighbour).
pub struct MapBounds {
    levels: Vec<Level>,
    /// Map texels a base texel spans, each way.
    block: usize,
    /// The map's size in texels.
    map_size: (usize, usize),
    /// Mean luminance over the sphere (texels weighted by solid angle).
    pub sphere_mean: f32,
}

impl MapBounds {
    pub fn new(map: &EnvironmentMap) -> Self {
        let (width, height) = (map.width(), map.height());
        let block = width.div_ceil(BASE_WIDTH);
        let (base_width, base_height) = (width.div_ceil(block), height.div_ceil(block));
        // Rows of blocks in parallel: a 4k map has 8M texels to read.
        let rows: Vec<(Vec<Range>, f64, f64)> = (0..base_height)
            .into_par_iter()
            .map(|bj| {
                let mut row = vec![Range::EMPTY; base_width];
                let mut counts = vec![0u32; base_width];
                let (mut weighted, mut weights) = (0.0f64, 0.0f64);
                for j in bj * block..((bj + 1) * block).min(height) {
                    let sin_theta = (PI * (j as f32 + 0.5) / height as f32).sin() as f64;
                    for (bi, r) in row.iter_mut().enumerate() {
                        for i in bi * block..((bi + 1) * block).min(width) {
                            let y = luminance(map.texel(i as i64, j as i64));
                            weighted += sin_theta * y as f64;
                            weights += sin_theta;
                            r.max = r.max.max(y);
                            r.min = r.min.min(y);
                            r.mean += y;
                            counts[bi] += 1;
                        }
                    }
                }
                for (r, n) in row.iter_mut().zip(counts) {
                    r.mean /= n as f32;
                }
                (row, weighted, weights)
            })
            .collect();
        let weighted: f64 = rows.iter().map(|r| r.1).sum();
        let weights: f64 = rows.iter().map(|r| r.2).sum();
        let base: Vec<Range> = rows.into_iter().flat_map(|r| r.0).collect();
        let mut levels = vec![Level {
            width: base_width,
            height: base_height,
            ranges: base,
        }];
        loop {
            let below = levels.last().expect("level 0");
            if below.width < 2 || below.height < 2 {
                break;
            }
            let (width, height) = (below.width.div_ceil(2), below.height.div_ceil(2));
            let ranges = (0..height)
                .flat_map(|j| (0..width).map(move |i| (i as i64, j as i64)))
                .map(|(i, j)| {
                    Range::of(
                        [(0, 0), (1, 0), (0, 1), (1, 1)]
                            .into_iter()
                            .map(|(di, dj)| below.at(2 * i + di, 2 * j + dj)),
                    )
                })
                .collect();
            levels.push(Level {
                width,
                height,
                ranges,
            });
        }
        MapBounds {
            levels,
            block,
            map_size: (width, height),
            sphere_mean: (weighted / weights.max(f64::MIN_POSITIVE)) as f32,
        }
    }

    /// The luminance's range over the disk of directions of angular radius
    /// `radius` around the unit direction `d`.
    pub fn over_disk(&self, d: Vec3, radius: f32) -> Range {
        let (w, h) = (self.map_size.0 as f32, self.map_size.1 as f32);
        // A level-k texel spans `block 2^k` map texels each way.
        let span = |k: usize| (self.block << k) as f32;
        let k = (0..self.levels.len())
            .find(|&k| PI * span(k) / h >= radius)
            .unwrap_or(self.levels.len() - 1);
        let level = &self.levels[k];
        let uv = direction_to_uv(d);
        // The map texel of `d`, then the level's texel holding it.
        let texel_i = ((uv.x * w) as i64).min(self.map_size.0 as i64 - 1);
        let texel_j = ((uv.y * h) as i64).min(self.map_size.1 as i64 - 1);
        let cells = (self.block << k) as i64;
        let (i, j) = (texel_i / cells, texel_j / cells);
        // The cap's longitudes: within asin(sin r / sin theta) of its
        // centre's, or all of them where it holds a pole.
        let theta = PI * uv.y;
        let columns = if theta - radius <= 0.0 || theta + radius >= PI {
            level.width as i64
        } else {
            let half_width = (radius.sin() / theta.sin()).min(1.0).asin();
            (half_width / (2.0 * PI / w) / span(k)).ceil() as i64 + 1
        };
        let columns = columns.min(level.width as i64 / 2 + 1);
        Range::of(
            (j - 1..=j + 1)
                .flat_map(|jj| (i - columns..=i + columns).map(move |ii| level.at(ii, jj))),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::environment::map::uv_to_direction;
    use crate::math::rng::sampler;
    use crate::math::Rgb;
    use glam::Vec2;
    use rand::Rng;

    /// A `w x h` map whose texel `(i, j)` has luminance `1 + i + 10000 j`
    /// (rows and columns told apart by value).
    fn ramp(w: usize, h: usize) -> EnvironmentMap {
        let texels = (0..w * h)
            .map(|k| Rgb::splat((1 + k % w + 10000 * (k / w)) as f32))
            .collect();
        EnvironmentMap::new("ramp", w, h, texels).unwrap()
    }

    #[test]
    fn a_constant_map_has_no_variance_anywhere() {
        let map = EnvironmentMap::from_fn("grey", 64, 32, |_| Rgb::splat(0.5)).unwrap();
        let bounds = MapBounds::new(&map);
        assert!((bounds.sphere_mean - 0.5).abs() < 1e-5);
        for (d, r) in [(Vec3::Y, 0.01), (Vec3::X, 0.3), (-Vec3::Z, 2.0)] {
            let range = bounds.over_disk(d, r);
            assert!((range.max - 0.5).abs() < 1e-5 && (range.min - 0.5).abs() < 1e-5);
            assert_eq!(range.variance_bound(), 0.0);
        }
    }

    /// Every texel a direction of the disk falls in lies within the
    /// range: directions drawn uniformly in caps of random centres and
    /// radii (poles included), their texels looked up in the map; on a
    /// map whose sides are powers of two, one whose are not (odd columns
    /// and rows at coarser levels), and one wider than [`BASE_WIDTH`]
    /// (the base in blocks). Checked by hand: the columns as `r / sin
    /// theta` without the poles' whole rows fails near a pole.
    #[test]
    fn the_range_covers_every_texel_of_the_disk() {
        for (w, h) in [(64, 32), (100, 50), (2 * BASE_WIDTH + 6, BASE_WIDTH + 3)] {
            covers_every_texel(&ramp(w, h));
        }
    }

    fn covers_every_texel(map: &EnvironmentMap) {
        let (w, h) = (map.width(), map.height());
        let bounds = MapBounds::new(map);
        let mut rng = sampler(7, 1);
        for _ in 0..2000 {
            let centre = uv_to_direction(Vec2::new(rng.gen::<f32>(), rng.gen::<f32>()));
            let radius = 0.001 + 0.5 * rng.gen::<f32>().powi(2);
            let range = bounds.over_disk(centre, radius);
            // A frame around the centre, and directions in its cap.
            let a = if centre.x.abs() < 0.9 {
                Vec3::X
            } else {
                Vec3::Y
            };
            let t = centre.cross(a).normalize();
            let b = centre.cross(t);
            for _ in 0..16 {
                let cos_max = radius.cos();
                let cos = 1.0 - rng.gen::<f32>() * (1.0 - cos_max);
                let sin = (1.0 - cos * cos).max(0.0).sqrt();
                let phi = 2.0 * PI * rng.gen::<f32>();
                let d = cos * centre + sin * (phi.cos() * t + phi.sin() * b);
                let uv = direction_to_uv(d);
                let (i, j) = (
                    ((uv.x * w as f32) as i64).min(w as i64 - 1),
                    ((uv.y * h as f32) as i64).min(h as i64 - 1),
                );
                let y = luminance(map.texel(i, j));
                assert!(
                    range.min <= y && y <= range.max,
                    "texel ({i}, {j}) = {y} outside [{}, {}] for radius {radius} at {centre}",
                    range.min,
                    range.max
                );
            }
        }
    }

    /// The bound is Bhatia and Davis's: zero at a constant, `(M - mu)(mu - m)` else.
    #[test]
    fn the_bound_is_bhatia_and_davis() {
        let range = Range {
            max: 10.0,
            min: 0.0,
            mean: 1.0,
        };
        assert_eq!(range.variance_bound(), 9.0);
    }
}
