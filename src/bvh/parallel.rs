//! The top of the tree built on several threads (rayon), for a pool of
//! more than one thread; the tree is the one the serial build makes.
//!
//! A node of at least [`PARALLEL_MIN`] references is split on the calling
//! thread, then its two children are built at once (`rayon::join`), each
//! into a node array of its own; the parent's array is the parent node,
//! then the first child's nodes, then the second's, with the children's
//! node links moved by where their arrays landed. Smaller subtrees are
//! built serially ([`build_subtree`]). The copies cost a pass over the
//! nodes per parallel level, a few levels in all.

use super::binning::{Bins, Ref};
use super::build::{build_subtree, split_node, BuildOptions, Subtree, SubtreeAt};
use super::{Link, Node};

/// Subtrees with fewer references than this are built serially.
pub const PARALLEL_MIN: usize = 1 << 16;

/// Builds the subtree over `refs` (and their `ids`), its two halves in
/// parallel while they are large.
pub(super) fn build_parallel(
    refs: &mut [Ref],
    ids: &mut [u32],
    at: SubtreeAt,
    options: &BuildOptions,
) -> Subtree {
    if refs.len() < PARALLEL_MIN {
        return build_subtree(refs, ids, at, options);
    }
    let mut bins = Bins::default();
    let split = split_node(&mut bins, refs, ids, at.depth, &at.bounds, options);
    let Some((mid, child_bounds)) = split else {
        return build_subtree(refs, ids, at, options);
    };
    let (left_refs, right_refs) = refs.split_at_mut(mid);
    let (left_ids, right_ids) = ids.split_at_mut(mid);
    let child = |i: usize, first_slot: usize| SubtreeAt {
        first_slot,
        depth: at.depth + 1,
        bounds: child_bounds[i],
    };
    let (left, right) = rayon::join(
        || build_parallel(left_refs, left_ids, child(0, at.first_slot), options),
        || {
            build_parallel(
                right_refs,
                right_ids,
                child(1, at.first_slot + mid),
                options,
            )
        },
    );
    // The parent first, then each child's nodes where they land.
    let (left_at, right_at) = (1, 1 + left.nodes.len());
    let mut nodes = Vec::with_capacity(right_at + right.nodes.len());
    nodes.push(Node::new(
        child_bounds.map(|b| b.aabb()),
        [moved(left.root, left_at), moved(right.root, right_at)],
    ));
    for (subtree, offset) in [(left, left_at), (right, right_at)] {
        nodes.extend(subtree.nodes.into_iter().map(|mut node| {
            node.children = node.children.map(|link| moved(link, offset));
            node
        }));
    }
    Subtree {
        root: Link { first: 0, count: 0 },
        nodes,
    }
}

/// `link` with an interior node's index moved by `offset` (leaf slots are
/// already final).
fn moved(link: Link, offset: usize) -> Link {
    if link.is_leaf() {
        link
    } else {
        Link {
            first: link.first + offset as u32,
            count: 0,
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::bvh::build::{build, BuildOptions};
    use crate::intersect::Primitives;
    use crate::scene::builtin::bumpy_sphere;

    /// Two threads build the very tree one thread builds, and it is valid.
    #[test]
    fn the_parallel_build_is_the_serial_one() {
        let primitives = Primitives::from_scene(&bumpy_sphere(400, 200));
        let bounds = crate::bvh::accel::primitive_bounds(&primitives);
        assert!(bounds.len() > 2 * super::PARALLEL_MIN);
        let on = |threads| {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            pool.install(|| build(&bounds, &BuildOptions::default()))
        };
        let (serial, parallel) = (on(1), on(2));
        assert_eq!(serial.root, parallel.root);
        assert_eq!(serial.order, parallel.order);
        assert!(serial.nodes == parallel.nodes);
        parallel.validate(&bounds).unwrap();
    }
}
