//! The probes of `Sphere::test`, `Sphere::intersect` and
//! `Sphere::has_intersection` (part 1).
//!
//! The rays: from outside through the ball (both roots ahead: the hit is
//! the nearer root `t1`), beside it, with the ball behind, from inside
//! (`t1 < 0 < t2`: the hit is `t2`), with `max_t` before `t1` (a miss),
//! between the roots (still `t1`), and `min_t` between them (then `t2`)
//! or past both (a miss). A hit gives its `t`, the outward normal
//! `(p - c) / R`, the primitive and its BSDF, and leaves `r.max_t = t`.
//! `test` is held only to what every reading of the handout agrees on:
//! for a ray with both roots inside `[min_t, max_t]` it is true with
//! `t1 < t2` the roots, and for a line that misses the ball it is false.

use glam::DVec3;

use super::driver::Driver;
use super::geometry::{close, num, same_direction, show, sphere_roots, tokens, vec_at, Ray64};
use super::verdict::{failure, Cases, Failure, Verdict};
use crate::mistakes::Mistake;

const CENTRE: DVec3 = DVec3::new(0.5, -0.2, 1.0);
const RADIUS: f64 = 0.7;

/// A ray and the root it must hit at (`None`: a miss).
struct Shot {
    ray: Ray64,
    hit: Option<f64>,
    /// Whether `test` is held to it (both roots in range, or no root).
    for_test: bool,
}

fn shots() -> Vec<Shot> {
    let aim = |from: DVec3, through: DVec3, scale: f64| {
        Ray64::new(CENTRE + from, (through - from) * scale)
    };
    let straight = aim(DVec3::new(0.2, 0.3, -3.0), DVec3::new(0.1, 0.0, 0.0), 0.5);
    let (t1, t2) = sphere_roots(&straight, CENTRE, RADIUS).expect("through the ball");
    let rays = [
        straight,
        // Beside the ball, 0.9 and 1.4 from its centre.
        aim(DVec3::new(-2.0, 1.5, 0.5), DVec3::new(0.0, 0.9, 0.0), 1.7),
        aim(DVec3::new(0.5, 2.0, 0.0), DVec3::new(1.4, 0.0, 0.0), 1.0),
        // Away from it.
        Ray64::new(straight.o, -straight.d),
        // From inside.
        aim(DVec3::new(0.1, 0.2, -0.1), DVec3::new(-0.2, 0.1, 0.3), 2.0),
        straight.between(0.0, 0.5 * t1),
        straight.between(0.0, 0.5 * (t1 + t2)),
        straight.between(0.5 * (t1 + t2), f64::INFINITY),
        straight.between(t2 * 1.5, f64::INFINITY),
    ];
    rays.into_iter()
        .map(|ray| {
            let roots = sphere_roots(&ray, CENTRE, RADIUS);
            let within = |t: &f64| *t >= ray.min_t && *t <= ray.max_t;
            Shot {
                ray,
                hit: roots.and_then(|(t1, t2)| [t1, t2].into_iter().find(within)),
                for_test: roots.is_none_or(|(t1, t2)| within(&t1) && within(&t2)),
            }
        })
        .collect()
}

/// Which function a run probes.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Which {
    Test,
    Intersect,
    HasIntersection,
}

/// Probes `Sphere::test`.
pub fn test(driver: &Driver) -> Verdict {
    probe(driver, Which::Test)
}

/// Probes `Sphere::intersect`.
pub fn intersect(driver: &Driver) -> Verdict {
    probe(driver, Which::Intersect)
}

/// Probes `Sphere::has_intersection`.
pub fn has_intersection(driver: &Driver) -> Verdict {
    probe(driver, Which::HasIntersection)
}

fn probe(driver: &Driver, which: Which) -> Verdict {
    let (name, verb, n) = match which {
        Which::Test => ("sphere_test", "sph_test", 4),
        Which::Intersect => ("sphere_intersect", "sph_hit", 8),
        Which::HasIntersection => ("sphere_has_intersection", "sph_any", 2),
    };
    let shots: Vec<Shot> = shots()
        .into_iter()
        .filter(|s| which != Which::Test || s.for_test)
        .collect();
    let mut commands = vec![format!("sphere {} {RADIUS}", tokens(CENTRE))];
    commands.extend(shots.iter().map(|s| format!("{verb} {}", s.ray.tokens())));
    let transcript = match driver.run(name, commands) {
        Ok(t) => t,
        Err(e) => return Verdict::Broken(e),
    };
    let mut cases = Cases::default();
    let mut stub_like = true;
    for (k, shot) in shots.iter().enumerate() {
        let got = match transcript.exactly(k + 1, n) {
            Ok(v) => v,
            Err(stop) => return Verdict::stopped(&stop, transcript.command(k + 1)),
        };
        stub_like &= got[0] == 1.0 && (which == Which::HasIntersection || !got[1].is_finite());
        let call = format!(
            "{} of the sphere c = {}, R = {RADIUS} with the ray {}",
            match which {
                Which::Test => "test",
                Which::Intersect => "intersect",
                Which::HasIntersection => "has_intersection",
            },
            show(CENTRE),
            shot.ray.show()
        );
        cases.record(match which {
            Which::Test => judge_test(&call, shot, &got),
            Which::Intersect => judge_hit(&call, shot, &got),
            Which::HasIntersection => judge_any(&call, shot, got[0] == 1.0),
        });
    }
    if stub_like {
        return Verdict::NotWritten(
            "it answers true for every ray and records nothing, the starter's `return true;`"
                .into(),
        );
    }
    cases.verdict(None)
}

