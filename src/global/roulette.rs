//! Russian roulette (Arvo and Kirk 1990): end a path at random, and divide
//! the paths that go on by the probability `q` of going on, so that the
//! expectation does not change: `E = q (X / q) + (1 - q) 0 = X`. A path's
//! throughput and its refractions' scale, what the rules read, travel
//! together in a [`PathWeight`].
//!
//! Two rules for `q`, never applied on the last ray (which only looks for
//! emission):
//!
//! - [`Roulette::Fixed`], the course's: `q = 0.65` ([`CONTINUE_PROBABILITY`])
//!   whatever the path carries, from the second scattering vertex on (never
//!   on the first indirect bounce).
//! - [`Roulette::Throughput`], pbrt-v4's rule (its PathIntegrator, section
//!   13.4) applied after [`THROUGHPUT_ROULETTE_AFTER`] bounces (8; Mitsuba 3's path tracer
//!   starts after 5, `rr_depth`): `q` follows what the path can still bring,
//!
//!   ```text
//!   q = min(1, max_channel(beta * eta_scale)),   eta_scale = prod eta_k^2
//!   ```
//!
//!   over the refractions `k` the path crossed. A bright path is never
//!   cut; a dark one is cut often, and the survivors come back at
//!   `beta / q`, about 1 per channel at most: little variance where the
//!   light still to come is about as bright as what the path has
//!   gathered (not so near a bright light seen through glass, below).
//!   Refraction into a denser medium
//!   scales radiance by `1 / eta^2` (the BSDF's `T / eta^2`), which says
//!   nothing about the light the path will find; `eta_scale` cancels it, so
//!   paths inside glass are not cut for it.
//!
//!   Why not from the second vertex, as pbrt-v4 does: after `k` diffuse
//!   bounces `beta` is about `albedo^k`, so `q` falls with every bounce and
//!   the first bounces, which carry most of the indirect light, get cut
//!   hardest. Measured on the course's scenes (docs/12-sampling.md), starting
//!   after 5 bounces halves the squared error of `CBspheres_microfacet_al_ag`
//!   at `-m 5` for 1.34 times the time, and gains 1.4 to 1.7 in efficiency
//!   on `CBspheres_lambertian` (`-m 8`) and `CBbunny`.
//!
//!   Why after 8 and not 5: `q` reads the throughput alone, not the
//!   radiance the path will find. Where a dark path can still reach a
//!   bright light through glass or a mirror (`CBspheres`), the few that
//!   survive come back at `1 / q` times a large value: after 5 bounces,
//!   roulette doubled `CBspheres`' squared error at `-m 8` (8.0e-4
//!   against 3.9e-4 without it) and saved 15 % of the time; after 8 it
//!   gains 1.44 times in efficiency at `-m 16`, and costs the diffuse
//!   `CBspheres_lambertian` 0.95 to 0.97 times, within the timing noise
//!   (docs/10-performance.md). A rule that weighs the radiance to come is
//!   Vorba and Křivánek's adjoint-driven roulette (ACM TOG 35(4), 2016).

use crate::math::Rgb;

/// The course's probability of continuing a path at each bounce after the
/// first indirect one.
pub const CONTINUE_PROBABILITY: f32 = 0.65;

/// Bounces a path makes before throughput roulette may end it.
pub const THROUGHPUT_ROULETTE_AFTER: u32 = 8;

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
    /// Whether the rule may end a path at its vertex number `bounces`
    /// (1 for the camera ray's hit): the fixed rule from the second vertex
    /// on, the throughput rule after [`THROUGHPUT_ROULETTE_AFTER`].
    pub fn applies_at(self, bounces: u32) -> bool {
        match self {
            Roulette::Off => false,
            Roulette::Fixed => bounces > 1,
            Roulette::Throughput => bounces > THROUGHPUT_ROULETTE_AFTER,
        }
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
}

/// What a path carries from vertex to vertex, as roulette reads it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PathWeight {
    /// The throughput `beta`: the product of `f |cos| / (pdf q)` so far.
    pub beta: Rgb,
    /// `eta_scale = prod eta_k^2` over the refractions crossed, `eta_k`
    /// the relative index of each (into glass of index 1.5 from air, 1.5;
    /// out of it, 1 / 1.5).
    pub eta_scale: f32,
}

impl PathWeight {
    /// A camera path before its first vertex.
    pub const START: PathWeight = PathWeight {
        beta: Rgb::ONE,
        eta_scale: 1.0,
    };

    /// The path past a vertex whose sample has weight `f |cos| / pdf` and
    /// refracts with relative index `eta` where `refraction` is given,
    /// before roulette: `beta weight`, and `eta_scale eta^2` on refraction.
    pub fn scattered(self, weight: Rgb, refraction: Option<f32>) -> PathWeight {
        PathWeight {
            beta: self.beta * weight,
            eta_scale: refraction.map_or(self.eta_scale, |eta| self.eta_scale * eta * eta),
        }
    }

    /// The path that went on with probability `q`: `beta / q`.
    pub fn survived(self, q: f32) -> PathWeight {
        PathWeight {
            beta: self.beta / q,
            ..self
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `eta_scale` gathers `eta^2` over refractions only, so that a path
    /// through a pane of glass and out again is back to 1, and inside it
    /// the radiance scale `1 / eta^2` does not get the path cut: its
    /// probability of going on is its throughput after the refraction with
    /// the `1 / eta^2` taken out. `q` never changes the expectation, so
    /// only a test of the values, like this one, can see a wrong
    /// `eta_scale` (mutants of it survived every estimator test).
    #[test]
    fn a_path_in_glass_is_not_cut_for_the_radiance_scale() {
        let weight = Rgb::new(0.9, 0.6, 0.3);
        let into = PathWeight::START.scattered(weight / 2.25, Some(1.5));
        assert_eq!(into.beta, weight / 2.25);
        assert!((into.eta_scale - 2.25).abs() < 1e-6);
        let p = Roulette::Throughput.continue_probability(into.beta, into.eta_scale);
        assert!((p - 0.9).abs() < 1e-6, "{p}");
        let out = into.scattered(Rgb::splat(2.25), Some(1.0 / 1.5));
        assert!((out.eta_scale - 1.0).abs() < 1e-6);
        // A reflection keeps the scale; the survivors are divided by q.
        let reflected = into.scattered(Rgb::splat(0.5), None);
        assert_eq!(reflected.eta_scale, into.eta_scale);
        assert_eq!(reflected.beta, into.beta * 0.5);
        let survived = reflected.survived(0.25);
        assert_eq!(survived.beta, reflected.beta / 0.25);
        assert_eq!(survived.eta_scale, reflected.eta_scale);
    }

    #[test]
    fn the_throughput_rule_starts_later_than_the_course_s() {
        assert!(!Roulette::Fixed.applies_at(1) && Roulette::Fixed.applies_at(2));
        let after = THROUGHPUT_ROULETTE_AFTER;
        assert!(!Roulette::Throughput.applies_at(after));
        assert!(Roulette::Throughput.applies_at(after + 1));
        assert!(!Roulette::Off.applies_at(100));
    }

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
