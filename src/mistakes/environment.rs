//! The starter's `EnvironmentLight` as a student writes it with the
//! catalogue's mistakes of part 7: called by
//! [`crate::course::StarterTracer`] only when one is chosen.
//!
//! The right density of a direction drawn from the map's cell `(u, v)` is
//! `p(u, v) w h / (2 pi^2 sin(theta))` (per steradian, from the density
//! `p(u, v) w h` over `[0, 1]^2`, with `d omega = 2 pi^2 sin(theta) du dv`);
//! the mistakes leave out the `sin(theta)` or the `2 pi^2`, or read the map
//! with `u` (the azimuth) or `v` (the polar angle) flipped.

use std::f32::consts::PI;

use glam::{Vec2, Vec3};

use super::{Mistake, Mistakes};
use crate::environment::EnvironmentLight;
use crate::lights::{LightPdf, LightSample};
use crate::math::Rgb;

/// Part 7's mistakes.
pub const ENVIRONMENT_MISTAKES: [Mistake; 4] = [
    Mistake::EnvPdfNoSin,
    Mistake::EnvPdfNoJacobian,
    Mistake::EnvMapUFlipped,
    Mistake::EnvMapVFlipped,
];

/// Whether any of part 7's mistakes is chosen.
pub fn any(mistakes: Mistakes) -> bool {
    ENVIRONMENT_MISTAKES.iter().any(|&m| mistakes.has(m))
}

/// The direction whose texel the student's lookup reads for `w`: `u`
/// flipped (`phi -> 2 pi - phi`) negates `w.z`, `v` flipped
/// (`theta -> pi - theta`) negates `w.y` (`u = phi / 2 pi` with
/// `phi = atan2(-z, x) + pi`, `v = theta / pi` with `theta = acos(y)`).
pub fn looked_up(w: Vec3, mistakes: Mistakes) -> Vec3 {
    let z = if mistakes.has(Mistake::EnvMapUFlipped) {
        -w.z
    } else {
        w.z
    };
    let y = if mistakes.has(Mistake::EnvMapVFlipped) {
        -w.y
    } else {
        w.y
    };
    Vec3::new(w.x, y, z)
}

/// `EnvironmentLight::sample_dir`: the radiance a ray escaping along `w` sees.
pub fn escaped_radiance(env: &EnvironmentLight, w: Vec3, mistakes: Mistakes) -> Rgb {
    env.escaped_radiance(looked_up(w, mistakes))
}

/// `EnvironmentLight::sample_L` with `mistakes`: the map's own sample, its
/// direction as the student's flipped lookup places it, its density
/// without `sin(theta)` or without `2 pi^2`.
pub fn sample(env: &EnvironmentLight, u: Vec2, mistakes: Mistakes) -> Option<LightSample> {
    let mut sample = env.sample_li(u)?;
    sample.wi = looked_up(sample.wi, mistakes);
    if let LightPdf::SolidAngle(pdf) = &mut sample.pdf {
        if mistakes.has(Mistake::EnvPdfNoSin) {
            *pdf *= sample.wi.x.hypot(sample.wi.z);
        }
        if mistakes.has(Mistake::EnvPdfNoJacobian) {
            *pdf *= 2.0 * PI * PI;
        }
    }
    Some(sample)
}
