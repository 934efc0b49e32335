//! The checks: per part, the course's flags that isolate it. Their
//! reference renders, by the course's renderer with or without a
//! catalogued mistake, are the stage's ([`super::stage`]).
//!
//! Every check renders at [`SIZE`] with a few samples per pixel (the
//! decision reads 16 x 16 pixel blocks). The checks of parts 2 to 4 take
//! fewer than 32, so that adaptive sampling, on by default in a binary
//! whose part 5 is written, never stops a pixel (its test runs every 32
//! samples). Part 5's sets `-a` itself: a batch of 2 and a tolerance of
//! 0.2 at `-s 8`, so that its test runs at 2, 4 and 6 samples and stops
//! about half the pixels of the box at one of them (where a mistake of
//! part 5 moves the most pixels), a quarter of a second a render on 2
//! cores; the reference writes the rate image as the course does
//! ([`super::rates`]).
//!
//! Part 2's renders a mesh ([`CheckScene::Mesh`]) in direct light at `-m 1
//! -s 4 -l 1`: a traversal that stops at the first hit or keeps the ray's
//! `max_t` shows the surfaces behind, a box test that misses from inside
//! drops the shadows (every shadow ray starts inside the root's box), and
//! permuted barycentrics reshade the smooth balls. A finished binary has
//! no flag for the normal shading of part 1, so part 1's mistakes are
//! suspects of this check and of every later one of 3-1; so are part 3's,
//! whose light sampling lights the mesh.
//!
//! The checks of assignment 3-2 ([`Check::assignment`]) render as its
//! correct solution does: the staff's parts 1 to 5, the lamps as the
//! lights' own quads ([`crate::course::CourseExact::lamps`]). Part 6's renders the box of
//! mirror and glass ([`CheckScene::Specular`]) at `-m 6 -s 4` (a path
//! through the cube meets several glass faces before a wall), and the
//! rough metal ([`CheckScene::Microfacet`]) at `-m 2 -s 4`, where each
//! ball shows the lamp's highlight (`f`, light sampled) and the lit walls
//! (the bounce `sample_f` draws), part 7's
//! the balls under the project's sky ([`CheckScene::Sky`], `-e`) at
//! `-m 1 -s 4 -l 4`, part 8's the diffuse box at `-m 1 -s 4` through a lens of radius 0.5 focused at
//! 3.8, the box's open front, whose edges against the black outside lie
//! at the image's borders, 15 to 19 degrees off the axis: there a lens
//! that focuses on a sphere of radius `d` instead of the plane `z = -d`
//! focuses at `d cos(theta)`, 0.2 nearer, and blurs them over
//! `f b (1 / (d cos theta) - 1 / d)`, about 6 pixels (`f`, 877 pixels,
//! the focal length of the 480 x 360 image). Measured: that mistake's
//! statistic is four times the threshold there, and only about at it
//! (0.94 to 1.02 times) focused at 4.5 with `-b 0.3`; at the course's
//! `-b 0.05` no block of the box changes by more than 0.2 %.

use super::scenes::CheckScene;
use crate::adaptive::Adaptive;
use crate::course::Assignment;
use crate::depth_of_field::ThinLens;
use crate::mistakes::materials::{MATERIAL_MISTAKES, MICROFACET_MISTAKES};
use crate::mistakes::Mistake;

pub use super::stage::{Render, Stage};

/// The image size of every check: the course frames a scene whole at
/// 480 x 360 only (smaller sizes zoom in on its middle).
pub const SIZE: (u32, u32) = (480, 360);

