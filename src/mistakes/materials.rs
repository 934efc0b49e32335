//! The starter's `MirrorBSDF`, `RefractionBSDF` and `GlassBSDF::sample_f`
//! as a student writes them with the catalogue's mistakes of part 6:
//! called by [`crate::course::StarterTracer`] only when one is chosen.
//! The rough metal's three ([`MICROFACET_MISTAKES`]) are a factor each, on
//! `f` ([`microfacet_f_factor`]) or on the sample's pdf
//! ([`microfacet_density`]).
//!
//! The right ones are [`crate::materials::Mirror`], [`Refraction`] and
//! [`Glass`]; these follow them step by step, with the mistaken step where
//! a mistake is chosen.

use glam::Vec3;

use super::{Mistake, Mistakes};
use crate::materials::specular::{reflect, refract};
use crate::materials::{fresnel, Bsdf, BsdfSample, Density, FresnelModel, Glass, Refraction};
use crate::math::Rgb;

/// Part 6's mistakes of mirror and glass.
pub const MATERIAL_MISTAKES: [Mistake; 5] = [
    Mistake::ReflectWrongAxis,
    Mistake::RefractionRatioInverted,
    Mistake::NoEtaSquared,
    Mistake::NoTotalInternalReflection,
    Mistake::SchlickR0NotSquared,
];

/// Part 6's mistakes of the rough metal, which [`crate::course::StarterTracer`]
/// makes where it evaluates and weights a BSDF.
pub const MICROFACET_MISTAKES: [Mistake; 3] = [
    Mistake::MicrofacetNoFour,
    Mistake::MicrofacetDNoCos4,
    Mistake::MicrofacetPdfNoJacobian,
];

/// What a student's `MicrofacetBSDF::f(wo, wi)` is times the right one:
/// 4 without the 4 of `F G D / (4 cos_o cos_i)`; `cos^4(theta_h)`, with
/// `h = normalize(wo + wi)`, with `D` written without the `cos^4(theta_h)`
/// of its denominator (the student's `sample_f` draws `theta_h` from its
/// own inverted cdf and keeps its pdf, so only `f` changes).
pub fn microfacet_f_factor(wo: Vec3, wi: Vec3, mistakes: Mistakes) -> f32 {
    let mut factor = 1.0;
    if mistakes.has(Mistake::MicrofacetNoFour) {
        factor *= 4.0;
    }
    if mistakes.has(Mistake::MicrofacetDNoCos4) {
        factor *= (wo + wi).normalize_or_zero().z.powi(4);
    }
    factor
}

/// The density a student's `MicrofacetBSDF::sample_f` gives `sample`,
/// drawn from `wo`: with `microfacet-pdf-no-jacobian`, the half vector's,
/// `p(h) = 4 (wo.h) p(wi)` (for a reflection `wo.h = wi.h`); else the
/// sample's own.
pub fn microfacet_density(
    bsdf: &Bsdf,
    wo: Vec3,
    sample: &BsdfSample,
    mistakes: Mistakes,
) -> Density {
    match (bsdf, sample.density) {
        (Bsdf::Conductor(_), Density::SolidAngle(p))
            if mistakes.has(Mistake::MicrofacetPdfNoJacobian) =>
        {
            let h = (wo + sample.wi).normalize_or_zero();
            Density::SolidAngle(p * 4.0 * wo.dot(h))
        }
        (_, density) => density,
    }
}

/// The sample a student's delta BSDF draws with `mistakes`, or `None` when
/// no material mistake is chosen or `bsdf` is not a delta BSDF (the right
/// sample applies). `Some(None)`: the student's BSDF returns no light.
pub fn sample_specular(
    bsdf: &Bsdf,
    wo: Vec3,
    uc: f32,
    mistakes: Mistakes,
) -> Option<Option<BsdfSample>> {
    if !MATERIAL_MISTAKES.iter().any(|&m| mistakes.has(m)) || wo.z <= 0.0 {
        return None;
    }
    match bsdf {
        Bsdf::Mirror(m) => Some(Some(reflection(wo, m.reflectance, 1.0, mistakes))),
        Bsdf::Refraction(r) => Some(refraction(r, wo, mistakes)),
        Bsdf::Glass(g) => Some(glass(g, wo, uc, mistakes)),
        _ => None,
    }
}

