//! Parts 3 to 7: direct lighting, global illumination, adaptive
//! sampling, materials and the environment light, and the full
//! `pathtracer`. Every part takes `-e FILE` (an environment map).

use super::course::{self, CoursePart};
use super::{build_wide_bvh, prepare, report_render, write_film, Prepared, Result};
use crate::adaptive::Adaptive;
use crate::cli::args::Builtin;
use crate::cli::CourseArgs;
use crate::direct::{DirectHemisphere, DirectLights};
use crate::environment::{
    builtin_sky, EnvironmentError, EnvironmentLight, EnvironmentMap, EnvironmentSampling,
    EnvironmentWeights,
};
use crate::glints::{allocate, Allocation, Decision};
use crate::global::{DirectStrategy, PathTracer, Roulette};
use crate::intersect::Intersector;
use crate::plan::light_samples::with_environment_samples;
use crate::plan::Plan;
use crate::raygen::Camera;
use crate::render::rendered::rate_image_path;
use crate::render::{render_image_with_factors, RenderSettings, Rendered};
use crate::sampling::SamplerKind;
use crate::scene::info::describe;
use crate::scene::Scene;
use crate::world::{Casters, World};

/// Renders `tracer`'s radiance estimate for every pixel, up to `-s`
/// samples each, stopping early where `adaptive` says so.
pub fn render_lighting<I: Intersector>(
    world: &World<I>,
    tracer: &PathTracer,
    camera: &Camera,
    settings: &RenderSettings,
    adaptive: Option<Adaptive>,
) -> Rendered {
    render_lighting_allocated(world, tracer, camera, settings, adaptive, None)
}

/// [`render_lighting`] with each pixel's samples multiplied by its factor
/// in `allocation` ([`crate::glints`]); the pilot's time is counted in the
/// render's.
pub fn render_lighting_allocated<I: Intersector>(
    world: &World<I>,
    tracer: &PathTracer,
    camera: &Camera,
    settings: &RenderSettings,
    adaptive: Option<Adaptive>,
    allocation: Option<&Allocation>,
) -> Rendered {
    let factors = allocation.map(|a| a.factors.as_slice());
    let mut rendered =
        render_image_with_factors(camera, settings, factors, adaptive, |ray, rng| {
            tracer.radiance(world, ray, rng)
        });
    rendered.stats.seconds += allocation.map_or(0.0, |a| a.seconds);
    rendered
}

/// The direct-lighting strategy the flags ask for: `-H` for hemisphere
/// sampling with (number of lights) x `-l` directions, else light sampling
/// with `-l` samples per area light (weighted by MIS unless `--no-mis`),
/// or none with `--bsdf-only`.
pub fn direct_strategy(args: &CourseArgs, scene: &Scene) -> DirectStrategy {
    if args.bsdf_only {
        DirectStrategy::BsdfOnly
    } else if args.hemisphere {
        let lights = scene.lights.len().max(1) as u32;
        DirectStrategy::Hemisphere(DirectHemisphere {
            samples: lights * args.light_samples(),
        })
    } else {
        DirectStrategy::Lights(DirectLights {
            samples_per_light: args.light_samples(),
            environment_samples: None,
            mis: !args.no_mis,
        })
    }
}

/// What a part renders: its path tracer and whether it samples adaptively.
struct Part {
    tracer: PathTracer,
    adaptive: Option<Adaptive>,
    rate_image: bool,
}

/// The environment light the flags ask for: the map of `-e` (read and
/// checked here, errors naming the file), else the built-in sky when the
/// binary asks for it, else none; sampled uniformly with `--env-uniform`,
/// else by importance with its cells weighted by `weights`.
pub fn environment_light(
    args: &CourseArgs,
    weights: EnvironmentWeights,
) -> std::result::Result<Option<EnvironmentLight>, EnvironmentError> {
    let map = match &args.environment {
        Some(path) => EnvironmentMap::load(path)?,
        None if args.builtin_sky => builtin_sky()?,
        None => return Ok(None),
    };
    let sampling = if args.env_uniform {
        EnvironmentSampling::Uniform
    } else {
        EnvironmentSampling::Importance
    };
    Ok(Some(EnvironmentLight::with_weights(map, sampling, weights)))
}

