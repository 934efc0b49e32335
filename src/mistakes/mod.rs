//! A catalogue of the mistakes students of the course make, each one
//! renderable (`--mistake NAME`, repeatable; `--mistake list` prints them).
//!
//! Each entry names the part and the starter function it belongs to, what
//! is wrong, and what it looks like ([`MistakeInfo`]). A mistake lives in
//! the course's own renderer ([`crate::course`], which `--mistake` turns
//! on), at the line a student would get wrong, as one branch on
//! [`Mistakes::has`]: parts 1, 5 and 8 in [`crate::course::pixel`] (the
//! starter's `raytrace_pixel` and `generate_ray`), parts 3 and 4 in
//! [`crate::course::tracer`], and where a mistake needs more than a
//! changed line, in this module's files ([`direct`], [`materials`],
//! [`environment`]), called from there. The project's own renderer has
//! none, and costs nothing more for them. Parts 1 and 2's intersection and
//! BVH mistakes are not in the catalogue yet. docs/13-symptoms.md shows each one beside the
//! correct image (`cargo run --release --example symptoms`), and
//! `tests/mistakes.rs` checks each one's symptom.
//!
//! To add one: a variant of [`Mistake`] and its entry in
//! [`Mistake::info`] and [`Mistake::ALL`]; the branch where the course's
//! renderer would go wrong; a test of its symptom (`tests/mistakes.rs`,
//! `tests/mistakes_3_2.rs`); how the gallery shows it (`showing` in
//! `examples/symptoms.rs`), then run the gallery again.

pub mod direct;
pub mod environment;
pub mod materials;

pub use direct::{shadow_ray_to_the_light, shadow_ray_without_offset, two_sided_rect_sample};

use std::fmt;

/// One mistake of the catalogue.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum Mistake {
    // Part 1: ray generation.
    FovFullAngle,
    // Part 3: direct lighting.
    NoCosine,
    NoPdf,
    HemispherePdfOneOverPi,
    BrdfIsAlbedo,
    ShadowAcne,
    ShadowRayReachesLight,
    LightFromBehind,
    LightSamplesNotAveraged,
    // Part 4: global illumination.
    RouletteNotDivided,
    EmissionEveryBounce,
    DepthOffByOne,
    NoAccumulationSumsAll,
    ThroughputWithoutCosPdf,
    // Part 5: adaptive sampling.
    AdaptiveNotSquareRooted,
    AdaptiveCountNotUpdated,
    // Part 6: mirror and glass.
    ReflectWrongAxis,
    RefractionRatioInverted,
    NoEtaSquared,
    NoTotalInternalReflection,
    SchlickR0NotSquared,
    // Part 7: environment light.
    EnvPdfNoSin,
    EnvPdfNoJacobian,
    EnvMapUFlipped,
    EnvMapVFlipped,
    // Part 8: depth of field.
    LensRadiusUnscaled,
    FocusOnASphere,
}

/// What the catalogue says of a mistake.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MistakeInfo {
    /// Its name on the command line (`--mistake NAME`).
    pub name: &'static str,
    /// The assignment's part (1 to 8; 6 to 8 are 3-2's).
    pub part: u8,
    /// The starter function a student writes it in.
    pub function: &'static str,
    /// What is wrong, in one line.
    pub what: &'static str,
    /// What the image shows, in one line.
    pub symptom: &'static str,
}

