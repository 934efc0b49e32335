//! Lights at infinity: the directional light and the ambient sky.
//!
//! - Directional light: radiance `L` from the single direction `d`, a delta
//!   distribution; power `Phi = pi R^2 L` through a scene of radius `R`.
//! - Ambient sky (the course's `<ambient>` light): radiance `L` from every
//!   direction of the hemisphere around +Y, 0 below it. Sampled uniformly
//!   on that hemisphere, `p_w = 1 / (2 pi)`; a ray that escapes upwards
//!   sees `L`. Power `Phi = 2 pi^2 R^2 L` (the irradiance `pi L` of a
//!   horizontal disk, over the `2 pi` of directions a sphere of radius
//!   `R` is crossed from, as pbrt-v4 counts its uniform infinite light).

use glam::{Vec2, Vec3};

use super::{LightPdf, LightSample};
use crate::math::warp::{sample_uniform_hemisphere, uniform_hemisphere_pdf};
use crate::math::{Frame, Rgb};

use std::f32::consts::PI;

/// Light from one direction, infinitely far away.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DirectionalLight {
    pub radiance: Rgb,
    /// Unit vector towards the light.
    pub direction: Vec3,
}

impl DirectionalLight {
    pub fn sample_li(&self) -> LightSample {
        LightSample {
            radiance: self.radiance,
            wi: self.direction,
            distance: f32::INFINITY,
            pdf: LightPdf::Delta,
        }
    }

    pub fn power(&self, scene_radius: f32) -> Rgb {
        PI * scene_radius * scene_radius * self.radiance
    }
}

/// A uniform sky over the hemisphere around +Y.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AmbientSky {
    pub radiance: Rgb,
}

impl AmbientSky {
    /// The frame of the sky's hemisphere: its pole is +Y.
    fn frame() -> Frame {
        Frame::from_z(Vec3::Y)
    }

    /// Whether the sky shines from the unit direction `w`.
    pub fn covers(w: Vec3) -> bool {
        w.y > 0.0
    }

    /// A direction uniform on the sky's hemisphere.
    pub fn sample_li(&self, u: Vec2) -> Option<LightSample> {
        let local = sample_uniform_hemisphere(u);
        let wi = Self::frame().to_world(local);
        Self::covers(wi).then(|| LightSample {
            radiance: self.radiance,
            wi,
            distance: f32::INFINITY,
            pdf: LightPdf::SolidAngle(uniform_hemisphere_pdf(local)),
        })
    }

    /// Density of [`Self::sample_li`] choosing `wi`.
    pub fn pdf_li(&self, wi: Vec3) -> f32 {
        if Self::covers(wi) {
            uniform_hemisphere_pdf(Vec3::Z)
        } else {
            0.0
        }
    }

    /// Radiance seen along a ray that escapes in the unit direction `w`.
    pub fn escaped_radiance(&self, w: Vec3) -> Rgb {
        if Self::covers(w) {
            self.radiance
        } else {
            Rgb::ZERO
        }
    }

    pub fn power(&self, scene_radius: f32) -> Rgb {
        2.0 * PI * PI * scene_radius * scene_radius * self.radiance
    }
}
