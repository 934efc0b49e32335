//! The probes of `Triangle::intersect` and `Triangle::has_intersection`
//! (part 1): rays with known answers, from the plain to the adversarial.
//!
//! Each triangle gets rays that hit it inside (from the front and from
//! behind: the course's triangles are two-sided), rays that miss beside
//! an edge, a ray pointing away, rays whose hit lies beyond `max_t` or
//! before `min_t` (with `max_t >= 1`, which the chained comparison
//! `min_t <= t <= max_t` lets through), and a ray parallel to its plane. A hit
//! must give `t`, the normal blended from the vertex normals with the
//! barycentrics (`(1 - b1 - b2) n1 + b1 n2 + b2 n3`), the primitive and
//! its BSDF, and leave `r.max_t = t`; a miss leaves the ray alone. Hits
//! and misses keep a margin of 0.05 in the barycentrics, so rounding
//! cannot decide them.

use glam::DVec3;
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

use super::driver::Driver;
use super::geometry::{close, num, same_direction, show, tokens, triangle_line, vec_at, Ray64};
use super::verdict::{failure, Cases, Failure, Verdict};
use crate::mistakes::Mistake;

/// A triangle: its corners and vertex normals.
#[derive(Debug, Clone, Copy)]
pub struct Tri {
    pub p: [DVec3; 3],
    pub n: [DVec3; 3],
}

impl Tri {
    /// The driver's `triangle` command.
    fn command(&self) -> String {
        let all: Vec<String> = self.p.iter().chain(&self.n).map(|v| tokens(*v)).collect();
        format!("triangle {}", all.join(" "))
    }

    /// The point of barycentrics `(b1, b2)`.
    pub fn at(&self, b1: f64, b2: f64) -> DVec3 {
        (1.0 - b1 - b2) * self.p[0] + b1 * self.p[1] + b2 * self.p[2]
    }

    /// The geometric normal (not normalised).
    pub fn face(&self) -> DVec3 {
        (self.p[1] - self.p[0]).cross(self.p[2] - self.p[0])
    }

    /// The shading normal at `(b1, b2)` with the weights on vertices
    /// `order`.
    fn blend(&self, b1: f64, b2: f64, order: [usize; 3]) -> DVec3 {
        let w = [1.0 - b1 - b2, b1, b2];
        (0..3).map(|i| w[i] * self.n[order[i]]).sum()
    }
}

/// The triangles: a unit right triangle in z = 0 with three different
/// normals, then random ones (fixed seed).
fn triangles() -> Vec<Tri> {
    let mut out = vec![Tri {
        p: [DVec3::ZERO, DVec3::X, DVec3::Y],
        n: [
            DVec3::Z,
            DVec3::new(1.0, 0.0, 1.0).normalize(),
            DVec3::new(0.0, 1.0, 1.0).normalize(),
        ],
    }];
    let mut rng = Pcg64::seed_from_u64(184);
    let point = |rng: &mut Pcg64| DVec3::new(rng.gen(), rng.gen(), rng.gen()) * 4.0 - 2.0;
    while out.len() < 8 {
        let p = [point(&mut rng), point(&mut rng), point(&mut rng)];
        let face = (p[1] - p[0]).cross(p[2] - p[0]);
        // Not too thin: the area at least a tenth of the longest edge squared.
        let longest = (0..3)
            .map(|i| (p[i] - p[(i + 1) % 3]).length_squared())
            .fold(0.0, f64::max);
        if face.length() < 0.2 * longest {
            continue;
        }
        let tilt = |rng: &mut Pcg64| (face.normalize() + 0.5 * (point(rng) / 2.0)).normalize();
        let n = [tilt(&mut rng), tilt(&mut rng), tilt(&mut rng)];
        out.push(Tri { p, n });
    }
    out
}

/// A ray and whether it must hit (at `(t, b1, b2)`).
#[derive(Debug, Clone, Copy)]
pub struct Shot {
    pub ray: Ray64,
    pub hit: Option<(f64, f64, f64)>,
}

