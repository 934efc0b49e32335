//! Shared mathematics: colours, orthonormal frames and floating-point helpers.
//!
//! Geometry is `f32` ([`glam::Vec3`]); colours are linear RGB in a [`Rgb`].

pub mod color;
pub mod float;

pub use color::{luminance, Rgb};
