//! The checker's part 5 check ([`pathtracer::check`]): adaptive sampling
//! at `-s 8 -a 2 0.2`, the image and the sample-rate image
//! (`check_rate.png`) held against a correct solution's. Stand-in
//! students are this project's `pathtracer --course-exact=3-1`, correct
//! or with one of part 5's mistakes (`tests/check/bench.rs`); the rate
//! statistic's false alarms and power are measured in process.

#![cfg(unix)]

#[path = "check/bench.rs"]
mod bench;

use std::time::Duration;

use bench::{
    others_that_fit, refusing, report_is_whole, script, stand_in, stand_in_choosing, Bench,
    PATHTRACER,
};
use pathtracer::adaptive::Adaptive;
use pathtracer::check::battery::SIZE;
use pathtracer::check::rates::RATE_ROUNDING;
use pathtracer::check::stats::{block_means, NullModel};
use pathtracer::check::verdict::severity;
use pathtracer::check::{battery, judge, Capabilities, Check, Outcome};
use pathtracer::mistakes::{Mistake, Mistakes};

/// The battery's part 5 check.
fn part5() -> Check {
    let checks = battery(&[5]);
    assert_eq!(checks.len(), 1);
    assert!(checks[0].adaptive.is_some());
    checks[0]
}

/// The rate fractions `rates` against `model` at false-alarm rate
/// `alpha`, as the checker decides them (its sum of `z^2` and its scan
/// over regions): above 1, they fail.
fn rate_severity(model: &NullModel, rates: &[f64], alpha: f64) -> f64 {
    severity(model, &block_means(SIZE.0, SIZE.1, 1, rates), 1, alpha)
}

/// The rate image's null model of `check` (8 renders, as the checker's).
fn rate_model(bench: &Bench, check: &Check) -> NullModel {
    let fractions: Vec<Vec<f64>> = (0..8)
        .map(|seed| {
            let render = bench.stage.render(check, Mistakes::NONE, 1000 + seed, 2);
            render.rates.expect("a check with -a has rates")
        })
        .collect();
    NullModel::of_values(SIZE.0, SIZE.1, 1, &fractions, RATE_ROUNDING)
}

/// A correct stand-in passes; each of part 5's mistakes fails the check
/// and is named first, and no other fits; the report shows both rate
/// images of each.
#[test]
fn part_5_mistakes_fail_and_are_named_first() {
    let bench = Bench::new();
    let check = part5();
    let mut all = bench.run(stand_in(bench.dir.path(), None, 1), &[check]);
    assert!(
        matches!(all[0].outcome, Outcome::Pass { .. }),
        "{:?}",
        all[0].outcome
    );
    for mistake in [
        Mistake::AdaptiveNotSquareRooted,
        Mistake::AdaptiveCountNotUpdated,
        Mistake::AdaptivePopulationVariance,
    ] {
        let r = bench
            .run(stand_in(bench.dir.path(), Some(mistake), 3), &[check])
            .remove(0);
        let Outcome::Fail { suspects, what, .. } = &r.outcome else {
            panic!("{mistake} passed: {:?}", r.outcome);
        };
        eprintln!("{mistake}: {what}; {:?}", &suspects[..3]);
        // Held out of the catalogue, it would be "none known fits".
        let others = others_that_fit(suspects, mistake);
        assert!(others.is_empty(), "{mistake}: {others:?} fit too");
        assert_eq!(suspects[0].mistake, mistake, "{suspects:?}");
        assert!(suspects[0].fits, "{suspects:?}");
        all.push(r);
    }
    report_is_whole(&all, bench.dir.path());
    let page = pathtracer::check::report::html("student", "scene.dae", &all);
    assert_eq!(page.matches("alt=\"your rate image\"").count(), all.len());
    for r in &all {
        let rates = r.images.as_ref().and_then(|i| i.rates.as_ref());
        let rates = rates.expect("a part 5 result has its rate images");
        assert_eq!(rates.student.len(), rates.reference.len());
    }
}

/// A 3-1 solution that tests convergence one sample late and writes a
/// pixel that stopped as the staff's library does (`n / (n - 1)` of its
/// mean, `n - 1` samples) fails the handout's model and passes as that
/// variant.
#[test]
fn the_staffs_stop_rule_passes_as_that_variant() {
    let bench = Bench::new();
    let binary = stand_in_choosing(bench.dir.path(), &["stop=staff"], 4);
    let r = bench.run(binary, &[part5()]).remove(0);
    let Outcome::Pass { variant, .. } = r.outcome else {
        panic!("{:?}", r.outcome);
    };
    assert_eq!(
        variant,
        Some("tests convergence one sample late, as the staff's library does")
    );
}

