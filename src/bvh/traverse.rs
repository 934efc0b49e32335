//! BVH traversal: closest hit and any hit.
//!
//! Closest hit visits the tree front to back: at an interior node both
//! child boxes are tested, the nearer child is visited next and the farther
//! one is pushed with its entry distance. A popped node whose entry
//! distance is beyond the closest hit found so far is skipped, and every
//! box test is clipped to that distance, so far subtrees are culled.
//!
//! Any hit (shadow rays) needs no order: it returns at the first primitive
//! hit in the ray's interval.

use glam::{Vec3, Vec3A};

use super::{Bvh, MAX_DEPTH};
use crate::intersect::Ray;

/// `1 / d` per component, infinite where `d` is zero.
#[inline(always)]
fn inverse_direction(dir: Vec3) -> Vec3A {
    Vec3A::ONE / Vec3A::from(dir)
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
        let root = self.boxes.first()?;
        let inv = inverse_direction(ray.dir);
        let origin = Vec3A::from(ray.origin);
        let mut t_max = ray.t_max;
        root.hit_distance(origin, inv, ray.t_min, t_max)?;
        let mut best = None;
        let mut stack = [(0u32, 0.0f32); MAX_DEPTH];
        let mut depth = 0;
        let mut index = 0usize;
        loop {
            let node = &self.nodes[index];
            if node.is_leaf() {
                for slot in node.first..node.first + node.count {
                    if let Some(t) = test(slot, t_max) {
                        t_max = t;
                        best = Some(t);
                    }
                }
            } else {
                let left = node.first as usize;
                let (a, b) = (&self.boxes[left], &self.boxes[left + 1]);
                let da = a.hit_distance(origin, inv, ray.t_min, t_max);
                let db = b.hit_distance(origin, inv, ray.t_min, t_max);
                match (da, db) {
                    (Some(da), Some(db)) => {
                        let (near, far, far_t) = if da <= db {
                            (left, left + 1, db)
                        } else {
                            (left + 1, left, da)
                        };
                        stack[depth] = (far as u32, far_t);
                        depth += 1;
                        index = near;
                        continue;
                    }
                    (Some(_), None) => {
                        index = left;
                        continue;
                    }
                    (None, Some(_)) => {
                        index = left + 1;
                        continue;
                    }
                    (None, None) => {}
                }
            }
            // Pop the next node that may still hold a closer hit.
            loop {
                if depth == 0 {
                    return best;
                }
                depth -= 1;
                let (next, entry) = stack[depth];
                if entry <= t_max {
                    index = next as usize;
                    break;
                }
            }
        }
    }

    /// Any-hit traversal: whether `test(slot)` is true for some primitive
    /// whose leaf box the ray meets within `[ray.t_min, ray.t_max]`.
    #[inline]
    pub fn any_hit(&self, ray: &Ray, mut test: impl FnMut(u32) -> bool) -> bool {
        if self.nodes.is_empty() {
            return false;
        }
        let inv = inverse_direction(ray.dir);
        let origin = Vec3A::from(ray.origin);
        let mut stack = [0u32; MAX_DEPTH];
        let mut depth = 1;
        while depth > 0 {
            depth -= 1;
            let index = stack[depth] as usize;
            if self.boxes[index]
                .hit_distance(origin, inv, ray.t_min, ray.t_max)
                .is_none()
            {
                continue;
            }
            let node = &self.nodes[index];
            if node.is_leaf() {
                if (node.first..node.first + node.count).any(&mut test) {
                    return true;
                }
            } else {
                stack[depth] = node.first;
                stack[depth + 1] = node.first + 1;
                depth += 2;
            }
        }
        false
    }
}
