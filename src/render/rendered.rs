//! A finished render: the film, what each pixel's samples gave, and how
//! long it took; with the summaries the binaries print.

use std::path::{Path, PathBuf};

use super::{write_png, Film, OutputError, PixelEstimate, RenderStats};
use crate::adaptive::rate_colour;
use crate::math::luminance;

/// The result of [`crate::render::render_tiles`] over pixel estimates.
pub struct Rendered {
    pub film: Film,
    /// Per pixel, row 0 at the top.
    pub estimates: Vec<PixelEstimate>,
    pub stats: RenderStats,
}

impl Rendered {
    pub fn new(width: u32, height: u32, estimates: Vec<PixelEstimate>, stats: RenderStats) -> Self {
        let film = Film {
            width,
            height,
            pixels: estimates.iter().map(|e| e.radiance).collect(),
        };
        Rendered {
            film,
            estimates,
            stats,
        }
    }

    /// Camera rays traced.
    pub fn samples(&self) -> u64 {
        self.estimates.iter().map(|e| e.samples as u64).sum()
    }

    /// Samples left out for a NaN or infinite radiance.
    pub fn rejected(&self) -> u64 {
        self.estimates.iter().map(|e| e.rejected as u64).sum()
    }

    /// Mean camera rays per pixel.
    pub fn mean_samples_per_pixel(&self) -> f64 {
        self.samples() as f64 / self.estimates.len().max(1) as f64
    }

    /// The image's relative error: the root mean square of the pixels'
    /// standard errors (of their mean luminance) over the mean luminance
    /// of the image,
    ///
    /// ```text
    /// e = sqrt(1/P sum_i SE_i^2) / (1/P sum_i Y_i)
    /// ```
    ///
    /// `None` when it cannot be estimated (one sample per pixel, or a black image).
    pub fn relative_error(&self) -> Option<f64> {
        let p = self.estimates.len().max(1) as f64;
        if self.estimates.iter().all(|e| e.samples - e.rejected < 2) {
            return None;
        }
        let mean_squared_error = self
            .estimates
            .iter()
            .map(|e| e.variance_of_mean)
            .sum::<f64>()
            / p;
        let mean = self
            .film
            .pixels
            .iter()
            .map(|&l| luminance(l) as f64)
            .sum::<f64>()
            / p;
        (mean > 0.0).then(|| mean_squared_error.sqrt() / mean)
    }

    /// Writes the course's sample-rate image (`max_samples` = `-s`).
    pub fn write_rate_image(&self, max_samples: u32, path: &Path) -> Result<(), OutputError> {
        let colours: Vec<_> = self
            .estimates
            .iter()
            .map(|e| rate_colour(e.samples, max_samples))
            .collect();
        write_png(self.film.width, self.film.height, &colours, path)
    }
}

/// `NAME_rate.png` beside `NAME.png`, as the course names it.
pub fn rate_image_path(image: &Path) -> PathBuf {
    let stem = image
        .file_stem()
        .map_or("render".into(), |s| s.to_string_lossy().into_owned());
    image.with_file_name(format!("{stem}_rate.png"))
}
