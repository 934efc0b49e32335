//! The scene, BVH and camera of a study, and its renders.
//!
//! A study renders a scene at a small size (160 x 120 by default) with the
//! camera the course would place for a 480 x 360 image, so the small image
//! shows the whole Cornell box (the course's field of view follows the
//! output size: a 160 x 120 render would crop the view, see
//! docs/01-raygen.md).

use std::error::Error;
use std::path::{Path, PathBuf};

use glam::Vec2;
use pathtracer::adaptive::Adaptive;
use pathtracer::bvh::BvhAccel;
use pathtracer::cli::drivers::render_lighting;
use pathtracer::environment::EnvironmentLight;
use pathtracer::global::PathTracer;
use pathtracer::intersect::Primitives;
use pathtracer::raygen::Camera;
use pathtracer::render::{pixel_ray, RenderSettings, Rendered};
use pathtracer::sampling::SamplerKind;
use pathtracer::scene::{course_files, Scene};
use pathtracer::world::{World, WorldOptions};

use crate::measure::Reference;

/// Seed of every reference render; test renders use small seeds.
pub const REFERENCE_SEED: u64 = 0x5EED_0000_0000;

/// A loaded scene, its BVH and the camera of a study.
pub struct Setup {
    pub name: String,
    pub scene: Scene,
    pub accel: BvhAccel,
    pub camera: Camera,
    pub width: u32,
    pub height: u32,
    pub threads: Option<usize>,
    /// The environment light of every render (`-e`), if any.
    pub environment: Option<EnvironmentLight>,
    /// The sampler of every render but the reference (which is always
    /// independent, so that its standard errors hold): independent unless
    /// a study says otherwise.
    pub sampler: SamplerKind,
}

impl Setup {
    /// Loads the course scene `file`, found by name under `dir` (`--scenes`)
    /// or else where [`pathtracer::scene::course_files`] looks
    /// (`$CS184_SCENES`), framed as the course frames a 480 x 360 render,
    /// rendered at `width` x `height`.
    pub fn load(
        dir: Option<&Path>,
        file: &str,
        (width, height): (u32, u32),
        threads: Option<usize>,
    ) -> Result<Self, Box<dyn Error>> {
        let path: PathBuf = match dir {
            Some(dir) => course_files::find_in(&[dir.to_path_buf()], file)
                .ok_or_else(|| format!("{file} not found under --scenes {}", dir.display()))?,
            None => course_files::find(file).ok_or_else(|| {
                format!(
                    "{file} not found ({}); {}, or pass --scenes DIR",
                    course_files::searched(),
                    course_files::HOW_TO_ENABLE
                )
            })?,
        };
        let scene = pathtracer::scene::load(&path)?;
        let primitives = Primitives::from_scene(&scene);
        let camera = Camera::course_placement(&scene.camera, &primitives.bounds(), 480, 360);
        Ok(Setup {
            name: file.to_string(),
            scene,
            accel: BvhAccel::new(primitives),
            camera,
            width,
            height,
            threads,
            environment: None,
            sampler: SamplerKind::Independent,
        })
    }

    /// Per pixel, whether none of 8 x 8 sub-pixel rays sees an emitter
    /// (with an environment light, escaping counts as seeing one).
    pub fn emitter_free_pixels(&self) -> Vec<bool> {
        let scene = World::new(&self.scene, &self.accel);
        let (w, h) = (self.width, self.height);
        let sees_emitter = |x, y| {
            (0..64).any(|k| {
                let offset = Vec2::new((k % 8) as f32 + 0.5, (k / 8) as f32 + 0.5) / 8.0;
                let ray = pixel_ray(&self.camera, (w, h), (x, y), offset, Vec2::splat(0.5));
                match scene.trace(&ray) {
                    Some(p) => p.emission != pathtracer::math::Rgb::ZERO,
                    // An escaping ray sees the environment map, if any.
                    None => self.environment.is_some(),
                }
            })
        };
        (0..h)
            .flat_map(|y| (0..w).map(move |x| (x, y)))
            .map(|(x, y)| !sees_emitter(x, y))
            .collect()
    }

    pub fn settings(&self, samples_per_pixel: u32, seed: u64) -> RenderSettings {
        RenderSettings {
            width: self.width,
            height: self.height,
            samples_per_pixel,
            threads: self.threads,
            seed,
            sampler: self.sampler,
            progress: false,
        }
    }

    /// Renders with the library's own pixel loop (what the binaries run).
    pub fn render(
        &self,
        tracer: &PathTracer,
        samples_per_pixel: u32,
        adaptive: Option<Adaptive>,
        seed: u64,
    ) -> Rendered {
        self.render_options(
            tracer,
            WorldOptions::default(),
            samples_per_pixel,
            adaptive,
            seed,
        )
    }

    /// [`Setup::render`] with the BSDF and light options of the flags
    /// (`--microfacet-sampling`, `--schlick`, ...), without adaptive sampling.
    pub fn render_with(
        &self,
        tracer: &PathTracer,
        options: WorldOptions,
        samples_per_pixel: u32,
        seed: u64,
    ) -> Rendered {
        self.render_options(tracer, options, samples_per_pixel, None, seed)
    }

    fn render_options(
        &self,
        tracer: &PathTracer,
        options: WorldOptions,
        samples_per_pixel: u32,
        adaptive: Option<Adaptive>,
        seed: u64,
    ) -> Rendered {
        let settings = self.settings(samples_per_pixel, seed);
        self.render_settings(tracer, options, &settings, adaptive)
    }

    fn render_settings(
        &self,
        tracer: &PathTracer,
        options: WorldOptions,
        settings: &RenderSettings,
        adaptive: Option<Adaptive>,
    ) -> Rendered {
        let scene = World::with_options(&self.scene, &self.accel, options)
            .with_environment(self.environment.clone());
        render_lighting(&scene, tracer, &self.camera, settings, adaptive)
    }

    /// The study's reference: `samples_per_pixel` samples, its own seed.
    pub fn reference(&self, tracer: &PathTracer, samples_per_pixel: u32) -> Reference {
        self.reference_with(tracer, WorldOptions::default(), samples_per_pixel)
    }

    /// [`Setup::reference`] with the options of the flags.
    pub fn reference_with(
        &self,
        tracer: &PathTracer,
        options: WorldOptions,
        samples_per_pixel: u32,
    ) -> Reference {
        let settings = RenderSettings {
            sampler: SamplerKind::Independent,
            ..self.settings(samples_per_pixel, REFERENCE_SEED)
        };
        let rendered = self.render_settings(tracer, options, &settings, None);
        let reference = Reference::new(&rendered, self.emitter_free_pixels());
        eprintln!(
            "reference {}: {} spp, {:.1} s, {} of {} pixels see no emitter, mean luminance {:.4}, own relative error {:.3} %",
            self.name,
            samples_per_pixel,
            reference.seconds,
            reference.mask.iter().filter(|&&m| m).count(),
            reference.mask.len(),
            reference.mean,
            100.0 * reference.own_error(&rendered)
        );
        reference
    }
}
