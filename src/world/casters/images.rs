//! Light images in mirror-like casters: a narrow cone for the caustic
//! that a mirror sphere throws on a diffuse surface.
//!
//! From a diffuse point `x`, the directions towards a mirror sphere
//! (centre `c`, radius `R`) whose reflection reaches a light are the
//! light's image in the sphere: a small patch of the sphere's disc, since
//! a convex mirror shrinks what it shows. Sampling the sphere's whole cone
//! finds it rarely; so next to the sphere's cone, each vertex gets a cone
//! around the image of each rectangle light, aimed at the reflection
//! point of the light's centre.
//!
//! **The reflection point** of `x` and the light's centre `y` is the
//! point `s = c + R n` whose normal bisects the directions to both
//! (Alhazen's problem; Glaeser 1999 gives its closed form, a quartic). A
//! cone only needs it roughly, so it is found by the fixed-point iteration
//!
//! ```text
//! n_0 = normalize(normalize(x - c) + normalize(y - c))
//! n_{k+1} = normalize(u_k + v_k),  u_k = normalize(x - s_k),  v_k = normalize(y - s_k)
//! ```
//!
//! for [`ITERATIONS`] steps, and accepted when the last step moved `n` by
//! less than [`SETTLED`] and both `x` and `y` are above the tangent plane
//! at `s` (near the sphere, where the iteration does not settle, the
//! vertex has the sphere's cone alone).
//!
//! **The cone's half-angle.** Paraxial optics of a convex mirror: turning
//! the direction from `x` by a small angle `phi` out of the plane of
//! incidence moves the reflection point by `a phi` (`a = |x - s|`), turns
//! the normal by `a phi / R`, and turns the reflected direction by
//! `phi (1 + 2 a cos(theta_i) / R)`; within the plane the factor is
//! `1 + 2 a / (R cos(theta_i))`, larger. So a light seen from `s` within
//! an angle `alpha` of its centre is seen in the mirror from `x` within
//!
//! ```text
//! phi = alpha / (1 + 2 a cos(theta_i) / R),   alpha = atan(rho / b) + spread
//! ```
//!
//! (computed with sines for angles: [`image_cone`])
//!
//! with `rho` the radius of the disc around the light's centre that holds
//! it, `b = |y - s|`, and `spread` the reflected lobe's width for a glossy
//! conductor ([`IMAGE_LOBE`] `alpha`; 0 for a mirror). On a grid of 96
//! points on the floor and walls of `CBspheres.dae`, at the 93 where the
//! iteration settled ([`SETTLED`]), this cone held every
//! direction that reaches the light (counted by brute force, 2e5
//! directions per point), and a direction uniform in it reached the light
//! 8.7 times as often as one uniform in the sphere's cone (the median;
//! 2.2 times at the least).
//!
//! The cone depends on the vertex alone, so the mixture's sampling and
//! density agree whatever these approximations are: they decide only how
//! well the cone covers the image, not whether the estimate is unbiased.

use glam::Vec3;

use super::cone::Cone;
use super::Caster;
use crate::lights::{Light, LightSet};

/// Fixed-point steps towards the reflection point: the start is already
/// close where the light and the point are a few radii from the sphere,
/// and two steps settle it at 93 of the 96 points of the grid above
/// (more steps changed no cone there).
pub const ITERATIONS: usize = 2;

/// The largest last step of the iteration (the length of the change of
/// `n`, about the angle in radians) that counts as settled: on the grid
/// above, `3e-2` after two steps gave a cone at 93 of the 96 points
/// (`1e-2` at 76).
pub const SETTLED: f32 = 3e-2;

/// The narrowest image cone, by the sine of its half-angle: in a narrower
/// one (a tiny light, or a tiny sphere far away) the rounding of its own
/// samples' directions (about `1e-7` in the sine), and the margin of
/// `5e-7` radians that [`super::cone`] adds at its edge for it, would be
/// a larger share of the cone; such a vertex has the sphere's cone instead.
pub const MIN_IMAGE_SINE: f32 = 1e-2;

/// The largest Beckmann roughness of a conductor sphere that gets light
/// images: past it the reflected lobe is as wide as the sphere's cone.
pub const IMAGE_ALPHA: f32 = 0.05;

