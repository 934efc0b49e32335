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

use glam::Vec3A;

use crate::math::float::gamma;

use crate::intersect::Aabb;

/// One node of the flattened tree.
///
/// Interior: `count == 0`, children at `first` and `first + 1`.
/// Leaf: primitives at slots `first .. first + count` of [`Bvh::order`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Node {
    pub first: u32,
    pub count: u32,
}

impl Node {
    pub fn is_leaf(&self) -> bool {
        self.count > 0
    }
}

/// A node's box, in SIMD lanes (32 bytes), stored apart from the [`Node`]s
/// so that the two sibling boxes that traversal tests together share one
/// 64-byte cache line.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(32))]
pub struct NodeBox {
    pub min: Vec3A,
    pub max: Vec3A,
}

impl NodeBox {
    pub fn aabb(&self) -> Aabb {
        Aabb {
            min: self.min.into(),
            max: self.max.into(),
        }
    }

    /// The ray's entry distance into the box within `[t_min, t_max]`
    /// (the slab test of [`Aabb::hit_distance`], four lanes at a time).
    #[inline(always)]
    pub fn hit_distance(
        &self,
        origin: Vec3A,
        inv_dir: Vec3A,
        t_min: f32,
        t_max: f32,
    ) -> Option<f32> {
        let t0 = (self.min - origin) * inv_dir;
        let t1 = (self.max - origin) * inv_dir;
        let near = t0.min(t1);
        let far = t0.max(t1) * (1.0 + 2.0 * gamma(3));
        let enter = near.max_element().max(t_min);
        let exit = far.min_element().min(t_max);
        (enter <= exit).then_some(enter)
    }
}

/// A flattened BVH. `nodes[0]` is the root; an empty BVH has no nodes.
/// `boxes[i]` is the box of `nodes[i]`.
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    pub nodes: Vec<Node>,
    pub boxes: Vec<NodeBox>,
    /// `order[slot]` is the primitive id stored at leaf slot `slot`.
    pub order: Vec<u32>,
}

/// Depth limit of the tree; traversal stacks are sized from it.
pub const MAX_DEPTH: usize = 64;

impl Bvh {
    /// Bounds of everything in the tree (empty for an empty tree).
    pub fn bounds(&self) -> Aabb {
        self.boxes.first().map_or(Aabb::EMPTY, NodeBox::aabb)
    }

    /// Number of leaves and the depth of the deepest one (root depth 1).
    pub fn leaf_stats(&self) -> (usize, usize) {
        let mut leaves = 0;
        let mut max_depth = 0;
        let mut stack = Vec::new();
        if !self.nodes.is_empty() {
            stack.push((0usize, 1usize));
        }
        while let Some((i, depth)) = stack.pop() {
            let node = &self.nodes[i];
            if node.is_leaf() {
                leaves += 1;
                max_depth = max_depth.max(depth);
            } else {
                stack.push((node.first as usize, depth + 1));
                stack.push((node.first as usize + 1, depth + 1));
            }
        }
        (leaves, max_depth)
    }
}
