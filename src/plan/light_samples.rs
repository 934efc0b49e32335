//! How many samples an environment light takes at each path vertex where
//! `-l` does not say: [`ENVIRONMENT_SAMPLES`] where they pay, else one
//! ([`splits_map`]; the plan's `environment samples` line; `-l N` gives
//! every light `N`).
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
//! - *A conductor whose lobe is much sharper than the map.* A map's
//!   samples follow its radiance, so at a near-mirror most of them fall
//!   outside the lobe and weigh nothing, yet each costs a lookup, a BSDF
//!   evaluation and often a shadow ray; the BSDF's own sample finds what
//!   the lobe reflects. Splitting pays where the map's `k` samples, at
//!   their densest, would take at least half of the power heuristic's
//!   weight at the lobe's peak: `k max p_map >= max p_bsdf`, with the
//!   map's [`EnvironmentLight::peak_density`] and Beckmann's `1 / (4 pi
//!   alpha^2)`, so from [`smallest_split_alpha`] up. Under the studio map
//!   (peak 2.6 per steradian) that is `alpha >= 0.087`: the near-mirror
//!   copper (`alpha` 0.05) takes one sample, while copper of `alpha` 0.1
//!   splits (a first rule without the `k`, cutting at 0.17, doubled the
//!   latter's variance). Under a sun (about 10^4) every conductor splits:
//!   there the map's samples find the sun in a lobe the BSDF's would
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
//! k(vertex) = ENVIRONMENT_SAMPLES   at a diffuse vertex in a scene without caustics,
//!                                   at a conductor with alpha >= 1 / sqrt(4 pi k max_w p_map(w))
//!           = 1                     elsewhere
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

/// The roughness from which a conductor splits the samples of a map
/// whose largest density per steradian is `map_peak`: where the map's
/// [`ENVIRONMENT_SAMPLES`] samples, at their densest, would take at
/// least half of the power heuristic's weight at the peak of the
/// conductor's lobe, `k p_map >= p_bsdf`, with Beckmann's peak density
/// `p_bsdf = 1 / (4 pi alpha^2)` (`D(h) = 1 / (pi alpha^2)` at `h = n`
/// times the half vector's Jacobian `1 / (4 wo.h)`, at normal incidence):
///
/// ```text
/// alpha >= 1 / sqrt(4 pi k max_w p_map(w))
/// ```
pub fn smallest_split_alpha(map_peak: f32) -> f32 {
    (4.0 * std::f32::consts::PI * ENVIRONMENT_SAMPLES as f32 * map_peak)
        .sqrt()
        .recip()
}

/// Whether a vertex of BSDF `bsdf` splits the samples of the map `map`
/// (in a scene that casts caustics when `caustics`): a diffuse vertex
/// where nothing casts caustics, a conductor from
/// [`smallest_split_alpha`] up. Other BSDFs take no light samples.
pub fn splits_map(bsdf: &Bsdf, map: &EnvironmentLight, caustics: bool) -> bool {
    match bsdf {
        Bsdf::Diffuse(_) => !caustics,
        Bsdf::Conductor(c) => c.distribution.alpha() >= smallest_split_alpha(map.peak_density()),
        _ => true,
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
    let alpha = smallest_split_alpha(peak);
    let diffuse = if caustics {
        "not at diffuse ones, whose noise here is the light of the mirror, glass or near-mirror \
         surfaces"
    } else {
        "and at diffuse ones"
    };
    let line = format!(
        "plan: environment samples: {ENVIRONMENT_SAMPLES} a vertex at conductors with alpha >= \
         {alpha:.3} (the map's peak density is {peak:.3} per steradian), {diffuse}; 1 elsewhere \
         (a map's samples follow its radiance alone; splitting them pays where they weigh in the \
         BSDF's lobe and are the noise that counts; -l N gives every light N)"
    );
    (t, line)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::environment::{EnvironmentMap, EnvironmentSampling};
    use crate::materials::{BsdfOptions, Conductor, Diffuse, MicrofacetSampling};
    use crate::math::Rgb;
    use std::f32::consts::PI;

    /// The threshold is where the map's `k` samples at their densest
    /// match Beckmann's peak density `1 / (4 pi alpha^2)`, written here
    /// from the definition, not from the function.
    #[test]
    fn the_threshold_is_where_k_map_samples_match_the_lobes_peak() {
        for map_peak in [1.0 / (4.0 * PI), 0.5, 2.648, 163.0, 1.0e4] {
            let alpha = smallest_split_alpha(map_peak);
            let lobe_peak = 1.0 / (4.0 * PI * alpha * alpha);
            let k_map = ENVIRONMENT_SAMPLES as f32 * map_peak;
            assert!(
                (lobe_peak / k_map - 1.0).abs() < 1e-5,
                "{map_peak}: {alpha}"
            );
        }
        assert!((smallest_split_alpha(2.648) - 0.0867).abs() < 1e-4);
    }

    /// Under a constant map (density `1 / (4 pi)` everywhere, so the
    /// threshold is `alpha = 0.5`) a conductor splits just above it and
    /// not just below; a diffuse vertex splits unless the scene casts
    /// caustics; a delta BSDF takes no light samples (true, unused).
    #[test]
    fn who_splits_under_a_constant_map() {
        let map = EnvironmentMap::from_fn("constant", 32, 16, |_| Rgb::ONE).unwrap();
        let light = EnvironmentLight::new(map, EnvironmentSampling::Importance);
        let peak = light.peak_density();
        assert!((peak * 4.0 * PI - 1.0).abs() < 0.01, "{peak}");
        let conductor = |alpha| {
            Bsdf::Conductor(Conductor::new(
                alpha,
                Rgb::ONE,
                Rgb::ONE,
                MicrofacetSampling::default(),
            ))
        };
        assert!(splits_map(&conductor(0.51), &light, false));
        assert!(!splits_map(&conductor(0.49), &light, false));
        assert!(!splits_map(&conductor(0.49), &light, true));
        let diffuse = Bsdf::Diffuse(Diffuse { albedo: Rgb::ONE });
        assert!(splits_map(&diffuse, &light, false));
        assert!(!splits_map(&diffuse, &light, true));
        let mirror = Bsdf::new(
            &crate::scene::Material::Mirror {
                reflectance: Rgb::ONE,
            },
            true,
            BsdfOptions::default(),
        );
        assert!(splits_map(&mirror, &light, true));
        // Uniform sampling's density is the flattest: 1 / (4 pi).
        let uniform = light.with_sampling(EnvironmentSampling::Uniform);
        assert!((uniform.peak_density() * 4.0 * PI - 1.0).abs() < 1e-6);
    }
}
