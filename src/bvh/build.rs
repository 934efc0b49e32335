//! Binned SAH construction, top-down and in place.
//!
//! For each node: bin the primitive centroids into [`BINS`] equal slices
//! of the centroid box along each axis, sweep the bins once from each side
//! to get the box and count left and right of every boundary, and take the
//! boundary of least SAH cost (see the module doc of [`crate::bvh`]). The
//! primitive references are then partitioned in place, so the build
//! allocates nothing per node and touches memory sequentially.
//!
//! Fallbacks keep any input buildable: when all centroids coincide, or the
//! tree is deeper than [`SAH_DEPTH_LIMIT`], the node is split at the median
//! count, which bounds the depth by [`super::MAX_DEPTH`].

use glam::Vec3A;

use super::{Bvh, Link, Node};
use crate::intersect::Aabb;

/// Number of bins per axis.
pub const BINS: usize = 16;

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
}

impl Default for BuildOptions {
    fn default() -> Self {
        BuildOptions {
            traversal_cost: 2.0,
            max_leaf_size: 8,
        }
    }
}

/// A primitive's box while building (SIMD-friendly).
#[derive(Clone, Copy)]
struct Ref {
    min: Vec3A,
    max: Vec3A,
}

impl Ref {
    #[inline(always)]
    fn centroid(&self) -> Vec3A {
        0.5 * (self.min + self.max)
    }
}

#[derive(Clone, Copy)]
struct Bin {
    min: Vec3A,
    max: Vec3A,
    count: u32,
}

const EMPTY_BIN: Bin = Bin {
    min: Vec3A::splat(f32::INFINITY),
    max: Vec3A::splat(f32::NEG_INFINITY),
    count: 0,
};

fn half_area(min: Vec3A, max: Vec3A) -> f32 {
    let e = (max - min).max(Vec3A::ZERO);
    e.x * e.y + e.y * e.z + e.z * e.x
}

/// The chosen split of a node.
struct Split {
    axis: usize,
    /// Primitives whose centroid bin is below this go left.
    bin: usize,
}

/// A subtree still to be built: its references, box and centroid box, and
/// where to link it.
struct Task {
    start: usize,
    end: usize,
    depth: usize,
    bounds: RefBounds,
    /// `(node, child)` whose link this subtree fills; `None` for the root.
    parent: Option<(usize, usize)>,
}

/// The box of some references and the box of their centroids.
#[derive(Clone, Copy)]
struct RefBounds {
    min: Vec3A,
    max: Vec3A,
    cmin: Vec3A,
    cmax: Vec3A,
}

impl RefBounds {
    fn of(refs: &[Ref]) -> Self {
        let inf = Vec3A::splat(f32::INFINITY);
        refs.iter().fold(
            RefBounds {
                min: inf,
                max: -inf,
                cmin: inf,
                cmax: -inf,
            },
            |b, r| {
                let c = r.centroid();
                RefBounds {
                    min: b.min.min(r.min),
                    max: b.max.max(r.max),
                    cmin: b.cmin.min(c),
                    cmax: b.cmax.max(c),
                }
            },
        )
    }

    fn aabb(&self) -> Aabb {
        Aabb {
            min: self.min.into(),
            max: self.max.into(),
        }
    }
}

