//! Binned SAH construction, top-down and in place.
//!
//! For each node: find the boundary of least SAH cost among equal slices
//! (bins) of the centroid box along each axis (`bvh::binning`; see
//! the module doc of [`crate::bvh`] for the cost), compare it with a
//! leaf, and partition the primitive references in place, gathering both
//! children's boxes on the way.
//!
//! What makes it fast (1,046,528 triangles on one core: 0.55 s before
//! these, 0.31-0.34 s of CPU time after, Embree 4.4's 0.33-0.37 s in the
//! same session; `docs/03-bvh.md`, "Scale"):
//! - one compact array of references (a box, 32 bytes, the centroid
//!   computed on the fly) and one of ids, partitioned in place, so the
//!   build reads memory in order and allocates nothing per node (the
//!   bins are one scratch array reused by every node);
//! - two passes over a node's references, binning and partition: the
//!   partition also gathers the children's boxes and centroid boxes;
//! - the bin count grows with the node (4 to 32), so small nodes near
//!   the leaves do not pay for sweeping 32 bins;
//! - a centroid's three bin indices come from one SIMD conversion;
//! - on a pool of more than one thread, the top levels are built in
//!   parallel (`bvh::parallel`).
//!
//! Fallbacks keep any input buildable: when all centroids coincide, or the
//! tree is deeper than [`SAH_DEPTH_LIMIT`], the node is split at the median
//! count, which bounds the depth by [`super::MAX_DEPTH`].

use super::binning::{partition, Bins, Ref, RefBounds, Split};
use super::{Bvh, Link, Node};
use crate::intersect::Aabb;

/// Below this depth the SAH decides; deeper nodes split at the median.
pub const SAH_DEPTH_LIMIT: usize = 30;

/// Cost constants of the SAH, in units of one primitive test.
#[derive(Clone, Copy, Debug)]
pub struct BuildOptions {
    /// Cost of visiting an interior node (two box tests in one 4-lane
    /// slab test), relative to one primitive test. Default 2: the two box
    /// tests of a visit.
    pub traversal_cost: f32,
    /// Leaves never hold more primitives than this (unless they all share
    /// one centroid and the depth limit is reached).
    pub max_leaf_size: usize,
    /// A node of at most this many primitives becomes a leaf without a
    /// split search (0, the default: the SAH decides every node). The
    /// wide BVH sets it to the size of the subtrees its collapse merges
    /// into one leaf anyway ([`crate::bvh::wide::collapse::MERGE`]), so
    /// the levels it would undo are never built.
    pub leaf_at_most: usize,
}

impl Default for BuildOptions {
    fn default() -> Self {
        BuildOptions {
            traversal_cost: 2.0,
            max_leaf_size: 8,
            leaf_at_most: 0,
        }
    }
}

/// A subtree still to be built: its references `start..end` (within
/// the slice being built), their bounds, and where to link it.
struct Task {
    start: usize,
    end: usize,
    depth: usize,
    bounds: RefBounds,
    /// `(node, child)` whose link this subtree fills; `None` for the root.
    parent: Option<(usize, usize)>,
}

/// What to do with a node.
enum Decision {
    Leaf,
    Split(Split),
    /// Halve the primitives by count (no useful SAH split exists).
    Median,
}

/// A built subtree: its root link and its interior nodes, numbered from
/// 0 in `nodes` (leaf slots are already those of the whole tree).
pub(super) struct Subtree {
    pub root: Link,
    pub nodes: Vec<Node>,
}

/// Builds a BVH over boxes `bounds[id]`; empty boxes are allowed and are
/// simply stored (they can never be hit).
pub fn build(bounds: &[Aabb], options: &BuildOptions) -> Bvh {
    build_from(bounds.iter().copied(), options)
}

/// [`build`] over boxes given one at a time, primitive `id` being the
/// `id`-th, so that a caller need not collect them first.
///
/// On a rayon pool of more than one thread, the top of the tree is built
/// in parallel (`bvh::parallel`); the tree is the same either way.
pub fn build_from(bounds: impl IntoIterator<Item = Aabb>, options: &BuildOptions) -> Bvh {
    // The references, and their bounds on the way.
    let mut all = RefBounds::EMPTY;
    let mut refs: Vec<Ref> = bounds
        .into_iter()
        .map(|b| {
            let r = Ref {
                min: b.min.into(),
                max: b.max.into(),
            };
            all.grow(&r);
            r
        })
        .collect();
    if refs.is_empty() {
        return Bvh::default();
    }
    let mut ids: Vec<u32> = (0..refs.len() as u32).collect();
    let bounds = all;
    let root = SubtreeAt {
        first_slot: 0,
        depth: 1,
        bounds,
    };
    let Subtree { root, mut nodes } = if rayon::current_num_threads() > 1 {
        super::parallel::build_parallel(&mut refs, &mut ids, root, options)
    } else {
        build_subtree(&mut refs, &mut ids, root, options)
    };
    nodes.shrink_to_fit();
    Bvh {
        bounds: bounds.aabb(),
        root: Some(root),
        nodes,
        order: ids,
    }
}

/// Where a subtree sits in the whole tree: its first leaf slot, its
/// depth and the bounds of its references.
#[derive(Clone, Copy)]
pub(super) struct SubtreeAt {
    pub first_slot: usize,
    pub depth: usize,
    pub bounds: RefBounds,
}

