//! A perfect mirror: all light leaves in the mirror direction, scaled by
//! the reflectance `R` (the course's `MirrorBSDF`).
//!
//! ```text
//! f(wo, wi) = R delta(wi - reflect(wo)) / |cos theta_i|
//! ```
//!
//! A delta lobe: `f` and `pdf` of any given direction are 0, and a sample
//! is the mirror direction with probability 1 and weight `f |cos| / 1 = R`.

use glam::Vec3;

use super::specular::reflect;
use super::{BsdfSample, Density};
use crate::math::Rgb;

/// Perfect specular reflection scaled by `reflectance`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mirror {
    pub reflectance: Rgb,
}

impl Mirror {
    /// The mirror direction of `wo`.
    pub fn sample(&self, wo: Vec3) -> Option<BsdfSample> {
        if wo.z <= 0.0 {
            return None;
        }
        let wi = reflect(wo);
        Some(BsdfSample {
            f: self.reflectance / wi.z,
            wi,
            density: Density::Delta(1.0),
            transmission: false,
            eta: 1.0,
        })
    }
}
