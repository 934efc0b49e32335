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

use crate::global::{DirectStrategy, PathTracer};
use crate::lights::{Light, LightChoice, LightSet};

/// Samples an environment light takes at each vertex unless `-l` is given.
pub const ENVIRONMENT_SAMPLES: u32 = 4;

/// `tracer` with [`ENVIRONMENT_SAMPLES`] for the environment light of
/// `lights`, where it samples lights, every light is sampled (not one
/// chosen by power) and one of them is an environment map that emits;
/// else `tracer` unchanged. The plan's line says which.
pub fn with_environment_samples(tracer: &PathTracer, lights: &LightSet) -> (PathTracer, String) {
    let mut t = *tracer;
    let DirectStrategy::Lights(d) = tracer.direct else {
        return (
            t,
            "plan: environment samples: none (no light sampling)".into(),
        );
    };
    let map = lights
        .lit()
        .any(|(_, l)| matches!(l, Light::Environment(_)));
    if !map {
        return (
            t,
            "plan: environment samples: none (no environment map)".into(),
        );
    }
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
    let line = format!(
        "plan: environment samples: {ENVIRONMENT_SAMPLES} a vertex (a map's samples follow its \
         radiance alone, and splitting them pays; -l N gives every light N)"
    );
    (t, line)
}
