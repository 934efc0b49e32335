//! Lights at a point: the point light and the spot light.
//!
//! A point light of intensity `I` (W/sr) at `x` lights `p` from the single
//! direction `wi = (x - p) / r`, a delta distribution: the estimator takes
//! `f I / r^2 cos` without dividing by a density. Power `Phi = 4 pi I`.
//! (The course's starter omits the `1 / r^2`; [`LightConvention::Course`]
//! reproduces that.)
//!
//! A spot light is parsed from the course's files but, as in the course,
//! lights nothing.

use glam::Vec3;

use super::{LightConvention, LightPdf, LightSample};
use crate::math::Rgb;

/// An isotropic point light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointLight {
    /// Radiant intensity, W/sr per channel.
    pub intensity: Rgb,
    pub position: Vec3,
    pub convention: LightConvention,
}

impl PointLight {
    /// The one direction from `p` to the light.
    #[doc(alias = "sample_L")]
    pub fn sample_li(&self, p: Vec3) -> Option<LightSample> {
        let to_light = self.position - p;
        let distance_squared = to_light.length_squared();
        if distance_squared.is_nan() || distance_squared <= 0.0 {
            return None;
        }
        let distance = distance_squared.sqrt();
        Some(LightSample {
            radiance: self.intensity / distance_squared * self.convention.point_factor(distance),
            wi: to_light / distance,
            distance,
            pdf: LightPdf::Delta,
        })
    }

    /// Radiant power, `4 pi I`.
    pub fn power(&self) -> Rgb {
        4.0 * std::f32::consts::PI * self.intensity
    }
}

/// A spot light: kept so that `--info` can list it; it lights nothing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpotLight {
    pub intensity: Rgb,
    pub position: Vec3,
    pub direction: Vec3,
}
