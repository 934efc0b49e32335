//! `--course-exact`: what each lighting binary renders when asked for the
//! image a correct course solution makes ([`crate::course`]).

use super::lighting::environment_light;
use super::{build_wide_bvh, prepare, report_render, Prepared, Result};
use crate::cli::CourseArgs;
use crate::course::{
    Assignment, CourseExact, CourseSampling, CourseView, StarterDirect, StarterTracer,
};
use crate::mistakes::Mistake;
use crate::render::rendered::rate_image_path;
use crate::render::write_image_quantized;
use crate::scene::info::describe;

/// What a binary is, as far as the course's image is concerned.
#[derive(Clone, Copy, Debug)]
pub struct CoursePart {
    /// The assignment `--course-exact` means without `=3-1` or `=3-2`.
    pub assignment: Assignment,
    /// Part 3's binary: direct light only (`-m 1`, whatever `-m` says).
    pub direct_only: bool,
    /// Whether the student has written part 5, so that adaptive sampling
    /// is on by default.
    pub part5_written: bool,
    /// Whether the binary writes the sample-rate image.
    pub rate_image: bool,
}

impl CoursePart {
    /// A binary of parts 1 to 4 of 3-1: no adaptive sampling by default,
    /// no rate image.
    pub const PART_3_1: CoursePart = CoursePart {
        assignment: Assignment::PathTracer1,
        direct_only: false,
        part5_written: false,
        rate_image: false,
    };
    /// A binary of 3-2: parts 1 to 5 written (the staff's), no rate image.
    pub const PART_3_2: CoursePart = CoursePart {
        assignment: Assignment::PathTracer2,
        direct_only: false,
        part5_written: true,
        rate_image: false,
    };
}

/// The course's image of the scene `args` name, or `None` when
/// `--course-exact` is not given.
pub fn render(args: &CourseArgs, part: CoursePart) -> Option<Result<()>> {
    if args.lists_mistakes() {
        return Some(crate::cli::say::text(&Mistake::catalogue()).map_err(Into::into));
    }
    let exact = args.course_exact(part.assignment)?;
    Some(run(args, part, exact))
}

fn run(args: &CourseArgs, part: CoursePart, exact: CourseExact) -> Result<()> {
    let Prepared {
        scene,
        primitives,
        camera,
    } = prepare(args)?;
    // Built with the handout's weights, so the course's render keeps it
    // as it is.
    let environment = environment_light(args, exact.environment_weights())?;
    let tracer = StarterTracer {
        direct: StarterDirect::from_hemisphere(args.hemisphere),
        light_samples: args.light_samples(),
        max_depth: if part.direct_only {
            1
        } else {
            args.max_depth()
        },
        accumulate: part.direct_only || args.accumulate == 1,
        lamps: exact.lamps(),
        choices: args.course_choices(exact.assignment)?,
        mistakes: args.mistake_set()?,
    };
    let adaptive = match args.adaptive_settings()? {
        Some(a) => Some(a),
        None => exact.default_adaptive(part.part5_written),
    };
    let mistakes: Vec<String> = tracer.mistakes.iter().map(|m| m.to_string()).collect();
    let course_line = format!(
        "course-exact: assignment {}, {:?} direct light, -m {}, -o {}, adaptive {}, roulette {} from vertex {}, stop rule {:?}, mistakes: {}",
        exact.assignment.name(),
        tracer.direct,
        tracer.max_depth,
        u8::from(tracer.accumulate),
        adaptive.map_or("off".into(), |a| format!("{} {}", a.batch, a.tolerance)),
        tracer.choices.continue_probability,
        tracer.choices.roulette_from,
        tracer.choices.stop_rule,
        if mistakes.is_empty() {
            "none".into()
        } else {
            mistakes.join(", ")
        },
    );
    if args.info {
        crate::cli::say::text(&describe(&scene, &camera))?;
        crate::say!("{course_line}")?;
        return Ok(());
    }
    crate::say_err!("{course_line}");
    let accel = build_wide_bvh(&scene.source, primitives)?;
    let view = CourseView {
        scene: &scene,
        camera: &camera,
        environment: environment.as_ref(),
    };
    let sampling = CourseSampling {
        settings: args.render_settings(),
        adaptive,
    };
    let rendered = exact.render(view, &accel, &tracer, &sampling);
    report_render(&rendered)?;
    let path = args.output_path();
    write_image_quantized(&rendered.film, &path, exact.quantization())?;
    crate::say!("wrote {}", path.display())?;
    if part.rate_image {
        let rate = rate_image_path(&path);
        rendered.write_rate_image(sampling.settings.samples_per_pixel, &rate)?;
        crate::say!("wrote {}", rate.display())?;
    }
    Ok(())
}
