//! Which lights direct lighting samples at a point: every light, or one
//! light per sample chosen in proportion to its power (pbrt-v4's
//! `PowerLightSampler`, section 12.6.2).
//!
//! - **Every light** (the course's `estimate_direct_lighting_importance`):
//!   each light gets its own `N_l` samples (`-l`, or 1 for a delta light),
//!
//!   ```text
//!   L = sum over lights l of 1/N_l sum_j f L_l |cos| / p_l(w_j)
//!   ```
//!
//!   The cost per vertex grows with the number of lights.
//! - **By power**: `N` samples (`-l`) in all; each first picks light `l`
//!   with probability `P(l) = Phi_l / sum Phi` (luminance of the power),
//!   then a direction from it:
//!
//!   ```text
//!   L = 1/N sum_j f L_l |cos| / (P(l_j) p_l(w_j))
//!   ```
//!
//!   unbiased for every light of positive power (a light of zero power,
//!   such as the course's spot light, contributes nothing either way).
//!   The cost per vertex no longer depends on how many lights there are,
//!   and bright lights get the samples.
//!
//! With multiple importance sampling the light strategy's density of a
//! direction is `N_l p_l(w)` for every light, `N P(l) p_l(w)` by power
//! ([`LightChoice::strategy`]).
//!
//! [`LightChoiceRule::Auto`] samples every light when there are at most
//! [`MANY_LIGHTS`] (stratified over the lights, as the course does, which
//! is better for a few) and by power beyond.

use super::Light;
use crate::math::distribution::Distribution1D;
use crate::math::luminance;

/// Up to this many lights, [`LightChoiceRule::Auto`] samples every light.
pub const MANY_LIGHTS: usize = 8;

/// How the lights to sample are chosen, as asked for (`--light-choice`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LightChoiceRule {
    /// Every light up to [`MANY_LIGHTS`] lights, by power beyond.
    #[default]
    Auto,
    /// Every light, `-l` samples each (the course's).
    EveryLight,
    /// `-l` samples in all, each of one light chosen by power.
    ByPower,
}

/// How the lights to sample are chosen, as decided for a light set.
#[derive(Clone, Debug, Default, PartialEq)]
pub enum LightChoice {
    /// Every light, with its own samples.
    #[default]
    EveryLight,
    /// One light per sample, light `i` with probability
    /// `pmf.cell_probability(i)`.
    ByPower(Distribution1D),
}

/// How a light's samples enter the estimate: how many samples the light
/// strategy takes, and the probability that one of them is of this light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightStrategy {
    pub samples: u32,
    pub probability: f32,
}

impl LightChoice {
    /// The choice `rule` makes for `lights` in a scene of radius `scene_radius`.
    pub fn new(rule: LightChoiceRule, lights: &[Light], scene_radius: f32) -> Self {
        let power: Vec<f32> = lights
            .iter()
            .map(|l| luminance(l.power(scene_radius)))
            .collect();
        let by_power = match rule {
            // Lights of no power are never sampled, so they do not count.
            LightChoiceRule::Auto => power.iter().filter(|&&p| p > 0.0).count() > MANY_LIGHTS,
            LightChoiceRule::EveryLight => false,
            LightChoiceRule::ByPower => true,
        };
        if !by_power || lights.is_empty() {
            return LightChoice::EveryLight;
        }
        LightChoice::ByPower(Distribution1D::new(&power))
    }

    /// The strategy of light `index` (`light`) when direct lighting takes
    /// `samples_per_light` (`-l`) samples.
    pub fn strategy(&self, index: usize, light: &Light, samples_per_light: u32) -> LightStrategy {
        let n = samples_per_light.max(1);
        match self {
            LightChoice::EveryLight => LightStrategy {
                samples: if light.is_delta() { 1 } else { n },
                probability: 1.0,
            },
            LightChoice::ByPower(pmf) => LightStrategy {
                samples: n,
                probability: pmf.cell_probability(index),
            },
        }
    }

    /// A name for `--info`.
    pub fn describe(&self) -> &'static str {
        match self {
            LightChoice::EveryLight => "every light, -l samples each (1 for a delta light)",
            LightChoice::ByPower(_) => "-l samples in all, each of one light chosen by power",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lights::{LightConvention, PointLight};
    use crate::math::Rgb;
    use glam::Vec3;

    fn point(intensity: f32) -> Light {
        Light::Point(PointLight {
            intensity: Rgb::splat(intensity),
            position: Vec3::ZERO,
            convention: LightConvention::Physical,
        })
    }

    #[test]
    fn auto_samples_every_light_up_to_many_lights() {
        let few: Vec<Light> = (0..MANY_LIGHTS).map(|_| point(1.0)).collect();
        let many: Vec<Light> = (0..=MANY_LIGHTS).map(|_| point(1.0)).collect();
        assert_eq!(
            LightChoice::new(LightChoiceRule::Auto, &few, 1.0),
            LightChoice::EveryLight
        );
        assert!(matches!(
            LightChoice::new(LightChoiceRule::Auto, &many, 1.0),
            LightChoice::ByPower(_)
        ));
    }

    #[test]
    fn by_power_chooses_in_proportion_to_power() {
        let lights = [point(1.0), point(3.0), point(0.0)];
        let choice = LightChoice::new(LightChoiceRule::ByPower, &lights, 1.0);
        let p: Vec<f32> = (0..3)
            .map(|i| choice.strategy(i, &lights[i], 4).probability)
            .collect();
        assert!((p[0] - 0.25).abs() < 1e-6 && (p[1] - 0.75).abs() < 1e-6 && p[2] == 0.0);
        assert_eq!(choice.strategy(1, &lights[1], 4).samples, 4);
        let every = LightChoice::EveryLight.strategy(1, &lights[1], 4);
        assert_eq!((every.samples, every.probability), (1, 1.0));
    }
}
