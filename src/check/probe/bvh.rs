//! The probes of the BVH (part 2): `BVHAccel::construct_bvh` by the tree
//! it builds, `BVHAccel::intersect` and `has_intersection` against a scan
//! of every triangle.
//!
//! The mesh is 600 small triangles scattered in a box, a third of them in
//! a dense cluster (fixed seed); the tree is built with the starter's leaf
//! size 4. The tree must hold every triangle in exactly one leaf, and
//! every box must contain its children's boxes (a leaf's, its
//! triangles'). Traversal must find, for each ray, the nearest of all the
//! triangles' hits (the exact answer, [`triangle_line`]; rays that graze
//! an edge or hit two triangles at nearly the same `t` are left out), and
//! `intersect(r, i, node)` on a child of the root must look only at that
//! child's triangles: the starter's stub, a loop over every primitive,
//! answers right at the root and wrong there.

use glam::DVec3;
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

use super::driver::{Driver, Transcript};
use super::geometry::{close, num, show, tokens, triangle_line, vec_at, Ray64};
use super::verdict::{failure, Cases, Failure, Verdict};
use crate::mistakes::Mistake;

/// The leaf size the starter passes to `BVHAccel`.
const LEAF: usize = 4;

/// The mesh's triangles, by their corners.
fn mesh() -> Vec<[DVec3; 3]> {
    let mut rng = Pcg64::seed_from_u64(2024);
    let unit = |rng: &mut Pcg64| DVec3::new(rng.gen(), rng.gen(), rng.gen()) - 0.5;
    (0..600)
        .map(|i| {
            let centre = if i % 3 == 0 {
                0.6 * unit(&mut rng) + 0.8
            } else {
                4.0 * unit(&mut rng)
            };
            let size = rng.gen_range(0.05..0.4);
            [
                centre + size * unit(&mut rng),
                centre + size * unit(&mut rng),
                centre + size * unit(&mut rng),
            ]
        })
        .collect()
}

