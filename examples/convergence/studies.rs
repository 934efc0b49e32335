//! The studies: each renders a reference once, then a series of renders,
//! and writes one chart (PNG) and one Markdown table (stdout). One module
//! per part of the assignment; here what they share.

mod adaptive;
mod direct;
mod environment;
mod global;
mod materials;

use std::error::Error;
use std::path::PathBuf;

use pathtracer::direct::{DirectHemisphere, DirectLights};
use pathtracer::global::{DirectStrategy, PathTracer, Roulette};

use crate::measure::Measurement;
use crate::plot::{Chart, Series};
use crate::setup::Setup;

pub use adaptive::adaptive;
pub use direct::{course, direct, samples};
pub use environment::environment;
pub use global::global;
pub use materials::materials;

pub type Result<T> = std::result::Result<T, Box<dyn Error>>;

/// What every study needs to know.
pub struct Options {
    /// `--scenes DIR`; `None`: `$CS184_SCENES` (see `course_files`).
    pub scenes: Option<PathBuf>,
    pub out: PathBuf,
    pub threads: Option<usize>,
    pub size: (u32, u32),
}

impl Options {
    pub fn setup(&self, file: &str) -> Result<Setup> {
        Setup::load(self.scenes.as_deref(), file, self.size, self.threads)
    }
}

const SPHERES: &str = "CBspheres_lambertian.dae";

fn lights(samples_per_light: u32, max_depth: u32, russian_roulette: bool) -> PathTracer {
    PathTracer {
        direct: DirectStrategy::Lights(DirectLights {
            samples_per_light,
            environment_samples: None,
            mis: true,
        }),
        max_depth,
        accumulate: true,
        roulette: if russian_roulette {
            Roulette::Fixed
        } else {
            Roulette::Off
        },
        glass_splits: 0,
    }
}

fn hemisphere(directions: u32) -> PathTracer {
    PathTracer {
        direct: DirectStrategy::Hemisphere(DirectHemisphere {
            samples: directions,
        }),
        max_depth: 1,
        accumulate: true,
        roulette: Roulette::Off,
        glass_splits: 0,
    }
}

/// Error against seconds, one series per group of measurements.
fn error_vs_time(title: &str, groups: &[(&str, &[Measurement])]) -> Chart {
    Chart {
        title: title.to_string(),
        x_label: "render time (s, wall clock, 2 cores)".into(),
        y_label: "relative RMS error (%)".into(),
        log_x: true,
        log_y: true,
        series: groups
            .iter()
            .map(|(name, ms)| {
                Series::new(
                    *name,
                    ms.iter().map(|m| (m.seconds, 100.0 * m.error)).collect(),
                )
            })
            .collect(),
    }
}
