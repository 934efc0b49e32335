//! What judging a check gives: its outcome (pass, fail with the
//! mistakes that fit, skipped, error), and the images the report shows.

use super::battery::Check;
use super::unwritten::Unwritten;
use crate::mistakes::Mistake;

/// A catalogued mistake held against a failed image.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Suspect {
    pub mistake: Mistake,
    /// [`super::stats::statistic`] per cell against the mistake's images (their mean,
    /// their noise or the correct images', the larger): about 1 or less
    /// when it fits.
    pub misfit: f64,
    /// Whether it passes where the correct image failed.
    pub fits: bool,
}

/// What a check found.
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// Both tests of the image passed: `statistic <= threshold`
    /// ([`super::stats::statistic`] and its chi-square quantile) and
    /// `region <= region_threshold` (the region test, [`super::scan`]: the
    /// largest window sum `max |S_w|` over the image's windows). A check
    /// with `-a` holds its rate image's sum in [`RateImages`]. The values
    /// are those of the model it fits.
    Pass {
        statistic: f64,
        threshold: f64,
        region: f64,
        region_threshold: f64,
        /// What the correct solution it fits chose, when not the course's
        /// ([`super::variants::Variant::chose`]).
        variant: Option<&'static str>,
    },
    /// One test failed or both (the values as for a pass; `what` says
    /// which, and where).
    Fail {
        statistic: f64,
        threshold: f64,
        region: f64,
        region_threshold: f64,
        /// What differs and where, in words.
        what: String,
        /// The mistakes that fit, best first, then the rest by misfit.
        suspects: Vec<Suspect>,
    },
    /// The image is the starter's own placeholder: a function still as
    /// handed out ([`super::unwritten`]).
    NotWritten(Unwritten),
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
    /// The command run on the student's binary (in its working folder),
    /// to reproduce the check by hand; empty when it was not run.
    pub command: Vec<String>,
}

impl Outcome {
    /// Its word in the table and the report.
    pub fn word(&self) -> &'static str {
        match self {
            Outcome::Pass { .. } => "pass",
            Outcome::Fail { .. } => "FAIL",
            Outcome::NotWritten(_) => "not written",
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

    /// The best mistake that fits, as the summary names it: with `(+N)`
    /// when N others fit too (a check cannot tell them apart; a later
    /// check, or the report's list, may).
    pub fn likely_mistake_named(&self) -> Option<String> {
        let best = self.likely_mistake()?;
        let fitting = match self {
            Outcome::Fail { suspects, .. } => suspects.iter().filter(|s| s.fits).count(),
            _ => 0,
        };
        Some(if fitting > 1 {
            format!("{best} (+{})", fitting - 1)
        } else {
            best.to_string()
        })
    }
}

/// The 8-bit images of a check (three bytes a pixel, [`super::battery::SIZE`]).
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
    /// The rate images, for a check with `-a`.
    pub rates: Option<RateImages>,
}

/// The sample-rate images of a check with `-a`, and their verdict.
#[derive(Clone, Debug, PartialEq)]
pub struct RateImages {
    /// The student's `check_rate.png` as it wrote it.
    pub student: Vec<u8>,
    /// The course's colours of the null renders' mean fraction per pixel.
    pub reference: Vec<u8>,
    /// Per block, the student's mean fraction over the reference's.
    pub ratio: Vec<f64>,
    /// The mean fraction of samples taken, the student's and the reference's.
    pub student_mean: f64,
    pub reference_mean: f64,
    /// [`super::stats::statistic`] of the rate cells and its threshold.
    pub statistic: f64,
    pub threshold: f64,
}

/// How many suspects the report shows.
pub const SHOWN_SUSPECTS: usize = 3;

#[cfg(test)]
mod tests {
    use super::*;

    fn failed(fits: &[(Mistake, bool)]) -> Outcome {
        Outcome::Fail {
            statistic: 3.0,
            threshold: 2.0,
            region: 0.0,
            region_threshold: 1.0,
            what: String::new(),
            suspects: fits
                .iter()
                .map(|&(mistake, fits)| Suspect {
                    mistake,
                    misfit: if fits { 0.1 } else { 3.0 },
                    fits,
                })
                .collect(),
        }
    }

    #[test]
    fn the_summary_says_how_many_others_fit_as_well() {
        use Mistake::*;
        let tie = failed(&[
            (TriangleChainedComparison, true),
            (MaxTNotShrunk, true),
            (NoPdf, false),
        ]);
        assert_eq!(tie.likely_mistake(), Some(TriangleChainedComparison));
        assert_eq!(
            tie.likely_mistake_named().as_deref(),
            Some("triangle-chained-comparison (+1)")
        );
        let one = failed(&[(MaxTNotShrunk, true), (NoPdf, false)]);
        assert_eq!(
            one.likely_mistake_named().as_deref(),
            Some("max-t-not-shrunk")
        );
        assert_eq!(failed(&[(NoPdf, false)]).likely_mistake_named(), None);
    }
}
