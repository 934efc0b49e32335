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
mod tests;
