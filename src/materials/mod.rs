//! BSDFs in the local shading frame (normal on +Z, `cos_theta(w) = w.z`).
//!
//! So far the diffuse BSDF of parts 3 and 4; mirror, glass and microfacet
//! (assignment 3-2) come later and render as diffuse with a warning until
//! then ([`Bsdf::for_material`]).

pub mod diffuse;

pub use diffuse::Diffuse;

use glam::{Vec2, Vec3};

use crate::math::Rgb;
use crate::scene::Material;

/// A sampled direction of a BSDF: the value `f(wo, wi)`, the direction and
/// its density per steradian.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BsdfSample {
    pub f: Rgb,
    pub wi: Vec3,
    pub pdf: f32,
}

/// The BSDF of a surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Bsdf {
    Diffuse(Diffuse),
}

impl Bsdf {
    /// The BSDF of `material`, and whether it is a stand-in: materials of
    /// later parts (mirror, glass, refraction, microfacet) render as
    /// diffuse of their main colour until those parts exist. Emission
    /// reflects nothing.
    pub fn for_material(material: &Material) -> (Bsdf, bool) {
        let diffuse = |albedo| Bsdf::Diffuse(Diffuse { albedo });
        match *material {
            Material::Diffuse { albedo } | Material::EmissiveDiffuse { albedo, .. } => {
                (diffuse(albedo), false)
            }
            Material::Emission { .. } => (diffuse(Rgb::ZERO), false),
            Material::Mirror { reflectance } => (diffuse(reflectance), true),
            Material::Glass { transmittance, .. } | Material::Refraction { transmittance, .. } => {
                (diffuse(transmittance), true)
            }
            Material::Microfacet { .. } => (diffuse(Rgb::splat(0.5)), true),
        }
    }

    /// `f(wo, wi)`, both in the local frame.
    pub fn f(&self, wo: Vec3, wi: Vec3) -> Rgb {
        match self {
            Bsdf::Diffuse(d) => d.f(wo, wi),
        }
    }

    /// Samples `wi` given `wo` from `u` in `[0, 1)^2`.
    #[doc(alias = "sample_f")]
    pub fn sample(&self, wo: Vec3, u: Vec2) -> Option<BsdfSample> {
        match self {
            Bsdf::Diffuse(d) => d.sample(wo, u),
        }
    }

    /// Density of [`Bsdf::sample`] choosing `wi`, per steradian.
    pub fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        match self {
            Bsdf::Diffuse(d) => d.pdf(wo, wi),
        }
    }
}