/// One check: a setting of the course's flags that isolates a part.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Check {
    pub part: u8,
    /// The assignment whose binary it checks: 3-1 or 3-2 for parts 1 to
    /// 5, 3-2 (whose parts 1 to 5 are the staff's library, its lamps the
    /// lights' own quads) for parts 6 to 8. The reference renders as its
    /// correct solution does.
    pub assignment: Assignment,
    /// The scene it renders.
    pub scene: CheckScene,
    /// Its name in the table.
    pub name: &'static str,
    /// The starter function it exercises most.
    pub function: &'static str,
    /// That function's file in the starter.
    pub file: &'static str,
    /// `-H`.
    pub hemisphere: bool,
    /// `-l`.
    pub light_samples: u32,
    /// `-m`.
    pub max_depth: u32,
    /// `-o 1` (true) or `-o 0`; `-o 0` needs a binary that has the flag.
    pub accumulate: bool,
    /// `-s`.
    pub spp: u32,
    /// `-a BATCH TOL`, and the rate image read back; `None`: no `-a` (the
    /// binary's default, which stops no pixel below 32 samples).
    pub adaptive: Option<Adaptive>,
    /// `-b R -d D`: the thin lens, when the check has one.
    pub lens: Option<ThinLens>,
    /// `-e FILE`: the scene's environment map
    /// ([`CheckScene::environment_file`]).
    pub environment: bool,
}

/// The battery: the checks of `parts`, those of parts 1 to 5 for a 3-1
/// binary and those of 6 to 8 for a 3-2 one; those of assignment 3-1
/// when `parts` is empty.
pub fn battery(parts: &[u8]) -> Vec<Check> {
    if parts.is_empty() {
        return battery_of(Assignment::PathTracer1);
    }
    every_check()
        .into_iter()
        .filter(|c| parts.contains(&c.part))
        .collect()
}

/// Every check of `assignment`'s binary: parts 1 to 5 for 3-1; for 3-2
/// those too, rendered as a correct 3-2 binary renders them (the staff's
/// library, its lamps the lights' own quads), then parts 6 to 8.
pub fn battery_of(assignment: Assignment) -> Vec<Check> {
    // Part 1's scene glows, and a 3-2 binary makes every glow nothing.
    let three_two = |c: &Check| assignment == Assignment::PathTracer2 && c.part >= 2;
    every_check()
        .into_iter()
        .filter(|c| c.assignment == assignment || three_two(c))
        .map(|c| Check { assignment, ..c })
        .collect()
}

/// The checks of `parts` (every one when empty) of `assignment`'s binary
/// ([`battery_of`]).
pub fn battery_for(assignment: Assignment, parts: &[u8]) -> Vec<Check> {
    battery_of(assignment)
        .into_iter()
        .filter(|c| parts.is_empty() || parts.contains(&c.part))
        .collect()
}

/// The assignment a binary checked for `parts` is of: 3-2 when any part
/// is 6 or more (only a 3-2 binary has them), else `None` (either).
pub fn assignment_of(parts: &[u8]) -> Option<Assignment> {
    parts
        .iter()
        .any(|&p| p >= 6)
        .then_some(Assignment::PathTracer2)
}

