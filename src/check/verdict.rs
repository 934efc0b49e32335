//! One check, decided: the student's render against the null model
//! ([`super::stats`]), what differs and where, and the catalogued mistakes
//! whose images fit it, best first.

use super::battery::{Check, Stage, SIZE};
use super::stats::{self, chi_square_quantile, student_cells, NullModel, BLOCK};
use super::student::{Capabilities, Student};
use crate::math::{luminance, Rgb};
use crate::mistakes::{Mistake, Mistakes};

/// Renders of a correct solution in the null model.
pub const NULL_RENDERS: usize = 8;

/// Renders of each suspected mistake.
pub const SUSPECT_RENDERS: usize = 2;

/// A catalogued mistake held against a failed image.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Suspect {
    pub mistake: Mistake,
    /// [`stats::statistic`] per cell against the mistake's images (their mean,
    /// their noise or the correct images', the larger): about 1 or less
    /// when it fits.
    pub misfit: f64,
    /// Whether it passes where the correct image failed.
    pub fits: bool,
}

/// What a check found.
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// `statistic <= threshold` ([`stats::statistic`] and its chi-square bound).
    Pass { statistic: f64, threshold: f64 },
    Fail {
        statistic: f64,
        threshold: f64,
        /// What differs and where, in words.
        what: String,
        /// The mistakes that fit, best first, then the rest by misfit.
        suspects: Vec<Suspect>,
    },
    /// Not run, and why (a flag the binary lacks).
    Skipped(String),
    /// The binary gave no image: why.
    Error(String),
}

#[derive(Clone, Debug, PartialEq)]
pub struct CheckResult {
    pub check: Check,
    pub outcome: Outcome,
    /// What the report shows, when the binary gave an image.
    pub images: Option<CheckImages>,
}

impl Outcome {
    /// Its word in the table and the report.
    pub fn word(&self) -> &'static str {
        match self {
            Outcome::Pass { .. } => "pass",
            Outcome::Fail { .. } => "FAIL",
            Outcome::Skipped(_) => "skipped",
            Outcome::Error(_) => "error",
        }
    }

    /// The best mistake that fits a failed image, if any.
    pub fn likely_mistake(&self) -> Option<Mistake> {
        match self {
            Outcome::Fail { suspects, .. } => suspects.iter().find(|s| s.fits).map(|s| s.mistake),
            _ => None,
        }
    }
}

/// The 8-bit images of a check (three bytes a pixel, [`SIZE`]).
#[derive(Clone, Debug, PartialEq)]
pub struct CheckImages {
    pub student: Vec<u8>,
    /// The mean of the null model's renders.
    pub reference: Vec<u8>,
    /// Per block, the student's luminance over the reference's, in
    /// radiance (display ratio to the power 2.2).
    pub ratio: Vec<f64>,
    /// The best suspects' images (a render of each), best first.
    pub suspects: Vec<(Mistake, Vec<u8>)>,
}

/// How many suspects the report shows.
pub const SHOWN_SUSPECTS: usize = 3;

