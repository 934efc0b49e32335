//! Helpers shared by the integration tests. Each test file is its own
//! crate and uses only part of this module.
#![allow(dead_code, unused_imports)]

pub mod collada;
pub mod exact;
pub mod geometry;

pub use collada::*;
pub use exact::*;
pub use geometry::*;
