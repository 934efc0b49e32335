//! The probe of `BBox::intersect(r, t0, t1)` (part 2): whether the ray's
//! stretch `[t0, t1]` meets the box.
//!
//! The slabs give the box's interval `[enter, exit]` along the line
//! ([`slab`]). Two readings of the handout are right: the staff's library
//! answers whether the line meets the box and writes `[enter, exit]` to
//! `t0, t1` (its caller compares them with the ray's range), and a
//! student may answer whether `[enter, exit]` overlaps `[t0, t1]`. So the
//! probe asks what both give: false when the line misses the box; true
//! when the overlap is not empty, with `t0, t1` written around it; either
//! when the line meets the box outside `[t0, t1]`. The rays:
//! through the box from outside, beside it, with the box behind, from
//! inside it (entering "before" the ray starts), along an axis (a zero
//! direction component, `inv_d` infinite) through and beside it, with
//! negative directions, and with `[t0, t1]` ending before the box or
//! starting after it; then random rays (fixed seed) that clear the box's
//! boundary by a margin. Every case keeps a margin of 1e-3 in `t`, so
//! rounding cannot decide it.

use glam::DVec3;
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

use super::driver::Driver;
use super::geometry::{num, show, slab, tokens, Ray64};
use super::verdict::{failure, Cases, Verdict};
use crate::mistakes::Mistake;

const MIN: DVec3 = DVec3::new(-1.0, -0.5, 0.0);
const MAX: DVec3 = DVec3::new(2.0, 1.0, 1.5);

/// A ray with its `[t0, t1]`.
struct Shot {
    ray: Ray64,
    t0: f64,
    t1: f64,
}

/// What a right answer is.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Answer {
    /// The line misses the box.
    False,
    /// `[t0, t1]` meets the box over `[lo, hi]`.
    True { lo: f64, hi: f64 },
    /// The line meets the box, but outside `[t0, t1]`.
    Either,
}

impl Shot {
    /// The right answer, or `None` when the case comes within the margin
    /// of another answer.
    fn answer(&self) -> Option<Answer> {
        let (enter, exit) = slab(&self.ray, MIN, MAX);
        if enter > exit {
            // A miss of the line: decided unless it grazes a corner.
            return (enter - exit > 1e-3 || enter.is_infinite()).then_some(Answer::False);
        }
        if exit - enter < 1e-3 {
            return None;
        }
        let (lo, hi) = (enter.max(self.t0), exit.min(self.t1));
        match hi - lo {
            d if d > 1e-3 => Some(Answer::True { lo, hi }),
            d if d < -1e-3 => Some(Answer::Either),
            _ => None,
        }
    }

    /// Whether the slabs taken without the swap, entered at `min` and left
    /// at `max` on every axis, leave `[t0, t1]` outside the box: what
    /// an intersect that forgets to swap them answers.
    fn unswapped_misses(&self) -> bool {
        let (mut enter, mut exit) = (self.t0, self.t1);
        for axis in 0..3 {
            let (o, d) = (self.ray.o[axis], self.ray.d[axis]);
            enter = enter.max((MIN[axis] - o) / d);
            exit = exit.min((MAX[axis] - o) / d);
        }
        enter > exit || enter.is_nan() || exit.is_nan()
    }

    /// Whether the ray's stretch starts inside the box (at `t0` it is
    /// already in: the origin inside, or `t0` past the entry).
    fn starts_inside(&self) -> bool {
        slab(&self.ray, MIN, MAX).0 < self.t0
    }
}