/// The rate statistic's false alarms, measured: 16 rate images of a
/// correct solution (in process, independent seeds) against one null
/// model at `alpha` = 0.1. At a true rate of 10 % or less, 8 or more
/// alarms in 16 happen with probability below 1e-4 (binomial tail,
/// 6.1e-5).
#[test]
fn the_rate_statistics_false_alarms_are_bounded() {
    let bench = Bench::new();
    let check = part5();
    let model = rate_model(&bench, &check);
    let values: Vec<f64> = (0..16)
        .map(|seed| {
            let render = bench.stage.render(&check, Mistakes::NONE, 50_000 + seed, 2);
            rate_severity(&model, &render.rates.unwrap(), 0.1)
        })
        .collect();
    let alarms = values.iter().filter(|&&s| s > 1.0).count();
    eprintln!("rate severity at alpha 0.1: {values:.2?}; {alarms} alarms");
    assert!(alarms < 8, "{alarms} of 16");
}

/// The rate statistic's power: a tolerance 10 % off either way (a
/// renderer whose pixels stop a little too early or too late) fails at
/// the battery's rate, where the same tolerance at a new seed passes.
#[test]
fn a_tolerance_ten_percent_off_fails_the_rates() {
    let bench = Bench::new();
    let check = part5();
    let model = rate_model(&bench, &check);
    let alpha = pathtracer::check::ALPHA / battery(&[]).len() as f64 / 2.0;
    let adaptive = check.adaptive.unwrap();
    for (scale, fails) in [(1.0, false), (0.9, true), (1.1, true)] {
        let student = Check {
            adaptive: Some(Adaptive {
                tolerance: adaptive.tolerance * scale,
                ..adaptive
            }),
            ..check
        };
        let render = bench.stage.render(&student, Mistakes::NONE, 7, 2);
        let s = rate_severity(&model, &render.rates.unwrap(), alpha);
        eprintln!("tolerance x {scale}: severity {s:.2}");
        assert_eq!(s > 1.0, fails, "x {scale}: {s:.2}");
    }
}

/// A binary without `-a`, or that writes no rate image, skips the check
/// saying why; a rate image of the wrong size is a clear error.
#[test]
fn no_rate_image_is_a_clear_line() {
    let bench = Bench::new();
    let dir = bench.dir.path();
    let check = part5();
    let caps = |adaptive_flag| Capabilities {
        accumulate_flag: true,
        adaptive_flag,
        lens_flag: true,
        environment_flag: true,
    };
    let judged = |body: &str, name: &str, adaptive_flag| {
        let student = bench.student(script(dir, name, body), Duration::from_secs(60));
        let r = judge(
            &check,
            &student,
            caps(adaptive_flag),
            &bench.scene_file,
            bench.stage,
            1e-3,
            2,
        );
        r.outcome
    };
    let run = format!("{PATHTRACER} --course-exact=3-1 --seed 1 \"$@\"");
    let outcome = judged(&format!("exec {run}"), "old-year.sh", false);
    assert!(
        matches!(&outcome, Outcome::Skipped(why) if why.contains("-a")),
        "{outcome:?}"
    );
    let outcome = judged(&format!("{run} && rm check_rate.png"), "no-rate.sh", true);
    assert!(
        matches!(&outcome, Outcome::Skipped(why) if why.contains("check_rate.png")),
        "{outcome:?}"
    );
    let small = format!(
        "{run} && {PATHTRACER} --course-exact=3-1 -r 64 48 -s 1 -f small.png && mv small_rate.png check_rate.png"
    );
    let outcome = judged(&small, "small-rate.sh", true);
    assert!(
        matches!(&outcome, Outcome::Error(why) if why.contains("check_rate.png") && why.contains("64x48")),
        "{outcome:?}"
    );
    // What a tiny render with -a says: the project's binary takes it; one
    // whose getopt refuses it (the usage, exit status 1) has none; one
    // that renders nothing at all is taken to have it, and its checks say
    // how it fails.
    let map = bench.map();
    for (body, adaptive) in [
        (format!("exec {PATHTRACER} \"$@\""), true),
        (format!("exec {PATHTRACER} --course-exact=3-1 \"$@\""), true),
        ("exit 0".to_string(), true),
    ] {
        let student = bench.student(script(dir, "usage.sh", &body), Duration::from_secs(60));
        let caps = student.capabilities(&bench.scene_file, map.as_deref());
        assert_eq!(caps.unwrap().adaptive_flag, adaptive, "{body}");
    }
    let body = format!("exec {PATHTRACER} \"$@\"");
    let student = bench.student(
        refusing(dir, "no-a.sh", &["-a"], &body),
        Duration::from_secs(60),
    );
    let caps = student
        .capabilities(&bench.scene_file, map.as_deref())
        .unwrap();
    assert_eq!(
        caps,
        Capabilities {
            adaptive_flag: false,
            ..Capabilities::ALL
        }
    );
}
