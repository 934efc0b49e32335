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
//! `w_bsdf = power_heuristic(1, p_bsdf, N, p_light)`, with `p_bsdf` the
//! density the continuation drew the ray with (the BSDF's, or its mixture
//! with the caustic casters' cones at a diffuse vertex): the BSDF sample's
//! side of the multiple importance sampling that [`crate::direct::DirectLights`]
//! weighs its `N` light samples with. With `-H` the hemisphere rays at the
//! previous vertex already counted every light (through [`found_emission`]
//! with the weights of `--bsdf-only`); with `--bsdf-only` nothing else
//! counts any (a stand-in's light is then found as its rectangle, like
//! every rectangle light after a scattering vertex).

use glam::Vec3;

use super::DirectStrategy;
use crate::intersect::{Hit, Intersector, Ray};
use crate::lights::{EmitterRole, LightHit};
use crate::math::mis::power_heuristic;
use crate::math::Rgb;
use crate::world::World;

/// Where the ray that found the emission started.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PrevVertex {
    /// The camera or a delta bounce: nothing else could find this light.
    CameraOrDelta,
    /// A scattering (non-delta) vertex at `p` whose continuation sampled
    /// the ray with density `bsdf_pdf` per steradian: the BSDF's, or at a
    /// diffuse vertex with caustic casters the mixture's
    /// ([`World::continuation_pdf`]); `splits_map` says whether light
    /// sampling there split an environment map's samples
    /// ([`World::splits_map`]), which its MIS weights count.
    Scattering {
        p: Vec3,
        bsdf_pdf: f32,
        splits_map: bool,
    },
}

/// What the found emission is, as far as its weight is concerned.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Emitter {
    /// Shown to the camera and through delta bounces only.
    Shown,
    /// Sampled by the light strategy, which takes `samples` samples per
    /// vertex and would have chosen this direction with density `light_pdf`
    /// per steradian (times the probability of choosing this light).
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

/// Emission that `ray`, leaving `prev`, finds under the strategy `direct`:
/// the surface it hits (`next`) by its role, the rectangle lights it
/// crosses before that surface (they are not geometry), or the lights at
/// infinity if it escapes; each weighted by [`emission_weight`]. Light
/// densities are evaluated only for multiple importance sampling.
///
/// The hemisphere estimator of part 3 counts its rays' light through here
/// too, with the weights of `--bsdf-only` (every light in full, stand-ins
/// not at all), so that it sees the same lights as light sampling.
pub fn found_emission<I: Intersector>(
    world: &World<I>,
    direct: &DirectStrategy,
    ray: &Ray,
    next: Option<&Hit>,
    prev: &PrevVertex,
) -> Rgb {
    let lights = &world.lights;
    // Light densities count only where light sampling at `prev` used MIS.
    let mis_at = match (direct, *prev) {
        (DirectStrategy::Lights(d), PrevVertex::Scattering { p, splits_map, .. }) if d.mis => {
            Some((d, p, splits_map))
        }
        _ => None,
    };
    // The density with which light sampling at `prev` picks `ray.dir`
    // towards `light` (0 when unused).
    let density = |light: usize, hit: Option<LightHit>| {
        mis_at.map_or(0.0, |(_, p, _)| {
            lights.lights[light].pdf_li(p, ray.dir, hit)
        })
    };
    // What light sampling at `prev` would have done for `light`, whose
    // density of `ray.dir` is `pdf_li` (0 when unused).
    let sampled = |light: usize, pdf_li: f32| match mis_at {
        Some((d, _, splits_map)) => {
            let strategy = d.strategy(lights, light, splits_map);
            Emitter::Sampled {
                light_pdf: strategy.probability * pdf_li,
                samples: strategy.samples,
            }
        }
        None => Emitter::Sampled {
            light_pdf: 0.0,
            samples: 1,
        },
    };
    let weight = |emitter| emission_weight(direct, prev, emitter);
    let mut le = Rgb::ZERO;
    let mut role = EmitterRole::Dark;
    match next {
        None => {
            for (i, light) in lights.infinite() {
                let (radiance, pdf_li) = light.escaped(ray.dir, mis_at.is_some());
                if radiance != Rgb::ZERO {
                    le += radiance * weight(sampled(i, pdf_li));
                }
            }
        }
        Some(hit) => {
            // The role says whether the surface emits (dark if not).
            role = lights.role(hit.primitive);
            let emitter = match role {
                EmitterRole::Dark => None,
                EmitterRole::Shown { .. } => Some(Emitter::Shown),
                EmitterRole::Unsampled => Some(Emitter::Unsampled),
                EmitterRole::Sampled { light, member } => {
                    let at = LightHit {
                        point: hit.p,
                        member,
                    };
                    let light = light as usize;
                    Some(sampled(light, density(light, Some(at))))
                }
            };
            if let Some(emitter) = emitter {
                le += world.material(hit).emission() * weight(emitter);
            }
        }
    }
    // Rectangle lights: after the camera or a delta bounce a rectangle
    // shows itself unless a stand-in shows it; after scattering, only the
    // strategies in which BSDF rays find lights count it.
    let after_scattering = matches!(prev, PrevVertex::Scattering { .. });
    let t_hit = next.map_or(f32::INFINITY, |h| h.t);
    for (i, rect, has_stand_in) in lights.rects() {
        let wanted = if after_scattering {
            direct.bsdf_rays_find_lights()
        } else {
            !has_stand_in
        };
        let Some(t) = rect.hit_distance(ray).filter(|_| wanted) else {
            continue;
        };
        // A stand-in lies on its rectangle's plane, behind it, or up to
        // 1e-4 of the diagonal in front (`lights::stand_ins`): seen from
        // near the light, more than the relative tolerance below allows.
        let slack = if role
            == (EmitterRole::Shown {
                light: Some(i as u32),
            }) {
            0.02 * rect.diagonal()
        } else {
            0.0
        };
        if t <= t_hit * (1.0 + 1e-3) + slack {
            // The course's light weighting scales light samples by the
            // distance; only the BSDF side of multiple importance sampling
            // weighs against them, so only it takes the same factor. The
            // camera, a delta bounce, `-H` and BSDF sampling alone see the
            // light's radiance.
            let radiance = if after_scattering && direct.mis() {
                rect.radiance_at(t)
            } else {
                rect.radiance
            };
            le += radiance * weight(sampled(i, density(i, None)));
        }
    }
    le
}
