//! A rough conductor: the Cook-Torrance microfacet BRDF with the Beckmann
//! distribution (the course's `MicrofacetBSDF`, assignment 3-2).
//!
//! With the half vector `h = normalize(wo + wi)`, `D` and the
//! height-correlated `G` of [`Beckmann`], and the exact conductor Fresnel
//! term `F` for the complex index `eta + i k` ([`fresnel::conductor`]),
//! for `wo` and `wi` both above the surface (Walter et al. 2007, eq. 20):
//!
//! ```text
//! f(wo, wi) = F(wo.h) G(wo, wi) D(h) / (4 cos(theta_o) cos(theta_i))
//! ```
//!
//! and 0 otherwise. Sampling draws `h` ([`MicrofacetSampling`]) and
//! reflects `wo` about it, `wi = 2 (wo.h) h - wo`; the Jacobian of that
//! map is `dh / dwi = 1 / (4 |wo.h|)` (Walter 2007, eq. 14), so
//!
//! ```text
//! p(wi) = p(h) / (4 |wo.h|)
//! ```
//!
//! `MicrofacetSampling::CosineHemisphere` draws `wi` directly, cosine-
//! weighted, `p(wi) = cos(theta_i) / pi` (no half vector, nothing
//! discarded): the baseline of docs/07-materials.md.
//!
//! A direction below the surface (or an `h` facing away from `wo`) is
//! discarded: `sample` returns `None`, and `p` is a sub-density whose
//! integral over the hemisphere is the probability of keeping the sample.
//! With visible-normal sampling the weight of a kept sample is
//! `f cos(theta_i) / p = F G(wo, wi) / G1(wo) <= F`.
//!
//! `MicrofacetSampling::Auto`, the default, picks between the two by
//! `wo`: the visible normals' density `G1(wo) (wo.h) D(h) / cos(theta_o)`
//! and `D(h) cos(theta_h)` differ by how far `wo.h / cos(theta_o)` and
//! `G1(wo)` stray from 1 over the lobe, which is a matter of the stretched
//! slope `s = alpha tan(theta_o)` alone (Beckmann is stretch-invariant).
//! Below [`AUTO_SLOPE`] the half-vector weight's variance is under about
//! `5e-3` per bounce for an albedo of 1 (docs/07's table: `alpha` 0.1 at
//! `cos_o` 0.7, `alpha` 0.01 at 0.1), so there `D cos` is drawn, by a
//! closed form, where the visible normals need `erf` inside Newton's
//! method; above it, the visible normals. The choice depends on `wo` only,
//! so `sample` and `pdf` use the same strategy for every pair.

use glam::{Vec2, Vec3};

use super::beckmann::Beckmann;
use super::{fresnel, BsdfSample, MicrofacetModel, MicrofacetSampling};
use crate::math::warp::{cosine_hemisphere_pdf, sample_cosine_hemisphere};
use crate::math::Rgb;

/// The stretched slope `alpha tan(theta_o)` below which
/// [`MicrofacetSampling::Auto`] samples `D(h) cos(theta_h)`.
pub const AUTO_SLOPE: f64 = 0.1;

/// What [`Conductor::f`] and [`Conductor::pdf`] share.
struct HalfTerms {
    h: Vec3,
    /// `wo.h = wi.h`.
    cos_h: f32,
    d: f64,
    lambda_o: f64,
}

/// A rough metal with Beckmann roughness and complex index `eta + i k`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Conductor {
    pub distribution: Beckmann,
    /// Real part of the index of refraction, per channel.
    pub eta: Rgb,
    /// Extinction coefficient, per channel.
    pub k: Rgb,
    pub sampling: MicrofacetSampling,
    /// The formulas of `f`: physical, or the course starter's.
    pub model: MicrofacetModel,
}

/// The normalised half vector `h` of two directions and `wo.h = wi.h`, or
/// `None` when they are opposite. The cosine is taken as `|wo + wi| / 2`,
/// not as `wo.h`: near grazing, the rounding of `wi` tilts `h` by far more
/// than `wo + wi`'s length changes, and `wo.h` would inherit that error
/// (a bias of 6 % in the albedo at `alpha = 1e-4`, `cos_o = 1e-3`).
fn half_vector(wo: Vec3, wi: Vec3) -> Option<(Vec3, f32)> {
    let sum = wo.as_dvec3() + wi.as_dvec3();
    let h = sum.try_normalize()?;
    Some((h.as_vec3(), (0.5 * sum.length()) as f32))
}

impl Conductor {
    /// A conductor of roughness `alpha` (clamped to
    /// [`beckmann::MIN_ALPHA`](super::beckmann::MIN_ALPHA)).
    pub fn new(alpha: f32, eta: Rgb, k: Rgb, sampling: MicrofacetSampling) -> Self {
        Conductor {
            distribution: Beckmann::new(alpha),
            eta,
            k,
            sampling,
            model: MicrofacetModel::Physical,
        }
    }

