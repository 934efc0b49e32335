//! The image a correct course solution renders (`--course-exact`).
//!
//! This project renders physically correct images by default, with
//! estimators that give less noise for the time. A student of the course
//! wants something else too: the image *their* correct solution should
//! render, starter code and handout included, to compare theirs with.
//! `--course-exact` gives it. Every difference between the two lives
//! behind this one switch, listed with its effect in
//! docs/14-course-image.md:
//!
//! | what | the project | the course (a correct solution) | where |
//! | --- | --- | --- | --- |
//! | integrator | MIS, the render plan | the starter's functions ([`tracer`]) | `pathtracer.cpp` |
//! | random numbers, roulette | Sobol', throughput roulette after 8 bounces | independent, `q = 0.65` from the second vertex | `random_util.h`, handout |
//! | area and point light samples | physical | the starter's `sample_L` ([`LightConvention::Course`]) | `static_scene/light.cpp` |
//! | `-H` | sees the area lights | sees geometry only (the lamp mesh) | `estimate_direct_lighting_hemisphere` |
//! | lamps in 3-2 | the lamp mesh | the light's own quad, `L / A cos` | 3-2 starter |
//! | glass Fresnel | exact | Schlick | `GlassBSDF::sample_f` |
//! | radiance across glass | `1 / eta^2`, eta far over near | the reciprocal convention | `GlassBSDF`, `RefractionBSDF` |
//! | microfacet `Lambda`, `F` | exact, `F(wo.h)` | `a pi` for `a sqrt(pi)`, `F(wi.z)` | `bsdf.h`, `MicrofacetBSDF::f` |
//! | microfacet sampling | visible normals where it pays | the half vector | handout |
//! | environment map's sampling weights | the bilinear lookup's average over a cell | the cell's texel | `EnvironmentLight::init` |
//! | adaptive sampling | only with `-a` | on by default (32, 0.05) once part 5 is written | `main.cpp` |
//! | pixels that stop early | their mean | 3-2: tested one sample late, written as the sum over one sample fewer | `libpt31.so` |
//! | PNG | rounded | truncated, `floor(255 v)` | `HDRImageBuffer::toColor` |
//!
//! The settings live in [`CourseExact`]; the integrator in [`tracer`]; the
//! pixel loop and the camera, as the starter's `raytrace_pixel` and
//! `generate_ray`, in [`pixel`].

pub mod choices;
pub mod image;
pub mod pixel;
pub mod tracer;

pub use choices::Choices;
pub use image::{CourseSampling, CourseView};
pub use tracer::{Lamps, StarterDirect, StarterTracer};

use crate::adaptive::Adaptive;
use crate::environment::EnvironmentWeights;
use crate::lights::{LightChoiceRule, LightConvention};
use crate::materials::{
    BsdfOptions, EtaScaling, FresnelModel, MicrofacetModel, MicrofacetSampling,
};
use crate::render::Quantization;
use crate::sampling::SamplerKind;
use crate::world::{CasterRule, WorldOptions};

/// Which of the course's two assignments the image is of.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Assignment {
    /// PathTracer 3-1 (parts 1 to 5): a student's own solution.
    PathTracer1,
    /// PathTracer 3-2 (parts 6 to 8), whose parts 1 to 5 are the staff's
    /// library (`libpt31.so`) and whose lamps are the lights' own quads.
    PathTracer2,
}

impl Assignment {
    /// Its name on the command line: `3-1` or `3-2`.
    pub fn name(self) -> &'static str {
        match self {
            Assignment::PathTracer1 => "3-1",
            Assignment::PathTracer2 => "3-2",
        }
    }
}

/// What a correct course solution computes, as render settings.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CourseExact {
    pub assignment: Assignment,
}

impl CourseExact {
    /// The world as the course's solutions see it: the starter's light
    /// weighting, Schlick's glass, the starter's microfacet formulas and
    /// sampler, the starter's radiance scaling across glass, every light
    /// sampled, no caustic casters.
    pub fn world_options(&self) -> WorldOptions {
        WorldOptions {
            light_convention: LightConvention::Course,
            bsdf: BsdfOptions {
                fresnel: FresnelModel::Schlick,
                microfacet: MicrofacetSampling::HalfVector,
                microfacet_model: MicrofacetModel::Starter,
                eta_scaling: EtaScaling::Starter,
            },
            light_choice: LightChoiceRule::EveryLight,
            casters: CasterRule::Off,
        }
    }

    /// The course's random numbers: independent uniform ones.
    pub fn sampler(&self) -> SamplerKind {
        SamplerKind::Independent
    }

    /// What the camera and `-H` see of a lamp.
    pub fn lamps(&self) -> Lamps {
        match self.assignment {
            Assignment::PathTracer1 => Lamps::MeshFaces,
            Assignment::PathTracer2 => Lamps::LightQuads,
        }
    }

    /// Adaptive sampling when `-a` is not given: the course's default
    /// (32, 0.05) once part 5 is written (`part5_written`), else none.
    pub fn default_adaptive(&self, part5_written: bool) -> Option<Adaptive> {
        part5_written.then(Adaptive::default)
    }

    /// What the environment map's importance sampling weighs a cell by:
    /// its texel's illuminance, as the handout's `pdf_envmap`.
    pub fn environment_weights(&self) -> EnvironmentWeights {
        EnvironmentWeights::Texel
    }

    /// How the PNG's 8-bit values are made: truncated.
    pub fn quantization(&self) -> Quantization {
        Quantization::Truncate
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each item of the switch is the course's: lights, Fresnel, microfacet
    /// formulas and sampler, radiance across glass, light choice, no
    /// casters, independent numbers, truncated PNG values, the environment
    /// map's weights, lamps by
    /// assignment, adaptive sampling once part 5 is written.
    #[test]
    fn the_switch_sets_every_item_to_the_courses() {
        let exact = CourseExact {
            assignment: Assignment::PathTracer1,
        };
        let o = exact.world_options();
        assert_eq!(o.light_convention, LightConvention::Course);
        assert_eq!(o.bsdf.fresnel, FresnelModel::Schlick);
        assert_eq!(o.bsdf.microfacet, MicrofacetSampling::HalfVector);
        assert_eq!(o.bsdf.microfacet_model, MicrofacetModel::Starter);
        assert_eq!(o.bsdf.eta_scaling, EtaScaling::Starter);
        assert_eq!(o.light_choice, LightChoiceRule::EveryLight);
        assert_eq!(o.casters, CasterRule::Off);
        assert_eq!(exact.sampler(), SamplerKind::Independent);
        assert_eq!(exact.quantization(), Quantization::Truncate);
        assert_eq!(exact.environment_weights(), EnvironmentWeights::Texel);
        assert_eq!(exact.lamps(), Lamps::MeshFaces);
        let three_two = CourseExact {
            assignment: Assignment::PathTracer2,
        };
        assert_eq!(three_two.lamps(), Lamps::LightQuads);
        assert_eq!(exact.default_adaptive(false), None);
        assert_eq!(exact.default_adaptive(true), Some(Adaptive::default()));
    }
}
