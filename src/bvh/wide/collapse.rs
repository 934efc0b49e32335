//! The wide tree from the binary one (Wald, Benthin and Boulos 2008,
//! section 3; Dammertz et al. 2008 collapse the same way).
//!
//! A wide node starts from a binary node's two children. While it has
//! fewer than eight, the interior child with the largest surface area is
//! replaced by its own two children: by the surface area heuristic the
//! largest box is the one a ray most likely enters, so opening it saves
//! the most node visits. Leaves stay leaves; each becomes ceil(n / 4)
//! triangle packs. A binary subtree of at most [`MERGE`] primitives
//! becomes one leaf too (the wide build makes such nodes leaves from the
//! start: [`super::accel::binary_options`]), so a leaf has at most three
//! packs.
//!
//! Nodes are written depth first, a node before its children, like the
//! binary tree. Collapsing never adds levels, so the depth limit of the
//! binary tree holds for the wide one.

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
    let mut out = Collapser {
        bvh,
        shapes,
        sizes: subtree_sizes(bvh),
        spheres: subtree_spheres(bvh, shapes),
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
    /// Whether each binary node's subtree holds a sphere.
    spheres: Vec<bool>,
    /// Reused list of a leaf's slots.
    scratch: Vec<u32>,
    nodes: Vec<WideNode>,
    packs: Vec<TrianglePack>,
}

impl Collapser<'_> {
    /// Whether `link` becomes a leaf: a binary leaf, or a small subtree of
    /// triangles only. A sphere keeps its own binary leaf and its tight box:
    /// its test is scalar and costly, so merged into a leaf of twelve it
    /// would be tested by every ray that enters the leaf (measured on
    /// `CBspheres_lambertian.dae`, where the spheres' scalar test was 11 %
    /// of the render with them merged).
    fn becomes_leaf(&self, link: Link) -> bool {
        link.is_leaf()
            || (self.sizes[link.first as usize] as usize <= MERGE
                && !self.spheres[link.first as usize])
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
        let mut children = [(Aabb::EMPTY, Link::default()); ARITY];
        children[0] = (binary.child_bounds(0), binary.children[0]);
        children[1] = (binary.child_bounds(1), binary.children[1]);
        // Each child's surface area if it can be opened, else -1.
        let openable = |(bounds, link): (Aabb, Link)| {
            if self.becomes_leaf(link) {
                -1.0
            } else {
                bounds.surface_area()
            }
        };
        let mut area = [-1.0f32; ARITY];
        area[0] = openable(children[0]);
        area[1] = openable(children[1]);
        let mut n = 2;
        while n < ARITY {
            // The interior child with the largest surface area, if any.
            let i = (0..n)
                .max_by(|&a, &b| area[a].total_cmp(&area[b]))
                .unwrap_or(0);
            if area[i] < 0.0 {
                break;
            }
            let grand = &self.bvh.nodes[children[i].1.first as usize];
            children[i] = (grand.child_bounds(0), grand.children[0]);
            children[n] = (grand.child_bounds(1), grand.children[1]);
            area[i] = openable(children[i]);
            area[n] = openable(children[n]);
            n += 1;
        }
        let me = self.nodes.len();
        self.nodes.push(WideNode::new(&[]));
        let mut wide = [(Aabb::EMPTY, WideLink::EMPTY); ARITY];
        for (slot, &(bounds, link)) in wide.iter_mut().zip(&children[..n]) {
            *slot = (bounds, self.link(link));
        }
        self.nodes[me] = WideNode::new(&wide[..n]);
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