impl Mistake {
    /// Every mistake, in the catalogue's order (by part).
    pub const ALL: [Mistake; 27] = [
        Mistake::FovFullAngle,
        Mistake::NoCosine,
        Mistake::NoPdf,
        Mistake::HemispherePdfOneOverPi,
        Mistake::BrdfIsAlbedo,
        Mistake::ShadowAcne,
        Mistake::ShadowRayReachesLight,
        Mistake::LightFromBehind,
        Mistake::LightSamplesNotAveraged,
        Mistake::RouletteNotDivided,
        Mistake::EmissionEveryBounce,
        Mistake::DepthOffByOne,
        Mistake::NoAccumulationSumsAll,
        Mistake::ThroughputWithoutCosPdf,
        Mistake::AdaptiveNotSquareRooted,
        Mistake::AdaptiveCountNotUpdated,
        Mistake::ReflectWrongAxis,
        Mistake::RefractionRatioInverted,
        Mistake::NoEtaSquared,
        Mistake::NoTotalInternalReflection,
        Mistake::SchlickR0NotSquared,
        Mistake::EnvPdfNoSin,
        Mistake::EnvPdfNoJacobian,
        Mistake::EnvMapUFlipped,
        Mistake::EnvMapVFlipped,
        Mistake::LensRadiusUnscaled,
        Mistake::FocusOnASphere,
    ];

