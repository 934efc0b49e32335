//! The fast BVH: eight children per node, SIMD box tests, triangles tested
//! four at a time. Part 2's binary [`Bvh`](super::Bvh) stays the readable
//! teaching version; this one is collapsed from it and finds the same hits
//! (same watertight test, bit for bit), only faster.
//!
//! Why wider nodes help (Dammertz, Hanika and Keller, "Shallow Bounding
//! Volume Hierarchies for Fast SIMD Ray Tracing of Incoherent Rays", 2008;
//! Wald, Benthin and Boulos, "Getting Rid of Packets", 2008; Ernst and
//! Greiner, "Multi Bounding Volume Hierarchies", 2008): one ray is tested
//! against the eight boxes of a node in two independent 4-lane slab
//! tests, which cost little more than one box, and the tree has about a
//! third as many levels as a binary one, so a ray visits fewer nodes and
//! waits on memory fewer times (eight children rather than four: 1.05-1.15x
//! the rays per second on the benchmark, `docs/03-bvh.md`).
//!
//! - [`node`]: the 256-byte [`WideNode`] (four cache lines: the boxes of its
//!   eight children stored plane by plane, two `Vec4` per plane, and eight
//!   links) and the ray-versus-eight-boxes slab test (`avx`: the same
//!   test in one 8-lane register where the processor has AVX; x86-64 only).
//! - [`collapse`]: the wide tree from the binary SAH tree, each wide node
//!   over a cut of up to eight of a binary node's descendants, chosen by
//!   [`grouping`]: the cuts and leaves of least SAH cost, solved exactly.
//! - [`leaf`]: triangles packed four to a [`TrianglePack`] (structure of
//!   arrays), and the watertight test of
//!   [`crate::intersect::triangle`] run on the four lanes at once
//!   (`avx_packs`: two packs in one AVX register, x86-64 only).
//! - [`traverse`]: closest hit, front to back with a short stack; any hit.
//! - [`validate`](WideBvh::validate): every primitive stored exactly once,
//!   boxes hold their contents, depth bounded.
//! - [`WideBvhAccel`]: the tree as an [`Intersector`](crate::intersect::Intersector).
//!
//! The SIMD comes from glam's `Vec4` and `BVec4A`, which compile to SSE2 on
//! x86-64 (part of the base instruction set, so no runtime detection is
//! needed), to NEON on aarch64, and to plain scalar code elsewhere: no
//! `unsafe` (but for the hints of [`crate::math::prefetch`] and
//! [`crate::math::huge_pages`]), and the same binary runs on any x86-64.
//!
//! Measured against the binary BVH and Embree in
//! `docs/maintainers/wide-bvh.md` and `docs/10-performance.md`.

pub mod accel;
#[cfg(target_arch = "x86_64")]
pub mod avx;
#[cfg(target_arch = "x86_64")]
pub mod avx_packs;
pub mod collapse;
pub mod grouping;
pub mod leaf;
pub mod node;
pub mod traverse;
pub mod validate;

pub use accel::WideBvhAccel;
pub use leaf::TrianglePack;
pub use node::WideNode;

use crate::intersect::Aabb;

/// Triangles per pack (SIMD lanes).
pub const WIDTH: usize = 4;

/// Children per node.
pub const ARITY: usize = 8;

/// A child of a wide node: an interior node, a leaf's packs, or nothing.
///
/// Aligned to its size, 8 bytes, so that the compiler treats it as one
/// word: the traversal loads a child's link into a general register and
/// tests it there. With the default alignment of 4, LLVM loaded it into
/// a vector register and moved each half out, some cycles more on the
/// chain each node waits on (a node's load, its test, the child's link,
/// the child's load): +2–3 % on the benchmark's primary rays and +2–5 %
/// on its random ones (`docs/maintainers/wide-bvh.md`, round 12).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[repr(C, align(8))]
pub struct WideLink {
    /// Interior: index into `WideBvh::nodes`. Leaf: first index into
    /// `WideBvh::packs`. Empty slot: [`WideLink::EMPTY`]'s value.
    pub first: u32,
    /// Interior and empty: 0. Leaf: number of packs (at least 1), with
    /// [`WideLink::HAS_SPHERES`] set when a lane holds a sphere.
    pub count: u32,
}

impl WideLink {
    /// Flag in `count`: some lane of this leaf is a sphere (tested by the
    /// scalar code; triangle lanes never need it).
    pub const HAS_SPHERES: u32 = 1 << 31;

    /// An unused child slot; its box is empty, so no ray ever enters it.
    pub const EMPTY: WideLink = WideLink {
        first: u32::MAX,
        count: 0,
    };

    #[inline(always)]
    pub fn is_leaf(&self) -> bool {
        self.count != 0
    }

    pub fn is_empty(&self) -> bool {
        *self == WideLink::EMPTY
    }

    /// The leaf's packs, as a range of indices into `WideBvh::packs`.
    #[inline(always)]
    pub fn packs(&self) -> std::ops::Range<usize> {
        let first = self.first as usize;
        first..first + (self.count & !Self::HAS_SPHERES) as usize
    }

    #[inline(always)]
    pub fn has_spheres(&self) -> bool {
        self.count & Self::HAS_SPHERES != 0
    }
}

/// A wide BVH: the root's box and link, the nodes and the triangle packs.
///
/// Made by [`collapse::collapse`]; its fields are private to `bvh`,
/// since closest-hit traversal relies on every interior link indexing
/// `nodes` (and reads the node without a bounds check).
#[derive(Clone, Debug, Default)]
pub struct WideBvh {
    /// Box of everything in the tree.
    pub(in crate::bvh) bounds: Aabb,
    /// The root: a leaf for a tiny scene, else `nodes[0]`; `None` when empty.
    pub(in crate::bvh) root: Option<WideLink>,
    /// Interior nodes; children of a node come after it.
    pub(in crate::bvh) nodes: Vec<WideNode>,
    /// Leaf contents, each leaf's packs contiguous.
    pub(in crate::bvh) packs: Vec<TrianglePack>,
}

impl WideBvh {
    /// Number of interior nodes and of triangle packs.
    pub fn sizes(&self) -> (usize, usize) {
        (self.nodes.len(), self.packs.len())
    }

    /// Number of leaves, the depth of the deepest one (root depth 1), and
    /// the number of occupied lanes over all packs.
    pub fn leaf_stats(&self) -> (usize, usize, usize) {
        let mut stack: Vec<(WideLink, usize)> = self.root.iter().map(|&l| (l, 1)).collect();
        let (mut leaves, mut depth) = (0, 0);
        while let Some((link, d)) = stack.pop() {
            if link.is_leaf() {
                leaves += 1;
                depth = depth.max(d);
            } else if let Some(node) = self.nodes.get(link.first as usize) {
                let live = node.children.iter().filter(|c| !c.is_empty());
                stack.extend(live.map(|&c| (c, d + 1)));
            }
        }
        let lanes = self.packs.iter().map(TrianglePack::occupied).sum();
        (leaves, depth, lanes)
    }
}
