//! Scenes: the scene model, the course's COLLADA loader, built-in scenes and
//! the course's rebuilt vertex normals.
//!
//! `load(path)` reads a `.dae` file; [`builtin::cornell_box`] makes the
//! default scene in code. Both give a [`Scene`] in world space (Y-up).
//! [`course_files`] finds the course's own scenes (`$CS184_SCENES`);
//! [`export`] writes a generated mesh as a `.dae` file.

pub mod builtin;
pub mod collada;
pub mod course_files;
pub mod course_normals;
pub mod error;
pub mod export;
pub mod export_scene;
pub mod info;
pub mod model;
pub mod normals;

pub use error::SceneError;
pub use model::{CameraInfo, Light, Material, MaterialId, Scene, Sphere, TriangleMesh};

use std::path::Path;

/// Loads a scene file (COLLADA `.dae` in the course's dialect).
///
/// Errors name the file, the element and what was wrong; this never panics
/// on bad input.
pub fn load(path: &Path) -> Result<Scene, SceneError> {
    collada::load_file(path)
}