/// Builds a BVH over boxes `bounds[id]`; empty boxes are allowed and are
/// simply stored (they can never be hit).
pub fn build(bounds: &[Aabb], options: &BuildOptions) -> Bvh {
    if bounds.is_empty() {
        return Bvh::default();
    }
    let mut refs: Vec<Ref> = bounds
        .iter()
        .map(|b| Ref {
            min: b.min.into(),
            max: b.max.into(),
        })
        .collect();
    let mut ids: Vec<u32> = (0..bounds.len() as u32).collect();
    let mut nodes: Vec<Node> = Vec::with_capacity(bounds.len());
    let root_bounds = RefBounds::of(&refs);
    let mut root = Link::default();
    let mut stack = vec![Task {
        start: 0,
        end: refs.len(),
        depth: 1,
        bounds: root_bounds,
        parent: None,
    }];
    while let Some(task) = stack.pop() {
        let count = task.end - task.start;
        let slice = &mut refs[task.start..task.end];
        let RefBounds { cmin, cmax, .. } = task.bounds;
        let can_use_sah = task.depth < SAH_DEPTH_LIMIT && cmax.cmpgt(cmin).any();
        let decision = if count <= 1 {
            Decision::Leaf
        } else if can_use_sah {
            let node_area = half_area(task.bounds.min, task.bounds.max);
            best_sah_split(slice, cmin, cmax, node_area, options)
        } else if count <= options.max_leaf_size {
            Decision::Leaf
        } else {
            Decision::Median
        };
        let mid = match decision {
            Decision::Leaf => {
                let leaf = Link {
                    first: task.start as u32,
                    count: count as u32,
                };
                set_link(&mut nodes, &mut root, task.parent, leaf);
                continue;
            }
            Decision::Split(split) => {
                partition(slice, &mut ids[task.start..task.end], &split, cmin, cmax)
            }
            Decision::Median => count / 2,
        };
        let split_at = task.start + mid;
        let halves = [(task.start, split_at), (split_at, task.end)];
        let child_bounds = halves.map(|(s, e)| RefBounds::of(&refs[s..e]));
        let index = nodes.len();
        nodes.push(Node::new(
            child_bounds.map(|b| b.aabb()),
            [Link::default(); 2],
        ));
        set_link(
            &mut nodes,
            &mut root,
            task.parent,
            Link {
                first: index as u32,
                count: 0,
            },
        );
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
    Bvh {
        bounds: root_bounds.aabb(),
        root: Some(root),
        nodes,
        order: ids,
    }
}

fn set_link(nodes: &mut [Node], root: &mut Link, parent: Option<(usize, usize)>, link: Link) {
    match parent {
        Some((node, child)) => nodes[node].children[child] = link,
        None => *root = link,
    }
}

/// What to do with a node.
enum Decision {
    Leaf,
    Split(Split),
    /// Halve the primitives by count (no useful SAH split exists).
    Median,
}

/// Maps a centroid to its bin along each axis.
#[inline(always)]
fn bin_of(c: Vec3A, cmin: Vec3A, scale: Vec3A) -> [usize; 3] {
    let b = ((c - cmin) * scale).min(Vec3A::splat(BINS as f32 - 1.0));
    [b.x as usize, b.y as usize, b.z as usize]
}

fn bin_scale(cmin: Vec3A, cmax: Vec3A) -> Vec3A {
    let extent = cmax - cmin;
    Vec3A::select(
        extent.cmpgt(Vec3A::ZERO),
        Vec3A::splat(BINS as f32) / extent,
        Vec3A::ZERO,
    )
}

/// The cheapest SAH split, or a leaf when that is cheaper and allowed
/// (or the median when no boundary separates anything).
fn best_sah_split(
    refs: &[Ref],
    cmin: Vec3A,
    cmax: Vec3A,
    node_area: f32,
    options: &BuildOptions,
) -> Decision {
    let scale = bin_scale(cmin, cmax);
    let mut bins = [[EMPTY_BIN; BINS]; 3];
    for r in refs {
        let b = bin_of(r.centroid(), cmin, scale);
        for axis in 0..3 {
            let bin = &mut bins[axis][b[axis]];
            bin.min = bin.min.min(r.min);
            bin.max = bin.max.max(r.max);
            bin.count += 1;
        }
    }
    let mut best: Option<(f32, Split)> = None;
    for (axis, bins) in bins.iter().enumerate() {
        if scale[axis] == 0.0 {
            continue;
        }
        // Sweep from the right: area and count of bins [i, BINS).
        let mut right_cost = [0.0f32; BINS];
        let mut acc = EMPTY_BIN;
        for i in (1..BINS).rev() {
            acc = merge(acc, bins[i]);
            right_cost[i] = half_area(acc.min, acc.max) * acc.count as f32;
        }
        // Sweep from the left and evaluate each boundary.
        let mut acc = EMPTY_BIN;
        for i in 1..BINS {
            acc = merge(acc, bins[i - 1]);
            if acc.count == 0 || acc.count as usize == refs.len() {
                continue;
            }
            let cost = half_area(acc.min, acc.max) * acc.count as f32 + right_cost[i];
            if best.as_ref().is_none_or(|(c, _)| cost < *c) {
                best = Some((cost, Split { axis, bin: i }));
            }
        }
    }
    let leaf_allowed = refs.len() <= options.max_leaf_size;
    let Some((cost, split)) = best else {
        return if leaf_allowed {
            Decision::Leaf
        } else {
            Decision::Median
        };
    };
    let split_cost = options.traversal_cost + cost / node_area.max(f32::MIN_POSITIVE);
    let leaf_cost = refs.len() as f32;
    if leaf_allowed && leaf_cost <= split_cost {
        Decision::Leaf
    } else {
        Decision::Split(split)
    }
}

fn merge(a: Bin, b: Bin) -> Bin {
    Bin {
        min: a.min.min(b.min),
        max: a.max.max(b.max),
        count: a.count + b.count,
    }
}

/// Moves the references whose centroid bin is below `split.bin` to the
/// front; returns how many there are.
fn partition(refs: &mut [Ref], ids: &mut [u32], split: &Split, cmin: Vec3A, cmax: Vec3A) -> usize {
    let scale = bin_scale(cmin, cmax);
    let (mut i, mut j) = (0, refs.len());
    while i < j {
        if bin_of(refs[i].centroid(), cmin, scale)[split.axis] < split.bin {
            i += 1;
        } else {
            j -= 1;
            refs.swap(i, j);
            ids.swap(i, j);
        }
    }
    i
}