    /// The same conductor with `f` computed by `model`.
    pub fn with_model(self, model: MicrofacetModel) -> Self {
        Conductor { model, ..self }
    }

    /// The terms `f` and `pdf` share for two directions above the surface:
    /// the half vector, `D(h)` and `Lambda(wo)`; `None` when a direction is
    /// below the surface or the two are opposite.
    fn half_terms(&self, wo: Vec3, wi: Vec3) -> Option<HalfTerms> {
        if wo.z <= 0.0 || wi.z <= 0.0 {
            return None;
        }
        let (h, cos_h) = half_vector(wo, wi)?;
        Some(HalfTerms {
            h,
            cos_h,
            d: f64::from(self.distribution.d(h)),
            lambda_o: f64::from(self.distribution.lambda(wo)),
        })
    }

    /// `F G D / (4 cos_o cos_i)` with `G = 1 / (1 + Lambda(wo) + Lambda(wi))`:
    /// `F(wo.h)` and the exact `Lambda`, or with [`MicrofacetModel::Starter`]
    /// the starter's `F(wi.z)` and `Lambda` ([`Beckmann::starter_lambda`]).
    fn value(&self, terms: &HalfTerms, wo: Vec3, wi: Vec3) -> Rgb {
        let (lambda_o, lambda_i, cos_fresnel) = match self.model {
            MicrofacetModel::Physical => (
                terms.lambda_o,
                f64::from(self.distribution.lambda(wi)),
                terms.cos_h,
            ),
            MicrofacetModel::Starter => (
                self.distribution.starter_lambda(wo),
                self.distribution.starter_lambda(wi),
                wi.z,
            ),
        };
        let scalar =
            terms.d / ((1.0 + lambda_o + lambda_i) * 4.0 * f64::from(wo.z) * f64::from(wi.z));
        if !scalar.is_finite() {
            return Rgb::ZERO;
        }
        fresnel::conductor(cos_fresnel, self.eta, self.k) * scalar as f32
    }

    /// The strategy used for `wo`: [`MicrofacetSampling::Auto`] resolved to
    /// half-vector or visible-normal sampling; the others as they are.
    fn strategy(&self, wo: Vec3) -> MicrofacetSampling {
        if self.sampling != MicrofacetSampling::Auto {
            return self.sampling;
        }
        let alpha = f64::from(self.distribution.alpha());
        let (x, y, z) = (f64::from(wo.x), f64::from(wo.y), f64::from(wo.z));
        // alpha^2 tan^2(theta_o) < AUTO_SLOPE^2, without dividing by z.
        if alpha * alpha * (x * x + y * y) < (AUTO_SLOPE * AUTO_SLOPE) * z * z {
            MicrofacetSampling::HalfVector
        } else {
            MicrofacetSampling::VisibleNormals
        }
    }

    /// The density of `wi` under the chosen strategy, `p(h) / (4 wo.h)`:
    /// `D(h) cos(theta_h) / (4 wo.h)` for the half vector, and for visible
    /// normals, with `p(h) = G1(wo) (wo.h) D(h) / wo.z`, the `wo.h` cancels:
    /// `D(h) / (4 wo.z (1 + Lambda(wo)))`.
    fn density(&self, terms: &HalfTerms, wo: Vec3, wi: Vec3) -> f32 {
        if terms.cos_h <= 0.0 {
            return 0.0;
        }
        let p = match self.strategy(wo) {
            MicrofacetSampling::HalfVector => {
                terms.d * f64::from(terms.h.z) / (4.0 * f64::from(terms.cos_h))
            }
            MicrofacetSampling::VisibleNormals | MicrofacetSampling::Auto => {
                terms.d / (4.0 * f64::from(wo.z) * (1.0 + terms.lambda_o))
            }
            MicrofacetSampling::CosineHemisphere => return cosine_hemisphere_pdf(wi),
        };
        if p.is_finite() {
            p as f32
        } else {
            0.0
        }
    }

    /// `F G D / (4 cos_o cos_i)` when both directions are above the surface.
    pub fn f(&self, wo: Vec3, wi: Vec3) -> Rgb {
        self.half_terms(wo, wi)
            .map_or(Rgb::ZERO, |terms| self.value(&terms, wo, wi))
    }

