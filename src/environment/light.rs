//! The environment light: radiance `L(w)` from every direction, read from a
//! latitude-longitude map, infinitely far away (pbrt-v4, section 12.5.2,
//! `ImageInfiniteLight`; the course's handout, 3-2 part 3).
//!
//! Two ways to sample a direction towards it:
//!
//! - **uniform** on the sphere (`--env-uniform`): `p(w) = 1 / (4 pi)`;
//! - **importance** by a piecewise-constant 2D distribution over the map's
//!   cells ([`Distribution2D`]: rows by their marginal, then the column in
//!   the row), proportional to the cell's luminance times `sin(theta)` of
//!   its centre. Sampling a point `(u, v)` of the unit square with density
//!   `p(u, v)` and mapping it to `w` with `theta = pi v`, `phi = 2 pi u`,
//!   where `d omega = sin(theta) d theta d phi = 2 pi^2 sin(theta) du dv`,
//!   gives the density per steradian
//!
//! ```text
//! p(w) = p(u, v) / (2 pi^2 sin(theta))      (= p_pixel w h / (2 pi^2 sin theta) in the course)
//! ```
//!
//! The `sin(theta)` in the distribution cancels this Jacobian up to its
//! variation across a row, so `L / p` stays bounded near the poles; at a
//! pole itself (`sin(theta) = 0`, a set of measure zero) no direction is
//! sampled and the density is 0.
//!
//! The course weights each cell by its texel (the handout's `pdf_envmap`,
//! [`EnvironmentWeights::Texel`], which `--course-exact` keeps); here a
//! cell's weight is the luminance of the *average of the bilinear lookup
//! over the cell* ([`EnvironmentMap::cell_average`],
//! [`EnvironmentWeights::CellAverage`]), since the light's radiance is the
//! bilinear lookup: a dark texel next to a bright one still shows some of
//! its light, and a density of 0 there would make the estimator miss it
//! (bias). Every cell where the lookup is somewhere positive has a positive
//! density.
//!
//! Power through a scene of radius `R`: `Phi = pi R^2 integral L dw` (as
//! pbrt-v4 counts lights at infinity; the ambient sky's `2 pi^2 R^2 L` is
//! the special case of a bright upper hemisphere).

use std::f32::consts::PI;
use std::sync::Arc;

use glam::{Vec2, Vec3};

use super::map::{direction_to_uv, uv_to_direction, EnvironmentMap};
use crate::lights::{LightPdf, LightSample};
use crate::math::distribution::Distribution2D;
use crate::math::warp::{sample_uniform_sphere, uniform_sphere_pdf};
use crate::math::{luminance, Rgb};

/// How [`EnvironmentLight::sample_li`] picks directions.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum EnvironmentSampling {
    /// By the map's luminance times `sin(theta)` (the default).
    #[default]
    Importance,
    /// Uniformly on the sphere (`--env-uniform`), to compare with.
    Uniform,
}

/// What a cell of the map weighs in the importance-sampling tables.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum EnvironmentWeights {
    /// The luminance of the bilinear lookup's average over the cell: a
    /// positive density wherever the light is (the default).
    #[default]
    CellAverage,
    /// The luminance of the cell's texel, as the handout builds
    /// `pdf_envmap` (`--course-exact`): a black texel next to a bright one
    /// gets no samples, though the lookup shows light there.
    Texel,
}

/// The map and the tables made from it, shared between clones.
#[derive(Debug)]
struct Tables {
    map: EnvironmentMap,
    distribution: Distribution2D,
    /// What the distribution weighs each cell by.
    weights: EnvironmentWeights,
    /// `integral L dw` over the sphere, per channel.
    radiant_integral: Rgb,
    /// The largest density per steradian of importance sampling, over the
    /// cells ([`EnvironmentLight::peak_density`]).
    peak_density: f32,
}

/// A light at infinity whose radiance comes from an environment map.
#[derive(Clone, Debug)]
pub struct EnvironmentLight {
    tables: Arc<Tables>,
    pub sampling: EnvironmentSampling,
}

