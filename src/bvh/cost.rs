//! The SAH cost of a whole tree: the measure of tree quality that the
//! builder minimises greedily, one node at a time.
//!
//! With the same constants as the build ([`BuildOptions`]), a tree with
//! root box `R` costs
//!
//! ```text
//! C = sum over interior nodes n: C_trav * SA(n) / SA(R)
//!   + sum over leaves l:         C_isect * N_l * SA(l) / SA(R)
//! ```
//!
//! (MacDonald and Booth, 1990; Wald, 2007, eq. 1), the expected cost of
//! a random ray that meets the root box, in primitive tests. Lower is
//! better; two builders are compared on the same primitives.

use super::{build::BuildOptions, Bvh, Link};
use crate::intersect::Aabb;

impl Bvh {
    /// The tree's SAH cost (above) with `C_isect = 1` and
    /// `C_trav = options.traversal_cost`; 0 for an empty tree.
    pub fn sah_cost(&self, options: &BuildOptions) -> f64 {
        let Some(root) = self.root else {
            return 0.0;
        };
        let root_area = f64::from(self.bounds.surface_area());
        if root_area <= 0.0 {
            return f64::from(root.count.max(1));
        }
        let mut total = 0.0;
        let mut stack: Vec<(Link, Aabb)> = vec![(root, self.bounds)];
        while let Some((link, bounds)) = stack.pop() {
            let area = f64::from(bounds.surface_area()) / root_area;
            if link.is_leaf() {
                total += area * f64::from(link.count);
                continue;
            }
            total += area * f64::from(options.traversal_cost);
            let node = &self.nodes[link.first as usize];
            for (i, &child) in node.children.iter().enumerate() {
                stack.push((child, node.child_bounds(i)));
            }
        }
        total
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bvh::build::build;
    use glam::Vec3;

    fn unit_box_at(x: f32) -> Aabb {
        Aabb {
            min: Vec3::new(x, 0.0, 0.0),
            max: Vec3::new(x + 1.0, 1.0, 1.0),
        }
    }

    /// One leaf: every ray that meets the root tests every primitive.
    #[test]
    fn a_single_leaf_costs_its_count() {
        let bvh = build(&[unit_box_at(0.0); 3], &BuildOptions::default());
        assert_eq!(bvh.sah_cost(&BuildOptions::default()), 3.0);
    }

    /// Two far-apart boxes: the root visit, plus each leaf with the
    /// probability `SA(leaf) / SA(root)`.
    #[test]
    fn two_leaves_cost_the_visit_and_their_area_ratios() {
        let options = BuildOptions {
            traversal_cost: 2.0,
            max_leaf_size: 1,
            leaf_at_most: 0,
        };
        let bvh = build(&[unit_box_at(0.0), unit_box_at(9.0)], &options);
        // SA(unit cube) = 6, SA(10 x 1 x 1) = 42.
        let expected = 2.0 + 2.0 * 6.0 / 42.0;
        assert!((bvh.sah_cost(&options) - expected).abs() < 1e-6);
    }
}
