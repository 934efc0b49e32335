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
//! - [`Bvh`]: the tree flattened into one array of 64-byte interior [`Node`]s
//!   (`size_of::<Node>()`, checked by a unit test), each holding the boxes
//!   of both its children and the links to them, so one 64-byte cache line
//!   holds both boxes that traversal tests next.
//! - [`traverse`]: closest-hit (front-to-back, nearer child first, with a
//!   stack) and any-hit (shadow rays: stop at the first hit).
//! - [`validate`]: structural checks used after every build in the tests;
//!   [`cost`]: the SAH cost of a whole tree, its quality.
//! - [`throughput`] and [`scale`]: the ray-throughput benchmark and the
//!   scale benchmark (build time, memory and ray rate from 10k to 10M
//!   triangles).
//! - [`BvhAccel`]: the BVH over a scene's primitives, an [`Intersector`](crate::intersect::Intersector).
//! - [`wide`]: the fast version the renderers use, [`WideBvhAccel`]: the
//!   same build collapsed to eight children per node, with SIMD box and
//!   triangle tests and the same hits.

pub mod accel;
mod binning;
pub mod build;
pub mod cost;
mod parallel;
pub mod scale;
pub mod throughput;
pub mod traverse;
pub mod validate;
pub mod wide;

pub use accel::BvhAccel;
pub use build::BuildOptions;
pub use validate::ValidationError;
pub use wide::WideBvhAccel;

use glam::{Vec3, Vec4, Vec4Swizzles};

use crate::intersect::Aabb;
use crate::math::float::gamma;

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
///
/// The boxes are stored by axis, one SIMD register each, so one ray is
/// tested against both children at once ([`Node::hit_children`]):
/// lanes `(child 0 min, child 1 min, child 0 max, child 1 max)`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(64))]
pub struct Node {
    pub x: Vec4,
    pub y: Vec4,
    pub z: Vec4,
    pub children: [Link; 2],
}

/// A ray prepared for box tests: origin and inverse direction, each
/// component splatted across four lanes.
#[derive(Clone, Copy, Debug)]
pub struct RayLanes {
    origin: [Vec4; 3],
    inv_dir: [Vec4; 3],
    /// Whether some direction component is zero: only then can a plane
    /// distance be NaN.
    has_zero_direction: bool,
}

impl RayLanes {
    /// `inv_dir` is `1 / d` per component (infinite for a zero component).
    pub fn new(origin: Vec3, inv_dir: Vec3) -> Self {
        RayLanes {
            origin: [origin.x, origin.y, origin.z].map(Vec4::splat),
            inv_dir: [inv_dir.x, inv_dir.y, inv_dir.z].map(Vec4::splat),
            has_zero_direction: !inv_dir.is_finite(),
        }
    }
}

impl Node {
    pub fn new(child_bounds: [Aabb; 2], children: [Link; 2]) -> Self {
        let [a, b] = child_bounds;
        let lanes = |axis: usize| Vec4::new(a.min[axis], b.min[axis], a.max[axis], b.max[axis]);
        Node {
            x: lanes(0),
            y: lanes(1),
            z: lanes(2),
            children,
        }
    }

    /// The box of child `i` (0 or 1).
    pub fn child_bounds(&self, i: usize) -> Aabb {
        let [x, y, z] = [self.x, self.y, self.z].map(|v| v.to_array());
        Aabb {
            min: Vec3::new(x[i], y[i], z[i]),
            max: Vec3::new(x[i + 2], y[i + 2], z[i + 2]),
        }
    }

    /// The slab test ([`Aabb::hit_distance`]) of both children at once:
    /// the entry distance into each child's box, or `None` for a miss.
    ///
    /// Per axis, `(planes - o) / d` gives the distances to all four
    /// planes; swapping the halves (`zwxy`) pairs each child's min plane
    /// with its max plane, so lanes 0 and 1 of their minimum are the near
    /// distances and of their maximum the far ones.
    ///
    /// A ray that does not move along an axis (`d = ±0`, `1/d = ±inf`) and
    /// starts exactly on one of the box's planes gets `0 · inf = NaN` for
    /// that plane. It lies inside the slab, so the NaN becomes the infinity
    /// opposite to the other plane's distance, making the slab `(-inf, inf)`.
    /// (If both planes are NaN, the box is flat and the ray lies in it: the
    /// NaN lanes are the first operands of `max`/`min`, which then return
    /// the second, so that axis is ignored.)
    #[inline(always)]
    pub fn hit_children(&self, ray: &RayLanes, t_min: f32, t_max: f32) -> [Option<f32>; 2] {
        let mut near = Vec4::splat(t_min);
        let mut far = Vec4::splat(t_max);
        for (axis, planes) in [self.x, self.y, self.z].into_iter().enumerate() {
            let t = (planes - ray.origin[axis]) * ray.inv_dir[axis];
            let t = if ray.has_zero_direction {
                Vec4::select(t.is_nan_mask(), -t.zwxy(), t)
            } else {
                t
            };
            let swapped = t.zwxy();
            near = t.min(swapped).max(near);
            far = (t.max(swapped) * (1.0 + 2.0 * gamma(3))).min(far);
        }
        let hit = near.cmple(far).bitmask();
        [
            (hit & 1 != 0).then_some(near.x),
            (hit & 2 != 0).then_some(near.y),
        ]
    }
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The layout the docs promise: one node, one 64-byte cache line.
    #[test]
    fn a_node_is_one_cache_line() {
        assert_eq!(std::mem::size_of::<Node>(), 64);
        assert_eq!(std::mem::align_of::<Node>(), 64);
        assert_eq!(std::mem::size_of::<Link>(), 8);
        // What a leaf's triangle costs in docs/03-bvh.md: three `Vec3`s
        // and the enum's tag.
        assert_eq!(std::mem::size_of::<crate::intersect::Shape>(), 40);
    }
}