impl EnvironmentLight {
    /// The light of `map`, sampled by `sampling`; builds the 2D distribution
    /// with the default weights.
    pub fn new(map: EnvironmentMap, sampling: EnvironmentSampling) -> Self {
        Self::with_weights(map, sampling, EnvironmentWeights::default())
    }

    /// The light of `map`, sampled by `sampling`, its cells weighted by
    /// `weights` (times `sin(theta)`).
    pub fn with_weights(
        mut map: EnvironmentMap,
        sampling: EnvironmentSampling,
        weights_by: EnvironmentWeights,
    ) -> Self {
        let (w, h) = (map.width(), map.height());
        let mut weights = Vec::with_capacity(w * h);
        let mut radiant_integral = Rgb::ZERO;
        // sin(theta) at each row's centre.
        let row_sines: Vec<f32> = (0..h)
            .map(|j| (PI * (j as f32 + 0.5) / h as f32).sin())
            .collect();
        for (j, &sin_theta) in row_sines.iter().enumerate() {
            for i in 0..w {
                let cell = match weights_by {
                    EnvironmentWeights::CellAverage => map.cell_average(i, j),
                    EnvironmentWeights::Texel => map.texel(i as i64, j as i64),
                };
                weights.push(luminance(cell) * sin_theta);
                radiant_integral += map.texel(i as i64, j as i64) * sin_theta;
            }
        }
        // Each cell spans (2 pi / w) (pi / h) in (phi, theta).
        radiant_integral *= 2.0 * PI * PI / (w * h) as f32;
        let distribution = Distribution2D::new(&weights, w, h);
        // The cells' densities, and on the way their largest per steradian.
        let mut peak_density = 0.0f32;
        map.set_cell_densities((0..w * h).map(|k| {
            let pdf = distribution.cell_pdf(k % w, k / w);
            peak_density = peak_density.max(pdf / row_sines[k / w]);
            pdf
        }));
        peak_density /= 2.0 * PI * PI;
        EnvironmentLight {
            tables: Arc::new(Tables {
                distribution,
                weights: weights_by,
                map,
                radiant_integral,
                peak_density,
            }),
            sampling,
        }
    }

    /// The map this light shows.
    pub fn map(&self) -> &EnvironmentMap {
        &self.tables.map
    }

    /// What the importance-sampling tables weigh each cell by.
    pub fn weights(&self) -> EnvironmentWeights {
        self.tables.weights
    }

    /// The same map with its cells weighted by `weights` (the tables made
    /// again unless they are already so weighted).
    pub fn reweighted(&self, weights: EnvironmentWeights) -> Self {
        if weights == self.weights() {
            return self.clone();
        }
        Self::with_weights(self.map().clone(), self.sampling, weights)
    }

    /// The largest density per steradian with which [`Self::sample_li`]
    /// picks a direction: `max p(u, v) / (2 pi^2 sin(theta))` over the
    /// cells, at their centres (`1 / (4 pi)` sampled uniformly). How
    /// sharp the light's sampling is: about 2.6 for a soft studio map,
    /// 10^4 for a sun a quarter of a degree wide that holds half the
    /// light ([`crate::plan::light_samples`] compares it with a BSDF's).
    pub fn peak_density(&self) -> f32 {
        match self.sampling {
            EnvironmentSampling::Uniform => uniform_sphere_pdf(),
            EnvironmentSampling::Importance => self.tables.peak_density,
        }
    }

    /// The same map sampled another way (the tables are shared).
    pub fn with_sampling(&self, sampling: EnvironmentSampling) -> Self {
        EnvironmentLight {
            tables: Arc::clone(&self.tables),
            sampling,
        }
    }

    /// A direction towards the environment for `u` in `[0, 1)^2`, with the
    /// radiance along it and its density per steradian; `None` at a pole.
    #[doc(alias = "sample_L")]
    pub fn sample_li(&self, u: Vec2) -> Option<LightSample> {
        let (wi, pdf, radiance) = match self.sampling {
            EnvironmentSampling::Uniform => {
                let wi = sample_uniform_sphere(u);
                (wi, uniform_sphere_pdf(), self.escaped_radiance(wi))
            }
            EnvironmentSampling::Importance => {
                let map = &self.tables.map;
                let s = (self.tables.distribution)
                    .sample_hinted(u, |v, column| map.prefetch_sampled_texels(column, v));
                let wi = uv_to_direction(s.x);
                let pdf = per_steradian(s.pdf, wi);
                (wi, pdf, map.lookup(s.x))
            }
        };
        (pdf > 0.0 && pdf.is_finite()).then_some(LightSample {
            radiance,
            wi,
            distance: f32::INFINITY,
            pdf: LightPdf::SolidAngle(pdf),
        })
    }

