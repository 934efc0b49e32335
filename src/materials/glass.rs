//! Smooth glass: a dielectric interface that reflects the Fresnel fraction
//! `F` of the light and transmits the rest (the course's `GlassBSDF`).
//!
//! With `eta` the relative index of refraction of the far side over the
//! near side (the glass's `ior` entering it, `1 / ior` leaving it),
//! reflectance `R` and transmittance `T`:
//!
//! ```text
//! f(wo, wi) = R F delta(wi - reflect(wo)) / |cos theta_i|
//!           + T (1 - F) / eta^2 delta(wi - refract(wo)) / |cos theta_i|
//! ```
//!
//! The `1 / eta^2` is the change of radiance across the boundary: a beam
//! squeezed into the smaller solid angle of a denser medium grows brighter
//! by `eta^2` (Veach 1997, section 5.2). Both lobes are deltas; sampling
//! picks reflection with probability `F` (the 1D number `uc`), so each
//! sample's weight `f |cos| / pdf` is `R` or `T / eta^2`. Under total
//! internal reflection `F = 1`. `F` is exact ([`fresnel::dielectric`]) or the
//! course's Schlick approximation ([`fresnel::schlick`]), see [`FresnelModel`].

use glam::Vec3;

use super::specular::{reflect, refract};
use super::{fresnel, BsdfSample, Density, FresnelModel};
use crate::math::Rgb;

/// Fresnel-weighted specular reflection and refraction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Glass {
    pub reflectance: Rgb,
    pub transmittance: Rgb,
    /// Index of the far side over the near side.
    pub eta: f32,
    pub fresnel: FresnelModel,
}

impl Glass {
    /// The Fresnel reflectance for `wo`.
    pub fn fresnel(&self, wo: Vec3) -> f32 {
        match self.fresnel {
            FresnelModel::Exact => fresnel::dielectric(wo.z, self.eta),
            FresnelModel::Schlick => fresnel::schlick(wo.z, self.eta),
        }
    }

    /// Reflection with probability `F`, else refraction, chosen by `uc`.
    pub fn sample(&self, wo: Vec3, uc: f32) -> Option<BsdfSample> {
        if wo.z <= 0.0 {
            return None;
        }
        let f = self.fresnel(wo);
        let refracted = refract(wo, self.eta);
        match refracted {
            Some(wi) if uc >= f => Some(BsdfSample {
                f: self.transmittance * (1.0 - f) / (self.eta * self.eta * wi.z.abs()),
                wi,
                density: Density::Delta(1.0 - f),
                transmission: true,
                eta: self.eta,
            }),
            _ => {
                let wi = reflect(wo);
                Some(BsdfSample {
                    f: self.reflectance * f / wi.z,
                    wi,
                    density: Density::Delta(f),
                    transmission: false,
                    eta: 1.0,
                })
            }
        }
    }
}
