//! One check, decided: the student's render against the null model
//! ([`super::stats`]), what differs and where, and the catalogued mistakes
//! whose images fit it, best first. A check with `-a` also holds the
//! student's rate image against the null renders' ([`super::rates`]). An
//! image that fails the course's solution may fit another correct one
//! ([`super::variants`]): then it passes, and the outcome says which.

use super::battery::{Check, Render, Stage, SIZE};
use super::means::{block_ratios, mean_fractions, mean_image};
use super::patterns;
use super::rates;
use super::scan::{scan, Scan, WINDOW};
use super::stats::{self, chi_square_quantile, NullModel, BLOCK};
use super::student::{Capabilities, Student};
use super::unwritten;
use super::variants;
use super::words::{describe, differing_blocks};
use crate::course::Assignment;
use crate::mistakes::Mistakes;

pub use super::outcome::{CheckImages, CheckResult, Outcome, RateImages, Suspect, SHOWN_SUSPECTS};

/// Renders of a correct solution in the null model.
pub const NULL_RENDERS: usize = 8;

/// Renders of each suspected mistake.
pub const SUSPECT_RENDERS: usize = 2;

/// What a check compares: the image's display values, three a pixel, and
/// with `-a` the rate image's fractions, one a pixel ([`rates`]).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Plane {
    Image,
    Rates,
}

impl Plane {
    /// The planes of `check`.
    fn of(check: &Check) -> &'static [Plane] {
        match check.adaptive {
            Some(_) => &[Plane::Image, Plane::Rates],
            None => &[Plane::Image],
        }
    }

    /// The null model of `renders` in this plane.
    fn model(self, renders: &[Render]) -> NullModel {
        match self {
            Plane::Image => {
                let images: Vec<Vec<u8>> = renders.iter().map(|r| r.image.clone()).collect();
                NullModel::new(SIZE.0, SIZE.1, &images)
            }
            Plane::Rates => {
                let fractions: Vec<Vec<f64>> =
                    renders.iter().filter_map(|r| r.rates.clone()).collect();
                NullModel::of_values(SIZE.0, SIZE.1, 1, &fractions, rates::RATE_ROUNDING)
            }
        }
    }

    /// Values a pixel, cells a block: RGB, or the one rate.
    fn channels(self) -> usize {
        match self {
            Plane::Image => 3,
            Plane::Rates => 1,
        }
    }

    /// The cells of `render` in this plane.
    fn cells(self, render: &Render) -> Vec<f64> {
        match (self, &render.rates) {
            (Plane::Image, _) => stats::cells(SIZE.0, SIZE.1, &render.image),
            (Plane::Rates, Some(f)) => stats::block_means(SIZE.0, SIZE.1, 1, f),
            (Plane::Rates, None) => Vec::new(),
        }
    }
}

/// One plane decided: the cells, their z against the model, the
/// statistic over every cell and the scan over its windows, each tested
/// at half the plane's `alpha` (Bonferroni).
struct Decided {
    x: Vec<f64>,
    z: Vec<f64>,
    statistic: f64,
    threshold: f64,
    scan: Scan,
}

impl Decided {
    fn new(x: &[f64], model: &NullModel, alpha: f64, channels: usize) -> Self {
        let z = model.z_scores(x);
        Decided {
            statistic: stats::statistic(&z),
            threshold: chi_square_quantile(x.len() as f64, alpha / 2.0),
            scan: scan(model, x, &z, channels, alpha / 2.0),
            x: x.to_vec(),
            z,
        }
    }

    fn passes(&self) -> bool {
        self.statistic <= self.threshold && self.scan.passes()
    }

    /// The larger of each test's value over its threshold: above 1, the
    /// plane fails.
    fn severity(&self) -> f64 {
        (self.statistic / self.threshold).max(self.scan.value / self.scan.threshold)
    }
}

/// How far the cells `x` (`channels` a block) are from `model` at
/// false-alarm rate `alpha`, as a check decides a plane: the larger of the
/// statistic over its threshold and the scan over its own; above 1, it
/// fails.
pub fn severity(model: &NullModel, x: &[f64], channels: usize, alpha: f64) -> f64 {
    Decided::new(x, model, alpha, channels).severity()
}

