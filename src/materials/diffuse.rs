//! The Lambertian (diffuse) BSDF: `f = albedo / pi` on the upper hemisphere.
//!
//! Sampling is cosine-weighted, `p(wi) = cos(theta_i) / pi`, so the
//! estimator `f cos / p` of one bounce is the constant `albedo`: the
//! cosine and the `1/pi` cancel, leaving no variance from the BSDF.

use glam::{Vec2, Vec3};

use super::BsdfSample;
use crate::math::warp::{cosine_hemisphere_pdf, sample_cosine_hemisphere};
use crate::math::Rgb;

/// Lambertian reflection with reflectance `albedo` (each channel in [0, 1]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Diffuse {
    pub albedo: Rgb,
}

impl Diffuse {
    /// `albedo / pi` when both directions are above the surface, else 0.
    pub fn f(&self, wo: Vec3, wi: Vec3) -> Rgb {
        if wo.z > 0.0 && wi.z > 0.0 {
            self.albedo / std::f32::consts::PI
        } else {
            Rgb::ZERO
        }
    }

    /// A cosine-weighted direction on the side of `wo`.
    pub fn sample(&self, wo: Vec3, u: Vec2) -> Option<BsdfSample> {
        if wo.z <= 0.0 {
            return None;
        }
        let wi = sample_cosine_hemisphere(u);
        let pdf = cosine_hemisphere_pdf(wi);
        BsdfSample::reflection(self.f(wo, wi), wi, pdf)
    }

    pub fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        if wo.z > 0.0 {
            cosine_hemisphere_pdf(wi)
        } else {
            0.0
        }
    }
}
