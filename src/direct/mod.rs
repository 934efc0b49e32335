//! Part 3: direct lighting.
//!
//! The radiance leaving a surface point `p` towards `wo` from light that
//! arrives directly from light sources is
//!
//! ```text
//! L_o(p, wo) = integral over the hemisphere of f(wo, wi) L_i(p, wi) cos(theta_i) dwi
//! ```
//!
//! estimated by Monte Carlo as the mean of `f L_i cos / pdf` over sampled
//! directions:
//!
//! - [`DirectHemisphere`] (`-H`): `wi` uniform on the hemisphere,
//!   `pdf = 1 / (2 pi)`; a sample carries light only if its ray hits an
//!   emissive surface or escapes into the ambient sky.
//! - [`DirectLights`]: `wi` sampled on each light ("light importance
//!   sampling"), `pdf` from [`lights`]; a shadow ray checks visibility.
//!   Delta lights are sampled once, other lights `-l` times each.
//!
//! Zero-bounce light (emission seen by the camera) is added by
//! [`zero_bounce`].

pub mod emitters;
pub mod estimators;
pub mod lights;
pub mod shading;

pub use estimators::{DirectHemisphere, DirectLights};
pub use shading::{zero_bounce, SceneTracer, ShadingPoint};
