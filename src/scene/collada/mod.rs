//! The course's COLLADA 1.4.1 dialect (the starter's `ColladaParser`,
//! `src/scene/collada/collada.cpp`), read into a world-space [`Scene`].
//!
//! The module tree, one step of the reading each:
//!
//! | module | reads |
//! | --- | --- |
//! | `nesting` | how deep elements nest, refused past a limit before parsing |
//! | `xml` | element lookup, `#id` references, element paths for errors |
//! | `numbers` | number lists, counts, colours (finite values only) |
//! | `transform` | node matrices and the Z_UP map G: `(x, y, z) -> (-x, z, y)` |
//! | `fields` | a CGL element's fields: unknown and repeated names, values out of range |
//! | `camera` | `<camera>`: the course's viewing direction and fields of view |
//! | `light` | `<light>`: area, point, directional, ambient, spot |
//! | `material` | `<material>` -> `<effect>`: CGL BSDFs or phong diffuse |
//! | `source` | `<source>`: a float array through its accessor |
//! | `mesh` | `<mesh>`: `<polylist>` and `<triangles>`, fan-triangulated |
//! | `geometry` | `<geometry>`: a mesh or a CGL sphere |
//! | `builder` | world-space placement, material deduplication, normals |
//! | `visual_scene` | the node walk that ties them together |
//!
//! Loading never panics: every problem is a [`SceneError`] naming the
//! file, the element path (for example
//! `library_geometries/geometry[id=floor-mesh]/mesh/polylist/p`) and what
//! was wrong; tolerated oddities become [`Scene::warnings`].

mod builder;
mod camera;
mod fields;
mod geometry;
mod light;
mod material;
mod mesh;
mod nesting;
mod numbers;
mod source;
mod transform;
mod visual_scene;
mod xml;

use std::path::Path;

use glam::Mat4;

use super::{Scene, SceneError};
use builder::SceneBuilder;
use transform::{up_axis_map, Placement};
use visual_scene::{find_visual_scene, walk_visual_scene};
use xml::Doc;

/// Reads and parses a `.dae` file.
pub fn load_file(path: &Path) -> Result<Scene, SceneError> {
    let file = path.display().to_string();
    let text = std::fs::read_to_string(path)
        .map_err(|e| SceneError::new(&file, "", format!("cannot read the file: {e}")))?;
    load_str(&text, &file)
}

/// Parses COLLADA text; `file` names it in errors.
pub fn load_str(text: &str, file: &str) -> Result<Scene, SceneError> {
    if text.trim().is_empty() {
        return Err(SceneError::new(file, "", "the file is empty"));
    }
    nesting::check_nesting(text, file)?;
    let document = roxmltree::Document::parse(text)
        .map_err(|e| SceneError::new(file, "", format!("malformed XML: {e}")))?;
    let root = document.root_element();
    if root.tag_name().name() != "COLLADA" {
        return Err(SceneError::new(
            file,
            root.tag_name().name(),
            "the root element is not <COLLADA>",
        ));
    }
    let doc = Doc::new(&document, file);
    let placement = Placement {
        t: Mat4::IDENTITY,
        g: up_axis_map(&doc, root)?,
    };
    let visual_scene = find_visual_scene(&doc, root)?;
    let mut builder = SceneBuilder::new(file);
    walk_visual_scene(&doc, visual_scene, &placement, &mut builder)?;
    let mut scene = builder.finish();
    // The fields' and profiles' warnings first: they often explain the
    // walk's (a sphere skipped for a misspelt profile).
    let walk_warnings = std::mem::replace(&mut scene.warnings, doc.take_warnings());
    scene.warnings.extend(walk_warnings);
    Ok(scene)
}