/// Runs `check` with `student` on the scene file `scene_file` (which
/// `stage` holds loaded) and decides it at false-alarm rate `alpha`.
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
    };
    if !check.accumulate && !capabilities.accumulate_flag {
        return result(Outcome::Skipped("the binary has no -o".into()));
    }
    let mut args = check.flags(threads);
    args.push(scene_file.to_string());
    let image = match student.render(&args, "check.png", SIZE) {
        Ok(image) => image,
        Err(e) => return result(Outcome::Error(e.to_string())),
    };
    let x = student_cells(&image);
    let renders: Vec<Vec<u8>> = (0..NULL_RENDERS as u64)
        .map(|seed| stage.render(check, Mistakes::NONE, 1000 + seed, threads))
        .collect();
    let model = NullModel::new(SIZE.0, SIZE.1, &renders);
    let mut images = CheckImages {
        reference: mean_image(&renders),
        ratio: block_ratios(&x, &model.mean),
        student: image.rgb,
        suspects: Vec::new(),
    };
    let threshold = chi_square_quantile(x.len() as f64, alpha);
    let z = model.z_scores(&x);
    let statistic = stats::statistic(&z);
    if statistic <= threshold {
        return CheckResult {
            images: Some(images),
            ..result(Outcome::Pass {
                statistic,
                threshold,
            })
        };
    }
    let mut suspects: Vec<(Suspect, Vec<u8>)> = check
        .suspects()
        .into_iter()
        .map(|mistake| {
            let renders: Vec<Vec<u8>> = (0..SUSPECT_RENDERS as u64)
                .map(|seed| stage.render(check, Mistakes::of(&[mistake]), 2000 + seed, threads))
                .collect();
            let wrong = NullModel::new(SIZE.0, SIZE.1, &renders).widened(&model);
            let s = stats::statistic(&wrong.z_scores(&x));
            let suspect = Suspect {
                mistake,
                misfit: s / x.len() as f64,
                fits: s <= threshold,
            };
            (suspect, renders.into_iter().next().unwrap_or_default())
        })
        .collect();
    suspects.sort_by(|a, b| a.0.misfit.total_cmp(&b.0.misfit));
    images.suspects = suspects
        .iter()
        .take(SHOWN_SUSPECTS)
        .map(|(s, image)| (s.mistake, image.clone()))
        .collect();
    CheckResult {
        images: Some(images),
        ..result(Outcome::Fail {
            statistic,
            threshold,
            what: describe(&x, &model.mean, &z),
            suspects: suspects.into_iter().map(|(s, _)| s).collect(),
        })
    }
}

/// The per-value mean of 8-bit images.
fn mean_image(images: &[Vec<u8>]) -> Vec<u8> {
    let n = images.len().max(1) as f64;
    (0..images.first().map_or(0, Vec::len))
        .map(|i| (images.iter().map(|im| im[i] as f64).sum::<f64>() / n).round() as u8)
        .collect()
}

/// Per block, the luminance ratio of cells `x` over `mean`, in radiance.
fn block_ratios(x: &[f64], mean: &[f64]) -> Vec<f64> {
    let lum = |c: &[f64]| luminance(Rgb::new(c[0] as f32, c[1] as f32, c[2] as f32)) as f64;
    x.chunks(3)
        .zip(mean.chunks(3))
        .map(|(a, b)| match (lum(a), lum(b)) {
            (a, b) if a <= 0.0 && b <= 0.0 => 1.0,
            (a, b) => (a / b).powf(2.2),
        })
        .collect()
}

/// What differs, in words: the brightness ratio (linear, from the display
/// values' ratio to the power 2.2) and where the cells that differ most lie.
fn describe(x: &[f64], mean: &[f64], z: &[f64]) -> String {
    let (sx, sm): (f64, f64) = (x.iter().sum(), mean.iter().sum());
    let ratio = if sm > 0.0 {
        (sx / sm).powf(2.2)
    } else {
        f64::INFINITY
    };
    let bw = SIZE.0.div_ceil(BLOCK) as usize;
    let bh = SIZE.1.div_ceil(BLOCK) as usize;
    let far: Vec<usize> = (0..z.len()).filter(|&i| z[i] > 4.0).collect();
    let share = far.len() as f64 / z.len() as f64;
    let (mut cx, mut cy) = (0.0, 0.0);
    for &i in &far {
        let b = i / 3;
        cx += (b % bw) as f64 / bw as f64;
        cy += (b / bw) as f64 / bh as f64;
    }
    let n = far.len().max(1) as f64;
    let (cx, cy) = (cx / n, cy / n);
    let third = |v: f64, names: [&'static str; 3]| names[((v * 3.0) as usize).min(2)];
    let place = if far.is_empty() {
        "no block alone far off: a small difference spread over the image".to_string()
    } else if share > 0.6 {
        "all over the image".to_string()
    } else {
        format!(
            "mostly {} {}",
            third(cy, ["top", "middle", "bottom"]),
            third(cx, ["left", "centre", "right"])
        )
    };
    format!(
        "{:.2} times as bright as the course's image (radiance); {:.0} % of the 16 x 16 blocks differ, {place}",
        ratio,
        100.0 * share
    )
}
