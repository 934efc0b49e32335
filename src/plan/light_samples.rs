//! How many samples an environment light takes at each path vertex where
//! `-l` does not say: [`ENVIRONMENT_SAMPLES`] (the plan's
//! `environment samples` line; `-l N` gives every light `N`).
//!
//! Splitting: a camera path that takes `k` light samples at each vertex
//! (and one BSDF continuation) estimates a pixel with the variance and
//! cost of a two-stage sample (Cochran, *Sampling Techniques*, 3rd ed.,
//! 1977, section 10.6, the optimum number of second-stage units):
//!
//! ```text
//! V(k) = a + b / k         a: the path's own noise (its BSDF choices, its pixel position)
//!                          b: the noise of one light sample a vertex, given the path
//! C(k) = c_path + k c_light
//! efficiency(k) = 1 / (V(k) C(k)),   best at k* = sqrt((b / a) (c_path / c_light))
//! ```
//!
//! Every `k` renders the same image in expectation (the estimate at each
//! vertex is the mean of `k` unbiased ones, and MIS weighs them with `k`
//! light samples); `k` changes only noise and time.
//!
//! Measured on the project's scenes (480 x 360, 64 spp, variance from two
//! seeds over the image, time of the `render:` line; docs/10 has the
//! table and the command): `b / a` is 0.3 to 0.4 on the course's Cornell
//! boxes, whose light is a small quad that a sample finds well, and 2.5
//! to 8.5 under environment maps, whose samples follow the map's radiance
//! alone, blind to the BSDF, the cosine and what hides the sky; `c_path /
//! c_light` is 0.9 to 3.3. So one sample a vertex is best for lights in
//! the scene (`k*` 0.5 to 1) and four for a map (`k*` 2.3 to 5.3). A short pilot
//! render that measured `b / a` per scene was tried and left out: at a
//! few percent of the render's paths it could not see the few bright
//! pixels that hold most of the variance under a sun (the choice changed
//! with the seed), and a rule of the light's kind is the same on every
//! run.
//!
//! **Not where the light samples are not the noise.** The measure above
//! was taken where the samples' noise is much of the path's: at diffuse
//! and rough vertices, in scenes without caustics. Two kinds of vertex
//! differ, and take one sample:
//!
//! - *A vertex whose BSDF is sharper than the map.* At a near-mirror
//!   conductor the BSDF's own sample finds what the vertex reflects
//!   better than the map's samples do, unless the map is sharper still:
//!   a map's samples follow its radiance, so most of them fall outside a
//!   narrow lobe and weigh nothing there, yet each costs a lookup, a
//!   BSDF evaluation and often a shadow ray. So a vertex splits only
//!   where the map's largest density per steradian (its
//!   [`EnvironmentLight::peak_density`]) is at least the BSDF's
//!   ([`lobe_peak_density`]: `1 / pi` for a diffuse surface, `1 / (4 pi
//!   alpha^2)` for a conductor, its reflected direction's density at
//!   normal incidence). A soft studio map (peak 2.6 per steradian) is
//!   split at rough vertices (`alpha` 0.2: 2.0) and not at a near-mirror
//!   (`alpha` 0.05: 32); a sun (about 10^4) at both, since there the
//!   map's samples find the sun in a narrow lobe that the BSDF's would
//!   rarely reach.
//! - *A diffuse vertex in a scene that casts caustics* (a mirror, glass
//!   or near-mirror surface: [`crate::plan::BsdfKinds::casts_caustics`]).
//!   Its noise is then the light that reaches it through those surfaces,
//!   found only by its continuation (`a` large, so `k*` near 1): on
//!   `bunny_unlit.dae` with its bunny a mirror, glass or near-mirror
//!   copper under the studio map, four samples at the pedestal left the
//!   variance within 3 % of one sample's for 50–60 % more time (under a
//!   sun, within 3 % too; docs/10, section 2).
//!
//! ```text
//! k(vertex) = ENVIRONMENT_SAMPLES   if  max_w p_map(w) >= max_w p_bsdf(w),
//!                                   and the vertex is not diffuse in a scene with caustics
//!           = 1                     otherwise
//! ```
//!
//! Any rule of the vertex alone leaves the image's expectation
//! unchanged, provided the emission a BSDF ray finds is weighed with the
//! same `k` ([`crate::global::PrevVertex`] carries the vertex's choice,
//! [`crate::world::World::splits_map`]).

