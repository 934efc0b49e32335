//! Part 3: direct lighting.
//!
//! The radiance leaving a surface point `p` towards `wo` from light that
//! arrives directly from light sources is
//!
//! ```text
//! L_o(p, wo) = integral over the sphere of f(wo, wi) L_i(p, wi) |cos(theta_i)| dwi
//! ```
//!
//! estimated by Monte Carlo as the mean of `f L_i |cos| / pdf` over sampled
//! directions:
//!
//! - [`DirectHemisphere`] (`-H`): `wi` uniform on the hemisphere,
//!   `pdf = 1 / (2 pi)`; a sample carries light only if its ray hits an
//!   emissive surface or escapes into a light at infinity.
//! - [`DirectLights`]: `wi` sampled on each light ("light importance
//!   sampling", [`crate::lights`]); a shadow ray checks visibility.
//!   Delta lights are sampled once, other lights `-l` times each. With
//!   multiple importance sampling each sample is weighted against the
//!   chance that BSDF sampling finds the same direction; the integrator
//!   adds the BSDF-sampled half ([`crate::global`]).
//!
//! The scene these estimators read is a [`crate::world::World`].

pub mod estimators;

pub use estimators::{DirectHemisphere, DirectLights};
