//! Part 2: a bounding volume hierarchy (BVH) over the scene's primitives.
//!
//! - [`build`]: top-down binned surface-area-heuristic (SAH) build
//!   (Wald, "On fast Construction of SAH-based Bounding Volume Hierarchies",
//!   2007). The expected cost of splitting a node with box `A` into `L`, `R`:
//!
//!   ```text
//!   C(L, R) = C_trav + C_isect * (SA(L) N_L + SA(R) N_R) / SA(A)
//!   ```
//!
//!   against `C_isect * N` for a leaf; `SA` is surface area, because the
//!   chance that a random ray meeting `A` also meets a convex `B` inside it
//!   is `SA(B) / SA(A)`.
//! - [`Bvh`]: the tree flattened into one array of 32-byte [`Node`]s; the two
//!   children of an interior node sit side by side, so one cache line holds
//!   both boxes that traversal tests next.
//! - [`traverse`]: closest-hit (front-to-back, nearer child first, with a
//!   stack) and any-hit (shadow rays: stop at the first hit).
//! - [`validate`]: structural checks used after every build in the tests.
//! - [`BvhAccel`]: the BVH plus the shapes in leaf order, an [`Intersector`](crate::intersect::Intersector).

pub mod accel;
pub mod build;
pub mod throughput;
pub mod traverse;
pub mod validate;

pub use accel::BvhAccel;
pub use build::BuildOptions;
pub use validate::ValidationError;

use crate::intersect::Aabb;

/// A reference to a subtree: an interior node, or a leaf's range of slots.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Link {
    /// Interior: index into [`Bvh::nodes`]. Leaf: first slot in [`Bvh::order`].
    pub first: u32,
    /// Leaf: number of primitives (at least 1). Interior: 0.
    pub count: u32,
}

impl Link {
    pub fn is_leaf(&self) -> bool {
        self.count > 0
    }

    /// The leaf's slots (empty for an interior link).
    pub fn slots(&self) -> std::ops::Range<u32> {
        self.first..self.first + self.count
    }
}

/// An interior node: the boxes of its two children and the links to them,
/// 64 bytes, so one cache line holds everything traversal reads at a node.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(64))]
pub struct Node {
    pub child_bounds: [Aabb; 2],
    pub children: [Link; 2],
}

/// A flattened BVH: the root's box and link, and the interior nodes.
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    /// Box of everything in the tree.
    pub bounds: Aabb,
    /// The root: a leaf for a tiny scene, else `nodes[0]`; `None` when empty.
    pub root: Option<Link>,
    /// Interior nodes; children of a node come after it.
    pub nodes: Vec<Node>,
    /// `order[slot]` is the primitive id stored at leaf slot `slot`.
    pub order: Vec<u32>,
}

/// Depth limit of the tree; traversal stacks are sized from it.
pub const MAX_DEPTH: usize = 64;

impl Bvh {
    /// Every link with its depth (root depth 1), depth first.
    pub fn links(&self) -> Vec<(Link, usize)> {
        let mut out = Vec::new();
        let mut stack: Vec<(Link, usize)> = self.root.iter().map(|&l| (l, 1)).collect();
        while let Some((link, depth)) = stack.pop() {
            out.push((link, depth));
            if !link.is_leaf() {
                if let Some(node) = self.nodes.get(link.first as usize) {
                    stack.extend(node.children.iter().map(|&c| (c, depth + 1)));
                }
            }
        }
        out
    }

    /// Number of leaves and the depth of the deepest one (root depth 1).
    pub fn leaf_stats(&self) -> (usize, usize) {
        self.links()
            .iter()
            .filter(|(l, _)| l.is_leaf())
            .fold((0, 0), |(n, d), &(_, depth)| (n + 1, d.max(depth)))
    }
}