/// Hit or miss, rightly.
fn judge_any(call: &str, shot: &Shot, hit: bool) -> Option<Failure> {
    match (shot.hit, hit) {
        (Some(_), true) | (None, false) => None,
        (Some(t), false) => Some(failure(
            call,
            format!("a hit at t = {}", num(t)),
            "a miss",
            "a ray that hits the sphere counts as a miss",
            None,
        )),
        (None, true) => Some(failure(
            call,
            "a miss",
            "a hit",
            "a ray that misses counts as a hit",
            None,
        )),
    }
}

/// `test`: `HIT T1 T2 MAX_T`.
fn judge_test(call: &str, shot: &Shot, got: &[f64]) -> Option<Failure> {
    let roots = sphere_roots(&shot.ray, CENTRE, RADIUS);
    let said = format!(
        "{}, t1 = {}, t2 = {}",
        got[0] == 1.0,
        num(got[1]),
        num(got[2])
    );
    match roots {
        None if got[0] == 1.0 => Some(failure(
            call,
            "false",
            said,
            "a line that misses the sphere counts as meeting it",
            None,
        )),
        Some((t1, t2)) if got[0] != 1.0 || !close(got[1], t1, 1e-9) || !close(got[2], t2, 1e-9) => {
            Some(failure(
                call,
                format!("true, t1 = {}, t2 = {}", num(t1), num(t2)),
                said,
                "t1 and t2 are not the two roots, nearer first",
                None,
            ))
        }
        _ => None,
    }
}

/// `intersect`: `HIT T N PRIM BSDF MAX_T`.
fn judge_hit(call: &str, shot: &Shot, got: &[f64]) -> Option<Failure> {
    let (hit, t, n, prim, bsdf, max_t) = (
        got[0] == 1.0,
        got[1],
        vec_at(got, 2),
        got[5],
        got[6],
        got[7],
    );
    let Some(want_t) = shot.hit else {
        return judge_any(call, shot, hit);
    };
    if !hit {
        return judge_any(call, shot, hit);
    }
    let want_n = (shot.ray.o + want_t * shot.ray.d - CENTRE) / RADIUS;
    let expected = format!("t = {}, n = {}", num(want_t), show(want_n));
    let said = format!("t = {}, n = {}", num(t), show(n));
    if !close(t, want_t, 1e-9) {
        let far = sphere_roots(&shot.ray, CENTRE, RADIUS)
            .is_some_and(|(t1, t2)| close(t1, want_t, 1e-9) && close(t, t2, 1e-9));
        let what = if far {
            "the farther root is taken where the nearer one is in [min_t, max_t]"
        } else {
            "the hit's t is wrong"
        };
        return Some(failure(
            call,
            expected,
            said,
            what,
            far.then_some(Mistake::SphereFarRoot),
        ));
    }
    if !same_direction(n, want_n, 1e-6) {
        return Some(failure(
            call,
            expected,
            said,
            "the normal is not the outward (p - c) / R",
            None,
        ));
    }
    if !close(n.length(), 1.0, 1e-6) {
        return Some(failure(
            call,
            expected,
            said,
            "the normal is not unit length",
            None,
        ));
    }
    if prim != 1.0 || bsdf != 1.0 {
        return Some(failure(
            call,
            "isect->primitive = this, isect->bsdf = get_bsdf()",
            format!(
                "primitive {}, bsdf {}",
                if prim == 0.0 { "null" } else { "another" },
                if bsdf == 0.0 { "null" } else { "another" }
            ),
            "the hit record does not name the sphere and its BSDF",
            None,
        ));
    }
    if !close(max_t, want_t, 1e-9) {
        return Some(failure(
            call,
            format!("r.max_t = {} (the hit's t)", num(want_t)),
            format!("r.max_t = {}", num(max_t)),
            "r.max_t is not set to the hit's t, so a farther hit found later replaces this one",
            Some(Mistake::MaxTNotShrunk),
        ));
    }
    None
}
