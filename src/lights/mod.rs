//! The lights of a scene behind one interface (pbrt-v4's `Light`).
//!
//! Every kind answers the same questions:
//!
//! - [`Light::sample_li`]: a direction from a point `p` towards the light,
//!   with the radiance arriving along it, the distance to the light and
//!   the density: [`LightPdf::Delta`] for point and directional lights,
//!   else per steradian at `p`;
//! - [`Light::pdf_li`]: the density of a given direction (for multiple
//!   importance sampling), given where the direction meets the light;
//! - [`Light::escaped_radiance`]: the radiance a ray that escapes the scene
//!   sees (lights at infinity);
//! - [`Light::power`]: the radiant power (`--info` prints it in the
//!   plan; [`LightChoice::ByPower`] picks lights in proportion to it).
//!
//! | kind | file | sampled by |
//! | --- | --- | --- |
//! | rectangle (CGL `<area>`) | [`rect`] | uniform area, `p_w = r^2 / (A cos_l)` |
//! | point, spot | [`point`] | delta (the spot lights nothing, as in the course) |
//! | directional, ambient sky | [`distant`] | delta; uniform hemisphere around +Y |
//! | emissive triangles | [`triangles`] | power-proportional pick, uniform area |
//! | environment map (`-e`) | [`crate::environment`] | luminance x `sin(theta)` of the map, or uniform sphere |
//!
//! [`LightSet`] builds them once per render from the scene, and tells for
//! each primitive how its emission is counted ([`EmitterRole`]).
//! Densities are per steradian everywhere outside this module; the area
//! densities of surfaces become solid-angle ones in one place,
//! [`SurfacePoint::seen_from`].

pub mod choice;
pub mod convention;
pub mod distant;
pub mod point;
pub mod rect;
pub mod sample;
pub mod set;
pub mod stand_ins;
pub mod triangles;

pub use choice::{LightChoice, LightChoiceRule, LightStrategy, MANY_LIGHTS};
pub use convention::LightConvention;
pub use distant::{AmbientSky, DirectionalLight};
pub use point::{PointLight, SpotLight};
pub use rect::RectLight;
pub use sample::{LightPdf, LightSample, SurfacePoint};
pub use set::{EmitterRole, LightSet};
pub use stand_ins::StandIns;
pub use triangles::EmissiveTriangles;

use glam::{Vec2, Vec3};

use crate::environment::EnvironmentLight;
use crate::math::float::unit_cross;
use crate::math::Rgb;
use crate::scene::Light as SceneLight;

/// The unit normal of the plane the edges `a` and `b` span, on the side of
/// `direction` (the file's emitting direction, kept as it is when the
/// edges span no plane or it lies in their plane: the file contradicts
/// itself, and its stated direction is the one clue left). Tiny edges,
/// whose cross product's squared length is subnormal, still span their
/// plane: [`unit_cross`] scales before it normalises.
fn plane_normal(a: Vec3, b: Vec3, direction: Vec3) -> Vec3 {
    let n = unit_cross(a, b).unwrap_or(Vec3::ZERO);
    match n.dot(direction) {
        d if d > 0.0 => n,
        d if d < 0.0 => -n,
        _ => direction,
    }
}

/// Where a ray met a light that has an area: the point, and which member
/// of the light (which triangle of [`EmissiveTriangles`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightHit {
    pub point: Vec3,
    pub member: u32,
}

/// One light of the scene.
#[derive(Clone, Debug)]
pub enum Light {
    Rect(RectLight),
    Point(PointLight),
    Spot(SpotLight),
    Directional(DirectionalLight),
    Sky(AmbientSky),
    Triangles(EmissiveTriangles),
    Environment(EnvironmentLight),
}

impl Light {
    /// A light of the scene file behind this interface, its samples
    /// weighted by `convention`.
    pub fn from_scene(light: &SceneLight, convention: LightConvention) -> Light {
        match *light {
            SceneLight::Area {
                radiance,
                center,
                direction,
                dim_x,
                dim_y,
            } => Light::Rect(RectLight {
                radiance,
                center,
                normal: plane_normal(dim_x, dim_y, direction),
                dim_x,
                dim_y,
                convention,
            }),
            SceneLight::Point {
                intensity,
                position,
            } => Light::Point(PointLight {
                intensity,
                position,
                convention,
            }),
            SceneLight::Directional {
                radiance,
                direction,
            } => Light::Directional(DirectionalLight {
                radiance,
                direction,
            }),
            SceneLight::Ambient { radiance } => Light::Sky(AmbientSky { radiance }),
            SceneLight::Spot {
                intensity,
                position,
                direction,
            } => Light::Spot(SpotLight {
                intensity,
                position,
                direction,
            }),
        }
    }

