//! Perfect specular transmission only (the course's `RefractionBSDF`): all
//! light crosses the interface in the direction of Snell's law, scaled by
//! the transmittance `T` and by `1 / eta^2`, the change of radiance across
//! the boundary (see [`super::glass`]):
//!
//! ```text
//! f(wo, wi) = T / eta^2 delta(wi - refract(wo)) / |cos theta_i|
//! ```
//!
//! No Fresnel reflection, so the material is not physical; it shows
//! refraction alone. Under total internal reflection no direction
//! transmits, and the light reflects instead, scaled by `T` (the course's
//! code returns black there, losing that light).

use glam::Vec3;

use super::specular::{reflect, refract};
use super::EtaScaling;
use super::{BsdfSample, Density};
use crate::math::Rgb;

/// Specular transmission by Snell's law.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Refraction {
    pub transmittance: Rgb,
    /// Index of the far side over the near side.
    pub eta: f32,
    /// `1 / eta^2` on transmitted radiance, or the starter's `eta^2`.
    pub eta_scaling: EtaScaling,
}

impl Refraction {
    /// The refracted direction, or the mirror direction under total
    /// internal reflection.
    pub fn sample(&self, wo: Vec3) -> Option<BsdfSample> {
        if wo.z <= 0.0 {
            return None;
        }
        Some(match refract(wo, self.eta) {
            Some(wi) => BsdfSample {
                f: self.transmittance * self.eta_scaling.factor(self.eta) / wi.z.abs(),
                wi,
                density: Density::Delta(1.0),
                transmission: true,
                eta: self.eta,
            },
            None => {
                let wi = reflect(wo);
                BsdfSample {
                    f: self.transmittance / wi.z,
                    wi,
                    density: Density::Delta(1.0),
                    transmission: false,
                    eta: 1.0,
                }
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::super::EtaScaling;
    use super::*;

    /// The starter's convention multiplies transmitted radiance by `eta^2`
    /// where the physical one divides by it; both directions.
    #[test]
    fn the_starters_eta_scaling_is_the_reciprocal() {
        let steep = Vec3::new(0.3, 0.0, 0.91f32.sqrt());
        for eta in [1.5f32, 1.0 / 1.5] {
            let weight = |eta_scaling| {
                let r = Refraction {
                    eta_scaling,
                    transmittance: Rgb::splat(0.8),
                    eta,
                };
                r.sample(steep).unwrap().weight().x
            };
            assert!((weight(EtaScaling::Physical) - 0.8 / (eta * eta)).abs() < 1e-5);
            assert!((weight(EtaScaling::Starter) - 0.8 * eta * eta).abs() < 1e-5);
        }
    }

    #[test]
    fn refracts_or_under_total_internal_reflection_reflects() {
        let r = Refraction {
            eta_scaling: EtaScaling::Physical,
            transmittance: Rgb::splat(0.9),
            eta: 1.0 / 1.5,
        };
        let steep = Vec3::new(0.3, 0.0, 0.91f32.sqrt());
        let s = r.sample(steep).unwrap();
        assert!(s.transmission && s.wi.z < 0.0);
        assert!(
            (s.weight() - Rgb::splat(0.9 * 1.5 * 1.5))
                .abs()
                .max_element()
                < 1e-5
        );
        let grazing = Vec3::new(0.9, 0.0, 0.19f32.sqrt());
        let s = r.sample(grazing).unwrap();
        assert!(!s.transmission && s.wi.z > 0.0);
        assert!((s.weight() - Rgb::splat(0.9)).abs().max_element() < 1e-5);
    }
}