fn shots() -> Vec<Shot> {
    let all = |ray| Shot {
        ray,
        t0: 0.0,
        t1: f64::INFINITY,
    };
    let through = Ray64::new(DVec3::new(-3.0, -2.0, -1.0), DVec3::new(1.0, 0.8, 0.6));
    let mut shots = vec![
        all(through),
        all(Ray64::new(
            DVec3::new(-3.0, 3.0, -1.0),
            DVec3::new(1.0, 0.1, 0.6),
        )),
        all(Ray64::new(through.o, -through.d)),
        all(Ray64::new(
            DVec3::new(0.5, 0.2, 0.7),
            DVec3::new(0.3, -0.9, 0.2),
        )),
        all(Ray64::new(DVec3::new(0.5, 0.2, -2.0), DVec3::Z)),
        all(Ray64::new(DVec3::new(3.0, 0.2, -2.0), DVec3::Z)),
        all(Ray64::new(
            DVec3::new(4.0, 3.0, 5.0),
            DVec3::new(-1.0, -0.9, -1.4),
        )),
        Shot {
            ray: through,
            t0: 0.0,
            t1: 1.0,
        },
        Shot {
            ray: through,
            t0: 6.0,
            t1: 9.0,
        },
        Shot {
            ray: through,
            t0: 3.0,
            t1: 3.5,
        },
    ];
    let mut rng = Pcg64::seed_from_u64(2);
    while shots.len() < 60 {
        let o = DVec3::new(rng.gen(), rng.gen(), rng.gen()) * 8.0 - 4.0;
        let mut d = DVec3::new(rng.gen(), rng.gen(), rng.gen()) * 2.0 - 1.0;
        if shots.len() % 5 == 0 {
            d[shots.len() % 3] = 0.0;
        }
        let shot = all(Ray64::new(o, d));
        if shot.answer().is_some() && d != DVec3::ZERO {
            shots.push(shot);
        }
    }
    shots
}

/// Probes `BBox::intersect`.
pub fn intersect(driver: &Driver) -> Verdict {
    let shots = shots();
    let commands = shots
        .iter()
        .map(|s| {
            format!(
                "bbox {} {} {} {} {}",
                tokens(MIN),
                tokens(MAX),
                s.ray.tokens(),
                s.t0,
                s.t1
            )
        })
        .collect();
    let transcript = match driver.run("bbox_intersect", commands) {
        Ok(t) => t,
        Err(e) => return Verdict::Broken(e),
    };
    let mut cases = Cases::default();
    let mut stub_like = true;
    let mut inside_only = true;
    // Whether every failure is a miss the slabs taken unswapped predict
    // (a slab's near plane is `max` where the direction is negative).
    let mut unswapped_only = true;
    for (i, shot) in shots.iter().enumerate() {
        let got = match transcript.exactly(i, 3) {
            Ok(v) => v,
            Err(stop) => return Verdict::stopped(&stop, transcript.command(i)),
        };
        let hit = got[0] == 1.0;
        stub_like &= hit && got[1] == shot.t0 && got[2] == shot.t1;
        let Some(want) = shot.answer() else { continue };
        let what = match want {
            Answer::False if hit => "a ray whose line misses the box counts as a hit",
            Answer::True { .. } if !hit && shot.starts_inside() => {
                "a ray whose [t0, t1] starts inside the box misses it"
            }
            Answer::True { .. } if !hit => "a ray whose [t0, t1] meets the box misses it",
            Answer::True { lo, hi } if got[1] > lo + 1e-9 || got[2] < hi - 1e-9 => {
                "t0 and t1 are not written around the stretch of the ray inside the box"
            }
            _ => {
                cases.record(None);
                continue;
            }
        };
        inside_only &= !hit && shot.starts_inside();
        unswapped_only &= !hit && shot.unswapped_misses();
        let (enter, exit) = slab(&shot.ray, MIN, MAX);
        cases.record(Some(failure(
            format!(
                "intersect of the box min = {}, max = {} with the ray o = {}, d = {} and t0 = {}, t1 = {}",
                show(MIN),
                show(MAX),
                show(shot.ray.o),
                show(shot.ray.d),
                num(shot.t0),
                num(shot.t1)
            ),
            match want {
                Answer::False => "false (the line misses the box)".to_owned(),
                _ => format!("true, t0 <= {} and t1 >= {} (the line is in the box for t in [{}, {}])", num(enter.max(shot.t0)), num(exit.min(shot.t1)), num(enter), num(exit)),
            },
            format!("{hit}, t0 = {}, t1 = {}", num(got[1]), num(got[2])),
            what,
            None,
        )));
    }
    if stub_like {
        return Verdict::NotWritten(
            "it answers true for every ray, the starter's `return true;`".into(),
        );
    }
    match cases.verdict(None) {
        Verdict::Fail(mut f) if inside_only => {
            f.mistake = Some(Mistake::BoxMissesRaysFromInside);
            Verdict::Fail(f)
        }
        Verdict::Fail(mut f) if unswapped_only => {
            f.what = "rays whose direction has a negative component miss the box: where 1/d < 0 a slab is entered at its max plane, so (min - o)/d and (max - o)/d must be swapped".into();
            Verdict::Fail(f)
        }
        v => v,
    }
}
