//! The error measure of the convergence studies (their scenes and renders:
//! `setup.rs`).
//!
//! Error of an image `Y` (pixel luminances) against a reference `R`
//! rendered once per study with many samples and another seed, over the
//! `P` pixels that show no emitter:
//!
//! ```text
//! e = sqrt( 1/P sum_i (Y_i - R_i)^2  -  1/P sum_i SE_R,i^2 ) / (1/P sum_i R_i)
//! ```
//!
//! Pixels where any of 8 x 8 sub-pixel rays hits an emissive surface (or,
//! lit by an environment map, escapes and sees the map) are left out: the
//! edge of a light ten times brighter than the walls makes their variance
//! (the camera's sampling of the pixel area, the same for every lighting
//! estimator) outweigh the rest of the image.
//!
//! `E (Y_i - R_i)^2 = Var Y_i + Var R_i + bias_i^2` for independent
//! renders, so subtracting the reference's own squared standard errors
//! `SE_R,i^2` (which it estimates) leaves the error of `Y` alone, as if the
//! reference were exact.

use pathtracer::math::luminance;
use pathtracer::render::Rendered;

/// Pixel luminances of a reference render and their squared standard
/// errors, and which pixels the error is measured over.
pub struct Reference {
    pub luminance: Vec<f64>,
    pub variance_of_mean: Vec<f64>,
    pub mask: Vec<bool>,
    /// Mean luminance over the masked pixels.
    pub mean: f64,
    pub seconds: f64,
}

impl Reference {
    pub fn new(rendered: &Rendered, mask: Vec<bool>) -> Self {
        let luminance = pixel_luminance(rendered);
        Reference {
            mean: masked_mean(&luminance, &mask),
            variance_of_mean: rendered
                .estimates
                .iter()
                .map(|e| e.variance_of_mean)
                .collect(),
            luminance,
            mask,
            seconds: rendered.stats.seconds,
        }
    }

    /// RMS luminance error of `rendered` against this reference, less the
    /// reference's own noise, relative to the reference's mean luminance.
    pub fn relative_rms_error(&self, rendered: &Rendered) -> f64 {
        let y = pixel_luminance(rendered);
        self.rms_difference(&y, &self.variance_of_mean)
    }

    /// RMS difference of two references less both one's noise, relative
    /// to this one's mean luminance: how far apart their limits are.
    pub fn relative_rms_difference(&self, other: &Reference) -> f64 {
        let noise: Vec<f64> = self
            .variance_of_mean
            .iter()
            .zip(&other.variance_of_mean)
            .map(|(a, b)| a + b)
            .collect();
        self.rms_difference(&other.luminance, &noise)
    }

    fn rms_difference(&self, y: &[f64], noise: &[f64]) -> f64 {
        let squared: Vec<f64> = y
            .iter()
            .zip(&self.luminance)
            .map(|(a, b)| (a - b) * (a - b))
            .collect();
        let mse = masked_mean(&squared, &self.mask) - masked_mean(noise, &self.mask);
        mse.max(0.0).sqrt() / self.mean
    }

    /// RMS of the pixels' relative errors `(Y_i - R_i) / R_i`, less the
    /// reference's noise, over the masked pixels with `R_i` above 1 % of
    /// the mean: the measure the adaptive test aims at (every pixel to a
    /// given fraction of its own mean).
    pub fn rms_pixel_relative_error(&self, rendered: &Rendered) -> f64 {
        let y = pixel_luminance(rendered);
        let (mut sum, mut noise, mut n) = (0.0, 0.0, 0usize);
        let pixels = y
            .iter()
            .zip(&self.luminance)
            .zip(&self.variance_of_mean)
            .zip(&self.mask);
        for (((&y, &r), &v), &m) in pixels {
            if m && r > 0.01 * self.mean {
                sum += (y - r) * (y - r) / (r * r);
                noise += v / (r * r);
                n += 1;
            }
        }
        ((sum - noise) / n.max(1) as f64).max(0.0).sqrt()
    }

    /// The render's own estimate of its relative error over the same
    /// pixels: `Rendered::relative_error`'s formula (RMS of the pixels'
    /// standard errors over their mean luminance) restricted to the mask.
    pub fn own_error(&self, rendered: &Rendered) -> f64 {
        let variance: Vec<f64> = rendered
            .estimates
            .iter()
            .map(|e| e.variance_of_mean)
            .collect();
        masked_mean(&variance, &self.mask).sqrt()
            / masked_mean(&pixel_luminance(rendered), &self.mask)
    }

    /// Mean luminance of `rendered` over the mask, over the reference's.
    pub fn brightness(&self, rendered: &Rendered) -> f64 {
        masked_mean(&pixel_luminance(rendered), &self.mask) / self.mean
    }
}

pub fn masked_mean(values: &[f64], mask: &[bool]) -> f64 {
    let (sum, n) = values
        .iter()
        .zip(mask)
        .filter(|(_, &m)| m)
        .fold((0.0, 0usize), |(s, n), (v, _)| (s + v, n + 1));
    sum / n.max(1) as f64
}

pub fn pixel_luminance(rendered: &Rendered) -> Vec<f64> {
    rendered
        .film
        .pixels
        .iter()
        .map(|&l| luminance(l) as f64)
        .collect()
}

pub fn mean(values: &[f64]) -> f64 {
    values.iter().sum::<f64>() / values.len().max(1) as f64
}

/// One render of a study, measured.
#[derive(Clone, Debug)]
pub struct Measurement {
    pub label: String,
    /// `-s`: the maximum with adaptive sampling.
    pub samples_per_pixel: u32,
    pub mean_samples_per_pixel: f64,
    /// Wall-clock seconds of the render.
    pub seconds: f64,
    /// Relative RMS error against the reference.
    pub error: f64,
    /// RMS of the pixels' relative errors against the reference.
    pub pixel_error: f64,
    /// The estimator's own estimate of its relative standard error.
    pub own_error: Option<f64>,
    /// Mean luminance relative to the reference's.
    pub brightness: f64,
}

impl Measurement {
    pub fn new(label: &str, spp: u32, rendered: &Rendered, reference: &Reference) -> Self {
        let m = Measurement {
            label: label.to_string(),
            samples_per_pixel: spp,
            mean_samples_per_pixel: rendered.mean_samples_per_pixel(),
            seconds: rendered.stats.seconds,
            error: reference.relative_rms_error(rendered),
            pixel_error: reference.rms_pixel_relative_error(rendered),
            own_error: (rendered.samples() > rendered.estimates.len() as u64)
                .then(|| reference.own_error(rendered)),
            brightness: reference.brightness(rendered),
        };
        eprintln!("  {}", m.row());
        m
    }

    /// A row of the Markdown table printed by [`table`].
    pub fn row(&self) -> String {
        let own = self
            .own_error
            .map_or("–".to_string(), |e| format!("{:.2} %", 100.0 * e));
        format!(
            "| {} | {} | {:.1} | {:.3} | {:.2} % | {} | {:.4} | {:.2} % |",
            self.label,
            self.samples_per_pixel,
            self.mean_samples_per_pixel,
            self.seconds,
            100.0 * self.error,
            own,
            self.brightness,
            100.0 * self.pixel_error
        )
    }
}

/// Prints a study's measurements as a Markdown table on stdout.
pub fn table(title: &str, rows: &[Measurement]) {
    println!("\n{title}\n");
    println!("| render | -s | mean spp | seconds | RMS error vs reference | own relative SE | mean luminance / reference | RMS pixel relative error |");
    println!("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
    for m in rows {
        println!("{}", m.row());
    }
}