    /// Density per steradian with which [`Conductor::sample`] returns `wi`.
    pub fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        self.half_terms(wo, wi)
            .map_or(0.0, |terms| self.density(&terms, wo, wi))
    }

    /// `f(wo, wi)` and `pdf(wo, wi)` at once: one half vector, one `D` and
    /// one `Lambda(wo)` for both.
    pub fn eval(&self, wo: Vec3, wi: Vec3) -> (Rgb, f32) {
        self.half_terms(wo, wi).map_or((Rgb::ZERO, 0.0), |terms| {
            (self.value(&terms, wo, wi), self.density(&terms, wo, wi))
        })
    }

    /// Draws `h` by the chosen strategy and reflects `wo` about it; `None`
    /// when the reflection leaves below the surface.
    pub fn sample(&self, wo: Vec3, u: Vec2) -> Option<BsdfSample> {
        if wo.z <= 0.0 {
            return None;
        }
        let h = match self.strategy(wo) {
            MicrofacetSampling::HalfVector => self.distribution.sample_h(u),
            MicrofacetSampling::VisibleNormals | MicrofacetSampling::Auto => {
                self.distribution.sample_visible(wo, u)
            }
            MicrofacetSampling::CosineHemisphere => {
                return self.sample_cosine(wo, u);
            }
        };
        let cos_oh = wo.dot(h);
        if cos_oh <= 0.0 {
            return None;
        }
        let wi = (2.0 * cos_oh * h - wo).normalize();
        // Density and value from (wo, wi) alike, so that the weight is
        // exactly the ratio pdf() and f() give for this pair. A `wi` below
        // the surface (or NaN) has neither, and `reflection` refuses a
        // density of 0.
        let (f, pdf) = self.eval(wo, wi);
        BsdfSample::reflection(f, wi, pdf)
    }

    /// `wi` cosine-weighted on the hemisphere, whatever the lobe.
    fn sample_cosine(&self, wo: Vec3, u: Vec2) -> Option<BsdfSample> {
        // A `wi` in the surface has a density of 0, which `reflection`
        // refuses.
        let wi = sample_cosine_hemisphere(u);
        BsdfSample::reflection(self.f(wo, wi), wi, cosine_hemisphere_pdf(wi))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Gold's `eta` and `k` at red, green and blue.
    const GOLD: (Rgb, Rgb) = (Rgb::new(0.143, 0.375, 1.442), Rgb::new(3.983, 2.386, 1.603));

    /// The starter's model differs from the physical one by its `Lambda`
    /// and by where it takes the Fresnel term: `f_starter / f_physical =
    /// F(wi.z) / F(wo.h) x (1 + Lo + Li) / (1 + Lo' + Li')`, with `D` the
    /// same; checked on gold at three pairs of directions.
    #[test]
    fn the_starters_model_swaps_lambda_and_the_fresnel_angle() {
        let (eta, k) = GOLD;
        let physical = Conductor::new(0.4, eta, k, MicrofacetSampling::HalfVector);
        let starter = physical.with_model(MicrofacetModel::Starter);
        let b = physical.distribution;
        for (wo, wi) in [
            (Vec3::new(0.3, 0.1, 0.9), Vec3::new(-0.5, 0.2, 0.8)),
            (Vec3::new(0.9, 0.0, 0.2), Vec3::new(-0.8, 0.1, 0.3)),
            (Vec3::new(0.0, 0.6, 0.7), Vec3::new(0.1, -0.7, 0.6)),
        ] {
            let (wo, wi) = (wo.normalize(), wi.normalize());
            let h = (wo + wi).normalize();
            let g = |l: f64, m: f64| 1.0 / (1.0 + l + m);
            let g_ratio = g(b.starter_lambda(wo), b.starter_lambda(wi))
                / g(f64::from(b.lambda(wo)), f64::from(b.lambda(wi)));
            let expected = fresnel::conductor(wi.z, eta, k) / fresnel::conductor(wo.dot(h), eta, k)
                * g_ratio as f32;
            let got = starter.f(wo, wi) / physical.f(wo, wi);
            assert!(
                (got - expected).abs().max_element() < 1e-4,
                "{got} vs {expected}"
            );
            // The sampler is the same: so is the density.
            assert_eq!(starter.pdf(wo, wi), physical.pdf(wo, wi));
        }
    }

    fn gold(sampling: MicrofacetSampling) -> Conductor {
        Conductor::new(0.3, GOLD.0, GOLD.1, sampling)
    }

    /// `wo` at the stretched slope `alpha tan(theta_o) = slope`, at an
    /// azimuth where `x` and `y` both count (`x^2 + y^2` made `x^2 - y^2`
    /// or `x^2 y^2` moves the slope far from the boundary).
    fn at_slope(alpha: f32, slope: f32, azimuth: f32) -> Vec3 {
        let tan = slope / alpha;
        Vec3::new(tan * azimuth.cos(), tan * azimuth.sin(), 1.0).normalize()
    }

    // The rule of `Auto` (its doc, and docs/07): the half vector below the
    // stretched slope AUTO_SLOPE = 0.1, the visible normals above, taken
    // 2 % either side of the boundary at three roughnesses whose `alpha^2`
    // is far from `2 alpha` and from 1. Fails with each arithmetic mutant of
    // the comparison, `<` made `==` or `>`, the guard `!=` made `==`, or
    // the strategy made `Default::default()` (which is `Auto`); the
    // density checks that `pdf` follows the strategy chosen.
    // (`<` made `<=` differs only where the two products are equal in f64.)
    #[test]
    fn auto_draws_the_half_vector_below_the_stretched_slope_and_visible_normals_above() {
        use MicrofacetSampling::{HalfVector, VisibleNormals};
        let slope = AUTO_SLOPE as f32;
        for alpha in [0.05, 0.3, 0.8] {
            let auto = Conductor {
                distribution: Beckmann::new(alpha),
                ..gold(MicrofacetSampling::Auto)
            };
            for azimuth in [0.4_f32, 2.2] {
                for (s, expected) in [
                    (0.0, HalfVector),
                    (0.98 * slope, HalfVector),
                    (1.02 * slope, VisibleNormals),
                    (20.0 * slope, VisibleNormals),
                ] {
                    let wo = at_slope(alpha, s, azimuth);
                    let what = format!("alpha {alpha}, slope {s}, azimuth {azimuth}");
                    assert_eq!(auto.strategy(wo), expected, "{what}");
                    let explicit = Conductor {
                        sampling: expected,
                        ..auto
                    };
                    let wi = Vec3::new(-0.2, 0.1, 0.97).normalize();
                    assert_eq!(auto.pdf(wo, wi), explicit.pdf(wo, wi), "{what}");
                }
            }
        }
    }

    #[test]
    fn an_explicit_sampling_strategy_is_kept_whatever_the_slope() {
        for sampling in [
            MicrofacetSampling::CosineHemisphere,
            MicrofacetSampling::HalfVector,
            MicrofacetSampling::VisibleNormals,
        ] {
            for slope in [0.0, 2.0] {
                let wo = at_slope(0.3, slope, 0.4);
                assert_eq!(gold(sampling).strategy(wo), sampling, "slope {slope}");
            }
        }
    }

    // A direction below (or in) the surface gets neither value nor density,
    // whichever of the two it is. Fails with `half_terms`' `||` made `&&`
    // (then one direction below is let through: `f` comes out negative and
    // the visible normals' density positive).
    #[test]
    fn a_direction_below_the_surface_has_no_value_and_no_density() {
        let above = Vec3::new(0.3, 0.1, 0.9).normalize();
        for below in [
            Vec3::new(-0.2, 0.1, -0.9).normalize(),
            Vec3::new(-0.6, 0.8, 0.0),
        ] {
            for sampling in [
                MicrofacetSampling::HalfVector,
                MicrofacetSampling::VisibleNormals,
                MicrofacetSampling::Auto,
            ] {
                let conductor = gold(sampling);
                for (wo, wi) in [(above, below), (below, above)] {
                    assert_eq!(conductor.eval(wo, wi), (Rgb::ZERO, 0.0), "{wo} {wi}");
                    assert_eq!(conductor.f(wo, wi), Rgb::ZERO, "{wo} {wi}");
                    assert_eq!(conductor.pdf(wo, wi), 0.0, "{wo} {wi}");
                }
            }
        }
    }

    // Every strategy's sample is the pair its `f` and `pdf` describe, above
    // the surface, and most draws are kept. Fails with `sample_cosine`
    // made `None` (the cosine baseline keeps nothing), or with a sample
    // weighed by another pair than the one it returns.
    #[test]
    fn each_strategy_samples_what_its_f_and_pdf_describe() {
        let wo = Vec3::new(0.4, -0.2, 0.9).normalize();
        for sampling in [
            MicrofacetSampling::CosineHemisphere,
            MicrofacetSampling::HalfVector,
            MicrofacetSampling::VisibleNormals,
            MicrofacetSampling::Auto,
        ] {
            let conductor = gold(sampling);
            let mut kept = 0;
            for i in 0..16 {
                for j in 0..16 {
                    let u = Vec2::new((i as f32 + 0.5) / 16.0, (j as f32 + 0.5) / 16.0);
                    let Some(sample) = conductor.sample(wo, u) else {
                        continue;
                    };
                    kept += 1;
                    let wi = sample.wi;
                    assert!(wi.z > 0.0 && !sample.transmission, "{sampling:?} {wi}");
                    assert_eq!(sample.f, conductor.f(wo, wi), "{sampling:?} {wi}");
                    assert_eq!(sample.pdf(), conductor.pdf(wo, wi), "{sampling:?} {wi}");
                }
            }
            assert!(kept >= 200, "{sampling:?} kept {kept} of 256 draws");
        }
    }
}