/// The checks of both assignments, by part.
fn every_check() -> Vec<Check> {
    let direct = Check {
        part: 3,
        assignment: Assignment::PathTracer1,
        scene: CheckScene::Lambertian,
        name: "direct light, uniform hemisphere (-H -m 1)",
        function: "PathTracer::estimate_direct_lighting_hemisphere",
        file: "src/pathtracer/pathtracer.cpp",
        hemisphere: true,
        light_samples: 1,
        max_depth: 1,
        accumulate: true,
        spp: 16,
        adaptive: None,
        lens: None,
        environment: false,
    };
    let all = [
        Check {
            part: 1,
            scene: CheckScene::Glowing,
            name: "first hits of camera rays (-m 0)",
            function: "Camera::generate_ray, Triangle::intersect, Sphere::intersect",
            file: "src/pathtracer/camera.cpp, src/scene/triangle.cpp, src/scene/sphere.cpp",
            hemisphere: false,
            max_depth: 0,
            spp: 4,
            ..direct
        },
        Check {
            part: 2,
            scene: CheckScene::Mesh,
            name: "a mesh, direct light (-m 1 -l 1)",
            function: "BVHAccel::intersect",
            file: "src/scene/bvh.cpp, src/scene/bbox.cpp",
            hemisphere: false,
            spp: 4,
            ..direct
        },
        direct,
        Check {
            name: "direct light, light sampling (-l 4 -m 1)",
            function: "PathTracer::estimate_direct_lighting_importance",
            hemisphere: false,
            light_samples: 4,
            spp: 2,
            ..direct
        },
        Check {
            part: 4,
            name: "global illumination (-m 4)",
            function: "PathTracer::at_least_one_bounce_radiance",
            hemisphere: false,
            max_depth: 4,
            spp: 4,
            ..direct
        },
        Check {
            part: 4,
            name: "the second bounce alone (-m 2 -o 0)",
            function: "PathTracer::at_least_one_bounce_radiance",
            hemisphere: false,
            max_depth: 2,
            accumulate: false,
            spp: 4,
            ..direct
        },
        Check {
            part: 5,
            name: "adaptive sampling, rate image (-s 8 -a 2 0.2)",
            function: "PathTracer::raytrace_pixel",
            hemisphere: false,
            spp: 8,
            adaptive: Some(Adaptive {
                batch: 2,
                tolerance: 0.2,
            }),
            ..direct
        },
        Check {
            part: 6,
            assignment: Assignment::PathTracer2,
            scene: CheckScene::Specular,
            name: "mirror and glass (-m 6)",
            function: "GlassBSDF::sample_f",
            file: "src/pathtracer/advanced_bsdf.cpp",
            hemisphere: false,
            max_depth: 6,
            spp: 4,
            ..direct
        },
        Check {
            part: 6,
            assignment: Assignment::PathTracer2,
            scene: CheckScene::Microfacet,
            name: "rough metal (-m 2)",
            function: "MicrofacetBSDF::f / sample_f",
            file: "src/pathtracer/advanced_bsdf.cpp",
            hemisphere: false,
            max_depth: 2,
            spp: 4,
            ..direct
        },
        Check {
            part: 7,
            assignment: Assignment::PathTracer2,
            scene: CheckScene::Sky,
            name: "environment light (-e, -l 4 -m 1)",
            function: "EnvironmentLight::sample_L",
            file: "src/scene/environment_light.cpp",
            hemisphere: false,
            light_samples: 4,
            max_depth: 1,
            spp: 4,
            environment: true,
            ..direct
        },
        Check {
            part: 8,
            assignment: Assignment::PathTracer2,
            name: "thin lens (-b 0.5 -d 3.8)",
            function: "Camera::generate_ray_for_thin_lens",
            file: "src/pathtracer/camera_lens.cpp",
            hemisphere: false,
            max_depth: 1,
            spp: 4,
            lens: Some(ThinLens {
                radius: 0.5,
                focal_distance: 3.8,
            }),
            ..direct
        },
    ];
    all.into()
}

impl Check {
    /// The course's flags for this check (without `-f` and the scene).
    pub fn flags(&self, threads: usize) -> Vec<String> {
        let mut flags = vec![
            "-t".to_string(),
            threads.to_string(),
            "-s".into(),
            self.spp.to_string(),
            "-l".into(),
            self.light_samples.to_string(),
            "-m".into(),
            self.max_depth.to_string(),
            "-r".into(),
            SIZE.0.to_string(),
            SIZE.1.to_string(),
        ];
        if self.hemisphere {
            flags.push("-H".into());
        }
        if !self.accumulate {
            flags.extend(["-o".to_string(), "0".to_string()]);
        }
        if let Some(lens) = self.lens {
            flags.extend([
                "-b".to_string(),
                lens.radius.to_string(),
                "-d".to_string(),
                lens.focal_distance.to_string(),
            ]);
        }
        if let Some(a) = self.adaptive {
            flags.extend([
                "-a".to_string(),
                a.batch.to_string(),
                a.tolerance.to_string(),
            ]);
        }
        flags
    }

