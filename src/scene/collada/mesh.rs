//! `<mesh>`: positions and the triangles of its `<polylist>` and
//! `<triangles>` elements, in the geometry's own (file) space.
//!
//! Each primitive element has `<input>`s with a `semantic`, a `source` and
//! an `offset`. `<p>` interleaves one index per distinct offset for every
//! polygon corner, so its stride is `max offset + 1`. `VERTEX` (required)
//! points at the mesh's `<vertices>`, whose `POSITION` input gives the
//! positions; `NORMAL`, `TEXCOORD` and others are optional and only checked
//! (their indices must be in range): the course rebuilds normals itself.
//!
//! `<polylist count="n">` has `n` entries in `<vcount>`, each at least 3, and
//! `<p>` holds `sum(vcount) * stride` indices. `<triangles count="n">` has
//! `3 n * stride`. A polygon `v0 v1 ... vk` is fan-triangulated into
//! `(v0, vi, vi+1)`; the course keeps only its first triangle, but every
//! course file has only triangles, so the two agree there.
//!
//! The primitive's `material` attribute is a symbol that the instancing
//! node's `<bind_material>` maps to a `<material>`.

use glam::Vec3;
use roxmltree::Node;

use super::super::SceneError;
use super::numbers::{count_attr, indices};
use super::source::source;
use super::xml::{children, require_attr, require_child, Doc};

/// A mesh in file space, before its node's transform.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct LocalMesh {
    pub positions: Vec<Vec3>,
    /// One entry per primitive element, in document order.
    pub parts: Vec<Part>,
}

/// The triangles of one `<polylist>` or `<triangles>` element.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Part {
    /// The `material` symbol, if any.
    pub symbol: Option<String>,
    /// Indices into [`LocalMesh::positions`].
    pub triangles: Vec<[u32; 3]>,
}

/// One `<input>` of a primitive: its offset in a corner and the number of
/// elements its indices may address.
struct Input {
    offset: usize,
    elements: usize,
    semantic: String,
}

/// Reads the `<mesh>` element `mesh`. Unsupported primitive elements
/// (`<polygons>`, `<lines>`, ...) are skipped with a warning.
pub fn mesh(doc: &Doc, mesh: Node, warnings: &mut Vec<String>) -> Result<LocalMesh, SceneError> {
    let vertices = require_child(doc, mesh, "vertices")?;
    let position_input = children(vertices, "input")
        .find(|i| i.attribute("semantic") == Some("POSITION"))
        .ok_or_else(|| doc.err(vertices, "missing <input semantic=\"POSITION\">"))?;
    let positions_source = source(doc, doc.resolve(position_input, "source", "source")?)?;
    if positions_source.stride < 3 {
        return Err(doc.err(
            position_input,
            format!(
                "positions need 3 numbers each, the accessor's stride is {}",
                positions_source.stride
            ),
        ));
    }
    let positions = positions_source.points();

    let mut parts = Vec::new();
    for element in mesh.children().filter(Node::is_element) {
        let name = element.tag_name().name();
        match name {
            "polylist" | "triangles" => {
                parts.push(primitive(doc, element, vertices, positions.len())?)
            }
            "polygons" | "lines" | "linestrips" | "trifans" | "tristrips" => {
                warnings.push(doc.note(element, format!("<{name}> is not supported; skipped")))
            }
            _ => {}
        }
    }
    Ok(LocalMesh { positions, parts })
}

/// Reads one `<polylist>` or `<triangles>` element.
fn primitive(
    doc: &Doc,
    element: Node,
    vertices: Node,
    position_count: usize,
) -> Result<Part, SceneError> {
    let mut inputs = Vec::new();
    let mut vertex_offset = None;
    for input in children(element, "input") {
        let semantic = require_attr(doc, input, "semantic")?;
        let offset = count_attr(doc, input, "offset", None)?;
        let elements = if semantic == "VERTEX" {
            if doc.resolve(input, "source", "vertices")? != vertices {
                return Err(doc.err(input, "VERTEX must refer to this mesh's <vertices>"));
            }
            vertex_offset.get_or_insert(offset);
            position_count
        } else {
            source(doc, doc.resolve(input, "source", "source")?)?.count
        };
        inputs.push(Input {
            offset,
            elements,
            semantic: semantic.to_string(),
        });
    }
    let Some(vertex_offset) = vertex_offset else {
        return Err(doc.err(element, "missing <input semantic=\"VERTEX\">"));
    };
    let stride = inputs
        .iter()
        .map(|i| i.offset)
        .max()
        .unwrap_or(0)
        .saturating_add(1);

    let count = count_attr(doc, element, "count", None)?;
    let p_node = require_child(doc, element, "p")?;
    let p = indices(doc, p_node)?;
    let sizes = polygon_sizes(doc, element, count)?;
    let corners: usize = sizes.iter().map(|&n| n as usize).sum();
    let expected = corners.checked_mul(stride);
    if expected != Some(p.len()) {
        return Err(doc.err(
            p_node,
            format!(
                "expected {corners} corners * {stride} indices = {} indices, found {}",
                expected.map_or("too many".to_string(), |e| e.to_string()),
                p.len()
            ),
        ));
    }

    // Every index of every input must address an element of its source.
    for (j, &index) in p.iter().enumerate() {
        let offset = j % stride;
        for input in inputs.iter().filter(|i| i.offset == offset) {
            if index as usize >= input.elements {
                return Err(doc.err(
                    p_node,
                    format!(
                        "index {index} (value {j} of <p>) is out of range for {} ({} elements)",
                        input.semantic, input.elements
                    ),
                ));
            }
        }
    }

    // Fan-triangulate each polygon.
    let vertex = |corner: usize| p.get(corner * stride + vertex_offset).copied().unwrap_or(0);
    let mut triangles = Vec::with_capacity(corners.saturating_sub(2 * sizes.len()));
    let mut first = 0usize;
    for &n in &sizes {
        let n = n as usize;
        for k in 1..n.saturating_sub(1) {
            triangles.push([vertex(first), vertex(first + k), vertex(first + k + 1)]);
        }
        first += n;
    }
    Ok(Part {
        symbol: element.attribute("material").map(str::to_string),
        triangles,
    })
}

/// The corner count of each polygon: `<vcount>` for a polylist (checked
/// against `count`, each at least 3), 3 for triangles.
fn polygon_sizes(doc: &Doc, element: Node, count: usize) -> Result<Vec<u32>, SceneError> {
    if element.tag_name().name() == "triangles" {
        // Bounded by the length check of <p> that follows: a huge count
        // fails there, so do not allocate `count` entries up front.
        let p_len = super::xml::child(element, "p")
            .and_then(|p| p.text())
            .map_or(0, |t| t.split_ascii_whitespace().count());
        if count > p_len {
            return Err(doc.err(
                element,
                format!("count=\"{count}\" triangles but <p> holds only {p_len} indices"),
            ));
        }
        return Ok(vec![3; count]);
    }
    let vcount_node = require_child(doc, element, "vcount")?;
    let sizes = indices(doc, vcount_node)?;
    if sizes.len() != count {
        return Err(doc.err(
            vcount_node,
            format!(
                "count=\"{count}\" polygons but <vcount> has {} entries",
                sizes.len()
            ),
        ));
    }
    if let Some((i, n)) = sizes.iter().enumerate().find(|(_, &n)| n < 3) {
        return Err(doc.err(
            vcount_node,
            format!("polygon {i} has {n} vertices; a polygon needs at least 3"),
        ));
    }
    Ok(sizes)
}
