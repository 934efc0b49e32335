//! Which binary nodes become wide nodes, which become leaves, and which
//! are passed over: the grouping of the binary tree into eight-wide
//! nodes of least expected cost (Ylitie, Karras and Laine, "Efficient
//! Incoherent Ray Traversal on GPUs Through Compressed Wide BVHs", HPG
//! 2017, section 4.1: dynamic programming over the binary tree).
//!
//! The cost is the surface area heuristic's (MacDonald and Booth 1990),
//! counted in wide node tests and triangle packs:
//!
//! ```text
//! node(n)   = A(n) C_node + split(n, 8)              n a wide node
//! leaf(n)   = A(n) C_pack ceil(N(n) / 4)             n one leaf of N(n) primitives
//! one(n)    = min(node(n), leaf(n))                  n a single child of its parent
//! many(n,j) = min(one(n), split(n, j))               n as at most j children, j = 1..8
//! split(n,j)= min over k = 1..j-1 of many(left, k) + many(right, j - k)
//! ```
//!
//! A binary leaf can only be a leaf; a subtree may become one leaf only
//! when it holds at most [`MERGE`] primitives and no sphere. A sphere
//! keeps its own binary leaf and its tight box: its test is scalar and
//! costly, so merged into a leaf of twelve it would be tested by every
//! ray that enters the leaf (measured on `CBspheres_lambertian.dae`,
//! where the spheres' scalar test was 11 % of the render with them
//! merged). Solved bottom up (children come after their parent in
//! [`Bvh::nodes`]), eight values per binary node, in about 4 ms for the
//! benchmark's 122k interior binary nodes.
//!
//! The greedy collapse this replaces opened the child of largest area
//! until a node had eight children. It could not pull a leaf up past a
//! node that had room, so the wide nodes near the leaves were often half
//! empty: on the benchmark's sphere, 3.9 children a node, where the
//! grouping finds 6.0 (41,068 nodes become 24,263; primary rays +2.3 %,
//! random rays +6-14 %: `docs/maintainers/wide-bvh.md`, round 10).

use super::collapse::MERGE;
use super::{ARITY, WIDTH};
use crate::bvh::{Bvh, Link};
use crate::intersect::Aabb;

/// Cost of a wide node's test: the unit.
pub const NODE_COST: f32 = 1.0;
/// Cost of one triangle pack's test, relative to a node's: about 8 ns
/// against 20 ns on the benchmark's primary rays. (It only matters where
/// a subtree may become one leaf or stay a node; with the wide build's
/// options every such subtree is already a binary leaf, each leaf's cost
/// is the same in every grouping, and the grouping minimises the area of
/// the wide nodes alone.)
pub const PACK_COST: f32 = 0.4;

/// How a binary subtree is represented with at most `j` children.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
enum Choice {
    /// The subtree's root is one child (a wide node or a leaf).
    #[default]
    Root,
    /// `k` children from the left subtree, `j - k` from the right.
    Split(u8),
}

/// The solved grouping of one binary tree.
pub struct Grouping {
    /// Per binary node, for `j = 1..=8` children: the choice.
    choices: Vec<[Choice; ARITY]>,
    /// Per binary node: its children as a wide node's, `k` from the left.
    node_split: Vec<u8>,
    /// Per binary node: as a single child, a leaf (else a wide node).
    as_leaf: Vec<bool>,
}

