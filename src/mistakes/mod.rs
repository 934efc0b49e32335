//! A catalogue of the mistakes students of the course make, each one
//! renderable (`--mistake NAME`, repeatable; `--mistake list` prints them).
//!
//! Each entry names the part and the starter function it belongs to, what
//! is wrong, and what it looks like ([`MistakeInfo`]). A mistake lives in
//! the course's own renderer ([`crate::course`], which `--mistake` turns
//! on), at the line a student would get wrong, as one branch on
//! [`Mistakes::has`]: the camera's and the pixel loop's (parts 1, 5 and 8)
//! in [`crate::course::pixel`] (the starter's `raytrace_pixel` and
//! `generate_ray`), parts 3 and 4 and the rough metal's in
//! [`crate::course::tracer`], and where
//! a mistake needs more than a changed line, in this module's files
//! ([`direct`], [`materials`], [`environment`]), called from there. Parts
//! 1 and 2's intersection and BVH mistakes live in [`intersect`]'s
//! [`StudentBvh`], the starter's recursive routines, which the course's
//! renderer puts in place of the project's BVH only when one of them is
//! chosen. The project's own renderer has none, and costs nothing more for
//! them. docs/13-symptoms.md shows each one beside the correct image
//! (`cargo run --release --example symptoms`), and
//! `tests/mistakes_1_2.rs`, `tests/mistakes.rs` and `tests/mistakes_3_2.rs` check each one's symptom.
//!
//! To add one: a variant of [`Mistake`] and its entry in
//! [`Mistake::info`] and [`Mistake::ALL`]; the branch where the course's
//! renderer would go wrong; a test of its symptom (`tests/mistakes_1_2.rs`, `tests/mistakes.rs`,
//! `tests/mistakes_3_2.rs`); how the gallery shows it (`showing` in
//! `examples/symptoms/showing.rs`), then run the gallery again.

mod catalogue;
pub mod direct;
pub mod environment;
pub mod intersect;
pub mod materials;

pub use direct::{
    shadow_ray_to_the_light, shadow_ray_without_offset, starter_radiance, two_sided_rect_sample,
};
pub use intersect::StudentBvh;

use std::fmt;

/// One mistake of the catalogue.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum Mistake {
    // Part 1: ray generation and primitive intersection.
    FovFullAngle,
    FovInDegrees,
    RayInCameraSpace,
    TriangleChainedComparison,
    SphereFarRoot,
    BarycentricsPermuted,
    // Part 2: bounding volume hierarchy.
    BoxMissesRaysFromInside,
    TraversalReturnsFirstHit,
    MaxTNotShrunk,
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
    AdaptivePopulationVariance,
    // Part 6: mirror, glass and the rough conductor.
    ReflectWrongAxis,
    RefractionRatioInverted,
    NoEtaSquared,
    NoTotalInternalReflection,
    SchlickR0NotSquared,
    MicrofacetNoFour,
    MicrofacetDNoCos4,
    MicrofacetPdfNoJacobian,
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
    pub const ALL: [Mistake; 39] = [
        Mistake::FovFullAngle,
        Mistake::FovInDegrees,
        Mistake::RayInCameraSpace,
        Mistake::TriangleChainedComparison,
        Mistake::SphereFarRoot,
        Mistake::BarycentricsPermuted,
        Mistake::BoxMissesRaysFromInside,
        Mistake::TraversalReturnsFirstHit,
        Mistake::MaxTNotShrunk,
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
        Mistake::AdaptivePopulationVariance,
        Mistake::ReflectWrongAxis,
        Mistake::RefractionRatioInverted,
        Mistake::NoEtaSquared,
        Mistake::NoTotalInternalReflection,
        Mistake::SchlickR0NotSquared,
        Mistake::MicrofacetNoFour,
        Mistake::MicrofacetDNoCos4,
        Mistake::MicrofacetPdfNoJacobian,
        Mistake::EnvPdfNoSin,
        Mistake::EnvPdfNoJacobian,
        Mistake::EnvMapUFlipped,
        Mistake::EnvMapVFlipped,
        Mistake::LensRadiusUnscaled,
        Mistake::FocusOnASphere,
    ];

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
