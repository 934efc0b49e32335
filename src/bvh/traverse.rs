//! BVH traversal: closest hit and any hit.
//!
//! Closest hit visits the tree front to back: at an interior node both
//! child boxes (stored in the node, one cache line) are tested; the nearer
//! child is visited next and the farther one is pushed with its entry
//! distance. A popped subtree whose entry distance is beyond the closest
//! hit found so far is skipped, and every box test is clipped to that
//! distance, so far subtrees are culled.
//!
//! Any hit (shadow rays) needs no order: it returns at the first primitive
//! hit in the ray's interval.

use std::mem::MaybeUninit;

use glam::Vec3;

use super::{Bvh, RayLanes, MAX_DEPTH};
use crate::intersect::Ray;

/// `1 / d` per component, infinite where `d` is zero.
#[inline(always)]
fn inverse_direction(dir: Vec3) -> Vec3 {
    Vec3::ONE / dir
}

impl Bvh {
    /// Closest-hit traversal. `test(slot, t_max)` intersects the primitive
    /// at leaf slot `slot` and returns its `t` if it is hit within
    /// `[ray.t_min, t_max]`. Returns the closest `t` found, if any.
    #[inline]
    pub fn closest_hit(
        &self,
        ray: &Ray,
        mut test: impl FnMut(u32, f32) -> Option<f32>,
    ) -> Option<f32> {
        let inv = inverse_direction(ray.dir);
        let mut t_max = ray.t_max;
        let mut link = self.root?;
        self.bounds
            .hit_distance(ray.origin.into(), inv.into(), ray.t_min, t_max)?;
        let lanes = RayLanes::new(ray.origin, inv);
        let mut best = None;
        let mut stack: Stack<_> = Stack::new();
        loop {
            if link.is_leaf() {
                for slot in link.slots() {
                    if let Some(t) = test(slot, t_max) {
                        t_max = t;
                        best = Some(t);
                    }
                }
            } else {
                let node = &self.nodes[link.first as usize];
                let [da, db] = node.hit_children(&lanes, ray.t_min, t_max);
                let [la, lb] = node.children;
                match (da, db) {
                    (Some(da), Some(db)) => {
                        let (near, far, far_t) = if da <= db { (la, lb, db) } else { (lb, la, da) };
                        stack.push((far, far_t));
                        link = near;
                        continue;
                    }
                    (Some(_), None) => {
                        link = la;
                        continue;
                    }
                    (None, Some(_)) => {
                        link = lb;
                        continue;
                    }
                    (None, None) => {}
                }
            }
            // Pop the next subtree that may still hold a closer hit.
            let Some(next) = stack.pop_within(t_max) else {
                return best;
            };
            link = next;
        }
    }

    /// Any-hit traversal: whether `test(slot)` is true for some primitive
    /// whose leaf box the ray meets within `[ray.t_min, ray.t_max]`.
    #[inline]
    pub fn any_hit(&self, ray: &Ray, mut test: impl FnMut(u32) -> bool) -> bool {
        let Some(root) = self.root else {
            return false;
        };
        let inv = inverse_direction(ray.dir);
        let inside = self
            .bounds
            .hit_distance(ray.origin.into(), inv.into(), ray.t_min, ray.t_max);
        if inside.is_none() {
            return false;
        }
        let lanes = RayLanes::new(ray.origin, inv);
        let mut stack: Stack<_> = Stack::new();
        stack.push(root);
        while let Some(link) = stack.pop() {
            if link.is_leaf() {
                if link.slots().any(&mut test) {
                    return true;
                }
                continue;
            }
            let node = &self.nodes[link.first as usize];
            let hits = node.hit_children(&lanes, ray.t_min, ray.t_max);
            for (hit, &child) in hits.iter().zip(&node.children) {
                if hit.is_some() {
                    stack.push(child);
                }
            }
        }
        false
    }
}

/// A fixed-capacity stack (`N` entries, [`MAX_DEPTH`] unless given) that
/// is not zeroed when created: traversal starts one per ray, and clearing
/// [`MAX_DEPTH`] entries each time showed up in profiles. The wide BVH's
/// traversal uses it too.
pub(crate) struct Stack<T, const N: usize = MAX_DEPTH> {
    items: [MaybeUninit<T>; N],
    len: usize,
}

impl<T: Copy, const N: usize> Stack<T, N> {
    #[inline(always)]
    pub(crate) fn new() -> Self {
        Stack {
            items: [const { MaybeUninit::uninit() }; N],
            len: 0,
        }
    }

    /// Pushes `item`. The BVH's depth is at most [`MAX_DEPTH`] (checked by
    /// `validate`), and a traversal holds at most one entry per level (the
    /// wide BVH: three), so this never overflows; if it did, indexing
    /// would panic, not corrupt.
    #[inline(always)]
    pub(crate) fn push(&mut self, item: T) {
        self.items[self.len].write(item);
        self.len += 1;
    }

    #[inline(always)]
    pub(crate) fn pop(&mut self) -> Option<T> {
        self.len = self.len.checked_sub(1)?;
        // SAFETY: every slot below the old `len` was written by `push`.
        Some(unsafe { self.items[self.len].assume_init() })
    }
}

impl<L: Copy, const N: usize> Stack<(L, f32), N> {
    /// Pops subtrees until one whose entry distance is within `t_max`
    /// (one that may still hold a closer hit); `None` when none is left.
    #[inline(always)]
    pub(crate) fn pop_within(&mut self, t_max: f32) -> Option<L> {
        while let Some((next, entry)) = self.pop() {
            if entry <= t_max {
                return Some(next);
            }
        }
        None
    }
}
