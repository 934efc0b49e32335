//! The values of the course's flags that are more than a number, and the
//! checks of the numbers: the microfacet sampling strategy, the light
//! choice, the sampler, the Russian roulette, and the built-in scenes.
//!
//! Every numeric flag takes the argument after it as its value, as the
//! course's `getopt` does, so `-s -1` is refused as a value of `-s`, not
//! mistaken for a flag `-1`: clap's message names the flag and quotes the
//! value as typed, and the text here says what the value must be, e.g.
//! ```text
//! error: invalid value '-1' for '-s <N>': must be a whole number from 1 to 1048576
//! ```
//! A flag where the value belongs (`-b -d 2`, text starting with `-` and
//! a letter) is reported as the missing value it is.

use std::ffi::OsStr;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;

use clap::builder::TypedValueParser;
use clap::error::{ContextKind, ContextValue, ErrorKind};
use clap::{Arg, Command};

use crate::global::Roulette;
use crate::lights::LightChoiceRule;
use crate::materials::MicrofacetSampling;
use crate::sampling::SamplerKind;
use crate::scene::{builtin, Scene};
use crate::world::CasterRule;

/// The rule of a whole number from `min` to `max`, as the messages say it.
fn whole_rule(min: u64, max: u64) -> String {
    if (min, max) == (0, 1) {
        "must be 0 or 1".to_owned()
    } else {
        format!("must be a whole number from {min} to {max}")
    }
}

/// A whole number from `min` to `max` (digits, an optional `+`), of the
/// flag's type; anything else, too big for the type included, is refused
/// with the rule.
pub fn whole<T>(min: T, max: T) -> impl Fn(&str) -> Result<T, String> + Clone + Send + Sync
where
    T: Copy + Into<u64> + TryFrom<u64> + Send + Sync + 'static,
{
    let (lo, hi) = (min.into(), max.into());
    move |s: &str| {
        s.parse::<u64>()
            .ok()
            .filter(|v| (lo..=hi).contains(v))
            .and_then(|v| T::try_from(v).ok())
            .ok_or_else(|| whole_rule(lo, hi))
    }
}

/// `f32::MAX` as the messages print it.
fn f32_max() -> String {
    format!("{:e}", f32::MAX)
}

/// A number from 0 to `f32::MAX` (`-b`).
pub fn non_negative(s: &str) -> Result<f32, String> {
    match s.parse::<f32>() {
        // + 0.0 turns -0 into 0.
        Ok(v) if v.is_finite() && v >= 0.0 => Ok(v + 0.0),
        _ => Err(format!("must be a number from 0 to {}", f32_max())),
    }
}

/// A number greater than 0, at most `f32::MAX` (`-d`, `-a`'s TOL).
pub fn positive(s: &str) -> Result<f32, String> {
    let rule = format!("must be a number greater than 0, at most {}", f32_max());
    match s.parse::<f32>() {
        Ok(v) if v.is_finite() && v > 0.0 => Ok(v),
        Ok(v) if v == 0.0 && s.parse::<f64>().is_ok_and(|x| x > 0.0) => {
            Err(format!("{rule} (this one is 0 as a 32-bit float)"))
        }
        _ => Err(rule),
    }
}

/// Whether a flag's value is a flag: `-` or `--` and a letter (`-d`,
/// `--info`) but not a number (`-inf`), or `--` alone.
fn is_flag(value: &OsStr) -> bool {
    let text = value.to_string_lossy();
    let name = text.strip_prefix("--").or_else(|| text.strip_prefix('-'));
    text == "--"
        || name.is_some_and(|n| n.starts_with(|c: char| c.is_ascii_alphabetic()))
            && text.parse::<f64>().is_err()
}

/// clap's error for a flag given no value: "a value is required for '-b
/// <RADIUS>' but none was supplied".
fn missing_value(cmd: &Command, arg: Option<&Arg>) -> clap::Error {
    let mut err = clap::Error::new(ErrorKind::InvalidValue).with_cmd(cmd);
    let name = arg.map_or_else(|| "...".to_owned(), Arg::to_string);
    err.insert(ContextKind::InvalidArg, ContextValue::String(name));
    err.insert(
        ContextKind::InvalidValue,
        ContextValue::String(String::new()),
    );
    err
}

/// A numeric flag's parser ([`whole`], [`non_negative`], [`positive`]) for
/// a flag that allows hyphen values: a flag where its value belongs is a
/// missing value, anything else is checked by the parser.
#[derive(Clone)]
pub struct Number<F>(pub F);

impl<F, T> TypedValueParser for Number<F>
where
    F: Fn(&str) -> Result<T, String> + Clone + Send + Sync + 'static,
    T: Clone + Send + Sync + 'static,
{
    type Value = T;

    fn parse_ref(&self, cmd: &Command, arg: Option<&Arg>, value: &OsStr) -> Result<T, clap::Error> {
        if is_flag(value) {
            return Err(missing_value(cmd, arg));
        }
        self.0.parse_ref(cmd, arg, value)
    }
}

/// The largest batch of `-a BATCH TOL`.
pub const MAX_BATCH: u32 = 1_000_000;

/// `-a BATCH TOL`'s values: BATCH a whole number from 1 to [`MAX_BATCH`],
/// TOL [`positive`]. clap has one parser for both values of a flag, so
/// this one counts them: clap parses a command line's values in order,
/// two for each `-a` (a flag where one belongs is refused, and so is a
/// missing last one), and the command is built anew for each parse.
#[derive(Clone, Debug, Default)]
pub struct AdaptiveValues {
    parsed: Arc<AtomicUsize>,
}

impl TypedValueParser for AdaptiveValues {
    type Value = f32;

    fn parse_ref(
        &self,
        cmd: &Command,
        arg: Option<&Arg>,
        value: &OsStr,
    ) -> Result<f32, clap::Error> {
        let batch = self.parsed.fetch_add(1, Ordering::Relaxed) % 2 == 0;
        let result = if batch {
            let parse = whole(1, MAX_BATCH);
            Number(move |s: &str| parse(s).map(|b| b as f32).map_err(|e| format!("BATCH {e}")))
                .parse_ref(cmd, arg, value)
        } else {
            Number(|s: &str| positive(s).map_err(|e| format!("TOL {e}"))).parse_ref(cmd, arg, value)
        };
        if result.is_err() {
            // The parse ends here; a command parsed again starts afresh.
            self.parsed.store(0, Ordering::Relaxed);
        }
        result
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
    /// Continue with probability 0.65 from the second vertex on (the course's).
    Fixed,
    /// After 8 bounces, continue with probability min(1, the path's throughput times the refractions' eta scale) (pbrt-v4's rule, the default).
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
    /// Diffuse surfaces sample towards the scene's smooth spheres, the spheres around its mirror-like meshes, and the lights' images in the mirror-like spheres too (the default).
    #[default]
    Auto,
    /// Towards the smooth spheres and mirror-like meshes, without the light images.
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

/// `--glints`: whether the render plan may give more samples to the
/// pixels that may see a glint ([`crate::glints`]).
#[derive(clap::ValueEnum, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum GlintsArg {
    /// Where the plan asks (an environment map, mirror or glass, a pinhole camera).
    #[default]
    Auto,
    /// Every pixel takes -s samples (the course's).
    Off,
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