/// The rays for one triangle, plain ones first.
fn shots(tri: &Tri) -> Vec<Shot> {
    let unit = tri.face().normalize();
    let across = (tri.p[1] - tri.p[0]).normalize();
    let inside = tri.at(0.2, 0.3);
    // From `dist` away on `side`, slanted, to meet `q` at `t`.
    let from = |q: DVec3, side: f64, dist: f64, t: f64| {
        let o = q + side * dist * (unit + 0.3 * across).normalize();
        Ray64::new(o, (q - o) / t)
    };
    let mut shots = Vec::new();
    let mut aim = |ray: Ray64, must_hit: bool| {
        let hit = triangle_line(&ray, tri.p).filter(|_| must_hit);
        shots.push(Shot { ray, hit });
    };
    let front = from(inside, 1.0, 2.0, 2.0);
    aim(front, true);
    aim(from(inside, -1.0, 2.0, 2.0), true);
    aim(from(tri.at(0.7, 0.6), 1.0, 2.0, 2.0), false);
    aim(from(tri.at(-0.2, 0.5), 1.0, 2.0, 2.0), false);
    aim(Ray64::new(front.o, -front.d), false);
    // Far hits: t = 4 with max_t = 2 (>= 1, so a chained comparison
    // passes it), and min_t past the hit.
    let far = from(inside, 1.0, 8.0, 4.0);
    aim(far.between(0.0, 2.0), false);
    aim(far.between(5.0, f64::INFINITY), false);
    aim(far.between(3.0, 6.0), true);
    // Parallel to the plane, off it: a zero determinant, so t = inf, which
    // only a finite max_t keeps out (the staff's library reports that hit
    // when max_t is infinite, with a normal of NaN). A ray in the plane is
    // left out: whether it meets an edge-on triangle is moot.
    aim(
        Ray64::new(inside + 0.5 * unit - across, across).between(0.0, 100.0),
        false,
    );
    shots
}

/// Random rays at random triangles: hits well inside, misses well
/// outside (fixed seed).
fn random_shots(tri: &Tri, rng: &mut Pcg64) -> Vec<Shot> {
    (0..6)
        .map(|k| {
            let (b1, b2) = if k % 2 == 0 {
                let b1: f64 = rng.gen_range(0.05..0.85);
                (b1, rng.gen_range(0.05..(0.95 - b1)))
            } else {
                (rng.gen_range(-0.8..-0.05), rng.gen_range(0.05..0.9))
            };
            let (b1, b2) = if k % 4 == 1 { (b2, b1) } else { (b1, b2) };
            let q = tri.at(b1, b2);
            let dir = DVec3::new(rng.gen(), rng.gen(), rng.gen()) - 0.5;
            let dir = if dir.dot(tri.face()).abs() < 0.2 * dir.length() * tri.face().length() {
                tri.face().normalize()
            } else {
                dir
            };
            let o = q - dir * rng.gen_range(0.5..5.0);
            let ray = Ray64::new(o, dir);
            let hit = triangle_line(&ray, tri.p).filter(|_| k % 2 == 0);
            Shot { ray, hit }
        })
        .collect()
}

/// Every (triangle, shot) the probes use.
fn all_shots() -> Vec<(Tri, Shot)> {
    let mut rng = Pcg64::seed_from_u64(61);
    let mut out = Vec::new();
    for tri in triangles() {
        for s in shots(&tri).into_iter().chain(random_shots(&tri, &mut rng)) {
            out.push((tri, s));
        }
    }
    out
}

/// Which of the two functions a run probes.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Which {
    Intersect,
    HasIntersection,
}

/// Probes `Triangle::intersect`.
pub fn intersect(driver: &Driver) -> Verdict {
    probe(driver, Which::Intersect)
}

/// Probes `Triangle::has_intersection`.
pub fn has_intersection(driver: &Driver) -> Verdict {
    probe(driver, Which::HasIntersection)
}

fn probe(driver: &Driver, which: Which) -> Verdict {
    let (name, verb, n) = match which {
        Which::Intersect => ("triangle_intersect", "tri_hit", 8),
        Which::HasIntersection => ("triangle_has_intersection", "tri_any", 2),
    };
    let shots = all_shots();
    let mut commands = Vec::new();
    let mut current = None;
    let mut index = Vec::new();
    for (tri, shot) in &shots {
        if current != Some(tri.p) {
            commands.push(tri.command());
            current = Some(tri.p);
        }
        index.push(commands.len());
        commands.push(format!("{verb} {}", shot.ray.tokens()));
    }
    let transcript = match driver.run(name, commands) {
        Ok(t) => t,
        Err(e) => return Verdict::Broken(e),
    };
    let mut cases = Cases::default();
    let mut stub_like = true;
    // Hits accepted before min_t and past max_t: a chained comparison
    // accepts both.
    let (mut before, mut past) = (false, false);
    for ((tri, shot), &i) in shots.iter().zip(&index) {
        let got = match transcript.exactly(i, n) {
            Ok(v) => v,
            Err(stop) => return Verdict::stopped(&stop, transcript.command(i)),
        };
        if let (true, None, Some((t, ..))) =
            (got[0] == 1.0, shot.hit, triangle_line(&shot.ray, tri.p))
        {
            before |= t < shot.ray.min_t;
            past |= t > shot.ray.max_t;
        }
        stub_like &= got[0] == 1.0 && (which == Which::HasIntersection || got[1].is_infinite());
        cases.record(match which {
            Which::Intersect => judge_hit(tri, shot, &got),
            Which::HasIntersection => judge_any("has_intersection", tri, shot, got[0] == 1.0),
        });
    }
    if stub_like {
        return Verdict::NotWritten(
            "it answers true for every ray and records nothing, the starter's `return true;`"
                .into(),
        );
    }
    match cases.verdict(None) {
        Verdict::Fail(mut f)
            if f.mistake == Some(Mistake::TriangleChainedComparison) && !(before && past) =>
        {
            f.mistake = None;
            f.what = if past {
                "a hit past max_t counts: the test ignores max_t".into()
            } else {
                "a hit before min_t counts: the test ignores min_t".into()
            };
            Verdict::Fail(f)
        }
        v => v,
    }
}