    /// The catalogue's entry.
    pub fn info(self) -> MistakeInfo {
        let (name, part, function, what, symptom) = match self {
            Mistake::FovFullAngle => (
                "fov-full-angle",
                1,
                "Camera::generate_ray",
                "the sensor's half-width taken as tan(hFov), not tan(hFov / 2)",
                "the view about twice as wide: the scene small in the middle of a dark frame",
            ),
            Mistake::NoCosine => (
                "no-cosine",
                3,
                "estimate_direct_lighting_hemisphere / _importance",
                "the cosine at the shading point, cos(theta) = wi.z, is left out",
                "surfaces seen by the light at a grazing angle are too bright: walls near the ceiling, the floor far from the lamp",
            ),
            Mistake::NoPdf => (
                "no-pdf",
                3,
                "estimate_direct_lighting_hemisphere / _importance",
                "a sample is not divided by its pdf",
                "-H: 2 pi times too dark; light sampling: too bright by the light's pdf, a small lamp's several per steradian",
            ),
            Mistake::HemispherePdfOneOverPi => (
                "hemisphere-pdf-1-over-pi",
                3,
                "estimate_direct_lighting_hemisphere",
                "the uniform hemisphere's pdf taken as 1/pi instead of 1/(2 pi)",
                "-H: twice too dark; light sampling unchanged",
            ),
            Mistake::BrdfIsAlbedo => (
                "brdf-is-albedo",
                3,
                "DiffuseBSDF::f",
                "the diffuse BRDF returns the albedo, not albedo / pi",
                "everything lit is pi times too bright (clipped to white)",
            ),
            Mistake::ShadowAcne => (
                "shadow-acne",
                3,
                "estimate_direct_lighting_importance",
                "shadow rays start at the hit point with min_t = 0, without the EPS_F offset",
                "speckles of shadow (acne) all over lit surfaces",
            ),
            Mistake::ShadowRayReachesLight => (
                "shadow-ray-reaches-light",
                3,
                "estimate_direct_lighting_importance",
                "the shadow ray's max_t is not shortened before the light, so the lamp's own mesh blocks it",
                "no direct light from the lamp: the room is black but for the lamp",
            ),
            Mistake::LightFromBehind => (
                "light-from-behind",
                3,
                "estimate_direct_lighting_importance",
                "light samples from behind a one-sided light are counted (its cosine taken as |cos|)",
                "the ceiling above the lamp is lit",
            ),
            Mistake::LightSamplesNotAveraged => (
                "light-samples-not-averaged",
                3,
                "estimate_direct_lighting_importance",
                "the sum over an area light's -l samples is not divided by their number",
                "direct light -l times too bright (the same as the correct image at -l 1)",
            ),
            Mistake::RouletteNotDivided => (
                "roulette-not-divided",
                4,
                "at_least_one_bounce_radiance",
                "a path that survives Russian roulette is not divided by its probability 0.65",
                "indirect light too dark: shadows and the ceiling darker, direct light unchanged",
            ),
            Mistake::EmissionEveryBounce => (
                "emission-every-bounce",
                4,
                "at_least_one_bounce_radiance",
                "the emission a bounced ray finds is added at every bounce, besides light sampling",
                "light counted twice: too bright, most near the lamp",
            ),
            Mistake::DepthOffByOne => (
                "depth-off-by-one",
                4,
                "at_least_one_bounce_radiance",
                "the depth test lets one bounce more through than -m says",
                "-m N renders like -m N+1: -m 1 shows indirect light",
            ),
            Mistake::NoAccumulationSumsAll => (
                "o0-accumulates",
                4,
                "at_least_one_bounce_radiance",
                "-o 0 returns the sum of every bounce instead of the m-th alone",
                "-o 0 renders like -o 1",
            ),
            Mistake::ThroughputWithoutCosPdf => (
                "throughput-without-cos-pdf",
                4,
                "at_least_one_bounce_radiance",
                "the bounced light is multiplied by f alone, not by f cos / pdf",
                "indirect light pi times too dark on diffuse surfaces",
            ),
            Mistake::AdaptiveNotSquareRooted => (
                "adaptive-n-not-square-rooted",
                5,
                "PathTracer::raytrace_pixel",
                "the confidence half-width taken as 1.96 sigma / n, not 1.96 sigma / sqrt(n)",
                "pixels stop at the first check: the rate image almost all blue, the image noisier",
            ),
            Mistake::AdaptiveCountNotUpdated => (
                "adaptive-count-not-updated",
                5,
                "PathTracer::raytrace_pixel",
                "the pixel's sample count is left at ns_aa when it stops early",
                "the rate image all red; pixels that stopped early too dark by the share of samples they took",
            ),
            Mistake::ReflectWrongAxis => (
                "reflect-wrong-axis",
                6,
                "BSDF::reflect",
                "wo reflected through the tangent plane, (wo.x, wo.y, -wo.z), not about the normal, (-wo.x, -wo.y, wo.z)",
                "a mirror ball turns dark inside a bright ring: its rays head into the ball instead of away",
            ),
            Mistake::RefractionRatioInverted => (
                "refraction-ratio-inverted",
                6,
                "BSDF::refract",
                "Snell's law with the ratio of indices upside down (ior entering, 1 / ior leaving)",
                "glass looks like a mirror: light that meets it from outside is mostly totally reflected, and what enters bends the wrong way",
            ),
            Mistake::NoEtaSquared => (
                "no-eta-squared",
                6,
                "GlassBSDF::sample_f, RefractionBSDF::sample_f",
                "the transmitted radiance is not divided by eta^2",
                "nothing on a closed glass object seen from outside (the factors entering and leaving cancel); a single refracting surface is eta^2 too bright or too dark",
            ),
            Mistake::NoTotalInternalReflection => (
                "no-total-internal-reflection",
                6,
                "GlassBSDF::sample_f",
                "when refract() fails (total internal reflection) the sample returns no light instead of reflecting",
                "glass balls look the same (light inside a ball never meets the critical angle); glass of other shapes turns black where light should reflect inside, like the sides of a block seen through its top",
            ),
            Mistake::SchlickR0NotSquared => (
                "schlick-r0-not-squared",
                6,
                "GlassBSDF::sample_f",
                "Schlick's R0 = ((1 - ior) / (1 + ior))^2 taken without the square",
                "glass reflects about five times too much near normal incidence: strong reflections of the lamp and the walls on glass",
            ),
            Mistake::EnvPdfNoSin => (
                "env-pdf-no-sin",
                7,
                "EnvironmentLight::sample_L",
                "the density per steradian left without the 1 / sin(theta) of the lat-long map's Jacobian",
                "light from near the horizon too strong, from near the poles too weak: a biased, brighter image",
            ),
            Mistake::EnvPdfNoJacobian => (
                "env-pdf-no-jacobian",
                7,
                "EnvironmentLight::sample_L",
                "the density per steradian left without the 1 / (2 pi^2) of the lat-long map's Jacobian",
                "direct light from the map 2 pi^2 (about 20) times too dark",
            ),
            Mistake::EnvMapUFlipped => (
                "env-map-u-flipped",
                7,
                "EnvironmentLight::sample_dir, sample_L",
                "the map read with u (the azimuth) flipped",
                "the environment mirrored left to right: the sun and the shadows on the other side",
            ),
            Mistake::EnvMapVFlipped => (
                "env-map-v-flipped",
                7,
                "EnvironmentLight::sample_dir, sample_L",
                "the map read with v (the polar angle) flipped",
                "the environment upside down: sky below, ground above, objects lit from below",
            ),
            Mistake::LensRadiusUnscaled => (
                "lens-radius-unscaled",
                8,
                "Camera::generate_ray_for_thin_lens",
                "the point on the lens taken on the unit disk, not scaled by the lens radius -b",
                "everything but the plane of focus blurred as by a lens of radius 1, whatever -b says",
            ),
            Mistake::FocusOnASphere => (
                "focus-on-a-sphere",
                8,
                "Camera::generate_ray_for_thin_lens",
                "the point in focus taken at distance d along the normalised pinhole ray, not on the plane z = -d",
                "the focus curves towards the lens away from the image's centre: the corners focus nearer than -d",
            ),
        };
        MistakeInfo {
            name,
            part,
            function,
            what,
            symptom,
        }
    }

