//! The vertex normals a course binary computes, read from the starters'
//! `util/halfEdgeMesh.cpp` (`HalfedgeMesh::build`, `Vertex::computeNormal`)
//! and `scene/gl_scene/mesh.cpp`: a halfedge mesh is built per geometry
//! from the file's winding, over positions already placed in the world.
//!
//! - A vertex inside the surface gets the area-weighted normal,
//!   `N(v) = normalize(sum_f (b - a) x (c - a))` over its faces
//!   ([`super::normals::area_weighted_vertex_normals`]).
//! - A vertex on the boundary does not. Its halfedge is made to point
//!   along the boundary loop (whose orientation is the opposite of the
//!   faces'), from `v` to the boundary vertex `x` before it, and
//!   `computeNormal` then walks around `x`, not `v`: for each face `F`
//!   holding `x`, the boundary loop among them,
//!
//!   ```text
//!   N(v) = normalize( sum_F (x - v) x (succ_F(x) - v) )
//!   ```
//!
//!   For a flat open patch (a wall of two triangles) this is the winding's
//!   normal reversed: the course's own Cornell boxes are wound outwards
//!   and shade inwards. A closed mesh has no boundary vertex.
//!
//! The course refuses a mesh it cannot make into halfedges (an edge
//! oriented the same way twice, a vertex where two boundary loops meet):
//! there this falls back to the area-weighted normals.

use std::collections::HashMap;

use glam::Vec3;

use super::normals::area_weighted_vertex_normals;

/// The course's vertex normals of `triangles` over `positions` (unit, or
/// zero where the sum vanishes).
pub fn course_vertex_normals(positions: &[Vec3], triangles: &[[u32; 3]]) -> Vec<Vec3> {
    let mut normals = area_weighted_vertex_normals(positions, triangles);
    let Some(before) = boundary_predecessors(positions.len(), triangles) else {
        return normals;
    };
    // Per vertex, its faces' successors of it: succ_F(x) for each F.
    let mut successors: Vec<Vec<u32>> = vec![Vec::new(); positions.len()];
    for t in triangles {
        for k in 0..3 {
            successors[t[k] as usize].push(t[(k + 1) % 3]);
        }
    }
    for (v, x) in before.iter().enumerate() {
        let Some(x) = *x else { continue };
        // The boundary loop runs against the faces: from x it goes on to
        // the boundary vertex before x.
        let Some(loop_next) = before[x as usize] else {
            continue;
        };
        let p = |i: u32| positions[i as usize];
        let (pv, px) = (positions[v], p(x));
        let sum: Vec3 = successors[x as usize]
            .iter()
            .chain([&loop_next])
            .map(|&s| (px - pv).cross(p(s) - pv))
            .sum();
        normals[v] = sum.normalize_or_zero();
    }
    normals
}

/// For each boundary vertex `v`, the vertex `x` with the boundary edge
/// `x -> v` (the faces' winding); `None` inside the surface. `None` for
/// the whole mesh where the course would refuse it.
fn boundary_predecessors(vertices: usize, triangles: &[[u32; 3]]) -> Option<Vec<Option<u32>>> {
    let mut edges: HashMap<(u32, u32), ()> = HashMap::with_capacity(3 * triangles.len());
    for t in triangles {
        if t[0] == t[1] || t[1] == t[2] || t[0] == t[2] {
            return None;
        }
        for k in 0..3 {
            if edges.insert((t[k], t[(k + 1) % 3]), ()).is_some() {
                return None;
            }
        }
    }
    let mut before = vec![None; vertices];
    for &(a, b) in edges.keys() {
        if !edges.contains_key(&(b, a)) {
            // A second boundary edge into b: two loops meet there.
            if before[b as usize].replace(a).is_some() {
                return None;
            }
        }
    }
    Some(before)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A flat square of two triangles wound counter-clockwise about +Z:
    /// every vertex is on the boundary, and each gets -Z.
    #[test]
    fn an_open_flat_patch_gets_its_winding_reversed() {
        let positions = vec![Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::Y];
        let n = course_vertex_normals(&positions, &[[0, 1, 2], [0, 2, 3]]);
        for v in n {
            assert!((v + Vec3::Z).length() < 1e-6, "{v}");
        }
    }

    /// A closed mesh (a tetrahedron) has no boundary: the area-weighted
    /// normals, outwards for an outward winding.
    #[test]
    fn a_closed_mesh_gets_the_area_weighted_normals() {
        let positions = vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z];
        let triangles = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
        let n = course_vertex_normals(&positions, &triangles);
        assert_eq!(n, area_weighted_vertex_normals(&positions, &triangles));
        assert!(n[3].z > 0.0 && n[0].dot(Vec3::ONE) < 0.0);
    }

    /// A mesh the course would refuse (an edge oriented the same way by
    /// two faces) keeps the area-weighted normals.
    #[test]
    fn a_mesh_the_course_refuses_falls_back() {
        let positions = vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::new(1.0, 1.0, 0.0)];
        let triangles = [[0, 1, 2], [0, 1, 3]];
        let n = course_vertex_normals(&positions, &triangles);
        assert_eq!(n, area_weighted_vertex_normals(&positions, &triangles));
    }
}
