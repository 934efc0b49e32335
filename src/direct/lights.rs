//! Sampling the scene's lights from a point ("light importance sampling").
//!
//! Every density is per steradian at the receiving point `p`. Delta lights
//! (point, directional) are their own variant, never "pdf = 1".
//!
//! - Area light, a one-sided rectangle of area `A`: a point `q` uniform on
//!   it has density `1 / A` per area; seen from `p` at distance `r` under
//!   the light's cosine `cos_l = n_l . (p - q) / r`, that is
//!   `p_w = r^2 / (A cos_l)` per steradian. Radiance `L` toward the side
//!   the light faces, 0 behind it. (The course's starter divides by an
//!   unnormalised direction here, which makes its area lights too bright by
//!   a factor of `r`; see `docs/04-direct.md`.)
//! - Point light of intensity `I`: radiance-like `I / r^2` from one
//!   direction (the course omits the `1 / r^2`).
//! - Directional light: radiance `L` from one direction, infinitely far.
//! - Ambient sky of radiance `L` over the hemisphere around +Y: directions
//!   uniform on that hemisphere, `p_w = 1 / (2 pi)`, infinitely far.

use glam::{Vec2, Vec3};

use crate::math::warp::{sample_uniform_hemisphere, uniform_hemisphere_pdf};
use crate::math::{Frame, Rgb};
use crate::scene::Light;

/// How a light sample was drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightPdf {
    /// From a delta distribution (point or directional light): the
    /// estimator uses the radiance without dividing by a density.
    Delta,
    /// With this density per steradian (positive).
    SolidAngle(f32),
}

/// Light arriving at a point from one sampled direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightSample {
    /// Radiance arriving along `-wi` (for delta lights, the delta's weight).
    pub radiance: Rgb,
    /// Unit direction from the point towards the light, world space.
    pub wi: Vec3,
    /// Distance to the sampled point of the light (infinite for lights at
    /// infinity); shadow rays stop short of it.
    pub distance: f32,
    pub pdf: LightPdf,
}

/// How light samples are weighted: correctly, or as the course's starter
/// code does (`--course-lights`), to compare with the course's images.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LightConvention {
    /// Area lights with the solid-angle pdf `r^2 / (A cos_l)`, point lights
    /// falling off as `1 / r^2`.
    #[default]
    Physical,
    /// The course's starter: its area light takes the light's cosine from
    /// the unnormalised vector `q - p`, so its pdf is `r^2 / (A r cos_l)`
    /// and each sample is `r` times too bright; its point light returns the
    /// intensity without `1 / r^2`, so `r^2` times too bright.
    Course,
}

impl LightConvention {
    /// Factor on a sample of `light` taken at distance `r` from the point.
    pub fn factor(self, light: &Light, r: f32) -> f32 {
        match (self, light) {
            (LightConvention::Course, Light::Area { .. }) => r,
            (LightConvention::Course, Light::Point { .. }) => r * r,
            _ => 1.0,
        }
    }
}

/// A point sampled on an emitting surface with a density per unit area.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfacePoint {
    pub q: Vec3,
    /// Unit normal of the surface at `q` (the emitting side if one-sided).
    pub normal: Vec3,
    /// Whether both sides emit.
    pub two_sided: bool,
    pub radiance: Rgb,
    /// Density with which `q` was chosen, per unit area.
    pub area_pdf: f32,
}

impl SurfacePoint {
    /// The light sample this point gives at `p`: the one place an area
    /// density becomes a solid-angle one, `p_w = p_A r^2 / cos_e` with
    /// `cos_e` the emitter's cosine towards `p`. `None` at zero distance
    /// or when `p` sees the back of a one-sided emitter.
    pub fn seen_from(&self, p: Vec3) -> Option<LightSample> {
        let to_light = self.q - p;
        let distance_squared = to_light.length_squared();
        let distance = distance_squared.sqrt();
        if distance.is_nan() || distance <= 0.0 {
            return None;
        }
        let wi = to_light / distance;
        let facing = -self.normal.dot(wi);
        let cos_emitter = if self.two_sided { facing.abs() } else { facing };
        if cos_emitter <= 0.0 {
            return None;
        }
        Some(LightSample {
            radiance: self.radiance,
            wi,
            distance,
            pdf: LightPdf::SolidAngle(self.area_pdf * distance_squared / cos_emitter),
        })
    }
}

