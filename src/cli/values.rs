//! The values of the course's flags that are more than a number: checked
//! numbers, the microfacet sampling strategy, the light choice, the
//! sampler, the Russian roulette, and the built-in scenes.

use crate::global::Roulette;
use crate::lights::LightChoiceRule;
use crate::materials::MicrofacetSampling;
use crate::sampling::SamplerKind;
use crate::scene::{builtin, Scene};
use crate::world::CasterRule;

/// A finite number `>= 0`.
pub fn non_negative(s: &str) -> Result<f32, String> {
    match s.parse::<f32>() {
        Ok(v) if v.is_finite() && v >= 0.0 => Ok(v),
        _ => Err(format!("expected a finite number of at least 0, not {s}")),
    }
}

/// A finite number `> 0`.
pub fn positive(s: &str) -> Result<f32, String> {
    match s.parse::<f32>() {
        Ok(v) if v.is_finite() && v > 0.0 => Ok(v),
        _ => Err(format!("expected a finite positive number, not {s}")),
    }
}

/// `--course-exact=ASSIGNMENT`: which of the course's assignments.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum AssignmentArg {
    /// PathTracer 3-1 (parts 1 to 5), a student's own solution.
    #[value(name = "3-1")]
    PathTracer1,
    /// PathTracer 3-2 (parts 6 to 8) on the staff's parts 1 to 5.
    #[value(name = "3-2")]
    PathTracer2,
}

impl From<AssignmentArg> for crate::course::Assignment {
    fn from(arg: AssignmentArg) -> Self {
        match arg {
            AssignmentArg::PathTracer1 => crate::course::Assignment::PathTracer1,
            AssignmentArg::PathTracer2 => crate::course::Assignment::PathTracer2,
        }
    }
}

/// `part2-bvh --accel`: which BVH the benchmark traces.
#[derive(clap::ValueEnum, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum AccelArg {
    /// Part 2's binary BVH (`bvh::BvhAccel`), the teaching version.
    Binary,
    /// The eight-wide SIMD BVH (`bvh::WideBvhAccel`) the renderers use.
    #[default]
    Wide,
}

/// `--microfacet-sampling`: the command line's names of
/// [`MicrofacetSampling`] (kept here so that the library needs no clap).
#[derive(clap::ValueEnum, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum MicrofacetSamplingArg {
    /// `wi` cosine-weighted on the hemisphere.
    Cosine,
    /// The Beckmann half vector from `D(h) cos(theta_h)` (the course's).
    HalfVector,
    /// The normals visible from `wo` (Heitz and d'Eon 2014).
    VisibleNormals,
    /// The half vector where `alpha tan(theta_o) < 0.1` (the two nearly
    /// coincide there, and it is faster), the visible normals elsewhere.
    #[default]
    Auto,
}

impl From<MicrofacetSamplingArg> for MicrofacetSampling {
    fn from(arg: MicrofacetSamplingArg) -> Self {
        match arg {
            MicrofacetSamplingArg::Cosine => MicrofacetSampling::CosineHemisphere,
            MicrofacetSamplingArg::HalfVector => MicrofacetSampling::HalfVector,
            MicrofacetSamplingArg::VisibleNormals => MicrofacetSampling::VisibleNormals,
            MicrofacetSamplingArg::Auto => MicrofacetSampling::Auto,
        }
    }
}

/// `--light-choice`: the command line's names of [`LightChoiceRule`].
#[derive(clap::ValueEnum, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LightChoiceArg {
    /// Every light up to 8 lights, by power beyond.
    #[default]
    Auto,
    /// Every light, -l samples each (the course's).
    Every,
    /// -l samples in all, each of one light chosen by its power.
    Power,
}

impl From<LightChoiceArg> for LightChoiceRule {
    fn from(arg: LightChoiceArg) -> Self {
        match arg {
            LightChoiceArg::Auto => LightChoiceRule::Auto,
            LightChoiceArg::Every => LightChoiceRule::EveryLight,
            LightChoiceArg::Power => LightChoiceRule::ByPower,
        }
    }
}

/// `--sampler`: the command line's names of [`SamplerKind`].
#[derive(clap::ValueEnum, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum SamplerArg {
    /// Independent uniform numbers, a PCG32 stream per pixel (the course's).
    Independent,
    /// Owen-scrambled Sobol' points in Morton order (the default, least noise).
    #[default]
    Zsobol,
}

impl From<SamplerArg> for SamplerKind {
    fn from(arg: SamplerArg) -> Self {
        match arg {
            SamplerArg::Independent => SamplerKind::Independent,
            SamplerArg::Zsobol => SamplerKind::ZSobol,
        }
    }
}

/// `--roulette`: the command line's names of the [`Roulette`] rules.
#[derive(clap::ValueEnum, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum RouletteArg {
    /// Continue with probability 0.65 after the first indirect bounce (the course's).
    Fixed,
    /// Continue with probability min(1, path throughput) (pbrt-v4's, the default).
    #[default]
    Throughput,
}

impl From<RouletteArg> for Roulette {
    fn from(arg: RouletteArg) -> Self {
        match arg {
            RouletteArg::Fixed => Roulette::Fixed,
            RouletteArg::Throughput => Roulette::Throughput,
        }
    }
}

/// `--casters`: the command line's names of the [`CasterRule`]s.
#[derive(clap::ValueEnum, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum CastersArg {
    /// Diffuse surfaces sample towards the scene's smooth spheres and the lights' images in the mirror-like ones too (the default).
    #[default]
    Auto,
    /// Towards the smooth spheres, without the light images.
    Spheres,
    /// Diffuse surfaces sample their BSDF alone (the course's).
    Off,
}

impl From<CastersArg> for CasterRule {
    fn from(arg: CastersArg) -> Self {
        match arg {
            CastersArg::Auto => CasterRule::Auto,
            CastersArg::Spheres => CasterRule::Spheres,
            CastersArg::Off => CasterRule::Off,
        }
    }
}

/// The built-in scenes a binary renders when no scene file is given.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Builtin {
    /// [`builtin::cornell_box`]: diffuse spheres (parts 1 to 5).
    #[default]
    CornellBox,
    /// [`builtin::materials_box`]: mirror, glass and copper (part 6).
    MaterialsBox,
    /// [`builtin::environment_spheres`]: two spheres on a floor, no
    /// light of their own (part 7).
    EnvironmentSpheres,
}

impl Builtin {
    pub fn scene(self) -> Scene {
        match self {
            Builtin::CornellBox => builtin::cornell_box(),
            Builtin::MaterialsBox => builtin::materials_box(),
            Builtin::EnvironmentSpheres => builtin::environment_spheres(),
        }
    }

    /// The file name stem of its default output.
    pub fn name(self) -> &'static str {
        match self {
            Builtin::CornellBox => "cornell-box",
            Builtin::MaterialsBox => "materials-box",
            Builtin::EnvironmentSpheres => "environment-spheres",
        }
    }
}
