//! Piecewise-constant distributions on `[0, 1]` and `[0, 1]^2`, sampled by
//! inverting their cumulative distribution functions (pbrt-v4, sections
//! A.4.2 and A.5.2 `PiecewiseConstant1D` / `PiecewiseConstant2D`).
//!
//! 1D: a function of `n` non-negative values `f_i`, constant on the cells
//! `[i/n, (i+1)/n)`. With `c = integral f = sum f_i / n`:
//!
//! ```text
//! p(x)    = f_i / c                  for x in cell i
//! P(x)    = cdf_i + (x n - i) f_i / (n c),   cdf_i = sum_{k<i} f_k / (n c)
//! sample: x = P^-1(u)
//! ```
//!
//! Finding the cell of `u` (the last `i` with `cdf_i <= u`) starts from a
//! guide table (Chen and Asau 1974, "On generating random variates from
//! an empirical distribution"): `guide[k]` is the cell of `u = k / n`, so
//! the search for `u` starts at `guide[floor(u n)]` and walks a few cells,
//! on average O(1) instead of the O(log n) of a binary search over the
//! whole table. The mapping from `u` to `x` is unchanged (monotone, so
//! stratified and low-discrepancy `u` stay well spread).
//!
//! A function that is zero everywhere (or not finite) becomes the uniform
//! distribution, so that sampling never divides by zero. Cells of zero
//! value are never sampled.
//!
//! 2D (`w` columns, `h` rows, row-major, row `v` first): the marginal
//! density of the row, `p(v) = integral f(u, v) du / c`, and in each row the
//! conditional density of the column, `p(u | v) = f(u, v) / integral f(u, v) du`;
//! `p(u, v) = p(v) p(u | v) = f(u, v) / c`. A sample draws the row from the
//! marginal with `u.y`, then the column from that row's conditional with
//! `u.x`; the inverse maps a point back to the `u` that gives it.
//!
//! Layout: the rows' tables lie in two flat arrays (every row's cdf, then
//! every row's guide), not in a vector per row: an environment map's are
//! tens of megabytes read at random, and one allocation each can be backed
//! by 2 MiB pages ([`crate::math::huge_pages`]) and holds no per-row
//! headers between the tables.

use crate::math::float::ONE_BELOW_ONE;
use crate::math::huge_pages;
use glam::Vec2;

/// A piecewise-constant density on `[0, 1]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Distribution1D {
    /// `cdf[i]`: probability of the cells before `i`; `cdf[n] = 1`.
    cdf: Vec<f32>,
    /// Integral of the function over `[0, 1]` (0 when it was made uniform).
    integral: f32,
    /// `guide[k]`: the cell of `u = k / n`, where the search for `u` in
    /// `[k / n, (k + 1) / n)` starts.
    guide: Vec<u32>,
}

/// A point drawn from a distribution and its density.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DistributionSample<T> {
    /// The point, in `[0, 1)` (1D) or `[0, 1)^2` (2D).
    pub x: T,
    /// Density at the point with respect to length (1D) or area (2D); positive.
    pub pdf: f32,
    /// The cell the point lies in (the column for 2D).
    pub cell: usize,
}

/// Appends the tables of the distribution proportional to `func` (not
/// empty): `n + 1` cumulative probabilities to `cdf`, `n` guide entries to
/// `guide`. Returns the integral, or 0 if `func` had no positive finite
/// value and the tables are the uniform distribution's.
fn tabulate(func: &[f32], cdf: &mut Vec<f32>, guide: &mut Vec<u32>) -> f32 {
    let n = func.len();
    let clean = |f: f32| if f.is_finite() { f.max(0.0) } else { 0.0 };
    // A sum of finite f32 values in f64 is finite, and their mean is at
    // most the largest: the integral is finite, and 0 only where every
    // value is 0 or the mean underflows f32.
    let total: f64 = func.iter().map(|&f| clean(f) as f64).sum();
    let integral = (total / n as f64) as f32;
    let uniform = integral == 0.0;
    let start = cdf.len();
    let mut running = 0.0f64;
    cdf.push(0.0);
    for &f in func {
        running += if uniform { 1.0 } else { clean(f) as f64 };
        cdf.push((running / if uniform { n as f64 } else { total }) as f32);
    }
    cdf[start + n] = 1.0;
    let row = &cdf[start..];
    guide.extend((0..n).map(|k| {
        let u = k as f32 / n as f32;
        // Below n but where n > 2^24 rounds `(n - 1) / n` up to 1 = cdf[n].
        (row.partition_point(|&c| c <= u).saturating_sub(1)).min(n - 1) as u32
    }));
    if uniform {
        0.0
    } else {
        integral
    }
}

