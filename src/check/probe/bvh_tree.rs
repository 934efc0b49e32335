//! The BVH's tree (part 2): the probe of `BVHAccel::construct_bvh`, and
//! the mesh, script and tree listing the traversal probes
//! ([`bvh`](mod@super::bvh)) share.
//!
//! The mesh is 600 small triangles scattered in a box, a third of them in
//! a dense cluster (fixed seed); the tree is built with the starter's leaf
//! size 4. The tree must hold every triangle in exactly one leaf, and
//! every box must contain its children's boxes (a leaf's, its
//! triangles').

use glam::DVec3;
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

use super::driver::{Driver, Transcript};
use super::geometry::{show, tokens, vec_at};
use super::verdict::{failure, Cases, Verdict};

/// The leaf size the starter passes to `BVHAccel`.
const LEAF: usize = 4;

/// The mesh's triangles, by their corners.
pub(super) fn mesh() -> Vec<[DVec3; 3]> {
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

/// A node of the student's tree, as the driver lists it.
#[derive(Debug, Clone)]
pub(super) struct Node {
    min: DVec3,
    max: DVec3,
    /// A leaf's triangles (by index), `None` for an inner node.
    leaf: Option<Vec<i64>>,
    pub(super) children: Vec<usize>,
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

/// Runs the script `name`: the mesh loaded and its tree built, then
/// `commands` (from command `mesh.len() + 2`). The transcript and the
/// student's tree, or the verdict when the driver cannot run or the tree
/// cannot be read.
pub(super) fn run(
    driver: &Driver,
    name: &str,
    mesh: &[[DVec3; 3]],
    commands: Vec<String>,
) -> Result<(Transcript, Vec<Node>), Verdict> {
    let mut all = script(mesh);
    all.extend(commands);
    let t = driver.run(name, all).map_err(Verdict::Broken)?;
    let nodes = tree(&t, mesh.len())?;
    Ok((t, nodes))
}

/// The script that loads the mesh and builds its tree: the mesh's
/// triangles from command 1, `bvh` at command `mesh.len() + 1`.
fn script(mesh: &[[DVec3; 3]]) -> Vec<String> {
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
    let nodes = match run(driver, "bvh_construct", &mesh, Vec::new()) {
        Ok((_, nodes)) => nodes,
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
pub(super) fn under(nodes: &[Node], k: usize) -> Vec<usize> {
    let n = &nodes[k];
    match &n.leaf {
        Some(p) => p.iter().filter_map(|&i| usize::try_from(i).ok()).collect(),
        None => n.children.iter().flat_map(|&c| under(nodes, c)).collect(),
    }
}

/// The leaf (by node index) of each of `count` triangles, `None` for a
/// triangle in no leaf.
pub(super) fn leaf_of(nodes: &[Node], count: usize) -> Vec<Option<usize>> {
    let mut out = vec![None; count];
    for (k, node) in nodes.iter().enumerate() {
        for &i in node.leaf.iter().flatten() {
            if let Some(slot) = usize::try_from(i).ok().and_then(|i| out.get_mut(i)) {
                *slot = Some(k);
            }
        }
    }
    out
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
        assert_eq!(leaf_of(&nodes, 4), [Some(1), Some(2), Some(1), None]);
        assert_eq!(nodes.len(), 3);
        assert_eq!(nodes[0].children, vec![1, 2]);
        assert_eq!(nodes[1].leaf, Some(vec![0, 2]));
        assert_eq!(under(&nodes, 0), vec![0, 2, 1]);
        assert!(parse_tree(&v[..12]).is_err());
    }
}
