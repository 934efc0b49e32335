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
use super::{fresnel, BsdfSample, Density, EtaScaling, FresnelModel};
use crate::math::Rgb;

/// Fresnel-weighted specular reflection and refraction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Glass {
    pub reflectance: Rgb,
    pub transmittance: Rgb,
    /// Index of the far side over the near side.
    pub eta: f32,
    pub fresnel: FresnelModel,
    /// `1 / eta^2` on transmitted radiance, or the starter's `eta^2`.
    pub eta_scaling: EtaScaling,
}

impl Glass {
    /// The Fresnel reflectance for `wo`.
    pub fn fresnel(&self, wo: Vec3) -> f32 {
        match self.fresnel {
            FresnelModel::Exact => fresnel::dielectric(wo.z, self.eta),
            FresnelModel::Schlick => fresnel::schlick(wo.z, self.eta),
        }
    }

    /// Both lobes at once, each taken for sure (density 1), so that each
    /// one's weight is its share: `R F` and `T (1 - F) / eta^2`. `None`
    /// where light from `wo` does not both reflect and refract: from
    /// below, or under total internal reflection.
    pub fn both_lobes(&self, wo: Vec3) -> Option<[BsdfSample; 2]> {
        if wo.z <= 0.0 {
            return None;
        }
        let refracted = refract(wo, self.eta)?;
        let f = self.fresnel(wo);
        Some([
            self.reflection(wo, f, 1.0),
            self.refraction(refracted, f, 1.0),
        ])
    }

    /// Reflection with probability `F`, else refraction, chosen by `uc`.
    pub fn sample(&self, wo: Vec3, uc: f32) -> Option<BsdfSample> {
        if wo.z <= 0.0 {
            return None;
        }
        let f = self.fresnel(wo);
        Some(match refract(wo, self.eta) {
            Some(wi) if uc >= f => self.refraction(wi, f, 1.0 - f),
            _ => self.reflection(wo, f, f),
        })
    }

    /// The reflected lobe for `wo` and Fresnel reflectance `f`, taken with
    /// probability `p`.
    fn reflection(&self, wo: Vec3, f: f32, p: f32) -> BsdfSample {
        let wi = reflect(wo);
        BsdfSample {
            f: self.reflectance * f / wi.z,
            wi,
            density: Density::Delta(p),
            transmission: false,
            eta: 1.0,
        }
    }

