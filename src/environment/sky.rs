//! The project's own environment maps, made in code so that
//! `part7-environment` runs with no download: a clear sky with a sun.
//!
//! - Sky (`y > 0`): blue at the zenith, brightening to a pale horizon,
//!   `L = mix(zenith, horizon, (1 - y)^3)`, with a glow around the sun,
//!   `+ glow exp(-angle / 0.15)`.
//! - Ground (`y < 0`): a dim warm grey (or black, [`Sky::ground`]),
//!   blended into the horizon over the first 3 degrees below it so that
//!   the lookup has no hard seam.
//! - Sun: a disk of angular radius `r` and radiance `L_sun` around the
//!   sun's direction. A surface facing it receives `pi r^2 L_sun` from it;
//!   the built-in sky ([`SUN_RADIUS`], [`SUN_RADIANCE`], 35 degrees high)
//!   gives 7.7, against about 2 from the sky: sharp shadows, and a map
//!   whose power sits in a few hundred of its 131,072 texels, where
//!   importance sampling pays. [`Sky::with_sun_radius`] keeps that
//!   irradiance for a sun of any size (the real sun's radius is 0.27
//!   degrees, a few texels of a 2k map: the hard case for a sampler; a
//!   map holds only what its texels' centres see, [`Sky::sun_in_map`]).
//!
//! Not a physical sky model (for that see Preetham, Shirley and Smits,
//! "A Practical Analytic Model for Daylight", SIGGRAPH 1999): its colours
//! are chosen to look right, and its numbers to exercise the sampler.

use glam::Vec3;

use super::map::{texel_direction, EnvironmentError, EnvironmentMap};
use crate::math::{luminance, Rgb};

/// The name the built-in sky carries in messages.
pub const BUILTIN_SKY: &str = "built-in: sky";

/// Angular radius of the built-in sky's sun, radians (2 degrees: four
/// times the real sun, so that a 512 x 256 map resolves it with a few
/// texels across).
pub const SUN_RADIUS: f32 = 0.035;

/// Radiance of the built-in sky's sun disk.
pub const SUN_RADIANCE: f32 = 2000.0;

/// Unit vector towards the built-in sky's sun: 35 degrees above the
/// horizon, 40 degrees from +Z towards +X (behind the course's camera, to
/// its right).
pub fn sun_direction() -> Vec3 {
    let (elevation, azimuth) = (35f32.to_radians(), 40f32.to_radians());
    Vec3::new(
        elevation.cos() * azimuth.sin(),
        elevation.sin(),
        elevation.cos() * azimuth.cos(),
    )
}

/// The sun's warm white, times its radiance.
const SUN_COLOUR: Rgb = Rgb::new(1.0, 0.95, 0.85);

/// The sun as a map of the sky holds it ([`Sky::sun_in_map`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SunInMap {
    /// Texels whose centre lies in the sun's disk.
    pub texels: usize,
    /// The power the sun adds to them (luminance times solid angle).
    pub power_in_map: f64,
    /// The disk's own power.
    pub power: f64,
}

/// A clear sky with a sun (this module's docs give the formulas).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sky {
    /// Unit vector towards the sun.
    pub sun: Vec3,
    /// Angular radius of the sun's disk, radians.
    pub sun_radius: f32,
    /// Radiance of the sun's disk (times a warm white).
    pub sun_radiance: f32,
    /// Radiance below the horizon.
    pub ground: Rgb,
}

impl Default for Sky {
    /// The built-in sky.
    fn default() -> Self {
        Sky {
            sun: sun_direction(),
            sun_radius: SUN_RADIUS,
            sun_radiance: SUN_RADIANCE,
            ground: Rgb::new(0.2, 0.18, 0.15),
        }
    }
}

impl Sky {
    /// The same sky with a sun of angular radius `radius` (radians), its
    /// radiance scaled by `(r_old / r)^2` so that it lights a surface as
    /// before.
    pub fn with_sun_radius(self, radius: f32) -> Self {
        Sky {
            sun_radius: radius,
            sun_radiance: self.sun_radiance * (self.sun_radius / radius).powi(2),
            ..self
        }
    }

    /// Radiance in the unit direction `d`.
    pub fn radiance(&self, d: Vec3) -> Rgb {
        let zenith = Rgb::new(0.18, 0.32, 0.75);
        let horizon = Rgb::new(0.85, 0.9, 1.0);
        let angle = self.angle_to_sun(d);
        let sky = |y: f32| {
            let t = (1.0 - y.max(0.0)).powi(3);
            zenith.lerp(horizon, t) + Rgb::new(1.0, 0.85, 0.6) * (2.0 * (-angle / 0.15).exp())
        };
        let below = 3f32.to_radians().sin();
        let mut l = if d.y >= 0.0 {
            sky(d.y)
        } else {
            self.ground.lerp(sky(0.0), (1.0 + d.y / below).max(0.0))
        };
        if angle <= self.sun_radius {
            l += SUN_COLOUR * self.sun_radiance;
        }
        l
    }

