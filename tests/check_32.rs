//! The checker's checks of assignment 3-2 ([`pathtracer::check`]): part 6
//! (mirror and glass, on the project's box of mirror and glass,
//! [`CheckScene::Specular`]), part 7 (the environment light, `-e` with
//! the project's sky, [`CheckScene::Sky`]) and part 8 (the thin lens,
//! `-b 0.5 -d 3.8`, on the diffuse box). Stand-in students are this project's
//! `pathtracer --course-exact=3-2`, correct or with one of the part's
//! mistakes (`tests/check/bench.rs`). The bench keeps every render, so
//! the null and suspect images of a check are rendered once for all the
//! tests here.

#![cfg(unix)]

#[path = "check/bench.rs"]
mod bench;

use std::time::Duration;

use bench::{all_pass, others_that_fit, refusing, report_is_whole, stand_in_of, Bench, PATHTRACER};
use pathtracer::check::battery::battery_of;
use pathtracer::check::{battery, judge, CheckScene, Outcome};
use pathtracer::course::Assignment;
use pathtracer::mistakes::materials::MICROFACET_MISTAKES;
use pathtracer::mistakes::Mistake;

const THREE_TWO: Assignment = Assignment::PathTracer2;

/// A correct 3-2 binary passes every check, decided each at the 3-2
/// battery's rate (`ALPHA / 4`); the report holds them.
#[test]
fn a_correct_3_2_renderer_passes_parts_6_to_8() {
    let bench = Bench::new();
    // A 3-2 binary's own parts; its parts 1 to 5 are the staff's.
    let checks: Vec<_> = battery_of(THREE_TWO)
        .into_iter()
        .filter(|c| c.part >= 6)
        .collect();
    assert_eq!(
        checks.iter().map(|c| c.part).collect::<Vec<_>>(),
        [6, 6, 7, 8],
        "the 3-2 battery"
    );
    assert_eq!(checks[0].scene, CheckScene::Specular);
    assert_eq!(checks[1].scene, CheckScene::Microfacet);
    assert_eq!(checks[2].scene, CheckScene::Sky);
    let binary = stand_in_of(THREE_TWO, bench.dir.path(), None, 1);
    let results = bench.run(binary, &checks);
    report_is_whole(&results, bench.dir.path());
    all_pass(results);
}

/// Each of `mistakes`, injected into a 3-2 stand-in, fails the check of
/// `part` and is named first, fitting, and no other fits (measured: every
/// one first, its misfit 0.4 a cell or less, the next one's 2.1 or more).
fn each_fails_and_is_named_first(part: u8, mistakes: &[Mistake]) {
    let bench = Bench::new();
    let check = battery(&[part])
        .into_iter()
        .find(|c| c.suspects().contains(&mistakes[0]))
        .expect("a check of the part suspects it");
    for &mistake in mistakes {
        let binary = stand_in_of(THREE_TWO, bench.dir.path(), Some(mistake), 3);
        let results = bench.run(binary, &[check]);
        match &results[0].outcome {
            Outcome::Fail {
                what,
                suspects,
                statistic,
                threshold,
                region,
                region_threshold,
            } => {
                eprintln!(
                    "{mistake}: {statistic:.0} of {threshold:.0}, region {region:.1} of {region_threshold:.1}; {what}; {:?}",
                    &suspects[..2]
                );
                // Held out of the catalogue, it would be "none known
                // fits", not another mistake (measured: none fits).
                let others = others_that_fit(suspects, mistake);
                assert!(others.is_empty(), "{mistake}: {others:?} fit too");
                assert!(
                    suspects[0].mistake == mistake && suspects[0].fits,
                    "{mistake}: {suspects:?}"
                );
            }
            other => panic!("{mistake} passed: {other:?}"),
        }
    }
}

/// Part 6's five mistakes on the box of mirror and glass: the cube shows
/// `no-total-internal-reflection`, the pane `no-eta-squared` (both
/// invisible in balls alone).
#[test]
fn part_6_mistakes_fail_and_are_named_first() {
    each_fails_and_is_named_first(
        6,
        &[
            Mistake::ReflectWrongAxis,
            Mistake::RefractionRatioInverted,
            Mistake::NoEtaSquared,
            Mistake::NoTotalInternalReflection,
            Mistake::SchlickR0NotSquared,
        ],
    );
}

/// Part 6's rough metal: `microfacet-no-4` (4 times too bright),
/// `microfacet-d-no-cos4` (the rough ball a fifth darker, most at its
/// rim) and `microfacet-pdf-no-jacobian` (what the balls reflect darker,
/// their highlights unchanged) on the box of copper balls at `-m 2`.
#[test]
fn microfacet_mistakes_fail_and_are_named_first() {
    each_fails_and_is_named_first(6, &MICROFACET_MISTAKES);
}

