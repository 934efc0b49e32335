//! The course's flags as clap parses them; the refusals' messages are in
//! `tests/cli_values.rs`.

use super::*;
use crate::adaptive::Adaptive;
use crate::global::Roulette;
use crate::materials::MicrofacetSampling;
use crate::sampling::SamplerKind;

#[test]
fn course_flags_parse() {
    let a = CourseArgs::try_parse_from([
        "p", "-s", "16", "-t", "2", "-r", "480", "360", "-f", "x.png", "s.dae",
    ])
    .unwrap();
    assert_eq!(
        (a.samples(), a.threads, a.width(), a.height()),
        (16, Some(2), 480, 360)
    );
    assert_eq!(a.output_path(), PathBuf::from("x.png"));
    assert_eq!(a.scene, Some(PathBuf::from("s.dae")));
    let b = CourseArgs::try_parse_from([
        "p", "-l", "4", "-m", "5", "-o", "0", "-a", "16", "0.1", "-H",
    ])
    .unwrap();
    assert_eq!(
        (b.light_samples, b.max_depth(), b.accumulate, b.hemisphere),
        (Some(4), 5, 0, true)
    );
    assert_eq!(
        b.adaptive_settings(),
        Ok(Some(Adaptive {
            batch: 16,
            tolerance: 0.1
        }))
    );
}

#[test]
fn bad_adaptive_settings_are_refused_by_the_parser() {
    for bad in [
        ["p", "-a", "0", "0.1"],
        ["p", "-a", "2.5", "0.1"],
        ["p", "-a", "8", "0"],
        ["p", "-a", "8", "nan"],
    ] {
        assert!(CourseArgs::try_parse_from(bad).is_err(), "{bad:?}");
    }
    // Each -a's two values are BATCH then TOL, whichever -a is last.
    let two = CourseArgs::try_parse_from(["p", "-a", "8", "0.5", "-a", "16", "0.25"]).unwrap();
    assert_eq!(two.adaptive, Some(vec![16.0, 0.25]));
    assert!(CourseArgs::try_parse_from(["p", "-a", "8", "0.5", "-a", "0.25", "16"]).is_err());
    let sizes = CourseArgs::try_parse_from(["p", "-r", "640", "480", "-r", "32", "24"]).unwrap();
    assert_eq!((sizes.width(), sizes.height()), (32, 24));
}

#[test]
fn defaults_are_the_course_defaults_with_a_scene_file() {
    let a = CourseArgs::try_parse_from(["p", "s.dae"]).unwrap();
    assert_eq!(a.defaults(), COURSE_DEFAULTS);
    assert_eq!(
        (a.samples(), a.max_depth(), a.width(), a.height()),
        (1, 1, 800, 600)
    );
    assert_eq!(a.render_settings().samples_per_pixel, 1);
    assert_eq!(
        (a.light_samples, a.accumulate, a.hemisphere),
        (None, 1, false)
    );
    assert_eq!(a.adaptive_settings(), Ok(None));
    assert_eq!(a.output_path(), PathBuf::from("s.png"));
}

#[test]
fn without_a_scene_file_the_defaults_are_the_builtin_render() {
    let a = CourseArgs::try_parse_from(["p"]).unwrap();
    assert_eq!(a.defaults(), BUILTIN_DEFAULTS);
    assert_eq!(
        (a.samples(), a.max_depth(), a.width(), a.height()),
        (64, 5, 480, 360)
    );
    let settings = a.render_settings();
    assert_eq!(
        (settings.samples_per_pixel, settings.width, settings.height),
        (64, 480, 360)
    );
    assert_eq!(
        (a.light_samples, a.accumulate, a.hemisphere),
        (None, 1, false)
    );
    assert_eq!(a.adaptive_settings(), Ok(None));
    assert_eq!(a.output_path(), PathBuf::from("cornell-box.png"));
    // Flags still override: the course's render of the built-in scene.
    let course =
        CourseArgs::try_parse_from(["p", "-s", "1", "-m", "1", "-r", "800", "600"]).unwrap();
    assert_eq!(
        (
            course.samples(),
            course.max_depth(),
            course.width(),
            course.height()
        ),
        (1, 1, 800, 600)
    );
    assert_eq!(a.world_options().bsdf.microfacet, MicrofacetSampling::Auto);
}

