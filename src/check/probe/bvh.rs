//! The probes of the BVH's traversal (part 2): `BVHAccel::intersect` and
//! `has_intersection` against a scan of every triangle, on
//! [`bvh_tree`]'s mesh and the student's tree of it.
//!
//! Traversal must find, for each ray, the nearest of all the triangles'
//! hits (the exact answer, [`triangle_line`]; rays that graze an edge or
//! hit two triangles at nearly the same `t` are left out), and
//! `intersect(r, i, node)` on a child of the root must look only at that
//! child's triangles: the starter's stub, a loop over every primitive,
//! answers right at the root and wrong there.

use glam::DVec3;
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

use super::bvh_tree::{self, mesh, under};
use super::driver::Driver;
use super::geometry::{close, num, triangle_line, Ray64};
use super::verdict::{failure, Cases, Failure, Verdict};
use crate::mistakes::Mistake;

/// `count` rays from points in the mesh's bounding box grown by 3/4
/// (seed `seed`): most aimed at a triangle's centroid, some anywhere;
/// none too close to call ([`nearest`]).
pub(super) fn rays(mesh: &[[DVec3; 3]], count: usize, seed: u64) -> Vec<Ray64> {
    let (lo, hi) = mesh
        .iter()
        .flatten()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(*p), hi.max(*p))
        });
    let mut rng = Pcg64::seed_from_u64(seed);
    let mut out = Vec::new();
    while out.len() < count {
        let unit = DVec3::new(rng.gen(), rng.gen(), rng.gen()) - 0.5;
        let o = (lo + hi) / 2.0 + 1.75 * (hi - lo) * unit;
        let d = if out.len() % 5 < 3 {
            let t = mesh[rng.gen_range(0..mesh.len())];
            (t[0] + t[1] + t[2]) / 3.0 - o
        } else {
            DVec3::new(rng.gen(), rng.gen(), rng.gen()) - 0.5
        };
        let ray = Ray64::new(o, d);
        if nearest(mesh, &ray, |_| true).is_ok() {
            out.push(ray);
        }
    }
    out
}

/// The nearest hit `(t, index)` among the triangles `keep` keeps (`None`
/// for none), or `Err` when the ray is too close to call: it grazes an
/// edge, or two hits are within 1e-7 in `t`.
pub(super) fn nearest(
    mesh: &[[DVec3; 3]],
    ray: &Ray64,
    keep: impl Fn(usize) -> bool,
) -> Result<Option<(f64, usize)>, ()> {
    let mut hits = Vec::new();
    for (i, tri) in mesh.iter().enumerate().filter(|(i, _)| keep(*i)) {
        let Some((t, b1, b2)) = triangle_line(ray, *tri) else {
            continue;
        };
        if t < ray.min_t || t > ray.max_t {
            continue;
        }
        let edge = b1.min(b2).min(1.0 - b1 - b2);
        if edge.abs() < 1e-6 {
            return Err(());
        }
        if edge > 0.0 {
            hits.push((t, i));
        }
    }
    hits.sort_by(|a, b| a.0.total_cmp(&b.0));
    match hits.as_slice() {
        [a, b, ..] if close(a.0, b.0, 1e-7) => Err(()),
        _ => Ok(hits.first().copied()),
    }
}

/// Probes `BVHAccel::intersect`.
pub fn intersect(driver: &Driver) -> Verdict {
    traversal(driver, true)
}

/// Probes `BVHAccel::has_intersection`.
pub fn has_intersection(driver: &Driver) -> Verdict {
    traversal(driver, false)
}