    /// Starts loading what [`Self::sample_li`] at `u` will read first, its
    /// guide entry ([`Distribution2D::prefetch_guide`]); nothing else.
    #[inline]
    pub fn prefetch_sample_guide(&self, u: Vec2) {
        if self.sampling == EnvironmentSampling::Importance {
            self.tables.distribution.prefetch_guide(u);
        }
    }

    /// The second step after [`Self::prefetch_sample_guide`]: the row's
    /// cdf where the search starts and the texels around that column.
    #[inline]
    pub fn prefetch_sample_cdf(&self, u: Vec2) {
        if self.sampling == EnvironmentSampling::Importance {
            let map = &self.tables.map;
            (self.tables.distribution)
                .prefetch_cdf(u, |v, column| map.prefetch_sampled_texels(column, v));
        }
    }

    /// Density per steradian with which [`Self::sample_li`] picks the
    /// direction `wi`: `p(u, v) / (2 pi^2 sin(theta))`, 0 at the poles.
    pub fn pdf_li(&self, wi: Vec3) -> f32 {
        match self.sampling {
            EnvironmentSampling::Uniform => uniform_sphere_pdf(),
            EnvironmentSampling::Importance => {
                let w = wi.normalize_or_zero();
                per_steradian(self.tables.map.cell_density(direction_to_uv(w)), w)
            }
        }
    }

    /// What a ray escaping in the unit direction `w` sees, and, if
    /// `with_pdf`, the density [`Self::pdf_li`] of `w` (else 0): one
    /// mapping to the map's `(u, v)` and one lookup for both (the map
    /// keeps each cell's density beside its texel), and no density where
    /// the radiance is black (it weighs nothing there).
    pub fn escaped(&self, w: Vec3, with_pdf: bool) -> (Rgb, f32) {
        let (radiance, density) = self.tables.map.lookup_with_density(direction_to_uv(w));
        let pdf = match self.sampling {
            _ if !with_pdf || radiance == Rgb::ZERO => 0.0,
            EnvironmentSampling::Uniform => uniform_sphere_pdf(),
            EnvironmentSampling::Importance => per_steradian(density, w),
        };
        (radiance, pdf)
    }

    /// Starts loading the texels [`Self::escaped`] in the unit direction
    /// `w` reads, for a ray that may escape; nothing else.
    #[inline]
    pub fn prefetch_escape(&self, w: Vec3) {
        self.tables.map.prefetch_uv(direction_to_uv(w));
    }

    /// Radiance seen along a ray that escapes in the unit direction `w`.
    #[doc(alias = "sample_dir")]
    pub fn escaped_radiance(&self, w: Vec3) -> Rgb {
        self.tables.map.radiance(w)
    }

    /// Power through a scene of radius `scene_radius`: `pi R^2 integral L dw`.
    pub fn power(&self, scene_radius: f32) -> Rgb {
        PI * scene_radius * scene_radius * self.tables.radiant_integral
    }
}

/// `sin(theta)` of the unit direction `w`, theta measured from +Y.
fn sin_theta(w: Vec3) -> f32 {
    (w.x * w.x + w.z * w.z).sqrt()
}

/// The density per steradian at the unit direction `w` of a density
/// `p(u, v)` per unit area of the map: `p(u, v) / (2 pi^2 sin(theta))`,
/// 0 at the poles.
fn per_steradian(density: f32, w: Vec3) -> f32 {
    let sin_theta = sin_theta(w);
    if sin_theta <= 0.0 {
        return 0.0;
    }
    density / (2.0 * PI * PI * sin_theta)
}

#[cfg(test)]
mod tests;