#[test]
fn microfacet_sampling_names_parse() {
    for (name, sampling) in [
        ("cosine", MicrofacetSampling::CosineHemisphere),
        ("half-vector", MicrofacetSampling::HalfVector),
        ("visible-normals", MicrofacetSampling::VisibleNormals),
        ("auto", MicrofacetSampling::Auto),
    ] {
        let a = CourseArgs::try_parse_from(["p", "--microfacet-sampling", name]).unwrap();
        assert_eq!(a.world_options().bsdf.microfacet, sampling, "{name}");
    }
    assert!(CourseArgs::try_parse_from(["p", "--microfacet-sampling", "ggx"]).is_err());
    assert!(CourseArgs::try_parse_from(["p", "--half-vector"]).is_err());
}

#[test]
fn sampler_and_roulette_default_to_the_better_ones_and_course_selects_the_courses() {
    let a = CourseArgs::try_parse_from(["p"]).unwrap();
    assert_eq!(
        (a.sampler_kind(), a.roulette()),
        (SamplerKind::ZSobol, Roulette::Throughput)
    );
    assert_eq!(a.render_settings().sampler, SamplerKind::ZSobol);
    let c = CourseArgs::try_parse_from(["p", "--course"]).unwrap();
    assert_eq!(
        (c.sampler_kind(), c.roulette()),
        (SamplerKind::Independent, Roulette::Fixed)
    );
    assert_eq!(c.render_settings().sampler, SamplerKind::Independent);
    let b = CourseArgs::try_parse_from(["p", "--sampler", "independent", "--roulette", "fixed"])
        .unwrap();
    assert_eq!(
        (b.sampler_kind(), b.roulette()),
        (SamplerKind::Independent, Roulette::Fixed)
    );
    assert!(CourseArgs::try_parse_from(["p", "--course", "--sampler", "zsobol"]).is_err());
    assert!(CourseArgs::try_parse_from(["p", "--sampler", "sobol"]).is_err());
}

#[test]
fn bad_values_are_refused() {
    for bad in [
        &["p", "-r", "0", "10"][..],
        &["p", "-s", "0"],
        &["p", "-r", "640"],
        &["p", "-t", "x"],
    ] {
        assert!(CourseArgs::try_parse_from(bad).is_err(), "{bad:?}");
    }
}

/// `--course-choice` sets each of the handout's choices on the
/// assignment's own, implies `--course-exact`, and names a wrong one.
#[test]
fn course_choices_set_the_solutions_choices() {
    use crate::course::pixel::StopRule;
    use crate::course::{Assignment, Choices};
    let a = CourseArgs::try_parse_from([
        "p",
        "--course-choice",
        "roulette-q=0.6",
        "--course-choice",
        "roulette-from=1",
        "--course-choice",
        "stop=staff",
    ])
    .unwrap();
    assert!(a.course_exact(Assignment::PathTracer1).is_some());
    assert_eq!(
        a.course_choices(Assignment::PathTracer1),
        Ok(Choices {
            continue_probability: 0.6,
            roulette_from: 1,
            stop_rule: StopRule::StaffOneLate,
        })
    );
    let plain = CourseArgs::try_parse_from(["p", "--course-exact"]).unwrap();
    assert_eq!(
        plain.course_choices(Assignment::PathTracer2),
        Ok(Choices::of(Assignment::PathTracer2))
    );
    for (bad, says) in [
        ("roulette-q=0", "(0, 1]"),
        ("roulette-q=x", "(0, 1]"),
        ("roulette-from=3", "1 or 2"),
        ("stop=never", "handout or staff"),
        ("speed=2", "the keys are"),
        ("roulette-q", "KEY=VALUE"),
    ] {
        let a = CourseArgs::try_parse_from(["p", "--course-choice", bad]).unwrap();
        let error = a.course_choices(Assignment::PathTracer1).unwrap_err();
        assert!(error.contains(bad) && error.contains(says), "{error}");
    }
    assert!(
        CourseArgs::try_parse_from(["p", "--course", "--course-choice", "stop=staff"]).is_err()
    );
}
