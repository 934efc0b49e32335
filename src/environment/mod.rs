//! Part 7 (assignment 3-2, part 3): lighting by an environment map, one
//! more light at infinity in the light set.
//!
//! - [`map`]: the latitude-longitude image (OpenEXR or Radiance `.hdr`),
//!   the course's direction <-> `(u, v)` mapping, bilinear lookup, checks
//!   (files are read by the private `reading`, `radiance` and `exr_layout`);
//! - [`light`]: the light: radiance of escaping rays, directions sampled
//!   uniformly or by importance (a 2D distribution of luminance x
//!   `sin(theta)`), their density per steradian, its power;
//! - [`sky`]: the map the project ships, a sky with a sun made in code.
//!
//! Once in the [`crate::lights::LightSet`] ([`crate::lights::LightSet::with_environment`]),
//! camera rays and paths that escape see the map, direct lighting samples
//! it `-l` times per vertex, and BSDF-sampled rays that escape are weighted
//! against those samples by multiple importance sampling, all through the
//! one integrator loop ([`crate::global`]).

mod exr_layout;
pub mod light;
pub mod map;
mod radiance;
mod reading;
pub mod sky;

pub use light::{EnvironmentLight, EnvironmentSampling, EnvironmentWeights};
pub use map::{direction_to_uv, uv_to_direction, EnvironmentError, EnvironmentMap};
pub use sky::builtin_sky;