    /// The angle (radians) between the unit direction `d` and the sun's.
    fn angle_to_sun(&self, d: Vec3) -> f32 {
        d.dot(self.sun).clamp(-1.0, 1.0).acos()
    }

    /// How the sun comes out in a `2 height x height` map of this sky: the
    /// texels whose centre lies in its disk, and the power those add,
    /// `sum L_sun dw_texel` (luminance; a texel's solid angle is
    /// `(2 pi / w)(pi / h) sin theta`), against the disk's own,
    /// `2 pi (1 - cos r) L_sun`.
    pub fn sun_in_map(&self, height: usize) -> SunInMap {
        let (w, h) = (2 * height, height);
        let radiance = f64::from(luminance(SUN_COLOUR * self.sun_radiance));
        let texel = (2.0 * std::f64::consts::PI / w as f64) * (std::f64::consts::PI / h as f64);
        let (mut texels, mut sin_thetas) = (0, 0.0);
        for j in 0..h {
            let sin_theta = (std::f64::consts::PI * (j as f64 + 0.5) / h as f64).sin();
            for i in 0..w {
                if self.angle_to_sun(texel_direction(i, j, w, h)) <= self.sun_radius {
                    texels += 1;
                    sin_thetas += sin_theta;
                }
            }
        }
        SunInMap {
            texels,
            power_in_map: radiance * texel * sin_thetas,
            power: 2.0 * std::f64::consts::PI * (1.0 - f64::from(self.sun_radius).cos()) * radiance,
        }
    }

    /// The sky as a `2 height x height` map named `source`, each texel
    /// the radiance at its centre. A sun many texels wide keeps its power;
    /// one a few texels wide roughly, and one smaller than a texel only
    /// where a centre falls inside it (the real sun, 0.27 degrees, is 7
    /// texels of a 2k map holding 77 % of its power, and none of a
    /// 512-wide one): [`Sky::sun_in_map`] says which.
    pub fn map(&self, source: &str, height: usize) -> Result<EnvironmentMap, EnvironmentError> {
        EnvironmentMap::from_fn(source, 2 * height, height, |d| self.radiance(d))
    }
}

/// Radiance of the built-in sky in the unit direction `d`.
pub fn sky_radiance(d: Vec3) -> Rgb {
    Sky::default().radiance(d)
}

/// The built-in sky as a 512 x 256 map.
pub fn builtin_sky() -> Result<EnvironmentMap, EnvironmentError> {
    Sky::default().map(BUILTIN_SKY, 256)
}

#[cfg(test)]
mod tests {
    use super::super::map::uv_to_direction;
    use super::*;
    use glam::Vec2;

    fn close(a: Rgb, b: Rgb) -> bool {
        (a - b).abs().max_element() <= 1e-5 * b.max_element().max(1.0)
    }

    /// The direction at `angle` from the sun, tilted towards the zenith.
    fn off_sun(sky: &Sky, angle: f32) -> Vec3 {
        let up = (Vec3::Y - sky.sun * sky.sun.y).normalize();
        sky.sun * angle.cos() + up * angle.sin()
    }

    /// 35 degrees above the horizon, 40 degrees from +Z towards +X.
    #[test]
    fn the_sun_stands_where_the_docs_say() {
        let sun = sun_direction();
        assert!((sun.length() - 1.0).abs() < 1e-6);
        assert!((sun.y - 35f32.to_radians().sin()).abs() < 1e-6);
        assert!((sun.x.atan2(sun.z) - 40f32.to_radians()).abs() < 1e-6);
    }

    /// The sky's colours by the docs' formula: the zenith and a horizon
    /// far from the sun, the sun's glow `2 exp(-angle / 0.15)` on both,
    /// the ground 3 degrees below the horizon and lower, and halfway
    /// between the two in between.
    #[test]
    fn the_sky_is_blue_above_a_pale_horizon_and_the_ground_below() {
        let sky = Sky::default();
        let zenith = Rgb::new(0.18, 0.32, 0.75);
        let horizon = Rgb::new(0.85, 0.9, 1.0);
        let glow = |angle: f32| Rgb::new(1.0, 0.85, 0.6) * (2.0 * (-angle / 0.15).exp());
        assert!(close(
            sky.radiance(Vec3::Y),
            zenith + glow(55f32.to_radians())
        ));
        let away = Vec3::new(-sky.sun.x, 0.0, -sky.sun.z).normalize();
        let angle = 145f32.to_radians();
        assert!(close(sky.radiance(away), horizon + glow(angle)));
        // Halfway up, (1 - y)^3 of the way to the horizon.
        let y = 0.5f32;
        let halfway = (away * (1.0 - y * y).sqrt() + Vec3::Y * y).normalize();
        let angle = halfway.dot(sky.sun).acos();
        let expected = zenith.lerp(horizon, 0.125) + glow(angle);
        assert!(close(sky.radiance(halfway), expected));
        let below = 3f32.to_radians();
        for depth in [below, 0.5, 1.5] {
            let d = away * depth.cos() - Vec3::Y * depth.sin();
            assert!(close(sky.radiance(d), sky.ground), "{depth}");
        }
        let d = away * (below / 2.0).cos() - Vec3::Y * (below / 2.0).sin();
        let at_horizon = horizon + glow(d.dot(sky.sun).acos());
        let expected = sky
            .ground
            .lerp(at_horizon, 1.0 - (below / 2.0).sin() / below.sin());
        assert!(close(sky.radiance(d), expected), "{}", sky.radiance(d));
    }