    /// The mistake named `name` on the command line.
    pub fn from_name(name: &str) -> Option<Mistake> {
        Mistake::ALL.into_iter().find(|m| m.info().name == name)
    }

    /// The catalogue as text, one mistake a line group (`--mistake list`).
    pub fn catalogue() -> String {
        let mut text = String::new();
        for m in Mistake::ALL {
            let info = m.info();
            text += &format!(
                "{} (part {}, {})\n    wrong: {}\n    shows: {}\n",
                info.name, info.part, info.function, info.what, info.symptom
            );
        }
        text
    }
}

impl fmt::Display for Mistake {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.info().name)
    }
}

/// A set of mistakes (none by default).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Mistakes(u64);

impl Mistakes {
    /// No mistake: the correct course solution.
    pub const NONE: Mistakes = Mistakes(0);

    /// The set holding `mistakes`.
    pub fn of(mistakes: &[Mistake]) -> Self {
        mistakes.iter().fold(Mistakes::NONE, |set, &m| set.with(m))
    }

    /// This set with `mistake` too.
    pub fn with(self, mistake: Mistake) -> Self {
        Mistakes(self.0 | 1 << mistake as u8)
    }

    /// Whether the set holds `mistake`.
    #[inline]
    pub fn has(self, mistake: Mistake) -> bool {
        self.0 & (1 << mistake as u8) != 0
    }

    pub fn is_empty(self) -> bool {
        self.0 == 0
    }

    /// The mistakes of the set, in the catalogue's order.
    pub fn iter(self) -> impl Iterator<Item = Mistake> {
        Mistake::ALL.into_iter().filter(move |&m| self.has(m))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_unique_and_found_again() {
        for m in Mistake::ALL {
            assert_eq!(Mistake::from_name(m.info().name), Some(m));
            let info = m.info();
            assert!((1..=8).contains(&info.part), "{m}");
            assert!(!info.what.is_empty() && !info.symptom.is_empty(), "{m}");
        }
        let mut names: Vec<_> = Mistake::ALL.iter().map(|m| m.info().name).collect();
        names.sort();
        names.dedup();
        assert_eq!(names.len(), Mistake::ALL.len());
        assert_eq!(Mistake::from_name("no-such-mistake"), None);
    }

    #[test]
    fn all_lists_every_variant_in_order() {
        for (i, m) in Mistake::ALL.into_iter().enumerate() {
            assert_eq!(m as usize, i, "{m}");
        }
    }

    #[test]
    fn a_set_holds_what_it_was_given() {
        let set = Mistakes::of(&[Mistake::NoPdf, Mistake::DepthOffByOne]);
        assert!(set.has(Mistake::NoPdf) && set.has(Mistake::DepthOffByOne));
        assert!(!set.has(Mistake::NoCosine));
        assert_eq!(
            set.iter().collect::<Vec<_>>(),
            [Mistake::NoPdf, Mistake::DepthOffByOne]
        );
        assert!(Mistakes::NONE.is_empty());
    }
}
