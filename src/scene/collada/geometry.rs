//! `<geometry>`: a triangle mesh (`<mesh>`, see [`super::mesh`]) or the
//! course's analytic sphere:
//!
//! ```xml
//! <geometry id="Sphere1-data"><extra><technique profile="CGL">
//!   <sphere><radius>.3</radius></sphere></technique></extra></geometry>
//! ```
//!
//! The sphere is centred on its node's origin; the node places it (see
//! [`super::visual_scene`]). A negative radius is an error; any other kind
//! of geometry is skipped with a warning.

use roxmltree::Node;

use super::super::SceneError;
use super::fields::Fields;
use super::mesh::{mesh, LocalMesh};
use super::numbers::single_float;
use super::xml::{cgl_technique, child, Doc};

/// What a `<geometry>` holds, in its own (file) space.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    Mesh(LocalMesh),
    /// A sphere of this radius around the node's origin.
    Sphere {
        radius: f32,
    },
}

/// Reads the `<geometry>` element `geometry`; `None` (with a warning) for a
/// kind the course does not know.
pub fn shape(
    doc: &Doc,
    geometry: Node,
    warnings: &mut Vec<String>,
) -> Result<Option<Shape>, SceneError> {
    if let Some(m) = child(geometry, "mesh") {
        return Ok(Some(Shape::Mesh(mesh(doc, m, warnings)?)));
    }
    let sphere = child(geometry, "extra")
        .and_then(|e| cgl_technique(doc, e))
        .and_then(|t| child(t, "sphere"));
    if let Some(sphere) = sphere {
        let radius_node = Fields::new(doc, sphere, &["radius"]).required("radius")?;
        let radius = single_float(doc, radius_node)?;
        if radius < 0.0 {
            return Err(doc.err(radius_node, format!("negative radius {radius}")));
        }
        return Ok(Some(Shape::Sphere { radius }));
    }
    warnings.push(doc.note(geometry, "neither a <mesh> nor a CGL <sphere>; skipped"));
    Ok(None)
}
