//! Mirror-like meshes as casters: each such material's triangles stand
//! in the casters' mixture as the sphere that bounds them.
//!
//! A mirror bunny in a Cornell box throws the light's reflections onto
//! the walls, the ceiling and the floor as a mirror sphere does, and
//! cosine sampling finds them as rarely: they were most of that scene's
//! error, in bright single pixels. The cones of [`super`] need only a
//! sphere to aim at, and any sphere keeps the estimate unbiased (the
//! mixture's density is the one the direction was drawn with, whatever
//! the cone), so a mesh's caster is the sphere around its triangles of
//! one material:
//!
//! ```text
//! c = (min + max) / 2   (the centre of their bounding box)
//! r = max_i |p_i - c|   (over their vertices)
//! ```
//!
//! not the smallest such sphere, but within a factor of `sqrt 3` of it.
//! It shows no light images ([`super::images`] needs the sphere to be the
//! mirror itself), and a vertex inside it (the floor where the bunny
//! stands) gets no cone, as for a sphere caster. Separate objects of one
//! material share one sphere, which spans the space between them: still
//! unbiased, but a wider cone, so fewer of its samples meet a mirror.
//!
//! Only mirror-like materials ([`casts_as_mesh`]) make mesh casters.
//! Measured on `CBbunny.dae` with its bunny changed (480 x 360, 64 spp,
//! `-m 5`, two seeds, `benches/compare/efficiency.py --only
//! CBbunny_mirror CBbunny_glass CBbunny_copper`): a mirror bunny's error
//! fell by 39 % for 16 % more time (1.41 times the efficiency; against
//! Mitsuba 3, 0.89 before and 1.27 after), but a glass bunny's by 8 % for
//! 20 % more (0.91 times: its light is bent through two irregular
//! surfaces and spread) and a copper one's (`alpha` 0.2) by 23 % for 24 %
//! more (1.05 times: its reflection is already blurred). Rays aimed at a
//! detailed mesh cost more to trace than rays to the walls, so a cone
//! must find much more light than cosine sampling to pay.

use glam::Vec3;

use super::{images, Caster};
use crate::intersect::Aabb;
use crate::scene::{Material, MaterialId, TriangleMesh};

/// Whether triangles of `material` make a mesh caster: a mirror, or a
/// conductor up to [`images::IMAGE_ALPHA`], the materials that show light
/// images on a sphere ([`images::image_spread`]), for the same reason: up
/// to that roughness a reflection keeps the light's shape.
pub fn casts_as_mesh(material: &Material) -> bool {
    images::image_spread(material).is_some()
}

/// The bounding spheres of `mesh`'s triangles of each material of
/// `materials` that [`casts_as_mesh`], in material order. Triangles whose
/// material is not in `materials` are left out.
pub fn mesh_casters(mesh: &TriangleMesh, materials: &[Material]) -> Vec<Caster> {
    let casts = |id: MaterialId| materials.get(id as usize).is_some_and(casts_as_mesh);
    let casting = || {
        mesh.triangles
            .iter()
            .zip(&mesh.materials)
            .filter(move |&(_, &m)| casts(m))
            .flat_map(|(triangle, &m)| triangle.map(|v| (m as usize, mesh.positions[v as usize])))
    };
    let mut boxes = vec![Aabb::EMPTY; materials.len()];
    for (m, p) in casting() {
        boxes[m] = boxes[m].grow(p);
    }
    let centers: Vec<Vec3> = boxes.iter().map(Aabb::centroid).collect();
    let mut radii = vec![0.0f32; materials.len()];
    for (m, p) in casting() {
        radii[m] = radii[m].max(p.distance(centers[m]));
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

#[cfg(test)]
pub(super) mod tests;
