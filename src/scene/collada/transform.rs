//! Node transforms and the course's up-axis map.
//!
//! A node's local matrix is the product, in document order, of its transform
//! elements: `<matrix>` (16 numbers, row major), `<translate>`, `<rotate>`
//! (axis and angle in degrees) and `<scale>`. Nested nodes compose
//! `T = T_parent * T_child`. A `<matrix>` of only 15 numbers (a real course
//! file has one) gets its missing last entry padded with 0, as the course
//! reader does, and the loader records a warning.
//!
//! The file is Z-up; world space is Y-up. With `<up_axis>Z_UP</up_axis>` the
//! course maps a file point `(x, y, z)` to `(-x, z, y)`: the linear map G,
//! applied after the composed node matrix. A point `p` of a node lands at
//! `G * (T * (p, 1)).xyz`, a direction `v` at `G * (T * (v, 0)).xyz`.
//! `.xyz` drops w without dividing by it, as the course does. G is a
//! reflection composed with a rotation, so it preserves lengths.

use glam::{Mat3, Mat4, Vec3};
use roxmltree::Node;

use super::super::SceneError;
use super::numbers::floats;
use super::xml::{descend, Doc};

/// Where a node puts things in world space: its composed matrix `t` (file
/// space) followed by the up-axis map `g`.
#[derive(Clone, Copy, Debug)]
pub struct Placement {
    pub t: Mat4,
    pub g: Mat3,
}

impl Placement {
    /// World position of the file-space point `p` of the node:
    /// `G * (T * (p, 1)).xyz`.
    pub fn point(&self, p: Vec3) -> Vec3 {
        self.g * (self.t * p.extend(1.0)).truncate()
    }

    /// World vector of the file-space direction `v`: `G * (T * (v, 0)).xyz`.
    pub fn vector(&self, v: Vec3) -> Vec3 {
        self.g * (self.t * v.extend(0.0)).truncate()
    }

    /// The placement of a child node with local matrix `local`.
    pub fn then(&self, local: Mat4) -> Placement {
        Placement {
            t: self.t * local,
            g: self.g,
        }
    }
}

/// The map G from file space to the Y-up world for the document's
/// `<asset><up_axis>`: Z_UP gives `(x, y, z) -> (-x, z, y)`; Y_UP or no
/// `<up_axis>` (the COLLADA default) is the identity; X_UP gives
/// `(x, y, z) -> (-y, x, z)`.
pub fn up_axis_map(doc: &Doc, root: Node) -> Result<Mat3, SceneError> {
    let Some(node) = descend(root, &["asset", "up_axis"]) else {
        return Ok(Mat3::IDENTITY);
    };
    match node.text().unwrap_or("").trim() {
        "Z_UP" => Ok(Mat3::from_cols(-Vec3::X, Vec3::Z, Vec3::Y)),
        "Y_UP" => Ok(Mat3::IDENTITY),
        "X_UP" => Ok(Mat3::from_cols(Vec3::Y, -Vec3::X, Vec3::Z)),
        other => Err(doc.err(
            node,
            format!("unknown up axis \"{other}\", expected X_UP, Y_UP or Z_UP"),
        )),
    }
}

/// The local matrix of `node`: the product of its transform elements.
/// Tolerated problems are appended to `warnings`.
pub fn local_matrix(doc: &Doc, node: Node, warnings: &mut Vec<String>) -> Result<Mat4, SceneError> {
    let mut m = Mat4::IDENTITY;
    for element in node.children().filter(Node::is_element) {
        let step = match element.tag_name().name() {
            "matrix" => matrix(doc, element, warnings)?,
            "translate" => Mat4::from_translation(vec3(doc, element)?),
            "scale" => Mat4::from_scale(vec3(doc, element)?),
            "rotate" => rotation(doc, element)?,
            "lookat" | "skew" => {
                return Err(doc.err(element, "this transform element is not supported"))
            }
            _ => continue,
        };
        m *= step;
    }
    Ok(m)
}

