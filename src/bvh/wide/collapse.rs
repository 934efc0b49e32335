//! The wide tree from the binary one (Wald, Benthin and Boulos 2008,
//! section 3; Dammertz et al. 2008 collapse the same way).
//!
//! A wide node starts from a binary node's two children. While it has
//! fewer than four, the interior child with the largest surface area is
//! replaced by its own two children: by the surface area heuristic the
//! largest box is the one a ray most likely enters, so opening it saves
//! the most node visits. Leaves stay leaves; each becomes ceil(n / 4)
//! triangle packs. The binary build's leaves hold at most 8 primitives,
//! so a leaf has at most two packs.
//!
//! Nodes are written depth first, a node before its children, like the
//! binary tree. Collapsing never adds levels, so the depth limit of the
//! binary tree holds for the wide one.

use super::leaf::TrianglePack;
use super::node::WideNode;
use super::{WideBvh, WideLink, WIDTH};
use crate::bvh::{Bvh, Link};
use crate::intersect::{Aabb, Shape};

/// The wide BVH over the same primitives as `bvh`; `shapes[id]` is
/// primitive `id`'s shape.
pub fn collapse(bvh: &Bvh, shapes: &[Shape]) -> WideBvh {
    let mut out = Collapser {
        bvh,
        shapes,
        sizes: subtree_sizes(bvh),
        nodes: Vec::with_capacity(bvh.nodes.len() / 2 + 1),
        packs: Vec::with_capacity(shapes.len() / 2 + 1),
    };
    let root = bvh.root.map(|root| out.link(root));
    WideBvh {
        bounds: bvh.bounds,
        root,
        nodes: out.nodes,
        packs: out.packs,
    }
}

/// Number of primitives under each binary node.
fn subtree_sizes(bvh: &Bvh) -> Vec<u32> {
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
    sizes: Vec<u32>,
    nodes: Vec<WideNode>,
    packs: Vec<TrianglePack>,
}

impl Collapser<'_> {
    /// Whether `link` becomes a leaf: a binary leaf, or a small subtree.
    fn becomes_leaf(&self, link: Link) -> bool {
        link.is_leaf() || self.sizes[link.first as usize] as usize <= WIDTH
    }

    fn link(&mut self, link: Link) -> WideLink {
        if self.becomes_leaf(link) {
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
        let binary = &self.bvh.nodes[index];
        let mut children: Vec<(Aabb, Link)> = (0..2)
            .map(|i| (binary.child_bounds(i), binary.children[i]))
            .collect();
        while children.len() < WIDTH {
            // The interior child with the largest surface area, if any.
            let open = children
                .iter()
                .enumerate()
                .filter(|(_, (_, link))| !self.becomes_leaf(*link))
                .max_by(|a, b| a.1 .0.surface_area().total_cmp(&b.1 .0.surface_area()))
                .map(|(i, _)| i);
            let Some(i) = open else { break };
            let (_, link) = children.swap_remove(i);
            let grand = &self.bvh.nodes[link.first as usize];
            children.extend((0..2).map(|j| (grand.child_bounds(j), grand.children[j])));
        }
        let me = self.nodes.len();
        self.nodes.push(WideNode::new(&[]));
        let wide: Vec<(Aabb, WideLink)> = children
            .into_iter()
            .map(|(bounds, link)| (bounds, self.link(link)))
            .collect();
        self.nodes[me] = WideNode::new(&wide);
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
        let mut slots = Vec::new();
        self.slots(link, &mut slots);
        for chunk in slots.chunks(WIDTH) {
            let lanes: Vec<(u32, Shape)> = chunk
                .iter()
                .map(|&slot| {
                    let id = self.bvh.order[slot as usize];
                    let shape = self.shapes[id as usize];
                    has_spheres |= matches!(shape, Shape::Sphere(_));
                    (id, shape)
                })
                .collect();
            self.packs.push(TrianglePack::new(&lanes));
        }
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
