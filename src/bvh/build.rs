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

use super::{Bvh, Node, NodeBox};
use crate::intersect::Aabb;

/// Number of bins per axis.
pub const BINS: usize = 16;

/// Below this depth the SAH decides; deeper nodes split at the median.
pub const SAH_DEPTH_LIMIT: usize = 30;

/// Cost constants of the SAH, in units of one primitive test.
#[derive(Clone, Copy, Debug)]
pub struct BuildOptions {
    /// Cost of visiting an interior node, relative to one primitive test.
    pub traversal_cost: f32,
    /// Leaves never hold more primitives than this (unless they all share
    /// one centroid and the depth limit is reached).
    pub max_leaf_size: usize,
}

impl Default for BuildOptions {
    fn default() -> Self {
        BuildOptions {
            traversal_cost: 1.0,
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
    let mut nodes = Vec::with_capacity(2 * bounds.len());
    let mut boxes = Vec::with_capacity(2 * bounds.len());
    let (min, max) = box_of(&refs);
    nodes.push(Node { first: 0, count: 0 });
    boxes.push(NodeBox { min, max });

    // (node index, first ref, end ref, depth)
    let mut stack = vec![(0usize, 0usize, refs.len(), 1usize)];
    while let Some((index, start, end, depth)) = stack.pop() {
        let count = end - start;
        let slice = &mut refs[start..end];
        let (cmin, cmax) = centroid_bounds(slice);
        let can_use_sah = depth < SAH_DEPTH_LIMIT && cmax.cmpgt(cmin).any();
        let decision = if count <= 1 {
            Decision::Leaf
        } else if can_use_sah {
            let node_area = half_area(boxes[index].min, boxes[index].max);
            best_sah_split(slice, cmin, cmax, node_area, options)
        } else if count <= options.max_leaf_size {
            Decision::Leaf
        } else {
            Decision::Median
        };
        let mid = match decision {
            Decision::Leaf => {
                nodes[index].first = start as u32;
                nodes[index].count = count as u32;
                continue;
            }
            Decision::Split(split) => partition(slice, &mut ids[start..end], &split, cmin, cmax),
            Decision::Median => count / 2,
        };
        let left = nodes.len();
        for (s, e) in [(start, start + mid), (start + mid, end)] {
            let (min, max) = box_of(&refs[s..e]);
            nodes.push(Node { first: 0, count: 0 });
            boxes.push(NodeBox { min, max });
        }
        nodes[index].first = left as u32;
        stack.push((left + 1, start + mid, end, depth + 1));
        stack.push((left, start, start + mid, depth + 1));
    }
    Bvh {
        nodes,
        boxes,
        order: ids,
    }
}

/// What to do with a node.
enum Decision {
    Leaf,
    Split(Split),
    /// Halve the primitives by count (no useful SAH split exists).
    Median,
}

fn box_of(refs: &[Ref]) -> (Vec3A, Vec3A) {
    refs.iter().fold(
        (Vec3A::splat(f32::INFINITY), Vec3A::splat(f32::NEG_INFINITY)),
        |(lo, hi), r| (lo.min(r.min), hi.max(r.max)),
    )
}

fn centroid_bounds(refs: &[Ref]) -> (Vec3A, Vec3A) {
    refs.iter().fold(
        (Vec3A::splat(f32::INFINITY), Vec3A::splat(f32::NEG_INFINITY)),
        |(lo, hi), r| {
            let c = r.centroid();
            (lo.min(c), hi.max(c))
        },
    )
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
            if best.as_ref().map_or(true, |(c, _)| cost < *c) {
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
