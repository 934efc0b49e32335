//! The one place where emission found by a ray is weighted, so that every
//! light is counted exactly once whatever the strategy.
//!
//! A ray leaves either the camera or a delta bounce (a mirror, glass),
//! where no other strategy could have found the same light, or a
//! scattering vertex, where direct lighting already estimated the light
//! arriving from every direction. What the ray's emission is worth then
//! depends on the direct-lighting strategy and on the emitter's role
//! ([`crate::lights::EmitterRole`]):
//!
//! | previous vertex | emitter | `-H` | lights, `--no-mis` | lights with MIS | `--bsdf-only` |
//! | --- | --- | --- | --- | --- | --- |
//! | camera or delta | any | 1 | 1 | 1 | 1 |
//! | scattering | shown only (a stand-in) | 0 | 0 | 0 | 0 |
//! | scattering | sampled by a light | 0 | 0 | `w_bsdf` | 1 |
//! | scattering | sampled by nothing | 0 | 1 | 1 | 1 |
//!
//! `w_bsdf = power_heuristic(1, p_bsdf, N, p_light)`: the BSDF sample's
//! side of the multiple importance sampling that [`crate::direct::DirectLights`]
//! weighs its `N` light samples with. With `-H` the hemisphere rays at the
//! previous vertex already counted every emitter; with `--bsdf-only`
//! nothing else counts any (a stand-in's light is then found as its
//! rectangle, like every rectangle light after a scattering vertex).

use glam::Vec3;

use super::DirectStrategy;
use crate::math::mis::power_heuristic;

/// Where the ray that found the emission started.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PrevVertex {
    /// The camera or a delta bounce: nothing else could find this light.
    CameraOrDelta,
    /// A scattering (non-delta) vertex at `p` whose BSDF sampled the ray
    /// with density `bsdf_pdf` per steradian.
    Scattering { p: Vec3, bsdf_pdf: f32 },
}

/// What the found emission is, as far as its weight is concerned.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Emitter {
    /// Shown to the camera and through delta bounces only.
    Shown,
    /// Sampled by a light that takes `samples` samples per vertex and would
    /// have chosen this direction with density `light_pdf` per steradian.
    Sampled { light_pdf: f32, samples: u32 },
    /// Sampled by no light.
    Unsampled,
}

/// The weight of emission from `emitter` found by a ray that left `prev`.
pub fn emission_weight(direct: &DirectStrategy, prev: &PrevVertex, emitter: Emitter) -> f32 {
    let PrevVertex::Scattering { bsdf_pdf, .. } = *prev else {
        return 1.0;
    };
    match (direct, emitter) {
        (DirectStrategy::Hemisphere(_), _) | (_, Emitter::Shown) => 0.0,
        (_, Emitter::Unsampled) | (DirectStrategy::BsdfOnly, _) => 1.0,
        (DirectStrategy::Lights(d), Emitter::Sampled { light_pdf, samples }) => {
            if d.mis {
                power_heuristic(1.0, bsdf_pdf, samples as f32, light_pdf)
            } else {
                0.0
            }
        }
    }
}