/// `BSDF::reflect`: about the normal, or (the mistake) through the
/// tangent plane, `(wo.x, wo.y, -wo.z)`, which sends the ray into the
/// surface.
fn reflected(wo: Vec3, mistakes: Mistakes) -> Vec3 {
    if mistakes.has(Mistake::ReflectWrongAxis) {
        Vec3::new(wo.x, wo.y, -wo.z)
    } else {
        reflect(wo)
    }
}

/// A delta reflection of weight `reflectance`, chosen with `probability`.
fn reflection(wo: Vec3, reflectance: Rgb, probability: f32, mistakes: Mistakes) -> BsdfSample {
    let wi = reflected(wo, mistakes);
    BsdfSample {
        f: reflectance * probability / wi.z.abs(),
        wi,
        density: Density::Delta(probability),
        transmission: wi.z < 0.0,
        eta: 1.0,
    }
}

/// The index ratio the student refracts with: the right one, or its
/// reciprocal.
fn ratio(eta: f32, mistakes: Mistakes) -> f32 {
    if mistakes.has(Mistake::RefractionRatioInverted) {
        1.0 / eta
    } else {
        eta
    }
}

/// A delta refraction into `wi` of weight `transmittance` times the
/// radiance scaling (left out by the mistake), chosen with `probability`.
fn transmission(
    wi: Vec3,
    transmittance: Rgb,
    scale: f32,
    probability: f32,
    eta: f32,
    mistakes: Mistakes,
) -> BsdfSample {
    let scale = if mistakes.has(Mistake::NoEtaSquared) {
        1.0
    } else {
        scale
    };
    BsdfSample {
        f: transmittance * scale * probability / wi.z.abs(),
        wi,
        density: Density::Delta(probability),
        transmission: true,
        eta,
    }
}

fn refraction(r: &Refraction, wo: Vec3, mistakes: Mistakes) -> Option<BsdfSample> {
    let eta = ratio(r.eta, mistakes);
    match refract(wo, eta) {
        Some(wi) => Some(transmission(
            wi,
            r.transmittance,
            r.eta_scaling.factor(eta),
            1.0,
            eta,
            mistakes,
        )),
        None if mistakes.has(Mistake::NoTotalInternalReflection) => None,
        None => Some(reflection(wo, r.transmittance, 1.0, mistakes)),
    }
}

fn glass(g: &Glass, wo: Vec3, uc: f32, mistakes: Mistakes) -> Option<BsdfSample> {
    let eta = ratio(g.eta, mistakes);
    let refracted = refract(wo, eta);
    if refracted.is_none() && mistakes.has(Mistake::NoTotalInternalReflection) {
        return None;
    }
    let f = if mistakes.has(Mistake::SchlickR0NotSquared) {
        schlick_with_r0_not_squared(wo.z, eta)
    } else {
        match g.fresnel {
            FresnelModel::Exact => fresnel::dielectric(wo.z, eta),
            FresnelModel::Schlick => fresnel::schlick(wo.z, eta),
        }
    };
    match refracted {
        Some(wi) if uc >= f => Some(transmission(
            wi,
            g.transmittance,
            g.eta_scaling.factor(eta),
            1.0 - f,
            eta,
            mistakes,
        )),
        _ => Some(reflection(wo, g.reflectance, f, mistakes)),
    }
}

/// Schlick's approximation with `R0 = |(1 - eta) / (1 + eta)|`, the square
/// left out: 0.18 for glass of index 1.45 where the right `R0` is 0.034.
pub fn schlick_with_r0_not_squared(cos_i: f32, eta: f32) -> f32 {
    let cos_i = cos_i.clamp(0.0, 1.0);
    if fresnel::refracted_cos(cos_i, eta).is_none() {
        return 1.0;
    }
    let r0 = ((1.0 - eta) / (1.0 + eta)).abs();
    r0 + (1.0 - r0) * (1.0 - cos_i).powi(5)
}
