//! Small renders of the course scenes (skipped, saying so, without the
//! course's files: see `common::course`): the path tracer with every
//! direct-lighting strategy and every BSDF option stays finite on real
//! meshes and every material of the course.

mod common;

use common::{course_scenes, tracer, HEMISPHERE, LIGHTS};
use pathtracer::bvh::BvhAccel;
use pathtracer::cli::drivers::render_lighting;
use pathtracer::direct::DirectLights;
use pathtracer::global::DirectStrategy;
use pathtracer::intersect::Primitives;
use pathtracer::materials::{BsdfOptions, FresnelModel, MicrofacetSampling};
use pathtracer::raygen::Camera;
use pathtracer::render::RenderSettings;
use pathtracer::sampling::SamplerKind;
use pathtracer::world::{World, WorldOptions};

/// Small renders of every course scene stay finite: samples with a NaN or
/// infinite radiance are counted in `Rendered::rejected()` and left out,
/// so the film has no non-finite pixel. Skipped (saying so) without the
/// course's files.
#[test]
fn course_scenes_render_without_nan_or_infinity() {
    let Some(files) = course_scenes() else {
        return;
    };
    let settings = RenderSettings {
        width: 64,
        height: 48,
        samples_per_pixel: 2,
        threads: Some(1),
        seed: 7,
        sampler: SamplerKind::default(),
        progress: false,
    };
    for path in files {
        let scene = pathtracer::scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
        let primitives = Primitives::from_scene(&scene);
        let camera = Camera::course_placement(
            &scene.camera,
            &primitives.bounds(),
            settings.width,
            settings.height,
        );
        let accel = BvhAccel::new(primitives);
        let course_options = WorldOptions {
            bsdf: BsdfOptions {
                fresnel: FresnelModel::Schlick,
                microfacet: MicrofacetSampling::HalfVector,
                ..BsdfOptions::default()
            },
            ..WorldOptions::default()
        };
        let no_mis = DirectStrategy::Lights(DirectLights {
            samples_per_light: 2,
            environment_samples: None,
            mis: false,
        });
        let runs = [
            (WorldOptions::default(), LIGHTS),
            (WorldOptions::default(), HEMISPHERE),
            (WorldOptions::default(), DirectStrategy::BsdfOnly),
            (course_options, no_mis),
        ];
        for (options, direct) in runs {
            let st = World::with_options(&scene, &accel, options);
            let rendered = render_lighting(&st, &tracer(direct, 6, true), &camera, &settings, None);
            let name = path.file_name().unwrap().to_string_lossy();
            eprintln!(
                "{name} {direct:?}: {} samples, {} rejected",
                rendered.samples(),
                rendered.rejected()
            );
            assert_eq!(
                rendered.samples(),
                (settings.width * settings.height * settings.samples_per_pixel) as u64
            );
            assert_eq!(
                rendered.film.non_finite_count(),
                0,
                "{name}: non-finite pixels"
            );
            assert_eq!(rendered.rejected(), 0, "{name}: rejected samples");
        }
    }
}
