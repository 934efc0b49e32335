//! The flags students know (the course starter's command line, parsed in
//! its `src/main.cpp` and listed in the assignment's handout), parsed by
//! clap; what they ask for in the library's terms is in
//! [`super::settings`]. A numeric flag takes the argument after it as its
//! value, a negative number included, and refuses one out of its range
//! with the rule ([`super::values`]); a flag given twice takes its last
//! value(s).

use std::path::PathBuf;

use clap::{ArgAction, Parser};

use crate::depth_of_field::COURSE_FOCAL_DISTANCE;
use crate::global::MAX_GLASS_SPLITS;

use super::values::{non_negative, positive, whole, AdaptiveValues, Number};
pub use super::values::{
    AccelArg, AssignmentArg, Builtin, CastersArg, GlintsArg, LightChoiceArg, MicrofacetSamplingArg,
    RouletteArg, SamplerArg,
};

/// Largest accepted image side, pixels.
pub const MAX_SIDE: u32 = 1 << 14;

/// The defaults of the flags whose default depends on whether a scene file
/// is given (`-s`, `-m`, `-r`); see [`CourseArgs::defaults`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Defaults {
    /// `-s`: camera rays per pixel.
    pub samples: u32,
    /// `-m`: maximum ray depth.
    pub max_depth: u32,
    /// `-r`: width and height in pixels.
    pub resolution: [u32; 2],
}

/// The course's defaults (the starter's `src/main.cpp`), used when a scene
/// file is given: one sample per pixel, direct light only, 800 x 600.
pub const COURSE_DEFAULTS: Defaults = Defaults {
    samples: 1,
    max_depth: 1,
    resolution: [800, 600],
};

/// The defaults when no scene file is given: a first render of the
/// built-in scene that looks finished (converged, with global
/// illumination) in a few seconds on 2 cores. 480 x 360 frames the
/// built-in box (the field of view follows the size; see
/// `docs/01-raygen.md`); the time and noise are in README, "A first render".
pub const BUILTIN_DEFAULTS: Defaults = Defaults {
    samples: 64,
    max_depth: 5,
    resolution: [480, 360],
};

/// The flags of this project's own rendering, which `--course-exact`,
/// `--mistake` and `--course-choice` (the course's image) exclude.
const BEYOND_THE_COURSE: [&str; 13] = [
    "course",
    "sampler",
    "roulette",
    "casters",
    "glass_splits",
    "glints",
    "bsdf_only",
    "no_mis",
    "course_lights",
    "schlick",
    "microfacet_sampling",
    "light_choice",
    "no_plan",
];

/// The course's flags that apply to parts 1 to 5.
#[derive(Parser, Clone, Debug, PartialEq)]
#[command(version, about, args_override_self = true)]
pub struct CourseArgs {
    /// Scene file (COLLADA .dae); the built-in Cornell box when absent.
    pub scene: Option<PathBuf>,

