//! A course scene (or one made in code) loaded and framed for the
//! galleries, its renders, and the tracers of the binaries the figures
//! stand for. Shared by `examples/gallery31` and `examples/gallery`
//! (`#[path]`); each defines the `Result` and the render size `SIZE` this
//! module uses.

use pathtracer::adaptive::Adaptive;
use pathtracer::bvh::BvhAccel;
use pathtracer::cli::drivers::render_lighting;
use pathtracer::direct::DirectLights;
use pathtracer::environment::EnvironmentLight;
use pathtracer::global::{DirectStrategy, PathTracer, Roulette};
use pathtracer::intersect::Primitives;
use pathtracer::plan::Plan;
use pathtracer::raygen::Camera;
use pathtracer::render::{RenderSettings, Rendered};
use pathtracer::sampling::SamplerKind;
use pathtracer::scene::{course_files, Scene};
use pathtracer::world::{World, WorldOptions};

use crate::{Result, SIZE};

/// The course frames scenes for this size; the galleries render them at
/// their own `SIZE`, of the same aspect, so they show the same view.
const FRAME: (u32, u32) = (480, 360);

/// A scene, its BVH, the camera the course places for [`FRAME`], and what
/// the world is lit and shaded with.
pub struct Setup {
    name: String,
    pub scene: Scene,
    pub accel: BvhAccel,
    pub camera: Camera,
    /// BSDF options and the rest (`--microfacet-sampling`, ...).
    pub options: WorldOptions,
    /// The environment light (`-e`), if any.
    pub environment: Option<EnvironmentLight>,
    threads: usize,
}

impl Setup {
    /// A course scene, found under `$CS184_SCENES`.
    pub fn load(file: &str, threads: usize) -> Result<Self> {
        let path = course_files::find(file).ok_or_else(|| {
            format!(
                "{file} not found ({}); {}",
                course_files::searched(),
                course_files::HOW_TO_ENABLE
            )
        })?;
        Ok(Setup::of(file, pathtracer::scene::load(&path)?, threads))
    }

    /// `scene` (a course scene changed in code, or one made in code),
    /// named `name` in what the renders print.
    pub fn of(name: &str, scene: Scene, threads: usize) -> Self {
        let primitives = Primitives::from_scene(&scene);
        let camera =
            Camera::course_placement(&scene.camera, &primitives.bounds(), FRAME.0, FRAME.1);
        Setup {
            name: name.to_string(),
            scene,
            accel: BvhAccel::new(primitives),
            camera,
            options: WorldOptions::default(),
            environment: None,
            threads,
        }
    }

    pub fn settings(&self, samples_per_pixel: u32, seed: u64) -> RenderSettings {
        RenderSettings {
            width: SIZE.0,
            height: SIZE.1,
            samples_per_pixel,
            threads: Some(self.threads),
            seed,
            // The independent sampler the documented studies were measured with.
            sampler: SamplerKind::Independent,
            progress: false,
        }
    }

    /// Renders as the binaries do: the tracer specialised by the scene's
    /// plan, `spp` camera rays per pixel, adaptive sampling if asked.
    pub fn render(
        &self,
        tracer: &PathTracer,
        spp: u32,
        adaptive: Option<Adaptive>,
        seed: u64,
    ) -> Rendered {
        let world = World::with_options(&self.scene, &self.accel, self.options)
            .with_environment(self.environment.clone());
        let plan = Plan::new(&self.scene, &world.lights, tracer, &self.camera.lens);
        let tracer = plan.specialise(tracer);
        let rendered = render_lighting(
            &world,
            &tracer,
            &self.camera,
            &self.settings(spp, seed),
            adaptive,
        );
        println!(
            "  {}: -s {spp} -m {} -o {}: {:.1} s, mean {:.0} spp",
            self.name,
            tracer.max_depth,
            tracer.accumulate as u8,
            rendered.stats.seconds,
            rendered.mean_samples_per_pixel()
        );
        rendered
    }
}

/// Light sampling with `l` samples per light and MIS (the default flags).
pub fn lights(l: u32) -> DirectStrategy {
    DirectStrategy::Lights(DirectLights {
        samples_per_light: l,
        environment_samples: None,
        mis: true,
    })
}

/// The path tracer of `part4-global`: `-l l -m m -o o`, Russian roulette.
pub fn paths(l: u32, m: u32, accumulate: bool) -> PathTracer {
    PathTracer {
        direct: lights(l),
        max_depth: m,
        accumulate,
        roulette: Roulette::Fixed,
        glass_splits: 0,
    }
}

/// The direct-only tracer of `part3-direct`.
#[allow(dead_code)] // Used by examples/gallery31, not by examples/gallery.
pub fn direct(strategy: DirectStrategy) -> PathTracer {
    PathTracer {
        direct: strategy,
        max_depth: 1,
        accumulate: true,
        roulette: Roulette::Off,
        glass_splits: 0,
    }
}