/// The rays: most aimed at a triangle's centroid, some anywhere.
fn rays(mesh: &[[DVec3; 3]]) -> Vec<Ray64> {
    let mut rng = Pcg64::seed_from_u64(7);
    let mut out = Vec::new();
    while out.len() < 300 {
        let o = DVec3::new(rng.gen(), rng.gen(), rng.gen()) * 7.0 - 3.5;
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
fn nearest(
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

/// A node of the student's tree, as the driver lists it.
#[derive(Debug, Clone)]
struct Node {
    min: DVec3,
    max: DVec3,
    /// A leaf's triangles (by index), `None` for an inner node.
    leaf: Option<Vec<i64>>,
    children: Vec<usize>,
}

/// Reads the preorder listing into nodes (the root first), or what is
/// malformed about it.
fn parse_tree(v: &[f64]) -> Result<Vec<Node>, String> {
    fn node(v: &[f64], at: &mut usize, out: &mut Vec<Node>) -> Result<usize, String> {
        let take = |at: &mut usize, n: usize| -> Result<&[f64], String> {
            let s = v.get(*at..*at + n).ok_or("the listing ends early")?;
            *at += n;
            Ok(s)
        };
        let head = take(at, 7)?;
        let (kind, min, max) = (head[0], vec_at(head, 1), vec_at(head, 4));
        let me = out.len();
        out.push(Node {
            min,
            max,
            leaf: None,
            children: Vec::new(),
        });
        if kind == 1.0 {
            let count = take(at, 1)?[0] as usize;
            out[me].leaf = Some(take(at, count)?.iter().map(|&i| i as i64).collect());
        } else {
            let has = take(at, 2)?.to_vec();
            for h in has {
                if h == 1.0 {
                    let child = node(v, at, out)?;
                    out[me].children.push(child);
                }
            }
        }
        Ok(me)
    }
    let mut out = Vec::new();
    let mut at = 0;
    node(v, &mut at, &mut out)?;
    Ok(out)
}

/// The script: the mesh, the tree, then each ray at the root and at the
/// root's two children.
fn script(mesh: &[[DVec3; 3]], rays: &[Ray64], verb: &str) -> Vec<String> {
    let mut commands = vec!["mesh_clear".to_owned()];
    for t in mesh {
        let n = (t[1] - t[0]).cross(t[2] - t[0]).normalize();
        commands.push(format!(
            "mesh_tri {} {} {} {} {} {}",
            tokens(t[0]),
            tokens(t[1]),
            tokens(t[2]),
            tokens(n),
            tokens(n),
            tokens(n)
        ));
    }
    commands.push(format!("bvh {LEAF}"));
    for r in rays {
        commands.push(format!("{verb} {}", r.tokens()));
        commands.push(format!("{verb}_at l {}", r.tokens()));
        commands.push(format!("{verb}_at r {}", r.tokens()));
    }
    commands
}

/// The tree the driver answered `bvh` with (command `mesh.len() + 1`).
fn tree(t: &Transcript, count: usize) -> Result<Vec<Node>, Verdict> {
    let at = count + 1;
    let line = t.line(at).map_err(|s| Verdict::stopped(&s, "bvh 4"))?;
    // `I` and `L` as 0 and 1, the rest numbers.
    let v: Option<Vec<f64>> = line
        .split_ascii_whitespace()
        .map(|w| match w {
            "I" => Some(0.0),
            "L" => Some(1.0),
            w => w.parse().ok(),
        })
        .collect();
    let v =
        v.ok_or_else(|| Verdict::Broken(format!("the tree's listing is not numbers: {line:.80}")))?;
    parse_tree(&v).map_err(|e| Verdict::Broken(format!("the tree's listing: {e}")))
}

/// Probes `BVHAccel::construct_bvh`.
pub fn construct(driver: &Driver) -> Verdict {
    let mesh = mesh();
    let t = match driver.run("bvh_construct", script(&mesh, &[], "bvh_hit")) {
        Ok(t) => t,
        Err(e) => return Verdict::Broken(e),
    };
    let nodes = match tree(&t, mesh.len()) {
        Ok(n) => n,
        Err(v) => return v,
    };
    if nodes.len() == 1 {
        return Verdict::NotWritten(format!(
            "the root is one leaf of all {} triangles, the starter's `construct_bvh`",
            mesh.len()
        ));
    }
    let mut cases = Cases::default();
    let mut seen = vec![0usize; mesh.len()];
    let inside = |a: &Node, min: DVec3, max: DVec3| {
        let slack = 1e-9 * (a.max - a.min).length().max(1.0);
        min.cmpge(a.min - slack).all() && max.cmple(a.max + slack).all()
    };
    let boxed = |n: &Node| format!("min {}, max {}", show(n.min), show(n.max));
    for (k, n) in nodes.iter().enumerate() {
        match &n.leaf {
            Some(prims) => {
                for &i in prims {
                    let Some(tri) = usize::try_from(i).ok().and_then(|i| mesh.get(i)) else {
                        cases.record(Some(failure(
                            format!("leaf {k}"),
                            "the mesh's primitives",
                            "a pointer not in the mesh",
                            "a leaf holds a primitive that is not one of the mesh's",
                            None,
                        )));
                        continue;
                    };
                    seen[i as usize] += 1;
                    let (lo, hi) = (
                        tri[0].min(tri[1]).min(tri[2]),
                        tri[0].max(tri[1]).max(tri[2]),
                    );
                    cases.record((!inside(n, lo, hi)).then(|| {
                        failure(
                            format!("leaf {k}, triangle {i}"),
                            format!("a box around min {}, max {}", show(lo), show(hi)),
                            boxed(n),
                            "a leaf's box does not contain its triangle",
                            None,
                        )
                    }));
                }
                if prims.is_empty() {
                    cases.record(Some(failure(
                        format!("node {k}"),
                        "a leaf with primitives",
                        "an empty leaf",
                        "a leaf holds nothing",
                        None,
                    )));
                }
            }
            None => {
                if n.children.len() != 2 {
                    cases.record(Some(failure(
                        format!("node {k}"),
                        "both l and r",
                        format!("{} children", n.children.len()),
                        "an inner node lacks a child (the traversal follows both)",
                        None,
                    )));
                }
                for &c in &n.children {
                    let child = &nodes[c];
                    cases.record((!inside(n, child.min, child.max)).then(|| {
                        failure(
                            format!("node {k} and its child {c}"),
                            format!("a box around the child's {}", boxed(child)),
                            boxed(n),
                            "a node's box does not contain its child's",
                            None,
                        )
                    }));
                }
            }
        }
    }
    for (i, &count) in seen.iter().enumerate() {
        cases.record((count != 1).then(|| {
            failure(
                format!("triangle {i}"),
                "in exactly one leaf",
                format!("in {count} leaves"),
                "the leaves do not split the primitives: each must be in exactly one",
                None,
            )
        }));
    }
    let leaves: Vec<usize> = nodes
        .iter()
        .filter_map(|n| n.leaf.as_ref().map(Vec::len))
        .collect();
    let note = format!(
        "{} nodes, {} leaves, the largest of {} triangles",
        nodes.len(),
        leaves.len(),
        leaves.iter().max().copied().unwrap_or(0)
    );
    cases.verdict(Some(note))
}

/// The triangles under node `k`.
fn under(nodes: &[Node], k: usize) -> Vec<usize> {
    let n = &nodes[k];
    match &n.leaf {
        Some(p) => p.iter().filter_map(|&i| usize::try_from(i).ok()).collect(),
        None => n.children.iter().flat_map(|&c| under(nodes, c)).collect(),
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

fn traversal(driver: &Driver, nearest_hit: bool) -> Verdict {
    let mesh = mesh();
    let rays = rays(&mesh);
    let (name, verb, n) = if nearest_hit {
        ("bvh_intersect", "bvh_hit", 4)
    } else {
        ("bvh_has_intersection", "bvh_any", 2)
    };
    let t = match driver.run(name, script(&mesh, &rays, verb)) {
        Ok(t) => t,
        Err(e) => return Verdict::Broken(e),
    };
    let nodes = match tree(&t, mesh.len()) {
        Ok(n) => n,
        Err(v) => return v,
    };
    if nodes.len() == 1 {
        return Verdict::Waits(
            "construct_bvh builds one leaf, so no traversal can be told from the starter's loop over every primitive".into(),
        );
    }
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
            cases.record(judge(&call, want, found, nearest_hit, side));
        }
    }
    if ignores_node {
        return Verdict::NotWritten(
            "it ignores the node it is given and tests every primitive, the starter's loop: its answers at the root and at both children agree for every ray".into(),
        );
    }
    cases.verdict(None)
}

/// One answer against the nearest hit.
fn judge(
    call: &str,
    want: Option<(f64, usize)>,
    found: Option<(f64, i64)>,
    nearest_hit: bool,
    side: usize,
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
        (Some((wt, _)), Some((t, _))) if t > wt => Some(failure(
            call,
            expected,
            got,
            "a farther triangle is reported, not the nearest",
            (side == 0).then_some(Mistake::TraversalReturnsFirstHit),
        )),
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
    fn a_listing_reads_as_a_tree() {
        // Root (inner, both children), a leaf of [0, 2], a leaf of [1].
        let v = [
            0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 1.0, //
            1.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 2.0, 0.0, 2.0, //
            1.0, 0.5, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 1.0,
        ];
        let nodes = parse_tree(&v).unwrap();
        assert_eq!(nodes.len(), 3);
        assert_eq!(nodes[0].children, vec![1, 2]);
        assert_eq!(nodes[1].leaf, Some(vec![0, 2]));
        assert_eq!(under(&nodes, 0), vec![0, 2, 1]);
        assert!(parse_tree(&v[..12]).is_err());
    }

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
