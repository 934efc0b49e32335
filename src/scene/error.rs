//! The error type of scene loading: every error names the file, the element
//! and what was expected.

use std::fmt;

/// A scene that could not be loaded.
#[derive(Debug)]
pub struct SceneError {
    /// The file (or built-in scene name) being read.
    pub file: String,
    /// The element where the problem is, as a path such as
    /// `library_geometries/geometry[id=floor-mesh]/mesh/polylist/p`,
    /// or empty when the problem is the file as a whole.
    pub element: String,
    /// What was wrong.
    pub problem: String,
}

impl SceneError {
    pub fn new(
        file: impl Into<String>,
        element: impl Into<String>,
        problem: impl Into<String>,
    ) -> Self {
        SceneError {
            file: file.into(),
            element: element.into(),
            problem: problem.into(),
        }
    }
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.element.is_empty() {
            write!(f, "{}: {}", self.file, self.problem)
        } else {
            write!(f, "{}: <{}>: {}", self.file, self.element, self.problem)
        }
    }
}

impl std::error::Error for SceneError {}