/// The point `P^-1(u)` of the distribution whose tables are `cdf`
/// (`n + 1` values) and `guide` (`n`), its density and its cell.
fn sample_tables(cdf: &[f32], guide: &[u32], u: f32) -> DistributionSample<f32> {
    let n = guide.len();
    let u = u.clamp(0.0, 1.0);
    // Last cell whose cdf is <= u: cdf[i] <= u < cdf[i + 1], from the
    // guide's cell onwards (back first, in case rounding put the guide's
    // `k / n` above `u`).
    let mut i = guide[cell_of(u, n)] as usize;
    while i > 0 && cdf[i] > u {
        i -= 1;
    }
    while i + 1 < n && cdf[i + 1] <= u {
        i += 1;
    }
    // Rounding can leave u on a cell of zero width: step back to one with mass.
    let i = (0..=i)
        .rev()
        .find(|&k| cdf[k + 1] - cdf[k] > 0.0)
        .unwrap_or(i);
    let width = cdf[i + 1] - cdf[i];
    let du = ((u - cdf[i]) / width).clamp(0.0, 1.0);
    let x = ((i as f32 + du) / n as f32).min(ONE_BELOW_ONE);
    DistributionSample {
        x,
        pdf: width * n as f32,
        cell: i,
    }
}

/// The cell of `x` in `[0, 1]` among `n` (1 belongs to the last cell):
/// how every table here finds a point's cell, and the environment map
/// its cell's density.
pub(crate) fn cell_of(x: f32, n: usize) -> usize {
    ((x * n as f32) as usize).min(n - 1)
}

/// The density at `x` of the distribution whose cdf is `cdf`.
fn pdf_tables(cdf: &[f32], x: f32) -> f32 {
    if !(0.0..=1.0).contains(&x) {
        return 0.0;
    }
    let n = cdf.len() - 1;
    let i = cell_of(x, n);
    (cdf[i + 1] - cdf[i]) * n as f32
}

/// The `u` that [`sample_tables`] maps to `x`.
fn invert_tables(cdf: &[f32], x: f32) -> f32 {
    let n = cdf.len() - 1;
    let x = x.clamp(0.0, 1.0);
    let i = cell_of(x, n);
    let t = (x * n as f32 - i as f32).clamp(0.0, 1.0);
    cdf[i] + t * (cdf[i + 1] - cdf[i])
}

impl Distribution1D {
    /// The distribution proportional to `func` (at least one cell).
    /// Negative or non-finite values count as 0; a function with no
    /// positive value gives the uniform distribution.
    ///
    /// # Panics
    ///
    /// If `func` is empty.
    pub fn new(func: &[f32]) -> Self {
        assert!(!func.is_empty(), "a distribution needs at least one cell");
        let (mut cdf, mut guide) = (Vec::new(), Vec::new());
        let integral = tabulate(func, &mut cdf, &mut guide);
        Distribution1D {
            cdf,
            integral,
            guide,
        }
    }

    /// Number of cells.
    pub fn len(&self) -> usize {
        self.guide.len()
    }

    /// Whether the distribution has no cells (never: [`Self::new`] refuses that).
    pub fn is_empty(&self) -> bool {
        self.guide.is_empty()
    }

    /// Integral of the (cleaned) function over `[0, 1]`; 0 if it had no
    /// positive value and the distribution is uniform instead.
    pub fn integral(&self) -> f32 {
        self.integral
    }

    /// The cumulative probabilities `cdf[0] = 0 <= ... <= cdf[n] = 1`.
    pub fn cdf(&self) -> &[f32] {
        &self.cdf
    }

    /// Probability of cell `i`.
    pub fn cell_probability(&self, i: usize) -> f32 {
        self.cdf[i + 1] - self.cdf[i]
    }

    /// The point `P^-1(u)` for `u` in `[0, 1)`, its density and its cell.
    /// The cell always has positive probability.
    pub fn sample(&self, u: f32) -> DistributionSample<f32> {
        sample_tables(&self.cdf, &self.guide, u)
    }

    /// The cell of `x` in `[0, 1]` (1 belongs to the last cell).
    pub fn cell_of(&self, x: f32) -> usize {
        cell_of(x, self.len())
    }

    /// Density at `x` in `[0, 1]`, per unit length.
    pub fn pdf(&self, x: f32) -> f32 {
        pdf_tables(&self.cdf, x)
    }

    /// The cumulative distribution `P(x)`: the `u` that [`Self::sample`]
    /// maps to `x` (for `x` in a cell of positive probability).
    pub fn invert(&self, x: f32) -> f32 {
        invert_tables(&self.cdf, x)
    }
}

/// A piecewise-constant density on `[0, 1]^2`: `width x height` cells.
#[derive(Clone, Debug, PartialEq)]
pub struct Distribution2D {
    width: usize,
    /// Each row's conditional cdf over the columns (`width + 1` values a
    /// row), row after row.
    cdf: Vec<f32>,
    /// Each row's guide table (`width` values a row), row after row.
    guide: Vec<u32>,
    /// Distribution of the rows, proportional to each row's integral.
    marginal: Distribution1D,
}