/// A glossy conductor's reflected directions spread about `IMAGE_LOBE
/// alpha` around the mirror direction (the half vector's slopes have a
/// standard deviation of `alpha / sqrt 2` per axis, twice that after
/// reflection: 2.8 standard deviations).
pub const IMAGE_LOBE: f32 = 4.0;

/// The extra width of the light that a caster of `material`'s kind
/// reflects: `Some(0)` for a mirror, `Some(IMAGE_LOBE alpha)` for a
/// conductor up to [`IMAGE_ALPHA`], `None` for the rest (glass bends
/// light through the sphere: no image cone).
pub fn image_spread(material: &crate::scene::Material) -> Option<f32> {
    use crate::scene::Material;
    match *material {
        Material::Mirror { .. } => Some(0.0),
        Material::Microfacet { alpha, .. } if alpha <= IMAGE_ALPHA => Some(IMAGE_LOBE * alpha),
        _ => None,
    }
}

/// A light as its image cones see it: the disc around its centre that
/// holds it, and the side it emits to.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImagedLight {
    pub center: Vec3,
    /// Unit normal of the emitting side.
    pub normal: Vec3,
    /// Radius of the disc around `center` that holds the light.
    pub radius: f32,
}

impl ImagedLight {
    /// The rectangle lights of `lights` that emit.
    pub fn of(lights: &LightSet) -> Vec<ImagedLight> {
        lights
            .lights
            .iter()
            .filter_map(|light| match light {
                Light::Rect(rect) if rect.radiance.max_element() > 0.0 => Some(ImagedLight {
                    center: rect.center,
                    normal: rect.normal,
                    radius: 0.5 * rect.diagonal(),
                }),
                _ => None,
            })
            .collect()
    }
}

/// The unit normal of the point of the sphere `(c, r)` that reflects `x`
/// towards `y`, both outside it, or `None` where the iteration has not
/// settled (its last step moved `n` by more than [`SETTLED`]) or a side
/// is below the tangent plane there.
pub fn reflection_normal(x: Vec3, y: Vec3, c: Vec3, r: f32) -> Option<Vec3> {
    let mut n = ((x - c).normalize() + (y - c).normalize()).normalize();
    let mut step = f32::INFINITY;
    for _ in 0..ITERATIONS {
        let s = c + r * n;
        let next = ((x - s).normalize() + (y - s).normalize()).normalize();
        step = (next - n).length_squared();
        n = next;
    }
    let s = c + r * n;
    let above = (x - s).dot(n) > 0.0 && (y - s).dot(n) > 0.0;
    (step < SETTLED * SETTLED && above).then_some(n)
}

/// The cone, from `x`, around the image of `light` in `caster`, whose
/// reflection widens the light by the angle `spread`; `None` where there
/// is no image ([`reflection_normal`], or the light faces away from the
/// reflection point), or the cone would be no narrower than the sphere's
/// or narrower than [`MIN_IMAGE_SINE`].
///
/// Sines stand for the angles of the module's formula (`sin(atan(rho /
/// b)) = rho / sqrt(rho^2 + b^2)`, and `sin(phi)` from `sin(alpha)`), so
/// that the cone needs no trigonometric function; for the angles of a
/// light image they differ by a few per cent at most, and `sin(alpha) /
/// m <= sin(alpha / m)` errs on the narrow side, covered by the bounding
/// disc's margin.
pub fn image_cone(x: Vec3, caster: &Caster, light: &ImagedLight, spread: f32) -> Option<Cone> {
    let (c, r) = (caster.center, caster.radius);
    let n = reflection_normal(x, light.center, c, r)?;
    let s = c + r * n;
    let to_light = light.center - s;
    if light.normal.dot(to_light) >= 0.0 {
        return None;
    }
    let to_s = s - x;
    let a = to_s.length();
    let cos_i = -to_s.dot(n) / a;
    let rho = light.radius;
    let sin_alpha = rho / (rho * rho + to_light.length_squared()).sqrt() + spread;
    let sin_phi = sin_alpha / (1.0 + 2.0 * a * cos_i / r);
    // The sphere's own cone: sin^2(theta) = r^2 / |c - x|^2.
    let sin2_sphere = r * r / (c - x).length_squared();
    (sin_phi >= MIN_IMAGE_SINE && sin_phi * sin_phi < sin2_sphere)
        .then(|| Cone::around(to_s / a, sin_phi))
}

#[cfg(test)]
mod tests;
