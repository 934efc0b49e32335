//! The course's shading normals: area-weighted vertex normals rebuilt from
//! the mesh connectivity, ignoring any normals in the file.
//!
//! For vertex v with incident faces f = (a, b, c):
//!
//! ```text
//! N(v) = normalize( sum_f (b - a) x (c - a) )
//! ```
//!
//! The cross product's length is twice the face area, so larger faces weigh
//! more. A vertex whose faces all have zero area gets the zero vector; the
//! intersection code then falls back to the geometric normal.

use glam::Vec3;

/// Area-weighted vertex normals of `triangles` over `positions`.
pub fn area_weighted_vertex_normals(positions: &[Vec3], triangles: &[[u32; 3]]) -> Vec<Vec3> {
    let mut sums = vec![Vec3::ZERO; positions.len()];
    for &[a, b, c] in triangles {
        let (pa, pb, pc) = (
            positions[a as usize],
            positions[b as usize],
            positions[c as usize],
        );
        // Twice the face area, along the face normal.
        let n = (pb - pa).cross(pc - pa);
        for v in [a, b, c] {
            sums[v as usize] += n;
        }
    }
    sums.into_iter().map(|n| n.normalize_or_zero()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn larger_faces_weigh_more() {
        // Two faces around vertex 0: a unit one facing +Z, a 4x larger one facing +X.
        let positions = vec![
            Vec3::ZERO,
            Vec3::X,
            Vec3::Y,
            Vec3::new(0.0, 2.0, 0.0),
            Vec3::new(0.0, 0.0, 2.0),
        ];
        let triangles = vec![[0, 1, 2], [0, 3, 4]];
        let n = area_weighted_vertex_normals(&positions, &triangles);
        let expected = Vec3::new(4.0, 0.0, 1.0).normalize();
        assert!((n[0] - expected).length() < 1e-6, "{:?}", n[0]);
        assert!((n[1] - Vec3::Z).length() < 1e-6);
    }

    #[test]
    fn degenerate_faces_give_zero_not_nan() {
        let positions = vec![Vec3::ONE; 3];
        let n = area_weighted_vertex_normals(&positions, &[[0, 1, 2]]);
        assert!(n.iter().all(|v| *v == Vec3::ZERO));
    }
}
