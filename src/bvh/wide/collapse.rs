//! The wide tree from the binary one: each wide node stands for a binary
//! node, and its children for up to eight of that node's descendants
//! which together hold every leaf below it once (a cut of its subtree).
//!
//! Which cut each wide node takes, and which small subtrees become one
//! leaf, is [`super::grouping`]'s choice: the grouping of least expected
//! cost by the surface area heuristic, solved exactly over the binary
//! tree. (Before it, a greedy rule chose: open the interior child of
//! largest area until the node has eight children (Wald, Benthin and
//! Boulos 2008, section 3; Dammertz et al. 2008). It could not pull a
//! leaf up past a node with room, so the nodes near the leaves were often
//! half empty.)
//!
//! Leaves stay leaves; each becomes ceil(n / 4) triangle packs. A binary
//! subtree of at most [`MERGE`] primitives and no sphere may become one
//! leaf too (the wide build makes such nodes leaves from the start:
//! [`super::accel::binary_options`]), so a leaf has at most three packs.
//!
//! Nodes are written depth first, a node before its children, like the
//! binary tree. Collapsing never adds levels, so the depth limit of the
//! binary tree holds for the wide one.

use super::grouping::Grouping;
use super::leaf::TrianglePack;
use super::node::WideNode;
use super::{WideBvh, WideLink, ARITY, WIDTH};
use crate::bvh::{Bvh, Link};
use crate::math::huge_pages;
use glam::Vec3;

use crate::intersect::triangle::TriangleShape;
use crate::intersect::{Aabb, Shape};

/// Binary subtrees of at most this many primitives become one leaf.
pub const MERGE: usize = 3 * WIDTH;

/// The wide BVH over the same primitives as `bvh`; `shapes[id]` is
/// primitive `id`'s shape.
pub fn collapse(bvh: &Bvh, shapes: &[Shape]) -> WideBvh {
    let sizes = subtree_sizes(bvh);
    let spheres = subtree_spheres(bvh, shapes);
    let mut out = Collapser {
        bvh,
        shapes,
        grouping: Grouping::solve(bvh, &sizes, &spheres),
        scratch: Vec::new(),
        // Upper bounds (a wide node takes at least one binary node, a pack
        // at least one primitive), so the vectors never grow and copy;
        // only the pages written are ever backed by memory.
        nodes: Vec::with_capacity(bvh.nodes.len()),
        packs: Vec::with_capacity(shapes.len()),
    };
    // Traversal reads both at scattered places: huge pages spare it most
    // TLB misses (`math::huge_pages`; 10-25 % faster on the benchmark).
    huge_pages::advise(&out.nodes);
    huge_pages::advise(&out.packs);
    let root = bvh.root.map(|root| out.link(root));
    // Give the unused part of the bounds back (for large vectors the
    // allocator shrinks the mapping in place, no copy).
    out.nodes.shrink_to_fit();
    out.packs.shrink_to_fit();
    WideBvh {
        bounds: bvh.bounds,
        root,
        nodes: out.nodes,
        packs: out.packs,
    }
}

/// Whether a sphere lies under each binary node.
fn subtree_spheres(bvh: &Bvh, shapes: &[Shape]) -> Vec<bool> {
    let mut spheres = vec![false; bvh.nodes.len()];
    // One pass in memory order settles the common case, a mesh alone,
    // without reading the shapes at the leaves' scattered ids.
    if !shapes.iter().any(|s| matches!(s, Shape::Sphere(_))) {
        return spheres;
    }
    for index in (0..bvh.nodes.len()).rev() {
        spheres[index] = bvh.nodes[index].children.iter().any(|c| {
            if c.is_leaf() {
                c.slots().any(|slot| {
                    let id = bvh.order[slot as usize] as usize;
                    matches!(shapes[id], Shape::Sphere(_))
                })
            } else {
                spheres[c.first as usize]
            }
        });
    }
    spheres
}

/// Number of primitives under each binary node.
pub(super) fn subtree_sizes(bvh: &Bvh) -> Vec<u32> {
    let mut sizes = vec![0u32; bvh.nodes.len()];
    // Children come after their parent, so a reverse sweep sees them first.
    for index in (0..bvh.nodes.len()).rev() {
        sizes[index] = bvh.nodes[index]
            .children
            .iter()
            .map(|c| {
                if c.is_leaf() {
                    c.count
                } else {
                    sizes[c.first as usize]
                }
            })
            .sum();
    }
    sizes
}

struct Collapser<'a> {
    bvh: &'a Bvh,
    shapes: &'a [Shape],
    grouping: Grouping,
    /// Reused list of a leaf's slots.
    scratch: Vec<u32>,
    nodes: Vec<WideNode>,
    packs: Vec<TrianglePack>,
}

impl Collapser<'_> {
    fn link(&mut self, link: Link) -> WideLink {
        if self.grouping.is_leaf(link) {
            self.leaf(link)
        } else {
            self.node(link.first as usize)
        }
    }

    /// The leaf slots of the binary subtree `link`, in order.
    fn slots(&self, link: Link, out: &mut Vec<u32>) {
        if link.is_leaf() {
            out.extend(link.slots());
        } else {
            for &child in &self.bvh.nodes[link.first as usize].children {
                self.slots(child, out);
            }
        }
    }

    /// The wide node for binary node `index`, and its subtrees.
    fn node(&mut self, index: usize) -> WideLink {
        let mut children = Vec::with_capacity(ARITY);
        self.grouping.children(self.bvh, index, &mut children);
        let me = self.nodes.len();
        self.nodes.push(WideNode::new(&[]));
        let mut wide = [(Aabb::EMPTY, WideLink::EMPTY); ARITY];
        for (slot, &(bounds, link)) in wide.iter_mut().zip(&children) {
            *slot = (bounds, self.link(link));
        }
        self.nodes[me] = WideNode::new(&wide[..children.len()]);
        WideLink {
            first: me as u32,
            count: 0,
        }
    }

    /// The primitives of a binary subtree (a leaf, or a subtree of at most
    /// four), four to a pack.
    fn leaf(&mut self, link: Link) -> WideLink {
        let first = self.packs.len();
        let mut has_spheres = false;
        let mut slots = std::mem::take(&mut self.scratch);
        slots.clear();
        self.slots(link, &mut slots);
        for chunk in slots.chunks(WIDTH) {
            let unused = Shape::Triangle(TriangleShape::new(Vec3::ZERO, Vec3::ZERO, Vec3::ZERO));
            let mut lanes = [(0, unused); WIDTH];
            for (lane, &slot) in lanes.iter_mut().zip(chunk) {
                let id = self.bvh.order[slot as usize];
                let shape = self.shapes[id as usize];
                has_spheres |= matches!(shape, Shape::Sphere(_));
                *lane = (id, shape);
            }
            self.packs.push(TrianglePack::new(&lanes[..chunk.len()]));
        }
        self.scratch = slots;
        let count = (self.packs.len() - first) as u32;
        WideLink {
            first: first as u32,
            count: if has_spheres {
                count | WideLink::HAS_SPHERES
            } else {
                count
            },
        }
    }
}
