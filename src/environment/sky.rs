//! The project's own environment map, made in code so that
//! `part7-environment` runs with no download: a clear sky with a sun.
//!
//! - Sky (`y > 0`): blue at the zenith, brightening to a pale horizon,
//!   `L = mix(zenith, horizon, (1 - y)^3)`, with a glow around the sun,
//!   `+ glow exp(-angle / 0.15)`.
//! - Ground (`y < 0`): a dim warm grey, blended into the horizon over the
//!   first 3 degrees below it so that the lookup has no hard seam.
//! - Sun: a disk of angular radius [`SUN_RADIUS`] and radiance [`SUN_RADIANCE`]
//!   around [`sun_direction`] (35 degrees high), which gives an irradiance
//!   of about `pi SUN_RADIUS^2 SUN_RADIANCE = 7.7` on a surface facing it,
//!   against about 2 from the sky: sharp shadows, and a map whose power sits
//!   in a few hundred of its 131,072 texels, where importance sampling pays.
//!
//! Not a physical sky model (for that see Preetham, Shirley and Smits,
//! "A Practical Analytic Model for Daylight", SIGGRAPH 1999): its colours
//! are chosen to look right, and its numbers to exercise the sampler.

use glam::Vec3;

use super::map::{EnvironmentError, EnvironmentMap};
use crate::math::Rgb;

/// The name the built-in sky carries in messages.
pub const BUILTIN_SKY: &str = "built-in: sky";

/// Angular radius of the sun, radians (2 degrees: four times the real sun,
/// so that a 512 x 256 map resolves it with a few texels across).
pub const SUN_RADIUS: f32 = 0.035;

/// Radiance of the sun's disk.
pub const SUN_RADIANCE: f32 = 2000.0;

/// Unit vector towards the sun: 35 degrees above the horizon, 40 degrees
/// from +Z towards +X (behind the course's camera, to its right).
pub fn sun_direction() -> Vec3 {
    let (elevation, azimuth) = (35f32.to_radians(), 40f32.to_radians());
    Vec3::new(
        elevation.cos() * azimuth.sin(),
        elevation.sin(),
        elevation.cos() * azimuth.cos(),
    )
}

/// Radiance of the built-in sky in the unit direction `d`.
pub fn sky_radiance(d: Vec3) -> Rgb {
    let zenith = Rgb::new(0.18, 0.32, 0.75);
    let horizon = Rgb::new(0.85, 0.9, 1.0);
    let ground = Rgb::new(0.2, 0.18, 0.15);
    let angle = d.dot(sun_direction()).clamp(-1.0, 1.0).acos();
    let sky = |y: f32| {
        let t = (1.0 - y.max(0.0)).powi(3);
        zenith.lerp(horizon, t) + Rgb::new(1.0, 0.85, 0.6) * (2.0 * (-angle / 0.15).exp())
    };
    let below = 3f32.to_radians().sin();
    let mut l = if d.y >= 0.0 {
        sky(d.y)
    } else {
        ground.lerp(sky(0.0), (1.0 + d.y / below).max(0.0))
    };
    if angle <= SUN_RADIUS {
        l += Rgb::new(1.0, 0.95, 0.85) * SUN_RADIANCE;
    }
    l
}

/// The built-in sky as a 512 x 256 map.
pub fn builtin_sky() -> Result<EnvironmentMap, EnvironmentError> {
    EnvironmentMap::from_fn(BUILTIN_SKY, 512, 256, sky_radiance)
}