/// Runs `check` with `student` on the scene file `scene_file` (which
/// `stage` holds loaded) and decides it at false-alarm rate `alpha`. A
/// check with `-a` decides the image and the rate image each at
/// `alpha / 2` (Bonferroni: they are not independent) and fails when
/// either fails; its outcome's statistic is the image's, the rate
/// image's is in [`RateImages`].
pub fn judge(
    check: &Check,
    student: &Student,
    capabilities: Capabilities,
    scene_file: &str,
    stage: &Stage,
    alpha: f64,
    threads: usize,
) -> CheckResult {
    let result = |outcome| CheckResult {
        check: *check,
        outcome,
        images: None,
        command: Vec::new(),
    };
    if !check.accumulate && !capabilities.accumulate_flag {
        return result(Outcome::Skipped("the binary has no -o".into()));
    }
    if check.adaptive.is_some() && !capabilities.adaptive_flag {
        return result(Outcome::Skipped(
            "the binary has no -a (adaptive sampling)".into(),
        ));
    }
    if check.lens.is_some() && !capabilities.lens_flag {
        return result(Outcome::Skipped(
            "the binary has no -b and -d (thin lens)".into(),
        ));
    }
    if check.environment && !capabilities.environment_flag {
        return result(Outcome::Skipped(
            "the binary has no -e (environment map)".into(),
        ));
    }
    let mut args = check.flags(threads);
    if check.environment {
        match check
            .scene
            .environment_file(std::path::Path::new(scene_file))
        {
            Some(map) => args.extend(["-e".to_string(), map.to_string_lossy().into_owned()]),
            None => return result(Outcome::Error("the scene has no environment map".into())),
        }
    }
    args.push(scene_file.to_string());
    let command = student.command_line(&args, "check.png");
    let result = |outcome| CheckResult {
        check: *check,
        outcome,
        images: None,
        command: command.clone(),
    };
    let image = match student.render(&args, "check.png", SIZE) {
        Ok(image) => image,
        Err(e) => return result(Outcome::Error(e.to_string())),
    };
    let mut written = Render {
        image: image.rgb,
        rates: None,
    };
    let mut rate_png = Vec::new();
    if check.adaptive.is_some() {
        match student.rate_image("check.png", SIZE) {
            None => {
                return result(Outcome::Skipped(
                    "it wrote check.png but no check_rate.png beside it (a year without the rate image?)".into(),
                ))
            }
            Some(Err(e)) => return result(Outcome::Error(format!("check_rate.png: {e}"))),
            Some(Ok(rate)) => {
                written.rates = Some(rates::fractions(&rate.rgb));
                rate_png = rate.rgb;
            }
        }
    }
    // The staff library's stamp is no part of a 3-2 image: for the
    // placeholders the row above it stands in, for the tests the
    // correct renders' mean.
    let stamped = check.assignment == Assignment::PathTracer2;
    if stamped {
        written.image = unwritten::stamp_from_row_above(&written.image);
    }
    if let Some(u) = unwritten::placeholder(check, &written.image, stage.shadings()) {
        return result(Outcome::NotWritten(u));
    }
    let renders: Vec<Render> = (0..NULL_RENDERS as u64)
        .map(|seed| stage.render(check, Mistakes::NONE, 1000 + seed, threads))
        .collect();
    let images_of: Vec<Vec<u8>> = renders.iter().map(|r| r.image.clone()).collect();
    let reference = mean_image(&images_of);
    if stamped {
        written.image = unwritten::stamp_from(&written.image, &reference);
        // The stamp's pixels record no sample in the rate image either.
        if let Some(rates) = &mut written.rates {
            let mean = mean_fractions(&renders);
            let width = SIZE.0 as usize;
            for (k, r) in rates.iter_mut().enumerate() {
                if k % width < unwritten::STAMP.0 && k / width >= unwritten::STAMP.1 {
                    *r = mean[k];
                }
            }
        }
    }
    let planes = Plane::of(check);
    let alpha = alpha / planes.len() as f64;
    let models: Vec<NullModel> = planes.iter().map(|p| p.model(&renders)).collect();
    let decided: Vec<Decided> = planes
        .iter()
        .zip(&models)
        .map(|(p, m)| Decided::new(&p.cells(&written), m, alpha, p.channels()))
        .collect();
    let mut images = CheckImages {
        reference,
        ratio: block_ratios(&decided[0].x, &models[0].mean),
        student: written.image.clone(),
        suspects: Vec::new(),
        rates: decided.get(1).zip(models.get(1)).map(|(d, m)| RateImages {
            student: rate_png,
            reference: rates::rate_image(&mean_fractions(&renders)),
            ratio: d
                .x
                .iter()
                .zip(&m.mean)
                .map(|(x, mu)| if *mu > 0.0 { x / mu } else { 1.0 })
                .collect(),
            student_mean: rates::mean(written.rates.as_deref().unwrap_or_default()),
            reference_mean: rates::mean(&mean_fractions(&renders)),
            statistic: d.statistic,
            threshold: d.threshold,
        }),
    };
    let pass = |decided: &[Decided], variant: Option<&'static str>| {
        result(Outcome::Pass {
            statistic: decided[0].statistic,
            threshold: decided[0].threshold,
            region: decided[0].scan.value,
            region_threshold: decided[0].scan.threshold,
            variant,
        })
    };
    if decided.iter().all(Decided::passes) {
        return CheckResult {
            images: Some(images),
            ..pass(&decided, None)
        };
    }
    for variant in variants::of(check) {
        let renders: Vec<Render> = (0..NULL_RENDERS as u64)
            .map(|seed| {
                stage.render_chosen(check, variant.choices, Mistakes::NONE, 4000 + seed, threads)
            })
            .collect();
        let judged = held_to(&renders, planes, &models, &decided, alpha);
        if judged.iter().all(Decided::passes) {
            return CheckResult {
                images: Some(images),
                ..pass(&judged, Some(variant.chose))
            };
        }
    }
    let (statistic, threshold) = (decided[0].statistic, decided[0].threshold);
    let (region, region_threshold) = (decided[0].scan.value, decided[0].scan.threshold);
    if check.part == 6 {
        // The starter's BSDFs of part 6 return zero: its surfaces black.
        let black = Stage::new(unwritten::blackened(stage.scene()));
        let renders: Vec<Render> = (0..NULL_RENDERS as u64)
            .map(|seed| black.render(check, Mistakes::NONE, 3000 + seed, threads))
            .collect();
        let model = Plane::Image.model(&renders).widened(&models[0]);
        if Decided::new(&decided[0].x, &model, alpha, 3).passes() {
            return CheckResult {
                images: Some(images),
                ..result(Outcome::NotWritten(unwritten::part_6(check)))
            };
        }
    }
    let cells: usize = decided.iter().map(|d| d.x.len()).sum();
    let mut suspects: Vec<(Suspect, Vec<u8>)> = check
        .suspects()
        .into_iter()
        .map(|mistake| {
            let renders: Vec<Render> = (0..SUSPECT_RENDERS as u64)
                .map(|seed| stage.render(check, Mistakes::of(&[mistake]), 2000 + seed, threads))
                .collect();
            // Held to the mistake's images by both tests, as the
            // student's image was to the course's.
            let judged = held_to(&renders, planes, &models, &decided, alpha);
            let sum: f64 = judged.iter().map(|d| d.statistic).sum();
            let suspect = Suspect {
                mistake,
                misfit: sum / cells as f64,
                fits: judged.iter().all(Decided::passes),
            };
            let image = renders.into_iter().next().map(|r| r.image);
            (suspect, image.unwrap_or_default())
        })
        .collect();
    suspects.sort_by(|a, b| a.0.misfit.total_cmp(&b.0.misfit));
    images.suspects = suspects
        .iter()
        .take(SHOWN_SUSPECTS)
        .map(|(s, image)| (s.mistake, image.clone()))
        .collect();
    let mut what = describe_planes(&decided, &models, check.spp);
    if let Some(patterns) = patterns::describe(&written.image, SIZE.0 as usize, &images_of) {
        what = format!("{what}; {patterns}");
    }
    CheckResult {
        images: Some(images),
        ..result(Outcome::Fail {
            statistic,
            threshold,
            region,
            region_threshold,
            what,
            suspects: suspects.into_iter().map(|(s, _)| s).collect(),
        })
    }
}

