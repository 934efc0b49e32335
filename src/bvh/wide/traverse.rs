//! Wide BVH traversal: closest hit and any hit, one ray at a time.
//!
//! Closest hit is the binary traversal's front-to-back order with eight
//! children: the eight boxes are tested at once ([`NodeTest`]: two 4-lane
//! groups, or one AVX register); of the
//! children hit, the nearest (by entry distance) is visited next and the
//! others are pushed farthest first, each with its entry distance, so they
//! pop nearest first. A popped subtree whose entry distance is beyond the
//! closest hit found so far is skipped, and box tests are clipped to it.
//!
//! A node pushes at most seven entries and the tree is at most
//! [`MAX_DEPTH`] deep, so `7 MAX_DEPTH + 1` entries always suffice.
//!
//! Any hit (shadow rays) needs no order: it returns at the first leaf
//! that reports a hit.
//!
//! When a node is entered, the memory of every child it hits is
//! prefetched (nodes: two lines; leaves: all their packs, 2.5 lines
//! each), so the cache misses of the nearest child and of those pushed
//! for later overlap; on the benchmark's random rays this gained 10-25 %,
//! and prefetching all of a leaf's packs rather than the first one's
//! three lines another 5-7 % (medians of 15 interleaved runs).

use glam::Vec3;

use super::node::{NodeTest, RayBoxes, WideNode};
use super::{WideBvh, WideLink, ARITY};
use crate::bvh::traverse::Stack;
use crate::bvh::MAX_DEPTH;
use crate::intersect::Ray;
use crate::math::prefetch::prefetch_lines;

/// Capacity of the traversal stack.
const STACK: usize = (ARITY - 1) * MAX_DEPTH + 1;

impl WideBvh {
    /// Closest-hit traversal. `leaf(link, t_max)` tests the leaf's
    /// primitives and returns the nearest `t` found within
    /// `[ray.t_min, t_max]`, if any. Returns the closest `t` found.
    #[inline]
    pub fn closest_hit<T: NodeTest>(
        &self,
        ray: &Ray,
        mut leaf: impl FnMut(WideLink, f32) -> Option<f32>,
    ) -> Option<f32> {
        let mut link = self.root?;
        if !traversable(ray) {
            return None;
        }
        let inv_dir = Vec3::ONE / ray.dir;
        self.bounds
            .hit_distance(ray.origin.into(), inv_dir.into(), ray.t_min, ray.t_max)?;
        let boxes = RayBoxes::from_inverse(ray.origin, inv_dir, ray.t_min);
        let mut t_max = ray.t_max;
        let mut best = None;
        let mut stack: Stack<(WideLink, f32), STACK> = Stack::new();
        loop {
            if link.is_leaf() {
                if let Some(t) = leaf(link, t_max) {
                    t_max = t;
                    best = Some(t);
                }
            } else {
                debug_assert!(!link.is_empty() && (link.first as usize) < self.nodes.len());
                // SAFETY: a link followed here indexes `self.nodes`. It
                // is a child the slab test hit, so not an empty slot (an
                // empty box is entered by no ray: its distances are +inf
                // and -inf, and `traversable` turned away the non-finite
                // rays whose NaN could mark it), hence an interior node's
                // link or the root; `collapse`, which makes every
                // `WideBvh` with nodes, pushes a node before it makes the
                // link to it, and the fields are private to `bvh`.
                // Unchecked because the check cost 2–3 % on primary rays
                // (`docs/maintainers/wide-bvh.md`, round 12).
                let node = unsafe { self.nodes.get_unchecked(link.first as usize) };
                let (mask, enter) = T::hit(node, &boxes, t_max);
                if mask != 0 {
                    self.prefetch_children(node, mask);
                    link = nearest_child(node, mask, enter, &mut stack);
                    continue;
                }
            }
            // Pop the next subtree that may still hold a closer hit.
            let Some(next) = stack.pop_within(t_max) else {
                return best;
            };
            link = next;
        }
    }