/// The input of a case, as a student reads it.
fn input(call: &str, tri: &Tri, ray: &Ray64) -> String {
    format!(
        "{call} of the triangle p1 = {}, p2 = {}, p3 = {} with the ray {}",
        show(tri.p[0]),
        show(tri.p[1]),
        show(tri.p[2]),
        ray.show()
    )
}

/// The mistake of a hit accepted outside `[min_t, max_t]` (the probe
/// keeps it only when hits on both sides are accepted).
fn out_of_range(shot: &Shot) -> Option<Mistake> {
    (shot.ray.max_t >= 1.0).then_some(Mistake::TriangleChainedComparison)
}

/// Whether `call` said hit or miss rightly.
fn judge_any(call: &str, tri: &Tri, shot: &Shot, hit: bool) -> Option<Failure> {
    let want = shot.hit.is_some();
    if hit == want {
        return None;
    }
    let call = input(call, tri, &shot.ray);
    Some(match (want, triangle_line(&shot.ray, tri.p)) {
        (false, Some((t, ..))) if t > shot.ray.max_t || t < shot.ray.min_t => failure(
            call,
            "false",
            "true",
            format!(
                "the ray meets the triangle at t = {}, outside [min_t, max_t]",
                num(t)
            ),
            out_of_range(shot),
        ),
        (false, _) => failure(
            call,
            "false",
            "true",
            "a ray that misses counts as a hit",
            None,
        ),
        (true, _) => failure(
            call,
            "true",
            "false",
            "a ray that hits counts as a miss",
            None,
        ),
    })
}

/// `intersect`: `HIT T N PRIM BSDF MAX_T`.
fn judge_hit(tri: &Tri, shot: &Shot, got: &[f64]) -> Option<Failure> {
    let call = input("intersect", tri, &shot.ray);
    let (hit, t, n, prim, bsdf, max_t) = (
        got[0] == 1.0,
        got[1],
        vec_at(got, 2),
        got[5],
        got[6],
        got[7],
    );
    let Some((want_t, b1, b2)) = shot.hit else {
        if hit {
            return judge_any("intersect", tri, shot, true);
        }
        if max_t != shot.ray.max_t {
            return Some(failure(
                call,
                format!("false, r.max_t left at {}", num(shot.ray.max_t)),
                format!("false, r.max_t = {}", num(max_t)),
                "a miss changed the ray's max_t",
                None,
            ));
        }
        return None;
    };
    let want_n = tri.blend(b1, b2, [0, 1, 2]);
    let expected = format!(
        "true, t = {}, n along {}",
        num(want_t),
        show(want_n.normalize())
    );
    let said = format!("{}, t = {}, n = {}", hit, num(t), show(n));
    if !hit {
        return judge_any("intersect", tri, shot, false);
    }
    if !close(t, want_t, 1e-9) {
        return Some(failure(call, expected, said, "the hit's t is wrong", None));
    }
    if !same_direction(n, want_n, 1e-6) {
        let permuted = [[1, 2, 0], [2, 0, 1], [0, 2, 1], [2, 1, 0], [1, 0, 2]]
            .iter()
            .any(|&order| same_direction(n, tri.blend(b1, b2, order), 1e-6));
        return Some(failure(
            call,
            expected,
            said,
            "the normal is not the vertex normals blended with the barycentrics",
            permuted.then_some(Mistake::BarycentricsPermuted),
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
            "the hit record does not name the triangle and its BSDF",
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
