//! Russian roulette (Arvo and Kirk 1990): end a path at random, and divide
//! the paths that go on by the probability `q` of going on, so that the
//! expectation does not change: `E = q (X / q) + (1 - q) 0 = X`.
//!
//! Two rules for `q`, both applied from the second scattering vertex on
//! (never on the first indirect bounce, nor on the last ray, which only
//! looks for emission):
//!
//! - [`Roulette::Fixed`], the course's: `q = 0.65` ([`CONTINUE_PROBABILITY`])
//!   whatever the path carries.
//! - [`Roulette::Throughput`], pbrt-v4's (section 13.1.6): `q` follows what
//!   the path can still bring,
//!
//!   ```text
//!   q = min(1, max_channel(beta * eta_scale)),   eta_scale = prod eta_k^2
//!   ```
//!
//!   over the refractions `k` the path crossed. A bright path is never
//!   cut; a dark one is cut often, and the survivors come back at
//!   `beta / q`, about 1 per channel at most, so roulette adds little
//!   variance where it saves most time. Refraction into a denser medium
//!   scales radiance by `1 / eta^2` (the BSDF's `T / eta^2`), which says
//!   nothing about the light the path will find; `eta_scale` cancels it, so
//!   paths inside glass are not cut for it.

use crate::math::Rgb;

/// The course's probability of continuing a path at each bounce after the
/// first indirect one.
pub const CONTINUE_PROBABILITY: f32 = 0.65;

/// How paths are ended (`--roulette`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Roulette {
    /// Paths go on to `-m` bounces.
    Off,
    /// `q = 0.65` (the course's).
    Fixed,
    /// `q = min(1, max channel of beta eta_scale)` (pbrt-v4's).
    #[default]
    Throughput,
}

impl Roulette {
    /// Whether paths are ended at random at all.
    pub fn is_on(self) -> bool {
        self != Roulette::Off
    }

    /// The probability of going on for a path whose throughput after the
    /// vertex is `beta`, having crossed refractions that scale radiance by
    /// `1 / eta_scale`.
    pub fn continue_probability(self, beta: Rgb, eta_scale: f32) -> f32 {
        match self {
            Roulette::Off => 1.0,
            Roulette::Fixed => CONTINUE_PROBABILITY,
            Roulette::Throughput => (beta * eta_scale).max_element().min(1.0),
        }
    }

    /// Its name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Roulette::Off => "off",
            Roulette::Fixed => "fixed",
            Roulette::Throughput => "throughput",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn throughput_roulette_keeps_bright_paths_and_cuts_dark_ones() {
        let t = Roulette::Throughput;
        assert_eq!(t.continue_probability(Rgb::new(0.2, 1.5, 0.1), 1.0), 1.0);
        assert_eq!(t.continue_probability(Rgb::new(0.2, 0.5, 0.1), 1.0), 0.5);
        // Inside glass of index 1.5 the radiance is 1/2.25 of what it was.
        let inside = Rgb::splat(0.9 / 2.25);
        assert!((t.continue_probability(inside, 2.25) - 0.9).abs() < 1e-6);
        assert_eq!(Roulette::Fixed.continue_probability(Rgb::ONE, 1.0), 0.65);
        assert_eq!(Roulette::Off.continue_probability(Rgb::ZERO, 1.0), 1.0);
    }
}