impl Grouping {
    /// Solves the grouping for `bvh`; `sizes[n]` is the number of
    /// primitives under binary node `n`, `spheres[n]` whether a sphere is.
    pub fn solve(bvh: &Bvh, sizes: &[u32], spheres: &[bool]) -> Self {
        let count = bvh.nodes.len();
        let mut many = vec![[0.0f32; ARITY]; count];
        let mut out = Grouping {
            choices: vec![[Choice::Root; ARITY]; count],
            node_split: vec![1; count],
            as_leaf: vec![false; count],
        };
        let leaf_cost = |area: f32, n: u32| area * PACK_COST * (n as usize).div_ceil(WIDTH) as f32;
        for n in (0..count).rev() {
            let node = &bvh.nodes[n];
            let areas = [0, 1].map(|c| node.child_bounds(c).surface_area());
            let child = |c: usize, j: usize| match node.children[c] {
                link if link.is_leaf() => leaf_cost(areas[c], link.count),
                link => many[link.first as usize][j - 1],
            };
            let mut split = [(f32::INFINITY, 0u8); ARITY];
            for (j, best) in split.iter_mut().enumerate().skip(1) {
                for k in 1..=j {
                    let cost = child(0, k) + child(1, j + 1 - k);
                    if cost < best.0 {
                        *best = (cost, k as u8);
                    }
                }
            }
            let area = node
                .child_bounds(0)
                .union(node.child_bounds(1))
                .surface_area();
            let node_cost = area * NODE_COST + split[ARITY - 1].0;
            let leaf = if sizes[n] as usize <= MERGE && !spheres[n] {
                leaf_cost(area, sizes[n])
            } else {
                f32::INFINITY
            };
            let one = node_cost.min(leaf);
            out.as_leaf[n] = leaf <= node_cost;
            out.node_split[n] = split[ARITY - 1].1;
            for (j, &(cost, k)) in split.iter().enumerate() {
                if cost < one {
                    many[n][j] = cost;
                    out.choices[n][j] = Choice::Split(k);
                } else {
                    many[n][j] = one;
                }
            }
        }
        out
    }

    /// Whether the binary subtree `link` becomes one leaf.
    pub fn is_leaf(&self, link: Link) -> bool {
        link.is_leaf() || self.as_leaf[link.first as usize]
    }

    /// The children of the wide node made from binary node `index`: the
    /// roots of the binary subtrees they stand for, at most eight.
    pub fn children(&self, bvh: &Bvh, index: usize, out: &mut Vec<(Aabb, Link)>) {
        out.clear();
        let node = &bvh.nodes[index];
        let k = self.node_split[index] as usize;
        self.expand(bvh, (node.child_bounds(0), node.children[0]), k, out);
        self.expand(
            bvh,
            (node.child_bounds(1), node.children[1]),
            ARITY - k,
            out,
        );
    }

