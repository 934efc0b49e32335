//! Helpers shared by the integration tests. Each test file is its own
//! crate and uses only part of this module.
#![allow(dead_code, unused_imports)]

pub mod collada;
pub mod course;
pub mod exact;
pub mod geometry;
pub mod radiometry;
pub mod scenes;
pub mod standins;
pub mod starters;
pub mod stats;
pub mod symptoms;

pub use collada::*;
pub use course::*;
pub use exact::*;
pub use geometry::*;
pub use radiometry::*;
pub use scenes::*;
pub use standins::*;
pub use starters::*;
pub use stats::*;
pub use symptoms::*;
