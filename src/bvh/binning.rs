//! The split search of the binned SAH build (Wald, "On fast Construction
//! of SAH-based Bounding Volume Hierarchies", 2007), and the in-place
//! partition that carries the chosen split out.
//!
//! A node's primitive centroids are dropped into `K` equal slices (bins)
//! of the node's centroid box along each axis; each bin keeps the box and
//! the count of its primitives. One sweep from each side then gives, for
//! each of the `K - 1` boundaries, the box and count of everything left
//! and right of it, hence the SAH cost of splitting there, in `O(K)`
//! instead of the `O(N)` of trying every primitive's position.
//!
//! `K` grows with the node: `K = min(32, 4 + N / 20)`, as in Embree's
//! binning (Wald, Woop, Benthin et al., "Embree: A Kernel Framework for
//! Efficient CPU Ray Tracing", 2014). Large nodes near the root, where a
//! good split matters most, get 32 bins; small nodes near the leaves,
//! where sweeping 32 bins would cost more than binning their few
//! primitives, get as few as 4.

use glam::Vec3A;

use crate::intersect::Aabb;

/// The most bins a node gets.
pub const MAX_BINS: usize = 32;

/// Bins for a node of `n` primitives (see the module doc).
pub fn bin_count(n: usize) -> usize {
    (4 + n / 20).min(MAX_BINS)
}

/// A primitive's box while building, in SIMD registers.
#[derive(Clone, Copy)]
pub struct Ref {
    pub min: Vec3A,
    pub max: Vec3A,
}

impl Ref {
    #[inline(always)]
    fn centroid(&self) -> Vec3A {
        0.5 * (self.min + self.max)
    }
}

/// The box of some references and the box of their centroids.
#[derive(Clone, Copy)]
pub struct RefBounds {
    pub min: Vec3A,
    pub max: Vec3A,
    pub cmin: Vec3A,
    pub cmax: Vec3A,
}

impl RefBounds {
    pub const EMPTY: RefBounds = RefBounds {
        min: Vec3A::INFINITY,
        max: Vec3A::NEG_INFINITY,
        cmin: Vec3A::INFINITY,
        cmax: Vec3A::NEG_INFINITY,
    };

    #[inline(always)]
    pub fn grow(&mut self, r: &Ref) {
        let c = r.centroid();
        self.min = self.min.min(r.min);
        self.max = self.max.max(r.max);
        self.cmin = self.cmin.min(c);
        self.cmax = self.cmax.max(c);
    }

    pub fn of(refs: &[Ref]) -> Self {
        let mut b = RefBounds::EMPTY;
        refs.iter().for_each(|r| b.grow(r));
        b
    }

    /// Half the surface area of the box (the SAH needs only ratios).
    pub fn half_area(&self) -> f32 {
        half_area(self.min, self.max)
    }

    pub fn aabb(&self) -> Aabb {
        Aabb {
            min: self.min.into(),
            max: self.max.into(),
        }
    }
}

fn half_area(min: Vec3A, max: Vec3A) -> f32 {
    let e = (max - min).max(Vec3A::ZERO);
    e.x * e.y + e.y * e.z + e.z * e.x
}

/// Maps a centroid to its bin along each axis: `K` equal slices of the
/// node's centroid box.
#[derive(Clone, Copy)]
pub struct Binner {
    cmin: Vec3A,
    /// `K / extent` per axis; 0 along an axis where all centroids agree.
    scale: Vec3A,
    count: usize,
}

impl Binner {
    pub fn new(bounds: &RefBounds, count: usize) -> Self {
        let extent = bounds.cmax - bounds.cmin;
        let scale = Vec3A::select(
            extent.cmpgt(Vec3A::ZERO),
            Vec3A::splat(count as f32) / extent,
            Vec3A::ZERO,
        );
        Binner {
            cmin: bounds.cmin,
            scale,
            count,
        }
    }

    /// The bin of `r` along each axis (the centroid on the box's far
    /// face would land in bin `K`: it joins bin `K - 1`).
    #[inline(always)]
    fn bins(&self, r: &Ref) -> [usize; 3] {
        let b = (r.centroid() - self.cmin) * self.scale;
        // Clamped to [0, K - 1]; a NaN lane (a NaN box) becomes 0, as
        // SSE's max returns its second operand when one is NaN (and
        // scalar `f32::max` returns the number).
        let b = b
            .max(Vec3A::ZERO)
            .min(Vec3A::splat(self.count as f32 - 1.0));
        let [x, y, z] = truncate(b);
        [x, y, z].map(|i| i as usize % MAX_BINS)
    }

    /// The bin of `r` along one axis: the same arithmetic as
    /// [`Binner::bins`], so a partition agrees with the binning.
    #[inline(always)]
    fn bin(&self, r: &Ref, axis: usize) -> usize {
        self.bins(r)[axis]
    }
}