/// Builds the subtree over `refs` (and their `ids`), top-down with an
/// explicit stack, on the calling thread.
pub(super) fn build_subtree(
    refs: &mut [Ref],
    ids: &mut [u32],
    at: SubtreeAt,
    options: &BuildOptions,
) -> Subtree {
    // A binary tree with at least one primitive per leaf has fewer
    // interior nodes than primitives.
    let mut nodes: Vec<Node> = Vec::with_capacity(refs.len().saturating_sub(1));
    let mut bins = Bins::default();
    let mut root = Link::default();
    let mut stack = vec![Task {
        start: 0,
        end: refs.len(),
        depth: at.depth,
        bounds: at.bounds,
        parent: None,
    }];
    while let Some(task) = stack.pop() {
        let range = task.start..task.end;
        let split = split_node(
            &mut bins,
            &mut refs[range.clone()],
            &mut ids[range.clone()],
            task.depth,
            &task.bounds,
            options,
        );
        let Some((mid, child_bounds)) = split else {
            let leaf = Link {
                first: (at.first_slot + task.start) as u32,
                count: range.len() as u32,
            };
            set_link(&mut nodes, &mut root, task.parent, leaf);
            continue;
        };
        let split_at = task.start + mid;
        let halves = [(task.start, split_at), (split_at, task.end)];
        let index = nodes.len();
        nodes.push(Node::new(
            child_bounds.map(|b| b.aabb()),
            [Link::default(); 2],
        ));
        let link = Link {
            first: index as u32,
            count: 0,
        };
        set_link(&mut nodes, &mut root, task.parent, link);
        for child in [1, 0] {
            stack.push(Task {
                start: halves[child].0,
                end: halves[child].1,
                depth: task.depth + 1,
                bounds: child_bounds[child],
                parent: Some((index, child)),
            });
        }
    }
    Subtree { root, nodes }
}

/// Splits a node's references in place: how many go to the first child
/// and both children's bounds; `None` for a leaf.
pub(super) fn split_node(
    bins: &mut Bins,
    refs: &mut [Ref],
    ids: &mut [u32],
    depth: usize,
    bounds: &RefBounds,
    options: &BuildOptions,
) -> Option<(usize, [RefBounds; 2])> {
    match decide(bins, refs, depth, bounds, options) {
        Decision::Leaf => None,
        Decision::Split(split) => Some(partition(refs, ids, &split)),
        Decision::Median => {
            let mid = refs.len() / 2;
            let (left, right) = refs.split_at(mid);
            Some((mid, [RefBounds::of(left), RefBounds::of(right)]))
        }
    }
}

/// Leaf, SAH split or median split for `refs`: the cheaper of the best
/// SAH split and a leaf, where a leaf is allowed.
fn decide(
    bins: &mut Bins,
    refs: &[Ref],
    depth: usize,
    bounds: &RefBounds,
    options: &BuildOptions,
) -> Decision {
    let count = refs.len();
    let leaf_allowed = count <= options.max_leaf_size;
    let can_use_sah = depth < SAH_DEPTH_LIMIT && bounds.cmax.cmpgt(bounds.cmin).any();
    // A split costs more than `C_trav` (the children's term is positive),
    // a leaf `count`: so a node of at most `C_trav` primitives is a leaf
    // without binning, the decision the SAH would take.
    if count <= 1
        || count <= options.leaf_at_most
        || (leaf_allowed && count as f32 <= options.traversal_cost)
    {
        return Decision::Leaf;
    }
    let split = if can_use_sah {
        bins.best_split(refs, bounds)
    } else {
        None
    };
    match split {
        None if leaf_allowed => Decision::Leaf,
        None => Decision::Median,
        Some(split) => {
            let node_area = bounds.half_area().max(f32::MIN_POSITIVE);
            let split_cost = options.traversal_cost + split.cost / node_area;
            if leaf_allowed && count as f32 <= split_cost {
                Decision::Leaf
            } else {
                Decision::Split(split)
            }
        }
    }
}

fn set_link(nodes: &mut [Node], root: &mut Link, parent: Option<(usize, usize)>, link: Link) {
    match parent {
        Some((node, child)) => nodes[node].children[child] = link,
        None => *root = link,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    /// Boxes with NaN, infinite or empty extents (from broken input) still
    /// build: every id lands in exactly one leaf, and nothing panics.
    #[test]
    fn broken_boxes_still_build() {
        let unit = |x: f32| Aabb {
            min: Vec3::new(x, 0.0, 0.0),
            max: Vec3::new(x + 1.0, 1.0, 1.0),
        };
        let mut boxes: Vec<Aabb> = (0..200).map(|i| unit(i as f32)).collect();
        boxes[3].min.x = f32::NAN;
        boxes[50].max = Vec3::splat(f32::INFINITY);
        boxes[51].min = Vec3::splat(f32::NEG_INFINITY);
        boxes[120] = Aabb::EMPTY;
        let bvh = build(&boxes, &BuildOptions::default());
        let mut order = bvh.order.clone();
        order.sort_unstable();
        assert_eq!(order, (0..200).collect::<Vec<u32>>());
        let slots: u32 = bvh
            .links()
            .iter()
            .filter(|(l, _)| l.is_leaf())
            .map(|(l, _)| l.count)
            .sum();
        assert_eq!(slots, 200);
    }
}
