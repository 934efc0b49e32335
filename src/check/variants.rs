//! The correct solutions a check accepts besides the course's own: the
//! choices the handout leaves to the student ([`Choices`]), each a null
//! model of its own.
//!
//! A student's image passes when it fits the course's solution or any
//! variant here, each tested at the check's `alpha`. A correct solution
//! with variant `j` then fails with probability at most `alpha`: it fails
//! only if it fails the test of its own model, `P(fail) <= P(fail_j) =
//! alpha`, so no share of `alpha` is given up to the others. Each
//! variant's noise is taken as the larger of its own and the course
//! solution's, per cell ([`super::stats::NullModel::widened`]).
//!
//! The variants, and when each can change an image:
//!
//! | variant | changes | acts when |
//! | --- | --- | --- |
//! | roulette `q` 0.6 or 0.7 from the first vertex | noise, so an 8-bit PNG's mean | `-m 2` and more |
//! | roulette `q` 0.6 or 0.7 from the second vertex | noise | `-m 3` and more |
//! | convergence tested one sample late, the staff's way | which pixels stop, their brightness | `-a` |
//!
//! Only a 3-1 binary has them: a 3-2 binary's parts 1-5 are the staff's
//! library, whose choices are the course's ([`Choices::of`]).

use super::battery::Check;
use crate::course::pixel::StopRule;
use crate::course::{Assignment, Choices};

/// A correct solution's choices other than the course's, and what it
/// chose in words (for the report: "a correct solution that ...").
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Variant {
    pub choices: Choices,
    pub chose: &'static str,
}

/// Roulette's continuation probabilities the handout allows besides 0.65.
const OTHER_Q: [f32; 2] = [0.6, 0.7];

/// The variants `check` accepts besides the course's solution: the
/// roulette and stop-rule choices that can change its image, and every
/// combination of them.
pub fn of(check: &Check) -> Vec<Variant> {
    if check.assignment != Assignment::PathTracer1 {
        return Vec::new();
    }
    let course = Choices::of(check.assignment);
    let mut roulettes = vec![(course, "")];
    for (from, chose) in [
        (1, "tosses roulette's coin from the first bounce"),
        (2, "tosses roulette's coin from the second bounce"),
    ] {
        // The coin at vertex k decides the bounce to vertex k + 1, which
        // is traced only when k < -m.
        if from >= check.max_depth {
            continue;
        }
        for q in OTHER_Q {
            let choices = Choices {
                continue_probability: q,
                roulette_from: from,
                ..course
            };
            roulettes.push((choices, chose));
        }
    }
    let mut stops = vec![(StopRule::EveryBatch, "")];
    if check.adaptive.is_some() {
        stops.push((
            StopRule::StaffOneLate,
            "tests convergence one sample late, as the staff's library does",
        ));
    }
    let mut variants = Vec::new();
    for &(roulette, roulette_chose) in &roulettes {
        for &(stop_rule, stop_chose) in &stops {
            let choices = Choices {
                stop_rule,
                ..roulette
            };
            if choices == course {
                continue;
            }
            let chose = match (roulette_chose, stop_chose) {
                (r, "") => r,
                ("", s) => s,
                _ => "chose another roulette and the staff's convergence test",
            };
            variants.push(Variant { choices, chose });
        }
    }
    variants
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::battery::battery_of;

    fn named(part: u8, depth: Option<u32>) -> Check {
        *battery_of(Assignment::PathTracer1)
            .iter()
            .find(|c| c.part == part && depth.is_none_or(|d| c.max_depth == d))
            .expect("the battery has the check")
    }

    /// `-m 1` traces no bounce, so roulette cannot act; `-m 2` has only
    /// the first vertex's coin; `-m 4` both; `-a` adds the staff's stop
    /// rule; a 3-2 binary has none.
    #[test]
    fn each_check_has_the_variants_that_can_change_its_image() {
        assert!(of(&named(3, Some(1))).is_empty());
        let second_bounce = of(&named(4, Some(2)));
        assert_eq!(second_bounce.len(), 2);
        assert!(second_bounce.iter().all(|v| v.choices.roulette_from == 1));
        let global = of(&named(4, Some(4)));
        assert_eq!(global.len(), 4);
        let qs: Vec<f32> = global
            .iter()
            .map(|v| v.choices.continue_probability)
            .collect();
        assert_eq!(qs, [0.6, 0.7, 0.6, 0.7]);
        let adaptive = of(&named(5, None));
        assert_eq!(adaptive.len(), 1);
        assert_eq!(adaptive[0].choices.stop_rule, StopRule::StaffOneLate);
        for check in battery_of(Assignment::PathTracer2) {
            assert!(of(&check).is_empty(), "{}", check.name);
        }
    }

    /// No variant is the course's own choice, and none repeats.
    #[test]
    fn variants_differ_from_the_course_and_each_other() {
        for check in battery_of(Assignment::PathTracer1) {
            let variants = of(&check);
            for (i, v) in variants.iter().enumerate() {
                assert_ne!(v.choices, Choices::of(check.assignment));
                assert!(!v.chose.is_empty());
                assert!(variants[..i].iter().all(|w| w.choices != v.choices));
            }
        }
    }
}