/// The integer parts of `v`'s lanes, all in `[0, MAX_BINS)`: one SIMD
/// instruction on x86-64, where Rust's `as` would check each lane for
/// NaN and overflow first (the `% MAX_BINS` of the caller then needs
/// no bounds check either).
#[inline(always)]
fn truncate(v: Vec3A) -> [u32; 3] {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{__m128, _mm_cvttps_epi32};
        // SAFETY: SSE2 is part of the x86-64 baseline.
        let lanes: [u32; 4] = unsafe { std::mem::transmute(_mm_cvttps_epi32(__m128::from(v))) };
        [lanes[0], lanes[1], lanes[2]]
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        [v.x as u32, v.y as u32, v.z as u32]
    }
}

#[derive(Clone, Copy)]
struct Bin {
    min: Vec3A,
    max: Vec3A,
    count: u32,
}

impl Bin {
    const EMPTY: Bin = Bin {
        min: Vec3A::INFINITY,
        max: Vec3A::NEG_INFINITY,
        count: 0,
    };

    #[inline(always)]
    fn merge(self, other: Bin) -> Bin {
        Bin {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
            count: self.count + other.count,
        }
    }

    /// The SAH's `SA · N` term for the primitives in this bin.
    fn cost(&self) -> f32 {
        half_area(self.min, self.max) * self.count as f32
    }
}

/// The bins of one node along each axis.
type AxisBins = [[Bin; MAX_BINS]; 3];

/// The bins of one node, allocated once per build and reused, so a node
/// allocates nothing.
pub struct Bins {
    bins: AxisBins,
}

impl Default for Bins {
    fn default() -> Self {
        Bins {
            bins: [[Bin::EMPTY; MAX_BINS]; 3],
        }
    }
}

/// Adds `r` to its bin `b[axis]` along each axis.
#[inline(always)]
fn add(bins: &mut AxisBins, b: [usize; 3], r: &Ref) {
    for (axis, bins) in bins.iter_mut().enumerate() {
        let bin = &mut bins[b[axis]];
        bin.min = bin.min.min(r.min);
        bin.max = bin.max.max(r.max);
        bin.count += 1;
    }
}

/// The cheapest split found: cut along `axis` below bin `bin`.
#[derive(Clone, Copy)]
pub struct Split {
    pub binner: Binner,
    pub axis: usize,
    pub bin: usize,
    /// `SA(L) N_L + SA(R) N_R`, with half areas.
    pub cost: f32,
}

impl Bins {
    /// The boundary of least SAH cost over the three axes, or `None` when
    /// no boundary has primitives on both sides.
    pub fn best_split(&mut self, refs: &[Ref], bounds: &RefBounds) -> Option<Split> {
        let binner = Binner::new(bounds, bin_count(refs.len()));
        let k = binner.count;
        for axis in &mut self.bins {
            axis[..k].fill(Bin::EMPTY);
        }
        for r in refs {
            add(&mut self.bins, binner.bins(r), r);
        }
        let mut best: Option<Split> = None;
        for (axis, bins) in self.bins.iter().enumerate() {
            if binner.scale[axis] == 0.0 {
                continue;
            }
            let bins = &bins[..k];
            // Sweep from the right: the cost term of bins [i, k).
            let mut right_cost = [0.0f32; MAX_BINS];
            let mut right = Bin::EMPTY;
            for i in (1..k).rev() {
                right = right.merge(bins[i]);
                right_cost[i] = right.cost();
            }
            // Sweep from the left, evaluating the boundary below bin i.
            let mut left = Bin::EMPTY;
            for i in 1..k {
                left = left.merge(bins[i - 1]);
                if left.count == 0 || left.count as usize == refs.len() {
                    continue;
                }
                let cost = left.cost() + right_cost[i];
                if best.is_none_or(|b| cost < b.cost) {
                    best = Some(Split {
                        binner,
                        axis,
                        bin: i,
                        cost,
                    });
                }
            }
        }
        best
    }
}

/// Moves the references (and their ids) whose bin along the split's axis
/// is below the split's bin to the front, in place; returns how many
/// there are and the bounds of both sides, gathered on the way so the
/// children need no pass of their own.
///
/// Hoare's scheme: scan from the front past references that belong left
/// and from the back past those that belong right, then swap the two
/// that stopped the scans; each reference is classified once, and only
/// misplaced ones move.
pub fn partition(refs: &mut [Ref], ids: &mut [u32], split: &Split) -> (usize, [RefBounds; 2]) {
    let goes_left = |r: &Ref| split.binner.bin(r, split.axis) < split.bin;
    let (mut left, mut right) = (RefBounds::EMPTY, RefBounds::EMPTY);
    let (mut i, mut j) = (0, refs.len());
    loop {
        while i < j && goes_left(&refs[i]) {
            left.grow(&refs[i]);
            i += 1;
        }
        while i < j && !goes_left(&refs[j - 1]) {
            right.grow(&refs[j - 1]);
            j -= 1;
        }
        if i == j {
            return (i, [left, right]);
        }
        // refs[i] belongs right and refs[j - 1] left.
        right.grow(&refs[i]);
        left.grow(&refs[j - 1]);
        refs.swap(i, j - 1);
        ids.swap(i, j - 1);
        i += 1;
        j -= 1;
    }
}
