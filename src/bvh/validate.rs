//! Structural checks of a built BVH, run after every build in the tests.
//!
//! A valid BVH: every child box lies inside its parent's box; every leaf
//! box holds the boxes of its primitives; every leaf slot is reached from
//! the root exactly once and every node once; `order` is a permutation of
//! the primitive ids; and no path is deeper than [`super::MAX_DEPTH`].

use std::fmt;

use super::{Bvh, MAX_DEPTH};
use crate::intersect::Aabb;

/// The first broken invariant found.
#[derive(Clone, Debug, PartialEq)]
pub struct ValidationError(pub String);

impl fmt::Display for ValidationError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "invalid BVH: {}", self.0)
    }
}

impl std::error::Error for ValidationError {}

impl Bvh {
    /// Checks the invariants above; `bounds[id]` is primitive `id`'s box.
    pub fn validate(&self, bounds: &[Aabb]) -> Result<(), ValidationError> {
        let fail = |m: String| Err(ValidationError(m));
        if self.order.len() != bounds.len() {
            return fail(format!(
                "{} slots for {} primitives",
                self.order.len(),
                bounds.len()
            ));
        }
        let mut seen_id = vec![false; bounds.len()];
        for &id in &self.order {
            match seen_id.get_mut(id as usize) {
                Some(seen) if !*seen => *seen = true,
                Some(_) => return fail(format!("primitive {id} stored twice")),
                None => return fail(format!("primitive id {id} out of range")),
            }
        }
        let Some(root) = self.root else {
            return if bounds.is_empty() && self.nodes.is_empty() {
                Ok(())
            } else {
                fail("no root but primitives or nodes".into())
            };
        };
        let mut slot_reached = vec![false; self.order.len()];
        let mut node_reached = vec![false; self.nodes.len()];
        // (link, its box, depth)
        let mut stack = vec![(root, self.bounds, 1usize)];
        while let Some((link, link_box, depth)) = stack.pop() {
            if depth > MAX_DEPTH {
                return fail(format!("depth {depth} > {MAX_DEPTH}"));
            }
            if link.is_leaf() {
                let end = link.first as usize + link.count as usize;
                if end > self.order.len() {
                    return fail(format!("leaf slots {}..{end} out of range", link.first));
                }
                for slot in link.slots() {
                    if std::mem::replace(&mut slot_reached[slot as usize], true) {
                        return fail(format!("slot {slot} in two leaves"));
                    }
                    let b = bounds[self.order[slot as usize] as usize];
                    if !link_box.contains(&b) {
                        return fail(format!(
                            "leaf box {link_box:?} does not hold primitive box {b:?}"
                        ));
                    }
                }
                continue;
            }
            let index = link.first as usize;
            let Some(node) = self.nodes.get(index) else {
                return fail(format!("link to node {index} out of range"));
            };
            if std::mem::replace(&mut node_reached[index], true) {
                return fail(format!("node {index} reached twice"));
            }
            for (i, &child) in node.children.iter().enumerate() {
                let child_box = &node.child_bounds(i);
                if !link_box.contains(child_box) {
                    return fail(format!(
                        "a child box of node {index} sticks out of its parent"
                    ));
                }
                if !child.is_leaf() && child.first as usize <= index {
                    return fail(format!("node {index} points back to {}", child.first));
                }
                stack.push((child, *child_box, depth + 1));
            }
        }
        if let Some(slot) = slot_reached.iter().position(|r| !r) {
            return fail(format!("slot {slot} is in no leaf"));
        }
        if let Some(node) = node_reached.iter().position(|r| !r) {
            return fail(format!("node {node} is unreachable"));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bvh::build::{build, BuildOptions};
    use glam::Vec3;

    fn boxes(n: usize) -> Vec<Aabb> {
        (0..n)
            .map(|i| {
                let p = Vec3::new((i * 7 % 13) as f32, (i * 5 % 11) as f32, i as f32 * 0.1);
                Aabb::from_points([p, p + Vec3::splat(0.5)])
            })
            .collect()
    }

    #[test]
    fn a_fresh_build_is_valid() {
        for n in [0, 1, 2, 9, 100] {
            let b = boxes(n);
            build(&b, &BuildOptions::default()).validate(&b).unwrap();
        }
    }

    #[test]
    fn each_broken_invariant_is_caught() {
        let b = boxes(100);
        let good = build(&b, &BuildOptions::default());
        let mut shrunk = good.clone();
        shrunk.nodes[0].x.z -= 1.0;
        let mut duplicated = good.clone();
        duplicated.order[1] = duplicated.order[0];
        let mut cut = good.clone();
        cut.nodes[0].children[1] = cut.nodes[0].children[0];
        let mut looped = good.clone();
        let first_interior = looped.nodes[0]
            .children
            .iter()
            .position(|c| !c.is_leaf())
            .unwrap();
        looped.nodes[0].children[first_interior].first = 0;
        for broken in [shrunk, duplicated, cut, looped] {
            assert!(broken.validate(&b).is_err());
        }
    }
}
