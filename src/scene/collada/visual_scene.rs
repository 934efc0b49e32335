//! The walk over a `<visual_scene>`: nested `<node>`s with their instances.
//!
//! A node's placement is its parent's matrix times its own (see
//! [`super::transform`]), followed by the up-axis map G. Each node may hold:
//!
//! - `<instance_geometry url>` with `<bind_material><technique_common>
//!   <instance_material symbol target>`: a mesh primitive's `material`
//!   symbol maps through these bindings to a `<material>`; an unbound
//!   symbol (a warning) or no symbol gives [`Material::DEFAULT`]. A sphere
//!   has no symbol of its own and takes the first binding.
//! - `<instance_light url>` and `<instance_camera url>`; the first camera
//!   found (document order, depth first) is the scene's camera.
//! - child `<node>`s. `<instance_node>` is not supported (a warning).
//!
//! Nesting deeper than [`MAX_DEPTH`] is an error, so a hostile file cannot
//! exhaust the stack.
//!
//! [`Material::DEFAULT`]: super::super::Material::DEFAULT

use roxmltree::Node;

use super::super::SceneError;
use super::builder::SceneBuilder;
use super::camera::camera_info;
use super::geometry::{shape, Shape};
use super::light::light;
use super::transform::{local_matrix, Placement};
use super::xml::{child, children, descend, require_attr, Doc};

/// The deepest node nesting accepted.
pub const MAX_DEPTH: usize = 256;

/// Walks the nodes of `visual_scene` into `builder`; `root` places the
/// scene (identity matrix and the document's up-axis map).
pub fn walk_visual_scene(
    doc: &Doc,
    visual_scene: Node,
    root: &Placement,
    builder: &mut SceneBuilder,
) -> Result<(), SceneError> {
    let mut walker = Walker {
        doc,
        builder,
        camera_found: false,
    };
    for node in children(visual_scene, "node") {
        walker.node(node, root, 1)?;
    }
    Ok(())
}

struct Walker<'d, 'a, 'input, 'b> {
    doc: &'d Doc<'a, 'input>,
    builder: &'b mut SceneBuilder,
    camera_found: bool,
}

impl<'a, 'input> Walker<'_, 'a, 'input, '_> {
    fn node(
        &mut self,
        node: Node<'a, 'input>,
        parent: &Placement,
        depth: usize,
    ) -> Result<(), SceneError> {
        let doc = self.doc;
        if depth > MAX_DEPTH {
            return Err(doc.err(node, format!("nodes nested deeper than {MAX_DEPTH} levels")));
        }
        let place = parent.then(local_matrix(doc, node, &mut self.builder.scene.warnings)?);
        for item in node.children().filter(Node::is_element) {
            match item.tag_name().name() {
                "node" => self.node(item, &place, depth + 1)?,
                "instance_geometry" => self.geometry(item, &place)?,
                "instance_light" => {
                    let element = doc.resolve(item, "url", "light")?;
                    let warnings = &mut self.builder.scene.warnings;
                    if let Some(l) = light(doc, element, &place, warnings)? {
                        self.builder.scene.lights.push(l);
                    }
                }
                "instance_camera" => {
                    let element = doc.resolve(item, "url", "camera")?;
                    let warnings = &mut self.builder.scene.warnings;
                    let info = camera_info(doc, element, &place, warnings)?;
                    if !self.camera_found {
                        self.builder.scene.camera = info;
                        self.camera_found = true;
                    }
                }
                "instance_node" => {
                    let note = doc.note(item, "<instance_node> is not supported; skipped");
                    self.builder.scene.warnings.push(note);
                }
                _ => {}
            }
        }
        Ok(())
    }

    fn geometry(
        &mut self,
        instance: Node<'a, 'input>,
        place: &Placement,
    ) -> Result<(), SceneError> {
        let doc = self.doc;
        let geometry = doc.resolve(instance, "url", "geometry")?;
        // The linear part: a matrix's last row may be padded (a warning of its own).
        if glam::Mat3::from_mat4(place.t).determinant() * place.g.determinant() == 0.0 {
            doc.warn(
                instance,
                "the node matrices are singular (determinant 0): the geometry collapses onto a plane, a line or a point",
            );
        }
        // Symbol -> <material> bindings of this instance.
        let mut bindings = Vec::new();
        if let Some(common) = descend(instance, &["bind_material", "technique_common"]) {
            for im in children(common, "instance_material") {
                let symbol = require_attr(doc, im, "symbol")?;
                bindings.push((symbol, doc.resolve(im, "target", "material")?));
            }
        }
        let Some(found) = shape(doc, geometry, &mut self.builder.scene.warnings)? else {
            return Ok(());
        };
        match found {
            Shape::Sphere { radius } => {
                let bound = bindings.first().map(|&(_, m)| m);
                let material = self.builder.material_id(doc, bound)?;
                self.builder
                    .add_sphere(doc, instance, radius, place, material)?;
            }
            Shape::Mesh(local) => {
                let mut materials = Vec::with_capacity(local.parts.len());
                for part in &local.parts {
                    let bound = part.symbol.as_deref().and_then(|s| {
                        bindings
                            .iter()
                            .find(|(symbol, _)| *symbol == s)
                            .map(|&(_, m)| m)
                    });
                    if let (Some(symbol), None) = (&part.symbol, bound) {
                        let note = doc.note(
                            instance,
                            format!("material symbol \"{symbol}\" is not bound; using the default material"),
                        );
                        self.builder.scene.warnings.push(note);
                    }
                    materials.push(self.builder.material_id(doc, bound)?);
                }
                self.builder
                    .add_mesh(doc, instance, &local, place, &materials)?;
            }
        }
        Ok(())
    }
}

/// The visual scene to render: `<scene><instance_visual_scene url>` when
/// present, else the first `<visual_scene>` of the file.
pub fn find_visual_scene<'a, 'input>(
    doc: &Doc<'a, 'input>,
    root: Node<'a, 'input>,
) -> Result<Node<'a, 'input>, SceneError> {
    if let Some(instance) = descend(root, &["scene", "instance_visual_scene"]) {
        return doc.resolve(instance, "url", "visual_scene");
    }
    child(root, "library_visual_scenes")
        .and_then(|l| child(l, "visual_scene"))
        .ok_or_else(|| doc.err(root, "no <visual_scene> to render"))
}