/// A `<matrix>`: 16 numbers, row major; 15 are padded with a last 0.
fn matrix(doc: &Doc, element: Node, warnings: &mut Vec<String>) -> Result<Mat4, SceneError> {
    let mut values = floats(doc, element)?;
    match values.len() {
        16 => {}
        15 => {
            values.push(0.0);
            warnings.push(doc.note(
                element,
                "15 numbers instead of 16; the last entry is taken as 0, as the course does",
            ));
        }
        n => {
            return Err(doc.err(element, format!("expected 16 numbers, found {n}")));
        }
    }
    let mut cols = [0.0f32; 16];
    cols.copy_from_slice(&values);
    // The file is row major, glam is column major.
    Ok(Mat4::from_cols_array(&cols).transpose())
}

/// A `<rotate>`: axis x y z, then the angle in degrees.
fn rotation(doc: &Doc, element: Node) -> Result<Mat4, SceneError> {
    match floats(doc, element)?.as_slice() {
        [x, y, z, angle] => {
            let axis = Vec3::new(*x, *y, *z)
                .try_normalize()
                .ok_or_else(|| doc.err(element, "the rotation axis has zero length"))?;
            Ok(Mat4::from_axis_angle(axis, angle.to_radians()))
        }
        other => Err(doc.err(
            element,
            format!("expected 4 numbers (axis, angle), found {}", other.len()),
        )),
    }
}

/// Three numbers as a vector (`<translate>`, `<scale>`).
fn vec3(doc: &Doc, element: Node) -> Result<Vec3, SceneError> {
    match floats(doc, element)?.as_slice() {
        [x, y, z] => Ok(Vec3::new(*x, *y, *z)),
        other => Err(doc.err(
            element,
            format!("expected 3 numbers, found {}", other.len()),
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec4;
    use roxmltree::Document;

    fn placement_of(text: &str) -> (Placement, Vec<String>) {
        let document = Document::parse(text).unwrap();
        let doc = Doc::new(&document, "t.dae");
        let root = document.root_element();
        let g = up_axis_map(&doc, root).unwrap();
        let node = document
            .descendants()
            .find(|n| n.has_tag_name("node"))
            .unwrap();
        let mut warnings = Vec::new();
        let t = local_matrix(&doc, node, &mut warnings).unwrap();
        (Placement { t, g }, warnings)
    }

    const Z_UP: &str = "<asset><up_axis>Z_UP</up_axis></asset>";

    #[test]
    fn z_up_maps_x_y_z_to_minus_x_z_y() {
        let (p, w) = placement_of(&format!(
            "<COLLADA>{Z_UP}<node><matrix>1 0 0 1 0 1 0 2 0 0 1 3 0 0 0 1</matrix></node></COLLADA>"
        ));
        assert!(w.is_empty());
        assert_eq!(p.point(Vec3::ZERO), Vec3::new(-1.0, 3.0, 2.0));
        assert_eq!(
            p.vector(Vec3::new(1.0, 2.0, 3.0)),
            Vec3::new(-1.0, 3.0, 2.0)
        );
    }

    #[test]
    fn fifteen_numbers_pad_with_zero_and_warn() {
        let (p, w) = placement_of(
            "<COLLADA><node><matrix>1 0 0 1 0 1 0 2 0 0 1 3 0 0 0</matrix></node></COLLADA>",
        );
        assert_eq!(w.len(), 1, "{w:?}");
        assert_eq!(p.t.row(3), Vec4::ZERO);
        assert_eq!(p.point(Vec3::ZERO), Vec3::new(1.0, 2.0, 3.0));
    }

    #[test]
    fn transform_elements_compose_in_order() {
        let (p, _) = placement_of(
            r#"<COLLADA><node><translate>1 0 0</translate><rotate>0 0 1 90</rotate>
               <scale>2 2 2</scale></node></COLLADA>"#,
        );
        let q = p.point(Vec3::X);
        assert!((q - Vec3::new(1.0, 2.0, 0.0)).length() < 1e-6, "{q}");
    }
}
