//! What the handout leaves to the student: choices that give different
//! but equally correct solutions.
//!
//! - **Russian roulette**: continue with probability `q` (the handout
//!   allows 0.6-0.7), from the first vertex (the camera ray's hit) or the
//!   second. A path that continues divides by `q`, so the expected
//!   radiance is the same for every `q`: `E[L'] = q (L / q) + (1 - q) 0 = L`.
//!   The noise is not, and in an 8-bit PNG, where `floor(255 v)` clips at
//!   255, more noise lowers the mean (docs/maintainers/checker.md,
//!   "Legitimate variants: the null holds them").
//! - **When an adaptive pixel tests convergence**: after every
//!   `samplesPerBatch` samples (the handout's loop), or one sample later
//!   as the staff's own library does ([`StopRule::StaffOneLate`]).
//!
//! [`Choices::of`] is what the course's solution of each assignment
//! chooses; [`crate::check`] holds a student's image to the others too.

use super::pixel::StopRule;
use super::Assignment;
use crate::global::CONTINUE_PROBABILITY;

/// The choices of one correct solution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Choices {
    /// Russian roulette's continuation probability `q`.
    pub continue_probability: f32,
    /// The first vertex whose bounce the coin decides: 1 for the camera
    /// ray's hit, 2 for the vertex after it.
    pub roulette_from: u32,
    /// When an adaptive pixel tests convergence, and how a pixel that
    /// stops early is written.
    pub stop_rule: StopRule,
}

impl Choices {
    /// The course's solution of `assignment`: `q = 0.65` from the second
    /// vertex; the handout's convergence test in 3-1, the staff library's
    /// in 3-2 (whose parts 1-5 are the staff's).
    pub const fn of(assignment: Assignment) -> Self {
        Choices {
            continue_probability: CONTINUE_PROBABILITY,
            roulette_from: 2,
            stop_rule: match assignment {
                Assignment::PathTracer1 => StopRule::EveryBatch,
                Assignment::PathTracer2 => StopRule::StaffOneLate,
            },
        }
    }

    /// The probability of going on from vertex `k` (1 for the camera
    /// ray's hit): `q` from [`Choices::roulette_from`] on, else 1.
    pub fn continue_probability_at(&self, k: u32) -> f32 {
        if k >= self.roulette_from {
            self.continue_probability
        } else {
            1.0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The course's roulette tosses no coin at the camera ray's hit and
    /// continues with 0.65 from the second vertex; a solution from the
    /// first vertex tosses it there too.
    #[test]
    fn the_coin_is_tossed_from_the_chosen_vertex() {
        let course = Choices::of(Assignment::PathTracer1);
        assert_eq!(course.continue_probability_at(1), 1.0);
        assert_eq!(course.continue_probability_at(2), 0.65);
        assert_eq!(course.continue_probability_at(7), 0.65);
        let early = Choices {
            continue_probability: 0.6,
            roulette_from: 1,
            ..course
        };
        assert_eq!(early.continue_probability_at(1), 0.6);
    }

    /// 3-1 tests convergence as the handout says, 3-2 as the staff's
    /// library does.
    #[test]
    fn each_assignment_has_its_stop_rule() {
        assert_eq!(
            Choices::of(Assignment::PathTracer1).stop_rule,
            StopRule::EveryBatch
        );
        assert_eq!(
            Choices::of(Assignment::PathTracer2).stop_rule,
            StopRule::StaffOneLate
        );
    }
}