/// Whether `light` is a delta light (sampled once, not `-l` times).
pub fn is_delta(light: &Light) -> bool {
    matches!(light, Light::Point { .. } | Light::Directional { .. })
}

/// Samples light arriving at `p` from `light`, with `u` in `[0, 1)^2`.
/// `None` when the sample carries no light (behind a one-sided light, at
/// zero distance, or a spot light, which the course ignores).
#[doc(alias = "sample_L")]
pub fn sample_light(light: &Light, p: Vec3, u: Vec2) -> Option<LightSample> {
    match *light {
        Light::Area {
            radiance,
            center,
            direction,
            dim_x,
            dim_y,
        } => {
            let q = center + (u.x - 0.5) * dim_x + (u.y - 0.5) * dim_y;
            let area = dim_x.length() * dim_y.length();
            if area <= 0.0 {
                return None;
            }
            let emitter = SurfacePoint {
                q,
                normal: direction,
                two_sided: false,
                radiance,
                area_pdf: 1.0 / area,
            };
            emitter.seen_from(p)
        }
        Light::Point {
            intensity,
            position,
        } => {
            let to_light = position - p;
            let distance_squared = to_light.length_squared();
            if distance_squared.is_nan() || distance_squared <= 0.0 {
                return None;
            }
            let distance = distance_squared.sqrt();
            Some(LightSample {
                radiance: intensity / distance_squared,
                wi: to_light / distance,
                distance,
                pdf: LightPdf::Delta,
            })
        }
        Light::Directional {
            radiance,
            direction,
        } => Some(LightSample {
            radiance,
            wi: direction,
            distance: f32::INFINITY,
            pdf: LightPdf::Delta,
        }),
        Light::Ambient { radiance } => {
            let local = sample_uniform_hemisphere(u);
            Some(LightSample {
                radiance,
                wi: sky_frame().to_world(local),
                distance: f32::INFINITY,
                pdf: LightPdf::SolidAngle(uniform_hemisphere_pdf(local)),
            })
        }
        Light::Spot { .. } => None,
    }
}

/// The frame of the ambient sky: its hemisphere is around +Y.
fn sky_frame() -> Frame {
    Frame::from_z(Vec3::Y)
}

/// Radiance of the ambient lights seen along the unit direction `w` by a
/// ray that escapes the scene (zero for directions below the horizon).
pub fn sky_radiance(lights: &[Light], w: Vec3) -> Rgb {
    lights
        .iter()
        .map(|l| match *l {
            Light::Ambient { radiance } if w.y > 0.0 => radiance,
            _ => Rgb::ZERO,
        })
        .sum()
}

/// Density per steradian with which [`sample_light`] picks `wi` from `p`
/// for a non-delta light (0 if it cannot). `hit_distance` is the distance
/// to the area light's plane along `wi`, used only for area lights.
pub fn light_pdf(light: &Light, p: Vec3, wi: Vec3) -> f32 {
    match *light {
        Light::Area {
            center,
            direction,
            dim_x,
            dim_y,
            ..
        } => {
            let cos_light = -direction.dot(wi);
            let denom = direction.dot(wi);
            if cos_light <= 0.0 || denom == 0.0 {
                return 0.0;
            }
            let t = direction.dot(center - p) / denom;
            let q = p + t * wi;
            let local = q - center;
            let (sx, sy) = (dim_x.length_squared(), dim_y.length_squared());
            let inside = t > 0.0
                && (local.dot(dim_x) / sx).abs() <= 0.5
                && (local.dot(dim_y) / sy).abs() <= 0.5;
            let area = sx.sqrt() * sy.sqrt();
            if inside && area > 0.0 {
                t * t / (area * cos_light)
            } else {
                0.0
            }
        }
        Light::Ambient { .. } if wi.y > 0.0 => 1.0 / (2.0 * std::f32::consts::PI),
        _ => 0.0,
    }
}
