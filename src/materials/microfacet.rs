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

use glam::{Vec2, Vec3};

use super::beckmann::Beckmann;
use super::{fresnel, BsdfSample, MicrofacetSampling};
use crate::math::warp::{cosine_hemisphere_pdf, sample_cosine_hemisphere};
use crate::math::Rgb;

/// A rough metal with Beckmann roughness and complex index `eta + i k`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Conductor {
    pub distribution: Beckmann,
    /// Real part of the index of refraction, per channel.
    pub eta: Rgb,
    /// Extinction coefficient, per channel.
    pub k: Rgb,
    pub sampling: MicrofacetSampling,
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
        }
    }

    /// `F G D / (4 cos_o cos_i)` when both directions are above the surface.
    pub fn f(&self, wo: Vec3, wi: Vec3) -> Rgb {
        if wo.z <= 0.0 || wi.z <= 0.0 {
            return Rgb::ZERO;
        }
        let Some((h, cos_h)) = half_vector(wo, wi) else {
            return Rgb::ZERO;
        };
        let b = &self.distribution;
        let scalar =
            f64::from(b.g(wo, wi)) * f64::from(b.d(h)) / (4.0 * f64::from(wo.z) * f64::from(wi.z));
        if !scalar.is_finite() {
            return Rgb::ZERO;
        }
        fresnel::conductor(cos_h, self.eta, self.k) * scalar as f32
    }

    /// Density per steradian of the half vector `h` (with `wo.h = cos_h`)
    /// under the chosen strategy.
    /// Not called for `CosineHemisphere`, which samples no half vector.
    fn pdf_h(&self, wo: Vec3, h: Vec3, cos_h: f32) -> f32 {
        match self.sampling {
            MicrofacetSampling::HalfVector => self.distribution.pdf_h(h),
            MicrofacetSampling::VisibleNormals => self.distribution.visible_density(wo, h, cos_h),
            MicrofacetSampling::CosineHemisphere => 0.0,
        }
    }

    /// Density per steradian with which [`Conductor::sample`] returns `wi`.
    pub fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        if wo.z <= 0.0 || wi.z <= 0.0 {
            return 0.0;
        }
        if self.sampling == MicrofacetSampling::CosineHemisphere {
            return cosine_hemisphere_pdf(wi);
        }
        let Some((h, cos_oh)) = half_vector(wo, wi) else {
            return 0.0;
        };
        if cos_oh <= 0.0 {
            return 0.0;
        }
        let p = f64::from(self.pdf_h(wo, h, cos_oh)) / (4.0 * f64::from(cos_oh));
        if p.is_finite() {
            p as f32
        } else {
            0.0
        }
    }

    /// Draws `h` by the chosen strategy and reflects `wo` about it; `None`
    /// when the reflection leaves below the surface.
    pub fn sample(&self, wo: Vec3, u: Vec2) -> Option<BsdfSample> {
        if wo.z <= 0.0 {
            return None;
        }
        let h = match self.sampling {
            MicrofacetSampling::HalfVector => self.distribution.sample_h(u),
            MicrofacetSampling::VisibleNormals => self.distribution.sample_visible(wo, u),
            MicrofacetSampling::CosineHemisphere => {
                return self.sample_cosine(wo, u);
            }
        };
        let cos_oh = wo.dot(h);
        if cos_oh <= 0.0 {
            return None;
        }
        let wi = (2.0 * cos_oh * h - wo).normalize();
        if wi.z <= 0.0 || !wi.is_finite() {
            return None;
        }
        // Density and value from (wo, wi) alike, so that the weight is
        // exactly the ratio pdf() and f() give for this pair.
        let pdf = self.pdf(wo, wi);
        BsdfSample::reflection(self.f(wo, wi), wi, pdf)
    }

    /// `wi` cosine-weighted on the hemisphere, whatever the lobe.
    fn sample_cosine(&self, wo: Vec3, u: Vec2) -> Option<BsdfSample> {
        let wi = sample_cosine_hemisphere(u);
        let pdf = cosine_hemisphere_pdf(wi);
        if wi.z <= 0.0 {
            return None;
        }
        BsdfSample::reflection(self.f(wo, wi), wi, pdf)
    }
}