    /// Inside the sun's disk the sun's warm white is added, outside only
    /// the glow; a smaller sun keeps `radius^2 radiance`, the irradiance
    /// it gives (`pi r^2 L`, 7.7 for the built-in sun).
    #[test]
    fn the_sun_is_a_disk_and_a_smaller_one_lights_as_much() {
        let sky = Sky::default();
        let disk = Rgb::new(1.0, 0.95, 0.85) * SUN_RADIANCE;
        let inside = sky.radiance(off_sun(&sky, 0.9 * SUN_RADIUS));
        let outside = sky.radiance(off_sun(&sky, 1.1 * SUN_RADIUS));
        let difference = inside - outside - disk;
        assert!(difference.abs().max_element() < 0.1, "{difference}");
        let irradiance = |s: &Sky| std::f32::consts::PI * s.sun_radius.powi(2) * s.sun_radiance;
        assert!(
            (irradiance(&sky) - 7.7).abs() < 0.01,
            "{}",
            irradiance(&sky)
        );
        let small = sky.with_sun_radius(SUN_RADIUS / 8.0);
        assert_eq!((small.sun, small.ground), (sky.sun, sky.ground));
        assert_eq!(small.sun_radius, SUN_RADIUS / 8.0);
        assert!((small.sun_radiance / (64.0 * SUN_RADIANCE) - 1.0).abs() < 1e-6);
        assert!((irradiance(&small) / irradiance(&sky) - 1.0).abs() < 1e-5);
        assert!(small.radiance(off_sun(&small, 0.9 * small.sun_radius)).x > 64.0 * 1000.0);
        assert!(small.radiance(off_sun(&small, 2.0 * small.sun_radius)).x < 3.0);
    }

    /// The map is `2 h x h` texels of the sky at their centres, named.
    #[test]
    fn the_map_is_the_sky_at_each_texels_centre() {
        let sky = Sky::default();
        let map = sky.map("sky test", 8).unwrap();
        assert_eq!(
            (map.width(), map.height(), map.source()),
            (16, 8, "sky test")
        );
        let centre = uv_to_direction(Vec2::new(3.5 / 16.0, 2.5 / 8.0));
        assert_eq!(map.texel(3, 2), sky.radiance(centre));
        assert_eq!(builtin_sky().unwrap().source(), BUILTIN_SKY);
        assert_eq!(sky_radiance(Vec3::Y), sky.radiance(Vec3::Y));
    }

    /// A sun many texels wide keeps its power in the map (the built-in
    /// sky's, 31 texels at 512 x 256 and 494 at 2048 x 1024, to within
    /// 1.5 %); the real sun (0.27 degrees) is 7 texels of a 2k map holding
    /// 77 % of its power, and none of a 512 x 256 one, where it falls
    /// between the texels' centres.
    #[test]
    fn a_small_sun_is_found_or_lost_by_the_texel_centres() {
        let ratio = |sun: SunInMap| sun.power_in_map / sun.power;
        let built_in = Sky::default();
        let (coarse, fine) = (built_in.sun_in_map(256), built_in.sun_in_map(1024));
        assert_eq!(coarse.texels, 31);
        assert!((ratio(coarse) - 1.0).abs() < 0.015, "{coarse:?}");
        assert!((ratio(fine) - 1.0).abs() < 0.015, "{fine:?}");
        let real = built_in.with_sun_radius(0.27f32.to_radians());
        let two_k = real.sun_in_map(1024);
        assert_eq!(two_k.texels, 7);
        assert!((ratio(two_k) - 0.77).abs() < 0.01, "{two_k:?}");
        assert_eq!(real.sun_in_map(256).texels, 0);
        assert_eq!(real.sun_in_map(256).power_in_map, 0.0);
        assert!((two_k.power - coarse.power).abs() < 1e-3 * coarse.power);
    }
}