    /// The refracted lobe along `wi` for Fresnel reflectance `f`, taken
    /// with probability `p`.
    fn refraction(&self, wi: Vec3, f: f32, p: f32) -> BsdfSample {
        BsdfSample {
            f: self.transmittance * (1.0 - f) * self.eta_scaling.factor(self.eta) / wi.z.abs(),
            wi,
            density: Density::Delta(p),
            transmission: true,
            eta: self.eta,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn glass(eta: f32, fresnel: FresnelModel) -> Glass {
        Glass {
            eta_scaling: EtaScaling::Physical,
            reflectance: Rgb::ONE,
            transmittance: Rgb::ONE,
            eta,
            fresnel,
        }
    }

    #[test]
    fn reflection_and_transmission_split_the_light_by_fresnel() {
        for fresnel in [FresnelModel::Exact, FresnelModel::Schlick] {
            for eta in [1.5f32, 1.0 / 1.5, 1.0] {
                for cos in [1.0f32, 0.7, 0.3, 0.05] {
                    let wo = Vec3::new((1.0 - cos * cos).sqrt(), 0.0, cos);
                    let g = glass(eta, fresnel);
                    let f = g.fresnel(wo);
                    // R + T = 1: the two lobes' probabilities.
                    let n = 1000;
                    let (mut reflected, mut p_sum) = (0, 0.0);
                    let mut seen = [false, false];
                    for i in 0..n {
                        let s = g.sample(wo, (i as f32 + 0.5) / n as f32).unwrap();
                        let crossing = s.transmission as usize;
                        if !seen[crossing] {
                            seen[crossing] = true;
                            p_sum += s.pdf();
                        }
                        let expected = if s.transmission {
                            Rgb::splat(1.0 / (eta * eta))
                        } else {
                            Rgb::ONE
                        };
                        assert!((s.weight() - expected).abs().max_element() < 1e-5);
                        assert!(s.is_delta() && (s.wi.length() - 1.0).abs() < 1e-5);
                        reflected += (!s.transmission) as u32;
                    }
                    assert!((reflected as f32 / n as f32 - f).abs() <= 1.0 / n as f32);
                    if seen[0] && seen[1] {
                        assert!((p_sum - 1.0).abs() < 1e-6, "{eta} {cos}: {p_sum}");
                    }
                }
            }
        }
    }

    /// Each lobe of `both_lobes` weighs what the coin's sample of it
    /// weighs times the coin's probability of it, so that following both
    /// is the coin's expectation; and the two go where the coin's go.
    #[test]
    fn both_lobes_are_the_coins_lobes_times_their_probabilities() {
        let models = [FresnelModel::Exact, FresnelModel::Schlick]
            .into_iter()
            .flat_map(|f| [EtaScaling::Physical, EtaScaling::Starter].map(|e| (f, e)));
        for (fresnel, eta_scaling) in models {
            for eta in [1.5f32, 1.0 / 1.5] {
                for cos in [1.0f32, 0.7, 0.3, 0.05] {
                    let wo = Vec3::new((1.0 - cos * cos).sqrt(), 0.0, cos);
                    let g = Glass {
                        reflectance: Rgb::new(0.9, 0.8, 0.7),
                        transmittance: Rgb::new(0.6, 0.5, 0.4),
                        eta_scaling,
                        ..glass(eta, fresnel)
                    };
                    let Some(both) = g.both_lobes(wo) else {
                        assert!(eta < 1.0 && cos < 0.75, "{eta} {cos}");
                        continue;
                    };
                    let f = g.fresnel(wo);
                    let coin = [g.sample(wo, 0.0), g.sample(wo, 0.999_999)];
                    for (lobe, coin) in both.iter().zip(coin) {
                        let coin = coin.unwrap();
                        assert_eq!(lobe.transmission, coin.transmission);
                        assert!((lobe.wi - coin.wi).length() < 1e-6);
                        assert!(lobe.is_delta() && lobe.pdf() == 1.0);
                        let expected = coin.weight() * coin.pdf();
                        assert!(
                            (lobe.weight() - expected).abs().max_element() < 1e-5,
                            "{eta} {cos}: {} against {expected}",
                            lobe.weight()
                        );
                    }
                    let reflected = both[0].weight();
                    assert!((reflected - g.reflectance * f).abs().max_element() < 1e-5);
                }
            }
        }
        // Index 1: no reflection, all of the light goes straight on.
        let wo = Vec3::new(0.6, 0.0, 0.8);
        let [reflected, refracted] = glass(1.0, FresnelModel::Exact).both_lobes(wo).unwrap();
        assert_eq!(reflected.weight(), Rgb::ZERO);
        assert!((refracted.weight() - Rgb::ONE).abs().max_element() < 1e-6);
        let inside = glass(1.0 / 1.5, FresnelModel::Exact);
        assert!(inside
            .both_lobes(Vec3::new(0.9, 0.0, 0.19f32.sqrt()))
            .is_none());
        assert!(inside.both_lobes(Vec3::new(0.0, 0.0, -1.0)).is_none());
    }

    #[test]
    fn total_internal_reflection_always_reflects() {
        let g = glass(1.0 / 1.5, FresnelModel::Exact);
        let wo = Vec3::new(0.9, 0.0, 0.19f32.sqrt());
        for uc in [0.0, 0.5, 0.999] {
            let s = g.sample(wo, uc).unwrap();
            assert!(!s.transmission && s.pdf() == 1.0 && s.wi.z > 0.0);
        }
        let index_one = glass(1.0, FresnelModel::Exact).sample(wo, 0.3).unwrap();
        assert!(index_one.transmission && (index_one.wi + wo).length() < 1e-6);
    }
}
