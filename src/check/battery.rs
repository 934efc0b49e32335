//! The checks: per part, the course's flags that isolate it, and the
//! reference renders of the same flags by the course's renderer
//! ([`CourseExact::render`]), with or without a catalogued mistake.
//!
//! Every check renders at [`SIZE`] with a few samples per pixel (the
//! decision reads 16 x 16 pixel blocks). The checks of parts 3 and 4 take
//! fewer than 32, so that adaptive sampling, on by default in a binary
//! whose part 5 is written, never stops a pixel (its test runs every 32
//! samples). Part 5's sets `-a` itself: a batch of 2 and a tolerance of
//! 0.2 at `-s 8`, so that its test runs at 2, 4 and 6 samples and stops
//! about half the pixels of the box at one of them (where a mistake of
//! part 5 moves the most pixels), a quarter of a second a render on 2
//! cores; the reference writes the rate image as the course does
//! ([`super::rates`]).

use std::collections::HashMap;
use std::sync::Mutex;

use super::rates;
use crate::adaptive::Adaptive;
use crate::bvh::WideBvhAccel;
use crate::course::{
    Assignment, CourseExact, CourseSampling, CourseView, Lamps, StarterDirect, StarterTracer,
};
use crate::intersect::Primitives;
use crate::math::Rgb;
use crate::mistakes::{Mistake, Mistakes};
use crate::raygen::Camera;
use crate::render::{quantize_display, tone_map, RenderSettings};
use crate::sampling::SamplerKind;
use crate::scene::Scene;

/// The image size of every check: the course frames a scene whole at
/// 480 x 360 only (smaller sizes zoom in on its middle).
pub const SIZE: (u32, u32) = (480, 360);

/// One check: a setting of the course's flags that isolates a part.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Check {
    pub part: u8,
    /// Its name in the table.
    pub name: &'static str,
    /// The starter function it exercises most.
    pub function: &'static str,
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
}

/// The battery: the checks of `parts` (all written parts when empty).
pub fn battery(parts: &[u8]) -> Vec<Check> {
    let direct = Check {
        part: 3,
        name: "direct light, uniform hemisphere (-H -m 1)",
        function: "PathTracer::estimate_direct_lighting_hemisphere",
        hemisphere: true,
        light_samples: 1,
        max_depth: 1,
        accumulate: true,
        spp: 16,
        adaptive: None,
    };
    let all = [
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
    ];
    all.into_iter()
        .filter(|c| parts.is_empty() || parts.contains(&c.part))
        .collect()
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
        if let Some(a) = self.adaptive {
            flags.extend([
                "-a".to_string(),
                a.batch.to_string(),
                a.tolerance.to_string(),
            ]);
        }
        flags
    }

    /// The mistakes that can show in this check: those of its part and of
    /// the parts before it, which every render goes through; part 5's only
    /// where the check sets `-a` (they change nothing below 32 samples
    /// otherwise).
    pub fn suspects(&self) -> Vec<Mistake> {
        Mistake::ALL
            .into_iter()
            .filter(|m| {
                let part = m.info().part;
                part <= self.part && (part != 5 || self.adaptive.is_some())
            })
            .collect()
    }
}

/// One render of a check as the course's binary writes it.
#[derive(Clone, Debug, PartialEq)]
pub struct Render {
    /// The PNG's 8-bit values, three a pixel.
    pub image: Vec<u8>,
    /// Per pixel, the sample fraction `n / ns_aa` its rate image holds
    /// (through the PNG's colours and 8 bits, [`rates`]), when the check
    /// sets `-a`.
    pub rates: Option<Vec<f64>>,
}

/// A scene ready for the course's renderer at [`SIZE`].
pub struct Stage {
    scene: Scene,
    camera: Camera,
    accel: WideBvhAccel,
    /// The images rendered so far, when the stage keeps them
    /// ([`Stage::remembering`]), by check, mistakes and seed.
    kept: Option<Mutex<HashMap<String, Render>>>,
}

impl Stage {
    pub fn new(scene: Scene) -> Self {
        let primitives = Primitives::from_scene(&scene);
        let camera = Camera::course_placement(&scene.camera, &primitives.bounds(), SIZE.0, SIZE.1);
        Stage {
            accel: WideBvhAccel::new(primitives),
            scene,
            camera,
            kept: None,
        }
    }

    /// A stage that keeps every image it renders (half a megabyte each)
    /// and hands it out again for the same check, mistakes and seed: for
    /// judging the same checks many times, as the checker's tests do. A
    /// battery judges each check once and needs no keeping.
    pub fn remembering(scene: Scene) -> Self {
        Stage {
            kept: Some(Mutex::default()),
            ..Stage::new(scene)
        }
    }

    /// What a correct course solution (with `mistakes`) writes for
    /// `check` with `seed`: its PNG's values and, with `-a`, its rate
    /// image's fractions. Neither depends on `threads`.
    pub fn render(&self, check: &Check, mistakes: Mistakes, seed: u64, threads: usize) -> Render {
        let Some(kept) = &self.kept else {
            return self.render_anew(check, mistakes, seed, threads);
        };
        let key = format!("{check:?} {mistakes:?} {seed}");
        if let Some(render) = kept.lock().unwrap_or_else(|e| e.into_inner()).get(&key) {
            return render.clone();
        }
        let render = self.render_anew(check, mistakes, seed, threads);
        kept.lock()
            .unwrap_or_else(|e| e.into_inner())
            .insert(key, render.clone());
        render
    }

    fn render_anew(&self, check: &Check, mistakes: Mistakes, seed: u64, threads: usize) -> Render {
        let exact = CourseExact {
            assignment: Assignment::PathTracer1,
        };
        let tracer = StarterTracer {
            direct: StarterDirect::from_hemisphere(check.hemisphere),
            light_samples: check.light_samples,
            max_depth: check.max_depth,
            accumulate: check.accumulate,
            lamps: Lamps::MeshFaces,
            mistakes,
        };
        let view = CourseView {
            scene: &self.scene,
            camera: &self.camera,
            environment: None,
        };
        let sampling = CourseSampling {
            settings: RenderSettings {
                width: SIZE.0,
                height: SIZE.1,
                samples_per_pixel: check.spp,
                threads: Some(threads),
                seed,
                sampler: SamplerKind::Independent,
                progress: false,
            },
            adaptive: check.adaptive,
        };
        let rendered = exact.render(view, &self.accel, &tracer, &sampling);
        let display: Vec<Rgb> = rendered.film.pixels.iter().map(|&p| tone_map(p)).collect();
        let rates = check.adaptive.map(|_| {
            let taken: Vec<f64> = rendered
                .estimates
                .iter()
                .map(|e| e.samples as f64 / check.spp.max(1) as f64)
                .collect();
            rates::fractions(&rates::rate_image(&taken))
        });
        Render {
            image: quantize_display(&display, exact.quantization()),
            rates,
        }
    }
}
