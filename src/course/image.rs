//! The course's whole image of a scene: the world as a course solution
//! sees it ([`CourseExact::world_options`]), the starter's integrator
//! ([`StarterTracer`]) in the starter's pixel loop ([`pixel::render`]),
//! the environment map sampled by the handout's weights, and pixels that
//! stop early written as the solution's stop rule writes them. With one of
//! parts 1 and 2's mistakes chosen, a student's BVH
//! ([`StudentBvh`]) stands in for the given intersector.

use super::{pixel, CourseExact, StarterTracer};
use crate::adaptive::Adaptive;
use crate::environment::EnvironmentLight;
use crate::intersect::Intersector;
use crate::mistakes::StudentBvh;
use crate::raygen::Camera;
use crate::render::{RenderSettings, Rendered};
use crate::scene::Scene;
use crate::world::World;

/// What the course's image is of: a scene, its camera and its
/// environment light (`-e`), if any.
#[derive(Clone, Copy)]
pub struct CourseView<'a> {
    pub scene: &'a Scene,
    pub camera: &'a Camera,
    pub environment: Option<&'a EnvironmentLight>,
}

/// How the image is sampled: the render settings and adaptive sampling.
#[derive(Clone, Copy, Debug)]
pub struct CourseSampling {
    pub settings: RenderSettings,
    pub adaptive: Option<Adaptive>,
}

impl CourseExact {
    /// The image of `view` that `tracer` renders (its mistakes made), on
    /// `intersector` (an accelerator over the scene's primitives).
    pub fn render<I: Intersector>(
        &self,
        view: CourseView,
        intersector: I,
        tracer: &StarterTracer,
        sampling: &CourseSampling,
    ) -> Rendered {
        let mut rendered = if StudentBvh::is_needed(tracer.mistakes) {
            let student = StudentBvh::new(intersector.primitives(), tracer.mistakes);
            self.trace(&self.world(view, student), view.camera, tracer, sampling)
        } else {
            self.trace(
                &self.world(view, intersector),
                view.camera,
                tracer,
                sampling,
            )
        };
        if sampling.adaptive.is_some() {
            (tracer.choices.stop_rule)
                .write_stopped(&mut rendered, sampling.settings.samples_per_pixel);
        }
        rendered
    }

    /// The world of `view` as a course solution sees it, on `intersector`.
    fn world<'a, I: Intersector>(&self, view: CourseView<'a>, intersector: I) -> World<'a, I> {
        let environment = view
            .environment
            .map(|e| e.reweighted(self.environment_weights()));
        World::with_options(view.scene, intersector, self.world_options())
            .with_environment(environment)
    }

    /// Every pixel by the starter's `raytrace_pixel`.
    fn trace<I: Intersector>(
        &self,
        world: &World<I>,
        camera: &Camera,
        tracer: &StarterTracer,
        sampling: &CourseSampling,
    ) -> Rendered {
        let settings = RenderSettings {
            sampler: self.sampler(),
            ..sampling.settings
        };
        pixel::render(
            camera,
            &settings,
            sampling.adaptive.map(|a| (a, tracer.choices.stop_rule)),
            tracer.mistakes,
            |ray, s| tracer.radiance(world, ray, s),
        )
    }
}
