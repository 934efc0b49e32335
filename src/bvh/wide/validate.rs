//! Structural checks of a wide BVH, run after every build in the tests.
//!
//! A valid wide BVH: every child box lies inside its parent's box and an
//! unused slot's box is empty; every node and every pack is reached from
//! the root exactly once; every primitive id sits in exactly one lane, in
//! a leaf whose box holds the primitive's box; a triangle's lanes hold its
//! corners bit for bit and a sphere's lane is marked as one (and its leaf
//! says so); unused lanes are NaN; no path is deeper than [`MAX_DEPTH`].

use super::leaf::{TrianglePack, PAD};
use super::{WideBvh, WIDTH};
use crate::bvh::{ValidationError, MAX_DEPTH};
use crate::intersect::{Aabb, Shape};

impl WideBvh {
    /// Checks the invariants above; `shapes[id]` is primitive `id`'s shape.
    pub fn validate(&self, shapes: &[Shape]) -> Result<(), ValidationError> {
        let fail = |m: String| Err(ValidationError(m));
        let Some(root) = self.root else {
            return if shapes.is_empty() && self.nodes.is_empty() && self.packs.is_empty() {
                Ok(())
            } else {
                fail("no root but primitives, nodes or packs".into())
            };
        };
        let mut seen_id = vec![false; shapes.len()];
        let mut pack_reached = vec![false; self.packs.len()];
        let mut node_reached = vec![false; self.nodes.len()];
        let mut stack = vec![(root, self.bounds, 1usize)];
        while let Some((link, link_box, depth)) = stack.pop() {
            if depth > MAX_DEPTH {
                return fail(format!("depth {depth} > {MAX_DEPTH}"));
            }
            if link.is_leaf() {
                let range = link.packs();
                if range.is_empty() || range.end > self.packs.len() {
                    return fail(format!("leaf packs {range:?} empty or out of range"));
                }
                let mut spheres = false;
                for p in range {
                    if std::mem::replace(&mut pack_reached[p], true) {
                        return fail(format!("pack {p} in two leaves"));
                    }
                    spheres |= check_pack(&self.packs[p], shapes, &link_box, &mut seen_id)
                        .map_err(|m| ValidationError(format!("pack {p}: {m}")))?;
                }
                if spheres != link.has_spheres() {
                    return fail(format!("leaf {link:?} misreports its spheres"));
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
                let child_box = node.child_bounds(i);
                if child.is_empty() {
                    if !child_box.is_empty() {
                        return fail(format!("node {index}: unused slot {i} has a box"));
                    }
                    continue;
                }
                if !link_box.contains(&child_box) {
                    return fail(format!("a child box of node {index} sticks out"));
                }
                if !child.is_leaf() && child.first as usize <= index {
                    return fail(format!("node {index} points back to {}", child.first));
                }
                stack.push((child, child_box, depth + 1));
            }
        }
        if let Some(id) = seen_id.iter().position(|s| !s) {
            return fail(format!("primitive {id} is in no leaf"));
        }
        if let Some(p) = pack_reached.iter().position(|r| !r) {
            return fail(format!("pack {p} is unreachable"));
        }
        if let Some(n) = node_reached.iter().position(|r| !r) {
            return fail(format!("node {n} is unreachable"));
        }
        Ok(())
    }
}

/// One pack's lanes against the shapes and the leaf box; marks the ids
/// seen. Returns whether a lane holds a sphere.
fn check_pack(
    pack: &TrianglePack,
    shapes: &[Shape],
    leaf_box: &Aabb,
    seen_id: &mut [bool],
) -> Result<bool, String> {
    let mut spheres = false;
    for lane in 0..WIDTH {
        let stored = pack.triangle(lane);
        let Some((id, sphere)) = pack.lane(lane) else {
            if pack.ids[lane] != PAD || !stored.p0.is_nan() {
                return Err(format!("unused lane {lane} is not NaN"));
            }
            continue;
        };
        match seen_id.get_mut(id as usize) {
            Some(seen) if !*seen => *seen = true,
            Some(_) => return Err(format!("primitive {id} stored twice")),
            None => return Err(format!("primitive id {id} out of range")),
        }
        let shape = &shapes[id as usize];
        match shape {
            Shape::Triangle(t) if !sphere => {
                let same = [t.p0, t.p1, t.p2]
                    .iter()
                    .zip([stored.p0, stored.p1, stored.p2])
                    .all(|(a, b)| a.to_array().map(f32::to_bits) == b.to_array().map(f32::to_bits));
                if !same {
                    return Err(format!("lane {lane} does not hold triangle {id}'s corners"));
                }
            }
            Shape::Sphere(_) if sphere => spheres = true,
            _ => return Err(format!("lane {lane} has the wrong kind for primitive {id}")),
        }
        if !leaf_box.contains(&shape.bounds()) {
            return Err(format!("leaf box does not hold primitive {id}"));
        }
    }
    Ok(spheres)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bvh::wide::{WideBvhAccel, WideLink};
    use crate::intersect::triangle::TriangleShape;
    use crate::intersect::Primitives;
    use glam::Vec3;

    fn primitives(n: usize) -> Primitives {
        let shapes = (0..n)
            .map(|i| {
                let p = Vec3::new((i * 7 % 13) as f32, (i * 5 % 11) as f32, i as f32 * 0.1);
                Shape::Triangle(TriangleShape::new(p, p + Vec3::X, p + Vec3::Y))
            })
            .collect();
        let mut p = Primitives::default();
        p.shapes = shapes;
        p
    }

    #[test]
    fn a_fresh_build_is_valid() {
        for n in [0, 1, 2, 5, 9, 100, 1000] {
            WideBvhAccel::new(primitives(n)).validate().unwrap();
        }
    }

    #[test]
    fn each_broken_invariant_is_caught() {
        let good = WideBvhAccel::new(primitives(300));
        let shapes = &good.primitives.shapes;
        let mut shrunk = good.wide.clone();
        shrunk.nodes[0].planes[3][0].x -= 1.0;
        let mut duplicated = good.wide.clone();
        duplicated.packs[1].ids[0] = duplicated.packs[0].ids[0];
        let mut moved = good.wide.clone();
        moved.packs[0].corners[0][0].x += 1e-3;
        let mut cut = good.wide.clone();
        cut.nodes[0].children[1] = cut.nodes[0].children[0];
        let mut looped = good.wide.clone();
        let interior = looped.nodes[0]
            .children
            .iter()
            .position(|c| !c.is_leaf() && !c.is_empty());
        looped.nodes[0].children[interior.unwrap()].first = 0;
        let mut lost = good.wide.clone();
        lost.nodes[0].children[0] = WideLink::EMPTY;
        for (name, broken) in [
            ("shrunk", shrunk),
            ("duplicated", duplicated),
            ("moved", moved),
            ("cut", cut),
            ("looped", looped),
            ("lost", lost),
        ] {
            assert!(broken.validate(shapes).is_err(), "{name} passed");
        }
    }
}