impl Distribution2D {
    /// The distribution proportional to `func`, `width x height` values in
    /// rows (row `j` is `func[j * width..(j + 1) * width]`; `v` runs down
    /// the rows).
    ///
    /// # Panics
    ///
    /// If `width` or `height` is 0 or `func` has not `width * height` values.
    pub fn new(func: &[f32], width: usize, height: usize) -> Self {
        assert!(width > 0 && height > 0 && func.len() == width * height);
        let mut cdf = Vec::with_capacity(height * (width + 1));
        let mut guide = Vec::with_capacity(height * width);
        huge_pages::advise(&cdf);
        huge_pages::advise(&guide);
        let row_integrals: Vec<f32> = func
            .chunks(width)
            .map(|row| tabulate(row, &mut cdf, &mut guide))
            .collect();
        Distribution2D {
            width,
            cdf,
            guide,
            marginal: Distribution1D::new(&row_integrals),
        }
    }

    pub fn width(&self) -> usize {
        self.width
    }

    pub fn height(&self) -> usize {
        self.marginal.len()
    }

    /// Row `j`'s conditional cdf.
    fn row_cdf(&self, j: usize) -> &[f32] {
        &self.cdf[j * (self.width + 1)..(j + 1) * (self.width + 1)]
    }

    /// A point for `u` in `[0, 1)^2` (row from `u.y`, column from `u.x`)
    /// with its density per unit area; `cell` is the column, the row is
    /// `floor(x.y * height)`.
    pub fn sample(&self, u: Vec2) -> DistributionSample<Vec2> {
        self.sample_hinted(u, |_, _| {})
    }

    /// [`Self::sample`], calling `hint(v, column)` once the row is drawn
    /// (`v` is the sample's second coordinate) and the guide table has
    /// given the column where the search starts (the sample's column is
    /// that one or a few after it): a caller that
    /// will read data of the sampled cell can start loading it there, so
    /// that its cache misses overlap the search's.
    pub fn sample_hinted(
        &self,
        u: Vec2,
        hint: impl FnOnce(f32, usize),
    ) -> DistributionSample<Vec2> {
        let row = self.marginal.sample(u.y);
        let entry = self.guide_entry(row.cell, u.x);
        hint(row.x, self.guide[entry] as usize);
        let guide = &self.guide[row.cell * self.width..(row.cell + 1) * self.width];
        let column = sample_tables(self.row_cdf(row.cell), guide, u.x);
        DistributionSample {
            x: Vec2::new(column.x, row.x),
            pdf: row.pdf * column.pdf,
            cell: column.cell,
        }
    }

    /// The index in [`Self::guide`] of the entry where the search for
    /// `u_x` in `row` starts: what every sample and prefetch reads first.
    #[inline(always)]
    fn guide_entry(&self, row: usize, u_x: f32) -> usize {
        row * self.width + cell_of(u_x.clamp(0.0, 1.0), self.width)
    }

    /// Starts loading the guide entry that [`Self::sample`] at `u` reads
    /// first, so that a caller with several samples to draw can overlap
    /// their cache misses (the marginal's tables are small and stay
    /// cached; the rows' guides and cdfs, megabytes in all, are read at
    /// random). Changes nothing else.
    #[inline]
    pub fn prefetch_guide(&self, u: Vec2) {
        let entry = self.guide_entry(self.marginal.sample(u.y).cell, u.x);
        crate::math::prefetch::prefetch_lines(&self.guide[entry], 1);
    }

    /// The second step after [`Self::prefetch_guide`]: reads the guide
    /// entry (loaded by then) and starts loading the cdf where the search
    /// will start, and, through `hint(v, column)` as in
    /// [`Self::sample_hinted`], whatever the caller reads at the cell.
    /// Changes nothing else.
    #[inline]
    pub fn prefetch_cdf(&self, u: Vec2, hint: impl FnOnce(f32, usize)) {
        let row = self.marginal.sample(u.y);
        let column = self.guide[self.guide_entry(row.cell, u.x)] as usize;
        crate::math::prefetch::prefetch_lines(&self.row_cdf(row.cell)[column], 1);
        hint(row.x, column);
    }

    /// Density at `p` in `[0, 1]^2`, per unit area.
    pub fn pdf(&self, p: Vec2) -> f32 {
        if !(0.0..=1.0).contains(&p.y) {
            return 0.0;
        }
        let row = self.marginal.cell_of(p.y);
        self.marginal.pdf(p.y) * pdf_tables(self.row_cdf(row), p.x)
    }

    /// The density per unit area in cell `(column, row)`: what
    /// [`Self::pdf`] gives at every point of it, bit for bit.
    pub fn cell_pdf(&self, column: usize, row: usize) -> f32 {
        let in_row = self.row_cdf(row);
        let n = self.width as f32;
        self.marginal.cell_probability(row)
            * self.height() as f32
            * ((in_row[column + 1] - in_row[column]) * n)
    }

    /// The `u` that [`Self::sample`] maps to `p`.
    pub fn invert(&self, p: Vec2) -> Vec2 {
        let row = self.marginal.cell_of(p.y.clamp(0.0, 1.0));
        Vec2::new(
            invert_tables(self.row_cdf(row), p.x),
            self.marginal.invert(p.y),
        )
    }
}

#[cfg(test)]
mod tests;