/// Part 7's four mistakes under the project's sky.
#[test]
fn part_7_mistakes_fail_and_are_named_first() {
    each_fails_and_is_named_first(
        7,
        &[
            Mistake::EnvPdfNoSin,
            Mistake::EnvPdfNoJacobian,
            Mistake::EnvMapUFlipped,
            Mistake::EnvMapVFlipped,
        ],
    );
}

/// Part 8's two mistakes through the lens of radius 0.5 focused at 3.8.
#[test]
fn part_8_mistakes_fail_and_are_named_first() {
    each_fails_and_is_named_first(8, &[Mistake::LensRadiusUnscaled, Mistake::FocusOnASphere]);
}

/// A binary whose getopt refuses `-e`, `-b` and `-d` (the usage, exit
/// status 1) skips parts 7 and 8, saying why, without running them.
#[test]
fn a_binary_without_a_lens_or_a_map_skips_parts_7_and_8() {
    let bench = Bench::new();
    let body = format!("exec {PATHTRACER} --course-exact=3-2 \"$@\"");
    let student = bench.student(
        refusing(bench.dir.path(), "old.sh", &["-e", "-b", "-d"], &body),
        Duration::from_secs(10),
    );
    let caps = student
        .capabilities(&bench.scene_file, bench.map().as_deref())
        .unwrap();
    assert!(!caps.lens_flag && !caps.environment_flag && caps.adaptive_flag);
    for (part, flag) in [(7, "-e"), (8, "-b")] {
        let check = battery(&[part])[0];
        let (file, stage) = bench.scene_of(&check);
        let r = judge(&check, &student, caps, file, stage, 1e-3, 2);
        assert!(
            matches!(&r.outcome, Outcome::Skipped(why) if why.contains(flag)),
            "{r:?}"
        );
    }
}

/// The measurements of docs/maintainers/checker.md, by hand (`cargo test --profile
/// quick --test check_32 -- --ignored --nocapture`, 2 to 4 minutes on 2
/// cores): per 3-2 check, one null model of 8 renders (as the checker's),
/// then 30 correct renders at new seeds, counting those over the
/// threshold at `alpha` = 0.05 (a correct rule exceeds it in at most 5 %:
/// 8 or more of 30 happen with probability 2e-4 at 5 %) and at the
/// battery's `ALPHA / 4`; then each of the part's mistakes at 5 seeds,
/// counting those over the battery's threshold (asserted: 4 of 5 or more).
#[test]
#[ignore = "a measurement, minutes long"]
fn false_alarms_and_power_measured() {
    use pathtracer::check::battery::SIZE;
    use pathtracer::check::stats::{cells, chi_square_quantile, statistic, NullModel};
    use pathtracer::check::verdict::severity;
    use pathtracer::mistakes::Mistakes;
    let bench = Bench::new();
    for check in battery_of(THREE_TWO).into_iter().filter(|c| c.part >= 6) {
        let (_, stage) = bench.scene_of(&check);
        let image = |mistakes, seed| stage.render(&check, mistakes, seed, 2).image;
        let null: Vec<Vec<u8>> = (0..8).map(|k| image(Mistakes::NONE, 1000 + k)).collect();
        let model = NullModel::new(SIZE.0, SIZE.1, &null);
        let cells_n = model.mean.len() as f64;
        let battery_alpha = pathtracer::check::ALPHA / battery_of(THREE_TWO).len() as f64;
        // The sum of z^2 is tested at half the battery's rate, the scan
        // over regions at the other half (`verdict::severity`).
        let tight = chi_square_quantile(cells_n, battery_alpha / 2.0);
        let cells_of = |im: &[u8]| cells(SIZE.0, SIZE.1, im);
        let judged = |im: &[u8]| {
            let x = cells_of(im);
            let s = statistic(&model.z_scores(&x));
            (
                s,
                severity(&model, &x, 3, 0.05),
                severity(&model, &x, 3, battery_alpha),
            )
        };
        let correct: Vec<(f64, f64, f64)> = (0..30)
            .map(|k| judged(&image(Mistakes::NONE, 50_000 + k)))
            .collect();
        let loose = correct.iter().filter(|c| c.1 > 1.0).count();
        let battery = correct.iter().filter(|c| c.2 > 1.0).count();
        let largest = correct.iter().map(|c| c.0).fold(0.0, f64::max);
        eprintln!(
            "{}: correct: {loose} of 30 fail at 0.05, {battery} at the battery's rate; largest statistic {largest:.0} (its threshold {tight:.0})",
            check.name,
        );
        assert!(loose < 8, "{}", check.name);
        for mistake in check.suspects() {
            let found: Vec<(f64, f64, f64)> = (0..5)
                .map(|k| judged(&image(Mistakes::of(&[mistake]), 60_000 + k)))
                .collect();
            let failed = found.iter().filter(|c| c.2 > 1.0).count();
            let statistics: Vec<f64> = found.iter().map(|c| c.0).collect();
            eprintln!("  {mistake}: {failed} of 5 fail; statistics {statistics:.0?}");
            assert!(failed >= 4, "{mistake}");
        }
    }
}