/// Both probes: the mesh, its tree, then each ray at the root and at
/// the root's two children.
fn traversal(driver: &Driver, nearest_hit: bool) -> Verdict {
    let mesh = mesh();
    let rays = rays(&mesh, 300, 7);
    let (name, verb, n) = if nearest_hit {
        ("bvh_intersect", "bvh_hit", 4)
    } else {
        ("bvh_has_intersection", "bvh_any", 2)
    };
    let commands = rays
        .iter()
        .flat_map(|r| ["", "_at l", "_at r"].map(|at| format!("{verb}{at} {}", r.tokens())))
        .collect();
    let (t, nodes) = match bvh_tree::run(driver, name, &mesh, commands) {
        Ok(r) => r,
        Err(v) => return v,
    };
    if nodes.len() == 1 {
        return Verdict::Waits(
            "construct_bvh builds one leaf, so no traversal can be told from the starter's loop over every primitive".into(),
        );
    }
    let leaves = bvh_tree::leaf_of(&nodes, mesh.len());
    // The triangles of the root's children, where it has two.
    let sides: Vec<Vec<bool>> = nodes[0]
        .children
        .iter()
        .map(|&c| {
            let mut mine = vec![false; mesh.len()];
            under(&nodes, c)
                .into_iter()
                .filter(|&i| i < mesh.len())
                .for_each(|i| mine[i] = true);
            mine
        })
        .collect();
    let mut cases = Cases::default();
    // The starter's stub loops over every primitive whatever node it is
    // given: its answers at the root and at both children agree for
    // every ray, which no traversal that uses the node does.
    let mut ignores_node = sides.len() == 2;
    // The first farther triangle of the nearest one's leaf: it decides
    // what the failure is, wherever it comes.
    let mut same_leaf: Option<Failure> = None;
    for (r, ray) in rays.iter().enumerate() {
        let at = mesh.len() + 2 + 3 * r;
        ignores_node &=
            t.line(at).ok() == t.line(at + 1).ok() && t.line(at).ok() == t.line(at + 2).ok();
        for (side, path) in ["", "l", "r"].iter().enumerate() {
            let keep = |i: usize| side == 0 || sides.get(side - 1).is_some_and(|s| s[i]);
            if side > 0 && sides.len() < 2 {
                continue;
            }
            let got = match t.exactly(at + side, n) {
                Ok(v) => v,
                Err(stop) => return Verdict::stopped(&stop, t.command(at + side)),
            };
            let Ok(want) = nearest(&mesh, ray, keep) else {
                continue;
            };
            let function = if nearest_hit {
                "intersect"
            } else {
                "has_intersection"
            };
            let call = if side == 0 {
                format!("{function} at the root with the ray {}", ray.show())
            } else {
                format!(
                    "{function}(r, i, node) at the root's child {path} with the ray {}",
                    ray.show()
                )
            };
            let found = (got[0] == 1.0).then(|| {
                if nearest_hit {
                    (got[1], got[2] as i64)
                } else {
                    (f64::NAN, -1)
                }
            });
            let failure = judge(&call, want, found, nearest_hit, side, &leaves);
            if let Some(f) = failure.as_ref().filter(|f| f.what == SAME_LEAF) {
                same_leaf.get_or_insert_with(|| f.clone());
            }
            cases.record(failure);
        }
    }
    if ignores_node {
        return Verdict::NotWritten(
            "it ignores the node it is given and tests every primitive, the starter's loop: its answers at the root and at both children agree for every ray".into(),
        );
    }
    if !cases.all_pass() {
        return match (cases.verdict(None), same_leaf) {
            (Verdict::Fail(f), Some(leaf)) => Verdict::Fail(Failure {
                failed: f.failed,
                cases: f.cases,
                ..leaf
            }),
            (v, _) => v,
        };
    }
    match super::bvh_race::race(driver, nearest_hit) {
        Ok(note) => cases.verdict(Some(note)),
        Err(v) => v,
    }
}

/// What a farther triangle of the nearest one's leaf says: only a leaf's
/// loop that stops at its first hit reports one (a traversal that stops
/// at its first hit, `bvh-first-hit`, still finds a leaf's nearest).
const SAME_LEAF: &str = "a farther triangle of the same leaf is reported: the loop over a leaf's primitives stops at its first hit, not its nearest";

/// One answer against the nearest hit (`side` 0: at the root; 1 and 2:
/// at its children); `leaf_of` gives each triangle's leaf.
pub(super) fn judge(
    call: &str,
    want: Option<(f64, usize)>,
    found: Option<(f64, i64)>,
    nearest_hit: bool,
    side: usize,
    leaf_of: &[Option<usize>],
) -> Option<Failure> {
    let show_hit = |h: Option<(f64, i64)>| {
        h.map_or("a miss".to_owned(), |(t, i)| {
            if nearest_hit {
                format!("triangle {i} at t = {}", num(t))
            } else {
                "a hit".to_owned()
            }
        })
    };
    let expected = show_hit(want.map(|(t, i)| (t, i as i64)));
    let got = show_hit(found);
    match (want, found) {
        (None, None) => None,
        (Some(_), Some(_)) if !nearest_hit => None,
        (Some((wt, wi)), Some((t, i))) if i == wi as i64 && close(t, wt, 1e-9) => None,
        (Some((wt, wi)), Some((t, i))) if t > wt => {
            let leaf = |i: usize| leaf_of.get(i).copied().flatten();
            let one_leaf =
                usize::try_from(i).is_ok_and(|i| leaf(i).is_some() && leaf(i) == leaf(wi));
            Some(if one_leaf {
                failure(call, expected, got, SAME_LEAF, None)
            } else {
                failure(
                    call,
                    expected,
                    got,
                    "a farther triangle is reported, not the nearest",
                    (side == 0).then_some(Mistake::TraversalReturnsFirstHit),
                )
            })
        }
        (Some(_), None) => Some(failure(
            call,
            expected,
            got,
            "a ray that hits a triangle is reported as a miss",
            None,
        )),
        (None, Some(_)) if side > 0 => Some(failure(
            call,
            expected,
            got,
            "a triangle outside the node is reported",
            None,
        )),
        _ => Some(failure(
            call,
            expected,
            got,
            "the hit is not the nearest triangle's",
            None,
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_nearest_hit_and_the_calls_too_close_to_make() {
        let tri = |z: f64| {
            [
                DVec3::new(-1.0, -1.0, z),
                DVec3::new(1.0, -1.0, z),
                DVec3::new(0.0, 1.0, z),
            ]
        };
        let mesh = [tri(2.0), tri(1.0), tri(1.0 + 1e-9)];
        let ray = Ray64::new(DVec3::ZERO, DVec3::Z);
        assert_eq!(nearest(&mesh[..2], &ray, |_| true), Ok(Some((1.0, 1))));
        assert_eq!(nearest(&mesh[..2], &ray, |i| i == 0), Ok(Some((2.0, 0))));
        assert_eq!(nearest(&mesh, &ray, |_| true), Err(()));
        let edge = Ray64::new(DVec3::new(0.0, -1.0, 0.0), DVec3::Z);
        assert_eq!(nearest(&mesh[..1], &edge, |_| true), Err(()));
    }
}