    /// Light arriving at `p` along a sampled direction: `uc` in `[0, 1)`
    /// picks a member of a light made of several shapes, `u` in `[0, 1)^2`
    /// the point or direction. `None` when the sample carries no light.
    #[doc(alias = "sample_L")]
    pub fn sample_li(&self, p: Vec3, uc: f32, u: Vec2) -> Option<LightSample> {
        match self {
            Light::Rect(l) => l.sample_li(p, u),
            Light::Point(l) => l.sample_li(p),
            Light::Spot(_) => None,
            Light::Directional(l) => Some(l.sample_li()),
            Light::Sky(l) => l.sample_li(u),
            Light::Triangles(l) => l.sample_li(p, uc, u),
            Light::Environment(l) => l.sample_li(u),
        }
    }

    /// Starts loading the memory [`Self::sample_li`] at `u` will read first,
    /// where that is a cache miss worth overlapping (an environment map's
    /// guide table); changes nothing.
    #[inline]
    pub fn prefetch_sample_guide(&self, u: Vec2) {
        if let Light::Environment(l) = self {
            l.prefetch_sample_guide(u);
        }
    }

    /// The second step after [`Self::prefetch_sample_guide`], once its
    /// loads have had time to arrive (an environment map's cdf and texels).
    #[inline]
    pub fn prefetch_sample_cdf(&self, u: Vec2) {
        if let Light::Environment(l) = self {
            l.prefetch_sample_cdf(u);
        }
    }

    /// Starts loading what a ray escaping along `w` will read of this
    /// light (an environment map's texels), while the ray is traced.
    #[inline]
    pub fn prefetch_escape(&self, w: Vec3) {
        if let Light::Environment(l) = self {
            l.prefetch_escape(w);
        }
    }

    /// Density per steradian with which [`Self::sample_li`] picks the unit
    /// direction `wi` from `p`. `hit` is where the ray met the light, for
    /// lights made of scene geometry (emissive triangles); the rectangle
    /// finds its own crossing, lights at infinity need none. 0 for delta lights.
    pub fn pdf_li(&self, p: Vec3, wi: Vec3, hit: Option<LightHit>) -> f32 {
        match self {
            Light::Rect(l) => l.pdf_li(p, wi),
            Light::Sky(l) => l.pdf_li(wi),
            Light::Environment(l) => l.pdf_li(wi),
            Light::Triangles(l) => hit.map_or(0.0, |h| l.pdf_li(p, h.member, h.point)),
            Light::Point(_) | Light::Spot(_) | Light::Directional(_) => 0.0,
        }
    }

    /// Radiance seen by a ray that escapes the scene in the unit direction `w`.
    #[doc(alias = "Le")]
    pub fn escaped_radiance(&self, w: Vec3) -> Rgb {
        match self {
            Light::Sky(l) => l.escaped_radiance(w),
            Light::Environment(l) => l.escaped_radiance(w),
            _ => Rgb::ZERO,
        }
    }

    /// [`Self::escaped_radiance`] and, if `with_pdf`, [`Self::pdf_li`] of
    /// the unit direction `w` (else 0), as one look-up where the light
    /// can (the density is 0 where the radiance is black).
    pub fn escaped(&self, w: Vec3, with_pdf: bool) -> (Rgb, f32) {
        match self {
            Light::Environment(l) => l.escaped(w, with_pdf),
            _ => {
                let radiance = self.escaped_radiance(w);
                let pdf = if with_pdf && radiance != Rgb::ZERO {
                    self.pdf_li(Vec3::ZERO, w, None)
                } else {
                    0.0
                };
                (radiance, pdf)
            }
        }
    }

    /// Radiant power, per channel; lights at infinity count what crosses a
    /// scene of radius `scene_radius`.
    pub fn power(&self, scene_radius: f32) -> Rgb {
        match self {
            Light::Rect(l) => l.power(),
            Light::Point(l) => l.power(),
            Light::Spot(_) => Rgb::ZERO,
            Light::Directional(l) => l.power(scene_radius),
            Light::Sky(l) => l.power(scene_radius),
            Light::Triangles(l) => l.power(),
            Light::Environment(l) => l.power(scene_radius),
        }
    }

    /// Whether the light is a delta distribution (sampled once, never hit).
    pub fn is_delta(&self) -> bool {
        matches!(
            self,
            Light::Point(_) | Light::Spot(_) | Light::Directional(_)
        )
    }

    /// Whether the light is infinitely far away (seen by escaping rays).
    pub fn is_infinite(&self) -> bool {
        matches!(
            self,
            Light::Directional(_) | Light::Sky(_) | Light::Environment(_)
        )
    }

    /// A short lower-case name of the light's kind.
    pub fn kind(&self) -> &'static str {
        match self {
            Light::Rect(_) => "area",
            Light::Point(_) => "point",
            Light::Spot(_) => "spot",
            Light::Directional(_) => "directional",
            Light::Sky(_) => "ambient",
            Light::Triangles(_) => "emissive triangles",
            Light::Environment(_) => "environment",
        }
    }
}

#[cfg(test)]
mod tests;