use crate::environment::EnvironmentLight;
use crate::global::{DirectStrategy, PathTracer};
use crate::lights::{Light, LightChoice, LightSet};
use crate::materials::Bsdf;

/// Samples an environment light takes at each vertex unless `-l` is given.
pub const ENVIRONMENT_SAMPLES: u32 = 4;

/// The largest density per steradian of `bsdf`'s sampling, as far as
/// the split needs it: `1 / pi` (the cosine's peak) for a diffuse
/// surface, `1 / (4 pi alpha^2)` for a conductor (Beckmann's `D(h) = 1 /
/// (pi alpha^2)` at `h = n`, times the half vector's Jacobian `1 / (4
/// wo.h)` at normal incidence), infinite for a delta BSDF (never light
/// sampled) and 0 for a black one.
pub fn lobe_peak_density(bsdf: &Bsdf) -> f32 {
    use std::f32::consts::{FRAC_1_PI, PI};
    match bsdf {
        Bsdf::Black => 0.0,
        Bsdf::Diffuse(_) => FRAC_1_PI,
        Bsdf::Conductor(c) => {
            let alpha = c.distribution.alpha();
            1.0 / (4.0 * PI * alpha * alpha)
        }
        Bsdf::Mirror(_) | Bsdf::Refraction(_) | Bsdf::Glass(_) => f32::INFINITY,
    }
}

/// Whether a vertex of BSDF `bsdf` splits the samples of the map `map`
/// (in a scene with caustic casters when `caustics`): a diffuse vertex
/// where there are no casters, and any vertex whose BSDF is no sharper
/// than the map.
pub fn splits_map(bsdf: &Bsdf, map: &EnvironmentLight, caustics: bool) -> bool {
    match bsdf {
        Bsdf::Diffuse(_) if caustics => false,
        _ => map.peak_density() >= lobe_peak_density(bsdf),
    }
}

/// `tracer` with [`ENVIRONMENT_SAMPLES`] for the environment light of
/// `lights`, where it samples lights, every light is sampled (not one
/// chosen by power) and one of them is an environment map that emits;
/// else `tracer` unchanged. The plan's line says which, and at which
/// vertices the map's samples are split ([`splits_map`]; `caustics`: the
/// scene has caustic casters).
pub fn with_environment_samples(
    tracer: &PathTracer,
    lights: &LightSet,
    caustics: bool,
) -> (PathTracer, String) {
    let mut t = *tracer;
    let DirectStrategy::Lights(d) = tracer.direct else {
        return (
            t,
            "plan: environment samples: none (no light sampling)".into(),
        );
    };
    let map = lights.lit().find_map(|(_, l)| match l {
        Light::Environment(map) => Some(map),
        _ => None,
    });
    let Some(map) = map else {
        return (
            t,
            "plan: environment samples: none (no environment map)".into(),
        );
    };
    if !matches!(lights.choice(), LightChoice::EveryLight) {
        return (
            t,
            "plan: environment samples: -l in all (lights chosen by power)".into(),
        );
    }
    t.direct = DirectStrategy::Lights(crate::direct::DirectLights {
        environment_samples: Some(ENVIRONMENT_SAMPLES),
        ..d
    });
    let peak = map.peak_density();
    let alpha = (1.0 / (4.0 * std::f32::consts::PI * peak)).sqrt();
    let diffuse = if caustics {
        "not at diffuse surfaces, whose noise here is the light of the mirror, glass or \
         near-mirror surfaces"
    } else if peak >= std::f32::consts::FRAC_1_PI {
        "at diffuse surfaces"
    } else {
        "not at diffuse surfaces, sharper than the map"
    };
    let line = format!(
        "plan: environment samples: {ENVIRONMENT_SAMPLES} a vertex whose BSDF is no sharper than \
         the map (its peak density {peak:.3} per steradian), else 1: at conductors with alpha >= \
         {alpha:.3}, {diffuse} (a map's samples follow its radiance alone; splitting them pays \
         where they land in the BSDF's lobe and are the noise that counts; -l N gives every \
         light N)"
    );
    (t, line)
}
