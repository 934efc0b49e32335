//! Part 1: camera rays, and normal shading to look at them.
//!
//! - [`Camera`]: the course's pinhole camera, placed as the course places it.
//! - [`NormalShading`]: colour = `(n + 1) / 2` of the first hit, the first
//!   picture of the assignment.

pub mod camera;
pub mod normal_shading;

pub use camera::{Camera, CameraSample};
pub use normal_shading::NormalShading;