fn run(args: &CourseArgs, part: impl Fn(&Scene) -> Result<Part>) -> Result<()> {
    let Prepared {
        scene,
        primitives,
        camera,
    } = prepare(args)?;
    let environment = environment_light(args, EnvironmentWeights::default())?;
    if let Some(env) = &environment {
        let map = env.map();
        let line = format!(
            "environment: {} ({} x {}), sampled {}",
            map.source(),
            map.width(),
            map.height(),
            match env.sampling {
                EnvironmentSampling::Importance => "by importance",
                EnvironmentSampling::Uniform => "uniformly",
            }
        );
        if args.info {
            crate::say!("{line}")?;
        } else {
            crate::say_err!("{line}");
        }
    }
    let part = part(&scene)?;
    let settings = args.render_settings();
    let glints_off = Decision::off_by_flags(
        args.glints() && !args.no_plan,
        settings.samples_per_pixel,
        part.adaptive.is_some(),
    );
    if args.info {
        crate::cli::say::text(&describe(&scene, &camera))?;
        let mut lights = args.world_options().lights(&scene);
        if let Some(env) = environment {
            lights = lights.with_environment(env);
        }
        let plan = Plan::new(&scene, &lights, &part.tracer, &camera.lens)
            .with_sampler(args.sampler_kind())
            .with_casters(&Casters::new(&scene, &lights, args.world_options().casters))
            .with_glass_splits(args.glass_splits())
            .with_glints(glints_off);
        for line in &plan.lines {
            crate::say!("{line}")?;
        }
        if args.light_samples.is_none() && !args.no_plan {
            let caustics = plan.bsdfs.casts_caustics();
            crate::say!(
                "{}",
                with_environment_samples(&part.tracer, &lights, caustics).1
            )?;
        }
        for w in &plan.warnings {
            crate::say!("plan: note: {w}")?;
        }
        return Ok(());
    }
    let accel = build_wide_bvh(&scene.source, primitives)?;
    let world =
        World::with_options(&scene, &accel, args.world_options()).with_environment(environment);
    let plan = Plan::new(&scene, &world.lights, &part.tracer, &camera.lens)
        .with_glass_splits(args.glass_splits())
        .with_glints(glints_off);
    for warning in &plan.warnings {
        crate::say_err!("warning: {}: {warning}", scene.source);
    }
    let tracer = match (args.no_plan, args.light_samples) {
        (true, _) => part.tracer,
        (false, Some(_)) => plan.specialise(&part.tracer),
        (false, None) => {
            let tracer = plan.specialise(&part.tracer);
            with_environment_samples(&tracer, &world.lights, world.caustics).0
        }
    };
    let allocation = plan
        .glints
        .then(|| allocate(&world, &camera, &settings, tracer.max_depth));
    if let Some(a) = &allocation {
        crate::say_err!(
            "glints: {} pixels take more samples (up to {} times -s), {:.2} % more samples in all ({:.1} % more rays by the pilot's count); pilot {:.3} s (in the render's time)",
            a.pixels_above_one(),
            a.largest(),
            100.0 * a.extra_fraction(),
            100.0 * a.extra_cost,
            a.seconds
        );
    }
    let rendered = render_lighting_allocated(
        &world,
        &tracer,
        &camera,
        &settings,
        part.adaptive,
        allocation.as_ref(),
    );
    report_render(&rendered)?;
    let bound = match settings.sampler {
        SamplerKind::ZSobol => ", assuming independent samples: an upper bound with zsobol",
        SamplerKind::Independent => "",
    };
    match rendered.relative_error() {
        Some(e) => crate::say!("noise: relative standard error {:.2} % (RMS of pixel standard errors / mean luminance{bound})", 100.0 * e)?,
        None => crate::say!("noise: not estimated (needs at least 2 samples per pixel)")?,
    }
    if part.adaptive.is_some() {
        crate::say!(
            "adaptive: mean samples per pixel {:.2} of {}",
            rendered.mean_samples_per_pixel(),
            settings.samples_per_pixel
        )?;
    }
    write_film(&rendered, args)?;
    if part.rate_image {
        let path = rate_image_path(&args.output_path());
        let largest = allocation.as_ref().map_or(1, Allocation::largest);
        rendered.write_rate_image(settings.samples_per_pixel * largest, &path)?;
        crate::say!("wrote {}", path.display())?;
    }
    Ok(())
}

