//! Accumulates the [`Scene`] while the visual scene is walked: places
//! meshes and spheres in world space and keeps one [`Material`] per
//! `<material>` element.
//!
//! - Mesh positions land at `G * (T * (p, 1)).xyz`; every instance appends
//!   its own copy of the vertices, so meshes never share vertices and each
//!   keeps its connectivity. The file's normals are ignored: [`finish`]
//!   rebuilds area-weighted vertex normals over the merged mesh, as the
//!   course does.
//! - A sphere's centre is `G * T * origin` and its radius is scaled by
//!   `|G * T * (1, 0, 0, 0)|` (G preserves lengths).
//! - Materials are deduplicated by the `<material>` element they come from;
//!   geometry with no bound material shares one [`Material::DEFAULT`].
//!
//! [`finish`]: SceneBuilder::finish

use std::collections::HashMap;

use glam::Vec3;
use roxmltree::Node;

use super::super::course_normals::course_vertex_normals;
use super::super::{Material, MaterialId, Scene, SceneError, Sphere};
use super::material::material;
use super::mesh::LocalMesh;
use super::transform::Placement;
use super::xml::Doc;
use crate::math::float::readable;

/// The scene under construction.
pub struct SceneBuilder {
    pub scene: Scene,
    /// Material index by `<material>` id; `None` is the default material.
    ids: HashMap<Option<String>, MaterialId>,
}

impl SceneBuilder {
    pub fn new(source: &str) -> Self {
        SceneBuilder {
            scene: Scene {
                source: source.to_string(),
                ..Scene::default()
            },
            ids: HashMap::new(),
        }
    }

    /// The index of the material a `<material>` element describes (or of
    /// the default material for `None`), reading it on first use.
    pub fn material_id(
        &mut self,
        doc: &Doc,
        element: Option<Node>,
    ) -> Result<MaterialId, SceneError> {
        let key = element.map(|e| e.attribute("id").unwrap_or("").to_string());
        if let Some(&id) = self.ids.get(&key) {
            return Ok(id);
        }
        let value = match element {
            Some(e) => material(doc, e)?,
            None => Material::DEFAULT,
        };
        let id = MaterialId::try_from(self.scene.materials.len())
            .map_err(|_| SceneError::new(doc.file, "", "too many materials"))?;
        self.scene.materials.push(value);
        self.ids.insert(key, id);
        Ok(id)
    }

    /// Appends `local` placed by `place` (for `instance`, named in errors);
    /// `materials[k]` is the material of `local.parts[k]`.
    pub fn add_mesh(
        &mut self,
        doc: &Doc,
        instance: Node,
        local: &LocalMesh,
        place: &Placement,
        materials: &[MaterialId],
    ) -> Result<(), SceneError> {
        let mesh = &mut self.scene.mesh;
        // Local indices are below local.positions.len(), so they fit too.
        let base = mesh.positions.len();
        if u32::try_from(base + local.positions.len()).is_err() {
            return Err(SceneError::new(doc.file, "", "more than 2^32 vertices"));
        }
        let base = base as u32;
        let placed: Vec<Vec3> = local.positions.iter().map(|&p| place.point(p)).collect();
        for &p in &placed {
            check_coordinates(doc, instance, p)?;
        }
        mesh.positions.extend(placed);
        for (part, &material) in local.parts.iter().zip(materials) {
            for &[a, b, c] in &part.triangles {
                mesh.triangles.push([base + a, base + b, base + c]);
                mesh.materials.push(material);
            }
        }
        Ok(())
    }

    /// Appends a sphere of file-space `radius` centred on the node's origin
    /// (for `instance`, named in errors).
    pub fn add_sphere(
        &mut self,
        doc: &Doc,
        instance: Node,
        radius: f32,
        place: &Placement,
        material: MaterialId,
    ) -> Result<(), SceneError> {
        let center = place.point(Vec3::ZERO);
        let radius = radius * place.vector(Vec3::X).length();
        check_coordinates(doc, instance, center + radius)?;
        check_coordinates(doc, instance, center - radius)?;
        self.scene.spheres.push(Sphere {
            center,
            radius,
            material,
        });
        Ok(())
    }

    /// The finished scene, with the vertex normals the course rebuilds
    /// ([`course_vertex_normals`]: reversed on an open patch's boundary).
    /// The course builds them per geometry; a placed geometry's vertices
    /// are its own, so the whole mesh at once gives the same.
    pub fn finish(mut self) -> Scene {
        let mesh = &mut self.scene.mesh;
        mesh.normals = course_vertex_normals(&mesh.positions, &mesh.triangles);
        self.scene
    }
}

/// The largest coordinate a placed vertex or sphere may have. Tracing
/// squares coordinates (a sphere's `|o - c|^2`, a triangle's edge
/// products), and `f32` squares overflow beyond about `1.8e19`; `1e15`
/// leaves room for ray distances and offsets.
pub const MAX_COORDINATE: f32 = 1e15;

/// Refuses a placed point `p` of `instance` that is not finite or lies
/// beyond [`MAX_COORDINATE`].
fn check_coordinates(doc: &Doc, instance: Node, p: Vec3) -> Result<(), SceneError> {
    if p.abs().max_element() <= MAX_COORDINATE {
        return Ok(());
    }
    let [x, y, z] = p.to_array().map(readable);
    Err(doc.err(
        instance,
        format!(
            "geometry is placed at ({x}, {y}, {z}): coordinates beyond {} (or not finite) cannot be \
             traced in 32-bit floats; check the node matrices",
            readable(MAX_COORDINATE)
        ),
    ))
}