    /// Camera rays per pixel [default: 1 with a scene file (the course's),
    /// 64 for the built-in scene].
    #[arg(short = 's', value_name = "N", allow_hyphen_values = true,
          value_parser = Number(whole(1u32, 1 << 20)))]
    pub samples: Option<u32>,

    /// Worker threads (default: every core).
    #[arg(short = 't', value_name = "N", allow_hyphen_values = true,
          value_parser = Number(whole(1u16, 256)))]
    pub threads: Option<u16>,

    /// Output size in pixels [default: 800 600 with a scene file (the
    /// course's), 480 360 for the built-in scene].
    #[arg(short = 'r', num_args = 2, value_names = ["WIDTH", "HEIGHT"], action = ArgAction::Set,
          allow_hyphen_values = true, value_parser = Number(whole(1, MAX_SIDE)))]
    pub resolution: Option<Vec<u32>>,

    /// Output image: .png (8-bit, tone mapped) or .exr (linear radiance);
    /// other names are refused. Checked before rendering.
    /// Default: the scene's name with .png, in the current directory.
    #[arg(short = 'f', value_name = "FILE")]
    pub output: Option<PathBuf>,

    /// Samples per area light (and per light for the ambient sky) at each
    /// path vertex [default: 1; an environment map (-e) 4, where the render
    /// plan is on and not in the course's modes: --info says so].
    #[arg(short = 'l', value_name = "N", allow_hyphen_values = true,
          value_parser = Number(whole(1u32, 1 << 16)))]
    pub light_samples: Option<u32>,

    /// Maximum ray depth: bounces of light (0 shows only emitters)
    /// [default: 1 with a scene file (the course's: direct light only), 5
    /// for the built-in scene].
    #[arg(short = 'm', value_name = "N", allow_hyphen_values = true,
          value_parser = Number(whole(0u32, 10_000)))]
    pub max_depth: Option<u32>,

    /// 1: add every bounce up to -m; 0: only the light of the m-th bounce.
    #[arg(short = 'o', value_name = "0|1", default_value_t = 1, allow_hyphen_values = true,
          value_parser = Number(whole(0u8, 1)))]
    pub accumulate: u8,

    /// Adaptive sampling: test every BATCH samples, stop when the 95 %
    /// confidence half-width is at most TOL times the pixel's mean (BATCH
    /// from 1 to 1000000, TOL positive).
    #[arg(short = 'a', num_args = 2, value_names = ["BATCH", "TOL"], action = ArgAction::Set,
          allow_hyphen_values = true, value_parser = AdaptiveValues::default())]
    pub adaptive: Option<Vec<f32>>,

    /// Direct lighting by uniform hemisphere sampling instead of light sampling.
    #[arg(short = 'H')]
    pub hemisphere: bool,

    /// Weight light samples as the course's starter code does (area lights
    /// too bright by the distance, point lights without 1/r^2), to compare
    /// with the course's images. Off: physically correct.
    #[arg(long)]
    pub course_lights: bool,

    /// Light sampling alone at each vertex, emission counted only after
    /// the camera and delta bounces: the course's estimator. Default:
    /// multiple importance sampling of lights and BSDFs.
    #[arg(long)]
    pub no_mis: bool,

    /// No light sampling: only the paths' BSDF-sampled rays find the
    /// lights (point and directional lights stay dark); the reference
    /// that light sampling and MIS improve on.
    #[arg(long, conflicts_with_all = ["hemisphere", "no_mis"])]
    pub bsdf_only: bool,

    /// Glass reflects by Schlick's approximation of the Fresnel equations,
    /// as the course computes it. Default: the exact Fresnel equations.
    #[arg(long)]
    pub schlick: bool,

    /// How microfacet BSDFs sample directions: `half-vector` as the
    /// course does (Beckmann D cos), `cosine` ignoring the lobe (the
    /// baseline), `visible-normals` (least noise, slower), or `auto` (the
    /// default: the half vector where alpha tan(theta_o) < 0.1, the two
    /// nearly coinciding there, the visible normals elsewhere).
    #[arg(long, value_enum, value_name = "STRATEGY", default_value_t = MicrofacetSamplingArg::Auto)]
    pub microfacet_sampling: MicrofacetSamplingArg,

    /// Lens radius (thin-lens depth of field, part 8); 0 is a pinhole.
    #[arg(short = 'b', value_name = "RADIUS", default_value_t = 0.0,
          allow_hyphen_values = true, value_parser = Number(non_negative))]
    pub lens_radius: f32,

    /// Focal distance: the distance of the plane in focus (part 8).
    #[arg(short = 'd', value_name = "DISTANCE", default_value_t = COURSE_FOCAL_DISTANCE,
          allow_hyphen_values = true, value_parser = Number(positive))]
    pub focal_distance: f32,

    /// Focus on the surface seen through pixel (X, Y) (row 0 at the top):
    /// sets -d to its distance (printed with --info).
    #[arg(long, num_args = 2, value_names = ["X", "Y"], action = ArgAction::Set,
          allow_hyphen_values = true,
          value_parser = Number(whole(0, u32::MAX)))]
    pub focus_at: Option<Vec<u32>>,

    /// Render with the general integrator, not the one specialised to
    /// what the scene calls for (the plan of --info), to compare them.
    #[arg(long)]
    pub no_plan: bool,

    /// Environment map lighting the scene from infinitely far away: a
    /// latitude-longitude OpenEXR (.exr) or Radiance (.hdr) image, 2:1.
    #[arg(short = 'e', value_name = "FILE")]
    pub environment: Option<PathBuf>,

    /// Sample the environment map uniformly on the sphere instead of by
    /// its luminance (to compare the two).
    #[arg(long)]
    pub env_uniform: bool,

    /// Which lights direct lighting samples at each vertex: `every` light
    /// with -l samples each (the course's), -l samples in all of lights
    /// chosen by `power`, or `auto`: every light up to 8, by power beyond.
    #[arg(long, value_enum, value_name = "CHOICE", default_value_t = LightChoiceArg::Auto)]
    pub light_choice: LightChoiceArg,

    /// Light the scene by the built-in sky when no -e is given (set by the
    /// binary, not a flag).
    #[arg(skip)]
    pub builtin_sky: bool,

    /// Print what the scene holds and the render plan, one item a line, and exit.
    #[arg(long)]
    pub info: bool,

    /// The scene rendered when no file is given (set by the binary, not a flag).
    #[arg(skip)]
    pub builtin: Builtin,

    /// Seed of the render's random numbers.
    #[arg(long, default_value_t = 0, allow_hyphen_values = true,
          value_parser = Number(whole(0, u64::MAX)))]
    pub seed: u64,

    /// Where the random numbers come from: `independent` uniform numbers
    /// (the course's) or Owen-scrambled Sobol' points in Morton order
    /// (`zsobol`, the default: less noise at equal samples).
    #[arg(long, value_enum, value_name = "SAMPLER", default_value_t = SamplerArg::Zsobol)]
    pub sampler: SamplerArg,

    /// Russian roulette: continue with probability 0.65 from the second
    /// vertex on (`fixed`, the course's), or after 8 bounces with
    /// probability min(1, the path's throughput times the refractions'
    /// eta scale) (`throughput`, the default; docs/05-global.md).
    #[arg(long, value_enum, value_name = "RULE", default_value_t = RouletteArg::Throughput)]
    pub roulette: RouletteArg,

    /// Caustic casters: at diffuse surfaces, draw a quarter of the path's
    /// directions towards the scene's smooth spheres (mirror, glass,
    /// conductors with alpha <= 0.3), the spheres around its mirror-like
    /// meshes and the lights' images in the mirror-like spheres, weighted
    /// so the image's expectation is unchanged (`auto`, the default),
    /// towards the same spheres without the light images (`spheres`), or
    /// none (`off`, the course's).
    #[arg(long, value_enum, value_name = "RULE", default_value_t = CastersArg::Auto)]
    pub casters: CastersArg,

    /// Glass splits: at the first N glass vertices of the camera's chain
    /// of mirror and glass bounces, follow both reflection and refraction
    /// instead of choosing one by a coin, weighted so the image's
    /// expectation is unchanged (0: the course's coin everywhere; at
    /// most 8). Without it the render plan chooses (2 where the scene has
    /// glass).
    #[arg(long, value_name = "N", value_parser = Number(whole(0u32, MAX_GLASS_SPLITS)))]
    pub glass_splits: Option<u32>,

    /// Glint samples: the pixels whose chains of mirror and glass bounces
    /// may see a small, bright part of the environment map (a sun) take
    /// up to 16 times -s samples, as a pilot of rays before the render
    /// decides, at most half again the render's cost (`auto`, the default,
    /// where the scene has a map and mirror or glass, from -s 16 and
    /// without -a), or every pixel -s (`off`, the course's).
    #[arg(long, value_enum, value_name = "RULE", default_value_t = GlintsArg::Auto)]
    pub glints: GlintsArg,

    /// The course's sampling: `--sampler independent --roulette fixed
    /// --casters off --glass-splits 0 --glints off`.
    #[arg(long, conflicts_with_all = ["sampler", "roulette", "casters", "glass_splits", "glints"])]
    pub course: bool,

    /// The image a correct course solution renders, starter code and
    /// handout included (docs/14-course-image.md): the starter's
    /// estimators, lights, Fresnel and microfacet formulas, random numbers
    /// and roulette, adaptive sampling by default where part 5 is written,
    /// truncated PNG values. `=3-1` or `=3-2` names the assignment; without
    /// it, 3-1 for parts 1 to 5 and 3-2 for parts 6 to 8 and `pathtracer`.
    #[arg(long, value_enum, value_name = "ASSIGNMENT", num_args = 0..=1,
          require_equals = true,
          conflicts_with_all = BEYOND_THE_COURSE)]
    pub course_exact: Option<Option<AssignmentArg>>,

    /// Make one of the catalogue's mistakes students make, to see what it
    /// looks like (repeatable; implies --course-exact); `--mistake list`
    /// prints the catalogue (docs/13-symptoms.md).
    #[arg(long = "mistake", value_name = "NAME",
          conflicts_with_all = BEYOND_THE_COURSE)]
    pub mistakes: Vec<String>,

    /// A choice the handout leaves to the student, for the image of a
    /// correct solution that made it (repeatable; implies
    /// --course-exact), as KEY=VALUE: `roulette-q=Q`, roulette's continuation
    /// probability (0.65 by default); `roulette-from=1` or `2`, the first
    /// vertex whose bounce its coin decides (1, the camera ray's hit; 2,
    /// the course's); `stop=handout` or `staff`, adaptive sampling's test
    /// every batch or one sample late (3-2's default).
    #[arg(long = "course-choice", value_name = "KEY=VALUE",
          conflicts_with_all = BEYOND_THE_COURSE)]
    pub course_choices: Vec<String>,
}

/// `part2-bvh`'s flags: the course's, plus the benchmarks.
#[derive(Parser, Clone, Debug, PartialEq)]
#[command(version, about, args_override_self = true)]
pub struct BvhArgs {
    #[command(flatten)]
    pub course: CourseArgs,

    /// Run the ray-throughput benchmark (1M triangles) instead of rendering.
    #[arg(long)]
    pub bench: bool,

    /// Print build time and ray rates against triangle count, as a table.
    #[arg(long)]
    pub scaling: bool,

    /// The BVH `--bench` traces: the eight-wide SIMD one the renderers use,
    /// or part 2's binary one.
    #[arg(long, value_enum, default_value_t)]
    pub accel: AccelArg,
}

#[cfg(test)]
mod tests;
