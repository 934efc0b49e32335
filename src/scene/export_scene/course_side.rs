//! What makes an exported scene shade in a course binary as it does here:
//! lamp meshes behind their lights, and each part wound for the normals
//! the course rebuilds.

use std::collections::HashMap;

use glam::Vec3;

use super::super::course_normals::course_vertex_normals;
use super::super::{Light, Scene};

/// How far behind its area light a lamp mesh is written: far enough
/// that no ray finds the two at one distance in `f32` or `f64`, near
/// enough to change no image.
pub const LAMP_SETBACK: f32 = 1e-5;

/// The mesh's positions, each vertex of an emissive triangle that lies in
/// an area light's plane moved [`LAMP_SETBACK`] behind it (against the
/// direction it emits). The course's boxes hold a lamp mesh in the plane
/// of their light, and a 3-2 binary turns the light into triangles of
/// its own, which then meet the mesh at one distance: which one a ray
/// sees turns on differences of 1e-8 between the file's numbers read as
/// `f32` (the mesh) and as `f64` (the light), measured on the 3-2
/// starter. Behind its light, the mesh is never seen first.
pub(super) fn behind_their_lights(scene: &Scene) -> Vec<Vec3> {
    let mesh = &scene.mesh;
    let mut positions = mesh.positions.clone();
    let planes: Vec<(Vec3, Vec3)> = scene
        .lights
        .iter()
        .filter_map(|l| match *l {
            Light::Area {
                center, direction, ..
            } => Some((center, direction.normalize_or_zero())),
            _ => None,
        })
        .collect();
    let mut moved = vec![false; positions.len()];
    for (t, &m) in mesh.triangles.iter().zip(&mesh.materials) {
        if scene.materials[m as usize].emission() == crate::math::Rgb::ZERO {
            continue;
        }
        for &(center, n) in &planes {
            let in_plane = |v: u32| (mesh.positions[v as usize] - center).dot(n).abs() < 1e-4;
            if t.iter().all(|&v| in_plane(v)) {
                for &v in t {
                    if !std::mem::replace(&mut moved[v as usize], true) {
                        positions[v as usize] -= LAMP_SETBACK * n;
                    }
                }
            }
        }
    }
    positions
}

/// `triangles` with each connected part wound so that the normals the
/// course rebuilds ([`course_vertex_normals`]) agree with `intended` at
/// the most vertices: an open part (a wall, a pane) the other way round,
/// since the course reverses the normals on a boundary, a closed one as
/// it is.
pub(super) fn wound_for_the_course(
    positions: &[Vec3],
    intended: &[Vec3],
    triangles: &[[u32; 3]],
) -> Vec<[u32; 3]> {
    let flipped: Vec<[u32; 3]> = triangles.iter().map(|&[a, b, c]| [a, c, b]).collect();
    let (as_is, reversed) = (
        course_vertex_normals(positions, triangles),
        course_vertex_normals(positions, &flipped),
    );
    // Connected parts: union-find over the vertices.
    let mut parent: HashMap<u32, u32> = HashMap::new();
    fn root(parent: &mut HashMap<u32, u32>, v: u32) -> u32 {
        let p = *parent.entry(v).or_insert(v);
        if p == v {
            return v;
        }
        let r = root(parent, p);
        parent.insert(v, r);
        r
    }
    for &[a, b, c] in triangles {
        for (u, w) in [(a, b), (b, c)] {
            let (ru, rw) = (root(&mut parent, u), root(&mut parent, w));
            parent.insert(ru, rw);
        }
    }
    // Per part, the vertices where reversing agrees better, less those
    // where keeping does.
    let mut vote: HashMap<u32, i64> = HashMap::new();
    let vertices: Vec<u32> = parent.keys().copied().collect();
    for v in vertices {
        let n = intended[v as usize];
        let score = |normals: &[Vec3]| (normals[v as usize].dot(n) > 0.0) as i64;
        let part = root(&mut parent, v);
        *vote.entry(part).or_default() += score(&reversed) - score(&as_is);
    }
    triangles
        .iter()
        .zip(&flipped)
        .map(|(&t, &f)| {
            if vote[&root(&mut parent, t[0])] > 0 {
                f
            } else {
                t
            }
        })
        .collect()
}