    /// Any-hit traversal: whether `leaf(link)` is true for some leaf whose
    /// box the ray meets within `[ray.t_min, ray.t_max]`.
    #[inline]
    pub fn any_hit<T: NodeTest>(&self, ray: &Ray, mut leaf: impl FnMut(WideLink) -> bool) -> bool {
        let Some(root) = self.root else {
            return false;
        };
        if !traversable(ray) {
            return false;
        }
        let inv_dir = Vec3::ONE / ray.dir;
        let inside =
            self.bounds
                .hit_distance(ray.origin.into(), inv_dir.into(), ray.t_min, ray.t_max);
        if inside.is_none() {
            return false;
        }
        let boxes = RayBoxes::from_inverse(ray.origin, inv_dir, ray.t_min);
        let mut stack: Stack<WideLink, STACK> = Stack::new();
        stack.push(root);
        while let Some(link) = stack.pop() {
            if link.is_leaf() {
                if leaf(link) {
                    return true;
                }
                continue;
            }
            let node = &self.nodes[link.first as usize];
            let (mut mask, _) = T::hit(node, &boxes, ray.t_max);
            while mask != 0 {
                stack.push(node.children[mask.trailing_zeros() as usize]);
                mask &= mask - 1;
            }
        }
        false
    }
}

/// Whether traversal can follow `ray`: a finite origin and direction.
/// A ray that is not (NaN from an overflow upstream) meets nothing: its
/// box tests would be NaN, and NaN lanes can mark empty child slots as
/// hit. Callers should never send one (a debug assertion says so).
#[inline(always)]
fn traversable(ray: &Ray) -> bool {
    let finite = ray.origin.is_finite() && ray.dir.is_finite();
    debug_assert!(
        finite,
        "a ray that is not finite reached traversal: {ray:?}"
    );
    finite
}

impl WideBvh {
    /// Asks for the memory of the children in `mask` (their nodes, or
    /// their leaves' first packs), so the misses of all of them overlap
    /// instead of each waiting its turn.
    #[inline(always)]
    fn prefetch_children(&self, node: &WideNode, mut mask: u32) {
        while mask != 0 {
            let child = node.children[mask.trailing_zeros() as usize];
            mask &= mask - 1;
            if child.is_leaf() {
                // All of the leaf's packs (160 bytes each), not only the
                // first: 2.4 packs a leaf on average.
                let pack = self.packs.as_ptr().wrapping_add(child.first as usize);
                let packs = child.packs().len();
                prefetch_lines(pack, (5 * packs).div_ceil(2));
            } else {
                let node = self.nodes.as_ptr().wrapping_add(child.first as usize);
                prefetch_lines(node, 4);
            }
        }
    }
}

/// Of the children in `mask` (at least one), pushes all but the nearest,
/// farthest first, and returns the nearest.
#[inline(always)]
fn nearest_child(
    node: &WideNode,
    mask: u32,
    enter: [f32; ARITY],
    stack: &mut Stack<(WideLink, f32), STACK>,
) -> WideLink {
    let first = mask.trailing_zeros() as usize;
    let rest = mask & (mask - 1);
    if rest == 0 {
        return node.children[first];
    }
    let second = rest.trailing_zeros() as usize;
    if rest & (rest - 1) == 0 {
        // Two children: the common case.
        let (near, far) = if enter[first] <= enter[second] {
            (first, second)
        } else {
            (second, first)
        };
        stack.push((node.children[far], enter[far]));
        return node.children[near];
    }
    // Three to eight: insertion sort by decreasing entry distance.
    let mut sorted = [(0.0f32, WideLink::EMPTY); ARITY];
    let mut n = 0;
    let mut bits = mask;
    while bits != 0 {
        let i = bits.trailing_zeros() as usize;
        bits &= bits - 1;
        let item = (enter[i], node.children[i]);
        let mut j = n;
        while j > 0 && sorted[j - 1].0 < item.0 {
            sorted[j] = sorted[j - 1];
            j -= 1;
        }
        sorted[j] = item;
        n += 1;
    }
    for &(t, child) in &sorted[..n - 1] {
        stack.push((child, t));
    }
    sorted[n - 1].1
}