    /// The mistakes that can show in this check. Of parts 1 to 5: those
    /// of parts 1 to 3 and of its own part, which every render goes
    /// through (part 2's check lights its mesh by part 3's light
    /// sampling); part 5's only where the check sets `-a` (they change
    /// nothing below 32 samples otherwise). Of parts 6 to 8, whose binary's
    /// parts 1 to 5 are the staff's: part 6's of mirror and glass where
    /// the scene has them, of the rough metal where it has that, part 7's
    /// with a map, part 8's where the check has a lens (each changes
    /// nothing elsewhere).
    pub fn suspects(&self) -> Vec<Mistake> {
        Mistake::ALL
            .into_iter()
            .filter(|m| match (self.part, m.info().part) {
                // A depth test off by one renders any -m as -m + 1, in
                // every check of a binary whose part 4 is written.
                (1..=5, _) if *m == Mistake::DepthOffByOne => true,
                (1..=5, part) => part <= self.part.max(3) && (part != 5 || self.adaptive.is_some()),
                (_, 6) => match self.scene {
                    CheckScene::Specular => MATERIAL_MISTAKES.contains(m),
                    CheckScene::Microfacet => MICROFACET_MISTAKES.contains(m),
                    _ => false,
                },
                (_, 7) => self.environment,
                (_, 8) => self.lens.is_some(),
                _ => false,
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The parts say the assignment; empty, 3-1; mixed, none.
    #[test]
    fn parts_say_which_assignment() {
        assert_eq!(assignment_of(&[]), None);
        assert_eq!(assignment_of(&[3, 5]), None);
        assert_eq!(assignment_of(&[6, 8]), Some(Assignment::PathTracer2));
        assert_eq!(assignment_of(&[5, 6]), Some(Assignment::PathTracer2));
        let parts = |a| battery_of(a).iter().map(|c| c.part).collect::<Vec<_>>();
        assert_eq!(parts(Assignment::PathTracer1), [1, 2, 3, 3, 4, 4, 5]);
        assert_eq!(
            parts(Assignment::PathTracer2),
            [2, 3, 3, 4, 4, 5, 6, 6, 7, 8]
        );
        assert!(battery_of(Assignment::PathTracer2)
            .iter()
            .all(|c| c.assignment == Assignment::PathTracer2));
        assert_eq!(battery(&[]), battery_of(Assignment::PathTracer1));
        let parts_for = |p: &[u8]| battery_for(Assignment::PathTracer2, p).len();
        assert_eq!(
            (parts_for(&[3]), parts_for(&[6, 8]), parts_for(&[])),
            (2, 3, 10)
        );
    }

    /// A check of parts 6 to 8 suspects only its own part's mistakes (its
    /// binary's parts 1 to 5 are the staff's), and passes its lens as `-b
    /// R -d D`; a 3-2 binary's checks of parts 1 to 5 suspect what a 3-1
    /// binary's do.
    #[test]
    fn three_two_checks_suspect_their_own_part() {
        let late = battery_of(Assignment::PathTracer2)
            .into_iter()
            .filter(|c| c.part >= 6);
        for check in late {
            let suspects = check.suspects();
            assert!(!suspects.is_empty());
            assert!(
                suspects.iter().all(|m| m.info().part == check.part),
                "{check:?}"
            );
        }
        let lens = battery(&[8])[0];
        let flags = lens.flags(2).join(" ");
        assert!(flags.ends_with("-b 0.5 -d 3.8"), "{flags}");
        assert_eq!(battery(&[6])[0].suspects().len(), 5);
        assert_eq!(battery(&[6])[1].suspects(), MICROFACET_MISTAKES);
        let early = |a| battery_of(a)[1].suspects();
        assert_eq!(
            early(Assignment::PathTracer2),
            early(Assignment::PathTracer1)
        );
    }
}
