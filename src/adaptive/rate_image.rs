//! The course's sample-rate image: each pixel coloured by the fraction
//! `r = n / ns_aa` of the maximum samples it took, from blue (few) through
//! green (half) to red (all):
//!
//! ```text
//! r <= 1/2:  (1 - 2r) blue + 2r green
//! r >  1/2:  (2 - 2r) green + (2r - 1) red
//! ```

use crate::math::Rgb;

/// The colour (display values in [0, 1]) of a pixel that took `samples`
/// of at most `max_samples`.
pub fn rate_colour(samples: u32, max_samples: u32) -> Rgb {
    let r = (samples as f32 / max_samples.max(1) as f32).clamp(0.0, 1.0);
    let (blue, green, red) = (Rgb::Z, Rgb::Y, Rgb::X);
    if r <= 0.5 {
        let w = (0.5 - r) / 0.5;
        blue * w + green * (1.0 - w)
    } else {
        let w = (1.0 - r) / 0.5;
        green * w + red * (1.0 - w)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn few_half_all_are_blue_green_red() {
        assert_eq!(rate_colour(0, 64), Rgb::Z);
        assert_eq!(rate_colour(32, 64), Rgb::Y);
        assert_eq!(rate_colour(64, 64), Rgb::X);
        assert_eq!(rate_colour(16, 64), Rgb::new(0.0, 0.5, 0.5));
    }
}
