//! The wrong ways of part 3's light sampling that need more than a changed
//! factor: the shadow ray's two classic mistakes, and a light sampled from
//! behind. Called by [`crate::course::StarterTracer`] only when the
//! mistake is chosen.

use crate::intersect::{Hit, Ray};
use glam::{Vec2, Vec3};

use crate::lights::{Light, LightSample, RectLight};
use crate::math::Rgb;

/// [`super::Mistake::ShadowAcne`]: the shadow ray starts at the hit point
/// itself with `min_t = 0`, so the surface it leaves, met again at `t`
/// within rounding of 0, blocks a share of the samples that rounding sets:
/// about half here; in a student's double arithmetic from 37 % to 88 % by
/// surface (docs/maintainers/checker.md).
pub fn shadow_ray_without_offset(hit: &Hit, sample: &LightSample) -> Ray {
    Ray {
        t_max: sample.distance,
        ..Ray::new(hit.p, sample.wi)
    }
}

/// [`super::Mistake::ShadowRayReachesLight`]: the shadow ray (offset
/// correctly) keeps the starter's default `max_t`, infinity, so whatever
/// lies on its line beyond the light sample blocks it: the lamp's own
/// mesh, the ceiling, the box's walls. In a closed room no light sample
/// is seen. (A student's C++ solution with this mistake renders the
/// course's `CBbunny.dae` black but for the lamp, as this does.)
pub fn shadow_ray_to_the_light(hit: &Hit, sample: &LightSample) -> Ray {
    Ray {
        t_max: f32::INFINITY,
        ..hit.spawn_ray(sample.wi)
    }
}

/// [`super::Mistake::NoPdf`]'s light: the radiance the starter's
/// `sample_L` returns, which a solution that never divides by the pdf
/// sees alone. The starter's area light puts its distance quirk in the
/// pdf (`r / (A cos_l)` for `r^2 / (A cos_l)`), where
/// [`crate::lights::LightConvention::Course`] puts it in the radiance
/// (`r L`): the same `L / pdf`, but not the same `L`. Point lights and
/// maps are alike in both.
pub fn starter_radiance(light: &Light, sample: &LightSample) -> Rgb {
    match light {
        Light::Rect(rect) => sample.radiance / rect.convention.area_factor(sample.distance),
        _ => sample.radiance,
    }
}

/// [`super::Mistake::LightFromBehind`]: the rectangle sampled as if it
/// emitted from both sides (its cosine taken as `|cos|`), with the light's
/// convention as [`RectLight::sample_li`] applies it.
pub fn two_sided_rect_sample(rect: &RectLight, p: Vec3, u: Vec2) -> Option<LightSample> {
    rect.sample_sided(p, u, true)
}
