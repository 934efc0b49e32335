//! Structural checks of a built BVH, run after every build in the tests.
//!
//! A valid BVH: every child box lies inside its parent's box; every leaf
//! box holds the boxes of its primitives; every leaf slot is reached from
//! the root exactly once; `order` is a permutation of the primitive ids;
//! and no path is deeper than [`super::MAX_DEPTH`].

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
        if self.boxes.len() != self.nodes.len() {
            return fail(format!(
                "{} boxes for {} nodes",
                self.boxes.len(),
                self.nodes.len()
            ));
        }
        if self.nodes.is_empty() {
            return if bounds.is_empty() {
                Ok(())
            } else {
                fail("no nodes but primitives".into())
            };
        }
        let mut slot_reached = vec![false; self.order.len()];
        let mut node_reached = vec![false; self.nodes.len()];
        let mut stack = vec![(0usize, 1usize)];
        while let Some((index, depth)) = stack.pop() {
            if depth > MAX_DEPTH {
                return fail(format!("node {index} at depth {depth} > {MAX_DEPTH}"));
            }
            if std::mem::replace(&mut node_reached[index], true) {
                return fail(format!("node {index} reached twice"));
            }
            let node = &self.nodes[index];
            let first = node.first as usize;
            if node.is_leaf() {
                let end = first + node.count as usize;
                if end > self.order.len() {
                    return fail(format!("leaf {index} slots {first}..{end} out of range"));
                }
                for slot in first..end {
                    if std::mem::replace(&mut slot_reached[slot], true) {
                        return fail(format!("slot {slot} in two leaves"));
                    }
                    let b = bounds[self.order[slot] as usize];
                    if !self.boxes[index].aabb().contains(&b) {
                        return fail(format!("leaf {index} does not hold primitive box {b:?}"));
                    }
                }
            } else {
                for child in [first, first + 1] {
                    let Some(c) = self.boxes.get(child) else {
                        return fail(format!("node {index} has child {child} out of range"));
                    };
                    if child <= index {
                        return fail(format!("node {index} points back to {child}"));
                    }
                    if !self.boxes[index].aabb().contains(&c.aabb()) {
                        return fail(format!("child {child} sticks out of parent {index}"));
                    }
                    stack.push((child, depth + 1));
                }
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
