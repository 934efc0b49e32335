//! Mirror-like meshes as casters: each such material's triangles stand
//! in the casters' mixture as the sphere that bounds them.
//!
//! A mirror bunny in a Cornell box throws the light's reflections onto
//! the walls and the floor as a mirror sphere does, and cosine sampling
//! finds them as rarely: they were most of that scene's error, in bright
//! single pixels. The cones of [`super`] need only a sphere to aim at,
//! and any sphere keeps the estimate unbiased (the mixture's density is
//! the one the direction was drawn with, whatever the cone), so a mesh's
//! caster is the sphere around its triangles of one material:
//!
//! ```text
//! c = (min + max) / 2   (the centre of their bounding box)
//! r = max_i |p_i - c|   (over their vertices)
//! ```
//!
//! not the smallest such sphere, but within a factor of `sqrt 3` of it.
//! It shows no light images ([`super::images`] needs the sphere to be the
//! mirror itself), and a vertex inside it (the floor where the bunny
//! stands) gets no cone, as for a sphere caster.
//!
//! Only mirror-like materials (a mirror, or a conductor up to
//! [`super::images::IMAGE_ALPHA`]) make mesh casters. Measured on
//! `CBbunny.dae` with its bunny changed (480 x 360, 64 spp, `-m 5`,
//! against Mitsuba 3, `benches/compare/efficiency.py --scene`): a mirror
//! bunny's error fell by 39 % for 15 % more time (efficiency against
//! Mitsuba 0.89 to 1.24), but a glass bunny's by 8 % for 20 % more (1.03
//! to 0.92: its light is bent through two irregular surfaces and spread)
//! and a copper one's (`alpha` 0.2) by 23 % for 24 % more (1.41 to
//! 1.44: its reflection is already blurred). Rays aimed at a detailed
//! mesh cost more to trace than rays to the walls, so a cone must find
//! much more light than cosine sampling to pay.

use glam::Vec3;

use super::{images, Caster};
use crate::intersect::Aabb;
use crate::scene::{Material, MaterialId, TriangleMesh};

/// The bounding spheres of `mesh`'s triangles of each mirror-like
/// material in `materials`, in material order.
pub fn mesh_casters(mesh: &TriangleMesh, materials: &[Material]) -> Vec<Caster> {
    let mirror_like = |id: MaterialId| {
        materials
            .get(id as usize)
            .and_then(images::image_spread)
            .is_some()
    };
    let mut boxes = vec![Aabb::EMPTY; materials.len()];
    for (triangle, &material) in mesh.triangles.iter().zip(&mesh.materials) {
        if mirror_like(material) {
            let corners = triangle.map(|v| mesh.positions[v as usize]);
            boxes[material as usize] = corners
                .into_iter()
                .fold(boxes[material as usize], Aabb::grow);
        }
    }
    let centers: Vec<Vec3> = boxes.iter().map(|b| (b.min + b.max) * 0.5).collect();
    let mut radii = vec![0.0f32; materials.len()];
    for (triangle, &material) in mesh.triangles.iter().zip(&mesh.materials) {
        if mirror_like(material) {
            let m = material as usize;
            for &v in triangle {
                radii[m] = radii[m].max(mesh.positions[v as usize].distance(centers[m]));
            }
        }
    }
    (0..materials.len())
        .filter(|&m| radii[m] > 0.0 && radii[m].is_finite())
        .map(|m| Caster {
            center: centers[m],
            radius: radii[m],
            image_spread: None,
        })
        .collect()
}
