//! The course's sample-rate image (`NAME_rate.png`) read back as numbers.
//!
//! The course colours a pixel that took `n` of at most `ns_aa` samples by
//! its fraction `r = n / ns_aa` ([`crate::adaptive::rate_colour`]):
//! `(0, 2r, 1 - 2r)` up to one half, `(2r - 1, 2 - 2r, 0)` above. Both
//! halves satisfy `R - B = 2r - 1`, so one formula inverts the map:
//!
//! ```text
//! r = (1 + R - B) / 2
//! ```
//!
//! with `R` and `B` the PNG's 8-bit values over 255. Each of `R` and `B`
//! is rounded (or truncated) to 1/255, so `r` is known to within 1/255,
//! with a rounding variance of `2 (1/255)^2 / 12 / 4` ([`RATE_ROUNDING`]).
//! The check compares these fractions per 16 x 16 block, as it does the
//! image's display values ([`super::stats::NullModel::of_values`]).

use crate::adaptive::rate_colour;
use crate::render::{quantize_display, Quantization};

/// The variance of a fraction's 8-bit rounding: half of one value's
/// `(1/255)^2 / 12`, from `(R - B) / 2` (two independent roundings of
/// 1/255 over 2).
pub const RATE_ROUNDING: f64 = super::stats::DISPLAY_ROUNDING / 2.0;

/// The sample fraction `n / ns_aa` a rate-image pixel `rgb` (three 8-bit
/// values) stands for, in `[0, 1]`.
pub fn fraction(rgb: &[u8]) -> f64 {
    let (red, blue) = (rgb[0] as f64 / 255.0, rgb[2] as f64 / 255.0);
    ((1.0 + red - blue) / 2.0).clamp(0.0, 1.0)
}

/// The fractions of a rate image (three bytes a pixel), one a pixel.
pub fn fractions(rgb: &[u8]) -> Vec<f64> {
    rgb.chunks_exact(3).map(fraction).collect()
}

/// The rate image of `fractions` (one a pixel, in `[0, 1]`) as the
/// course's PNG holds it: [`rate_colour`], rounded to 8 bits as
/// [`crate::render::Rendered::write_rate_image`] writes it.
pub fn rate_image(fractions: &[f64]) -> Vec<u8> {
    // rate_colour takes a count: a fraction to within 1e-6.
    const SCALE: f64 = 1e6;
    let colours: Vec<_> = fractions
        .iter()
        .map(|f| rate_colour((f.clamp(0.0, 1.0) * SCALE).round() as u32, SCALE as u32))
        .collect();
    quantize_display(&colours, Quantization::Round)
}

/// The mean of `fractions` (one image's), 0 for none.
pub fn mean(fractions: &[f64]) -> f64 {
    fractions.iter().sum::<f64>() / fractions.len().max(1) as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_colour_map_inverts_to_within_one_step() {
        // Every count of every -s up to 64, through the course's colours
        // and the PNG's 8 bits, and back.
        for max in 1..=64u32 {
            for n in 0..=max {
                let r = n as f64 / max as f64;
                let colour = quantize_display(&[rate_colour(n, max)], Quantization::Round);
                let back = fraction(&colour);
                assert!((back - r).abs() <= 1.0 / 255.0, "{n}/{max}: {back}");
                // Truncated values (another year's PNG writer) too.
                let colour = quantize_display(&[rate_colour(n, max)], Quantization::Truncate);
                assert!((fraction(&colour) - r).abs() <= 1.0 / 255.0);
            }
        }
        assert_eq!(fractions(&[0, 0, 255, 255, 0, 0]), vec![0.0, 1.0]);
        let image = rate_image(&[0.0, 0.25, 0.5, 1.0]);
        let back = fractions(&image);
        for (b, r) in back.iter().zip([0.0, 0.25, 0.5, 1.0]) {
            assert!((b - r).abs() <= 0.5 / 255.0, "{back:?}");
        }
    }
}