    /// The roots standing for subtree `link` with at most `j` children.
    fn expand(
        &self,
        bvh: &Bvh,
        (bounds, link): (Aabb, Link),
        j: usize,
        out: &mut Vec<(Aabb, Link)>,
    ) {
        if link.is_leaf() {
            out.push((bounds, link));
            return;
        }
        let index = link.first as usize;
        match self.choices[index][j - 1] {
            Choice::Root => out.push((bounds, link)),
            Choice::Split(k) => {
                let node = &bvh.nodes[index];
                let k = k as usize;
                self.expand(bvh, (node.child_bounds(0), node.children[0]), k, out);
                self.expand(bvh, (node.child_bounds(1), node.children[1]), j - k, out);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use glam::Vec3;
    use rand::Rng;

    use super::*;
    use crate::bvh::build::{build, BuildOptions};
    use crate::bvh::wide::collapse::subtree_sizes;
    use crate::math::rng::sampler;

    fn leaf_cost(area: f32, n: u32) -> f32 {
        area * PACK_COST * (n as usize).div_ceil(WIDTH) as f32
    }

    fn size(bvh: &Bvh, link: Link) -> u32 {
        match link {
            l if l.is_leaf() => l.count,
            l => bvh.nodes[l.first as usize]
                .children
                .iter()
                .map(|&c| size(bvh, c))
                .sum(),
        }
    }

    /// Whether a primitive marked in `sphere` lies under `link`.
    fn holds_sphere(bvh: &Bvh, link: Link, sphere: &[bool]) -> bool {
        if link.is_leaf() {
            return link
                .slots()
                .any(|slot| sphere[bvh.order[slot as usize] as usize]);
        }
        let node = &bvh.nodes[link.first as usize];
        node.children.iter().any(|&c| holds_sphere(bvh, c, sphere))
    }

    fn children(bvh: &Bvh, link: Link) -> [(Aabb, Link); 2] {
        let node = &bvh.nodes[link.first as usize];
        [0, 1].map(|c| (node.child_bounds(c), node.children[c]))
    }

    /// Every cut of the binary subtree under `(bounds, link)`: sets of
    /// descendants (itself included) that hold each leaf exactly once.
    fn cuts(bvh: &Bvh, (bounds, link): (Aabb, Link)) -> Vec<Vec<(Aabb, Link)>> {
        let mut all = vec![vec![(bounds, link)]];
        if !link.is_leaf() {
            let [left, right] = children(bvh, link).map(|c| cuts(bvh, c));
            for a in &left {
                for b in &right {
                    if a.len() + b.len() <= ARITY {
                        all.push([a.clone(), b.clone()].concat());
                    }
                }
            }
        }
        all
    }

    /// The least cost of the subtree as one child, by trying every
    /// grouping: a leaf where allowed, or a node over any cut of at most
    /// eight of its descendants, each of those at its least cost.
    fn brute_force(bvh: &Bvh, (bounds, link): (Aabb, Link), sphere: &[bool]) -> f32 {
        let area = bounds.surface_area();
        let n = size(bvh, link);
        if link.is_leaf() {
            return leaf_cost(area, n);
        }
        let leaf = if n as usize <= MERGE && !holds_sphere(bvh, link, sphere) {
            leaf_cost(area, n)
        } else {
            f32::INFINITY
        };
        let [left, right] = children(bvh, link).map(|c| cuts(bvh, c));
        let mut node = f32::INFINITY;
        for a in &left {
            for b in &right {
                if a.len() + b.len() <= ARITY {
                    let below: f32 = a
                        .iter()
                        .chain(b)
                        .map(|&c| brute_force(bvh, c, sphere))
                        .sum();
                    node = node.min(area * NODE_COST + below);
                }
            }
        }
        leaf.min(node)
    }

    /// The cost of the wide tree the grouping makes, and its widest node.
    fn grouped(bvh: &Bvh, g: &Grouping, (bounds, link): (Aabb, Link)) -> (f32, usize) {
        let area = bounds.surface_area();
        if g.is_leaf(link) {
            return (leaf_cost(area, size(bvh, link)), 0);
        }
        let mut kids = Vec::new();
        g.children(bvh, link.first as usize, &mut kids);
        kids.iter()
            .fold((area * NODE_COST, kids.len()), |(cost, widest), &c| {
                let (c, w) = grouped(bvh, g, c);
                (cost + c, widest.max(w))
            })
    }

    /// Random boxes (2 to 27) in binary trees with leaves of one to three
    /// primitives, with no sphere, some spheres, or spheres only (a
    /// subtree of up to twelve primitives and no sphere may merge into a
    /// leaf): the grouping's cost is the least over every grouping, and no
    /// node has more than eight children.
    #[test]
    fn the_grouping_is_the_cheapest_of_all() {
        let mut rng = sampler(2017, 0);
        let options = BuildOptions {
            max_leaf_size: 3,
            leaf_at_most: 0,
            traversal_cost: 0.5,
        };
        for case in 0..96 {
            let n = 2 + case / 3 % 26;
            let boxes: Vec<Aabb> = (0..n)
                .map(|_| {
                    let c = Vec3::new(rng.gen(), rng.gen(), rng.gen()) * 10.0;
                    let e = Vec3::new(rng.gen(), rng.gen(), rng.gen());
                    Aabb::from_points([c, c + e])
                })
                .collect();
            let share = [0.0, 0.3, 1.0][case % 3];
            let sphere: Vec<bool> = (0..n).map(|_| rng.gen::<f32>() < share).collect();
            let bvh = build(&boxes, &options);
            let root = (bvh.bounds, bvh.root.expect("a tree"));
            let sizes = subtree_sizes(&bvh);
            let spheres: Vec<bool> = (0..bvh.nodes.len())
                .map(|i| {
                    holds_sphere(
                        &bvh,
                        Link {
                            first: i as u32,
                            count: 0,
                        },
                        &sphere,
                    )
                })
                .collect();
            let grouping = Grouping::solve(&bvh, &sizes, &spheres);
            let (cost, widest) = grouped(&bvh, &grouping, root);
            let best = brute_force(&bvh, root, &sphere);
            assert!(widest <= ARITY, "a node of {widest} children");
            assert!(
                (cost - best).abs() <= 1e-4 * best,
                "{n} boxes: grouping {cost}, best {best}"
            );
        }
    }
}
