//! Shared mathematics: colours, orthonormal frames, warps, piecewise-constant
//! distributions, floating-point helpers and special functions.
//!
//! Geometry is `f32` ([`glam::Vec3`]); colours are linear RGB in a [`Rgb`].

pub mod color;
pub mod distribution;
pub mod float;
pub mod frame;
pub mod huge_pages;
pub mod mis;
pub mod prefetch;
pub mod rng;
pub mod special;
pub mod warp;

pub use color::{luminance, ratio_colour, Rgb, MAX_RADIANCE};
pub use frame::Frame;
