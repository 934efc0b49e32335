//! The stage of the checks: a scene loaded once, and what a correct
//! course solution (with or without catalogued mistakes) writes for a
//! check ([`Render`]): its PNG's 8-bit values and, with `-a`, its rate
//! image's sample fractions, rendered by the course's renderer
//! ([`CourseExact::render`]) at the check's flags, through the course's
//! tone map and truncation. A remembering stage keeps its renders for
//! tests that judge the same checks many times.

use std::collections::HashMap;
use std::sync::{Mutex, OnceLock};

use super::battery::{Check, SIZE};
use super::rates;
use super::unwritten::Shadings;
use crate::bvh::WideBvhAccel;
use crate::course::{
    Choices, CourseExact, CourseSampling, CourseView, StarterDirect, StarterTracer,
};
use crate::depth_of_field::ThinLens;
use crate::environment::EnvironmentLight;
use crate::intersect::{Intersector, Primitives};
use crate::math::Rgb;
use crate::mistakes::Mistakes;
use crate::raygen::Camera;
use crate::render::{quantize_display, tone_map, RenderSettings};
use crate::sampling::SamplerKind;
use crate::scene::Scene;

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
    /// The environment map lighting the scene (`-e`), if any.
    environment: Option<EnvironmentLight>,
    /// The starter's first-hit shadings, made when first asked for.
    shadings: OnceLock<Shadings>,
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
            environment: None,
            shadings: OnceLock::new(),
            kept: None,
        }
    }

    /// This stage lit by `environment` (the map of `-e`).
    pub fn lit_by(self, environment: EnvironmentLight) -> Self {
        Stage {
            environment: Some(environment),
            ..self
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

    /// The scene it renders.
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// The starter's first-hit shadings of this stage
    /// ([`super::unwritten::Shadings`]), from each pixel's centre ray;
    /// made once, for every check of the stage.
    pub fn shadings(&self) -> &Shadings {
        let (w, h) = (SIZE.0 as usize, SIZE.1 as usize);
        self.shadings.get_or_init(|| {
            Shadings::new((0..w * h).map(|k| {
                let (x, row) = (k % w, k / w);
                let ray = self.camera.ray(
                    (x as f32 + 0.5) / w as f32,
                    1.0 - (row as f32 + 0.5) / h as f32,
                );
                (ray.dir, self.accel.intersect(&ray).map(|hit| hit.n))
            }))
        })
    }

    /// What a correct course solution (with `mistakes`) writes for
    /// `check` with `seed`: its PNG's values and, with `-a`, its rate
    /// image's fractions. Neither depends on `threads`.
    pub fn render(&self, check: &Check, mistakes: Mistakes, seed: u64, threads: usize) -> Render {
        let choices = Choices::of(check.assignment);
        self.render_chosen(check, choices, mistakes, seed, threads)
    }

    /// What a course solution with `choices` (and `mistakes`) writes for
    /// `check` with `seed`, as [`Stage::render`].
    pub fn render_chosen(
        &self,
        check: &Check,
        choices: Choices,
        mistakes: Mistakes,
        seed: u64,
        threads: usize,
    ) -> Render {
        let solution = (choices, mistakes);
        let Some(kept) = &self.kept else {
            return self.render_anew(check, solution, seed, threads, &|_, _| 1.0);
        };
        let key = format!("{check:?} {choices:?} {mistakes:?} {seed}");
        if let Some(render) = kept.lock().unwrap_or_else(|e| e.into_inner()).get(&key) {
            return render.clone();
        }
        let render = self.render_anew(check, solution, seed, threads, &|_, _| 1.0);
        kept.lock()
            .unwrap_or_else(|e| e.into_inner())
            .insert(key, render.clone());
        render
    }

    /// What a correct solution writes for `check` with `seed` were its
    /// radiance at pixel `(x, y)` `gain(x, y)` times the right one (before
    /// the tone map): a renderer off by a factor everywhere or in a
    /// region, to measure the smallest error a check detects (its power,
    /// docs/maintainers/checker.md). Never kept.
    pub fn render_with_gain(
        &self,
        check: &Check,
        seed: u64,
        threads: usize,
        gain: &dyn Fn(usize, usize) -> f32,
    ) -> Render {
        let solution = (Choices::of(check.assignment), Mistakes::NONE);
        self.render_anew(check, solution, seed, threads, gain)
    }

    /// A render of `solution`: its choices, and the mistakes it makes.
    fn render_anew(
        &self,
        check: &Check,
        (choices, mistakes): (Choices, Mistakes),
        seed: u64,
        threads: usize,
        gain: &dyn Fn(usize, usize) -> f32,
    ) -> Render {
        let exact = CourseExact {
            assignment: check.assignment,
        };
        let tracer = StarterTracer {
            direct: StarterDirect::from_hemisphere(check.hemisphere),
            light_samples: check.light_samples,
            max_depth: check.max_depth,
            accumulate: check.accumulate,
            lamps: exact.lamps(),
            choices,
            mistakes,
        };
        let mut camera = self.camera;
        camera.lens = check.lens.unwrap_or(ThinLens::PINHOLE);
        let view = CourseView {
            scene: &self.scene,
            camera: &camera,
            environment: self.environment.as_ref(),
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
        let width = SIZE.0 as usize;
        let display: Vec<Rgb> = rendered
            .film
            .pixels
            .iter()
            .enumerate()
            .map(|(k, &p)| tone_map(p * gain(k % width, k / width)))
            .collect();
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