/// The student's cells of each plane (in `decided`) held to `renders`
/// (another correct solution's, or a mistake's) by both tests, each
/// plane's noise the larger of theirs and the course's (`models`).
fn held_to(
    renders: &[Render],
    planes: &[Plane],
    models: &[NullModel],
    decided: &[Decided],
    alpha: f64,
) -> Vec<Decided> {
    planes
        .iter()
        .zip(models)
        .zip(decided)
        .map(|((plane, model), d)| {
            let other = plane.model(renders).widened(model);
            Decided::new(&d.x, &other, alpha, plane.channels())
        })
        .collect()
}

/// What differs in each plane that failed, in words.
fn describe_planes(decided: &[Decided], models: &[NullModel], spp: u32) -> String {
    let mut parts = Vec::new();
    for (i, (d, m)) in decided.iter().zip(models).enumerate() {
        if d.passes() {
            continue;
        }
        let mut what = if i == 0 {
            describe(&d.x, &m.mean, &d.z)
        } else {
            let (share, place) = differing_blocks(&d.z, 1);
            format!(
                "the rate image: your pixels took {:.0} % of the {spp} samples on average, a correct solution's {:.0} %; {:.0} % of the blocks differ, {place}",
                100.0 * rates::mean(&d.x),
                100.0 * rates::mean(&m.mean),
                100.0 * share
            )
        };
        if !d.scan.passes() {
            let (x, y) = d.scan.at;
            let side = WINDOW * BLOCK;
            let (how, by) = match (d.scan.brighter, i) {
                (true, 0) => ("brighter", "the course's"),
                (false, 0) => ("darker", "the course's"),
                (true, _) => ("with more samples", "a correct solution's"),
                (false, _) => ("with fewer samples", "a correct solution's"),
            };
            what += &format!(
                "; a region {how} than {by}: the {side} x {side} pixels from ({x}, {y}) (the region test: {:.1} against {:.1})",
                d.scan.value, d.scan.threshold
            );
        }
        parts.push(what);
    }
    if decided.len() > 1 && decided[0].passes() {
        parts.insert(0, "the image is within the noise".into());
    }
    parts.join("; ")
}