/// `part3-direct`: emission plus direct lighting (`-H` or light sampling).
pub fn part3(args: &CourseArgs) -> Result<()> {
    let course_part = CoursePart {
        direct_only: true,
        ..CoursePart::PART_3_1
    };
    if let Some(done) = course::render(args, course_part) {
        return done;
    }
    run(args, |scene| {
        Ok(Part {
            tracer: PathTracer {
                direct: direct_strategy(args, scene),
                max_depth: 1,
                accumulate: true,
                roulette: Roulette::Off,
                glass_splits: args.glass_splits().unwrap_or(0),
            },
            adaptive: None,
            rate_image: false,
        })
    })
}

/// The path tracer the flags ask for (`-H`, `-l`, `-m`, `-o`, `--roulette`).
fn path_tracer(args: &CourseArgs, scene: &Scene) -> PathTracer {
    PathTracer {
        direct: direct_strategy(args, scene),
        max_depth: args.max_depth(),
        accumulate: args.accumulate == 1,
        roulette: args.roulette(),
        glass_splits: args.glass_splits().unwrap_or(0),
    }
}

/// Part 4's path tracer as the flags ask, with no adaptive sampling and
/// no rate image: parts 4, 6, 7 and 8 differ only in their built-in scene
/// and the flags they document.
fn render_paths(args: &CourseArgs) -> Result<()> {
    run(args, |scene| {
        Ok(Part {
            tracer: path_tracer(args, scene),
            adaptive: None,
            rate_image: false,
        })
    })
}

/// `part4-global`: paths up to `-m` bounces with Russian roulette
/// (`--roulette`).
pub fn part4(args: &CourseArgs) -> Result<()> {
    if let Some(done) = course::render(args, CoursePart::PART_3_1) {
        return done;
    }
    render_paths(args)
}

/// `part5-adaptive`: part 4 with adaptive sampling (`-a`, default 32 0.05)
/// and the sample-rate image.
pub fn part5(args: &CourseArgs) -> Result<()> {
    let course_part = CoursePart {
        part5_written: true,
        rate_image: true,
        ..CoursePart::PART_3_1
    };
    if let Some(done) = course::render(args, course_part) {
        return done;
    }
    run(args, |scene| {
        Ok(Part {
            tracer: path_tracer(args, scene),
            adaptive: Some(args.adaptive_settings()?.unwrap_or_default()),
            rate_image: true,
        })
    })
}

/// `part6-materials`: part 4's path tracer on mirror, glass and
/// microfacet materials; with no scene file, the built-in materials box.
pub fn part6(args: &CourseArgs) -> Result<()> {
    let mut args = args.clone();
    args.builtin = Builtin::MaterialsBox;
    if let Some(done) = course::render(&args, CoursePart::PART_3_2) {
        return done;
    }
    render_paths(&args)
}

/// `part7-environment`: part 4's path tracer lit by an environment map,
/// `-e FILE` or else the built-in sky ([`builtin_sky`]); with no scene
/// file, two spheres on a floor ([`crate::scene::builtin::environment_spheres`]).
pub fn part7(args: &CourseArgs) -> Result<()> {
    let mut args = args.clone();
    args.builtin = Builtin::EnvironmentSpheres;
    args.builtin_sky = true;
    if let Some(done) = course::render(&args, CoursePart::PART_3_2) {
        return done;
    }
    render_paths(&args)
}

/// `part8-dof`: part 4's path tracer through a thin lens (`-b`, `-d`,
/// `--focus-at`).
pub fn part8(args: &CourseArgs) -> Result<()> {
    if let Some(done) = course::render(args, CoursePart::PART_3_2) {
        return done;
    }
    render_paths(args)
}

/// `pathtracer`: parts 1 to 5 with the course's flags; adaptive sampling
/// only with `-a`, the sample-rate image always (as the course writes it).
pub fn pathtracer(args: &CourseArgs) -> Result<()> {
    let course_part = CoursePart {
        rate_image: true,
        ..CoursePart::PART_3_2
    };
    if let Some(done) = course::render(args, course_part) {
        return done;
    }
    run(args, |scene| {
        Ok(Part {
            tracer: path_tracer(args, scene),
            adaptive: args.adaptive_settings()?,
            rate_image: true,
        })
    })
}
