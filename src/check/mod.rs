//! `check`: runs a student's own `pathtracer` through the course's command
//! line, holds each image against what a correct course solution renders
//! at the same flags, and where one differs, names the catalogued mistakes
//! ([`crate::mistakes`]) whose images fit it.
//!
//! - [`student`]: running the binary (time-out, its own working folder,
//!   its image read back);
//! - [`battery`](mod@battery): the checks, one setting of the flags each;
//! - [`stage`]: the scene loaded once, and the course's renders of the
//!   checks;
//! - [`stats`]: the decision, against the distribution of a correct
//!   solution's images (false alarms at most [`ALPHA`] per battery), and
//!   [`scan`], its test of one region;
//! - [`rates`]: part 5's sample-rate image (`NAME_rate.png`) read back
//!   as the fraction of samples each pixel took, `r = (1 + R - B) / 2`;
//! - [`verdict`]: what differs and where ([`words`]), and which mistakes fit;
//! - [`patterns`]: single-pixel patterns of a failed image (holes, acne,
//!   fireflies) against a correct render's own;
//! - [`unwritten`]: the images of a starter's functions left as handed
//!   out, each named as "not written yet";
//! - [`outcome`]: what a judged check gives: its verdict and the images
//!   the report shows;
//! - [`report`]: `report.html`, one self-contained page;
//! - [`scenes`]: the scenes the checks render: the course's
//!   `CBspheres_lambertian.dae` and `CBspheres_microfacet_al_ag.dae`
//!   (part 6's rough metal) where found (`--scenes DIR`, else
//!   `CS184_SCENES`), else the project's own Cornell box, with copper
//!   balls; for part 2 the box with balls of triangles; for part 6's mirror
//!   and glass a box of the project's, for part 7 balls on a floor under a
//!   sky of the project's ([`sky`], an OpenEXR map the course's loader
//!   reads); each written in the course's dialect
//!   ([`crate::scene::export_scene`]) into the output folder.

pub mod battery;
mod means;
pub mod outcome;
pub mod patterns;
pub mod probe;
pub mod rates;
pub mod report;
pub mod scan;
pub mod scenes;
pub mod sky;
pub mod stage;
pub mod stats;
pub mod student;
pub mod unwritten;
pub mod variants;
pub mod verdict;
pub mod words;

use std::path::{Path, PathBuf};

use crate::scene::Scene;

pub use battery::{battery, Check, Stage};
pub use scenes::{CheckScene, SceneFile, COURSE_SCENE};
pub use student::{wait_at_most, Capabilities, RunError, Student};
pub use verdict::{judge, CheckImages, CheckResult, Outcome, Suspect};

/// The chance that a correct renderer fails one or more checks of a full
/// battery: each of its `n` checks is decided at `ALPHA / n` (a check
/// with `-a` splits that again between its image and its rate image).
pub const ALPHA: f64 = 0.01;

/// The scene file of [`CheckScene::Lambertian`] and the scene as this
/// project loads it ([`CheckScene::file`]).
pub fn scene_for_checks(scenes: Option<&Path>, out: &Path) -> Result<(PathBuf, Scene), String> {
    let from_env = crate::scene::course_files::env_root();
    CheckScene::Lambertian
        .file(scenes.or(from_env.as_deref()), out)
        .map(|f| (f.path, f.scene))
}

/// The summary table: part, check, verdict, the likely mistake and the
/// starter function to look at.
pub fn table(results: &[CheckResult]) -> String {
    let mut text = format!(
        "{:<4} {:<44} {:<8} {:<34} {}\n",
        "part", "check", "verdict", "likely mistake", "look at"
    );
    for r in results {
        let (mistake, function) = match (&r.outcome, r.outcome.likely_mistake()) {
            (_, Some(m)) => (
                r.outcome.likely_mistake_named().unwrap_or_default(),
                m.info().function.to_string(),
            ),
            (Outcome::Fail { .. }, None) => (
                "none known fits".into(),
                format!("{} ({})", r.check.function, r.check.file),
            ),
            (Outcome::NotWritten(u), None) => (
                format!("not written yet (part {})", u.part),
                format!("{} ({})", u.function, u.file),
            ),
            (Outcome::Skipped(why) | Outcome::Error(why), None) => (why.clone(), String::new()),
            _ => (String::new(), String::new()),
        };
        let verdict = r.outcome.word();
        text += &format!(
            "{:<4} {:<44} {:<8} {:<34} {}\n",
            r.check.part, r.check.name, verdict, mistake, function
        );
    }
    text
}
