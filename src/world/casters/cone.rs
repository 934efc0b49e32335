//! A cone of directions sampled uniformly: the solid angle a caster
//! subtends from a point, or a narrower cone around the image of a light
//! in a mirror-like caster ([`super::images`]).
//!
//! A cone is kept as its axis `a` (not necessarily unit) and the squared
//! sine of its half-angle times `|a|^2`: a unit direction `w` is inside
//! when `|w x a|^2 <= sin^2(theta_max) |a|^2` with `w . a > 0` (the bound
//! widened by the rounding of a drawn direction, `EDGE_ANGLE`). For a
//! sphere of radius `r` whose centre is at `a` from the point, that bound
//! is `r^2` (widened, `(r + EDGE_ANGLE |a|)^2`), and the test needs no
//! square root and no cosine (which, for a small sphere far away, agrees
//! with `cos(theta_max)` to all of `f32`'s digits). Uniform in the cone,
//! the density is `1 / (2 pi (1 - cos(theta_max)))` (pbrt-v4, section
//! 6.2.4).

use glam::{Vec2, Vec3};

use crate::math::warp::{sample_uniform_cone, uniform_cone_pdf};
use crate::math::Frame;

/// How far past the cone's edge, as an angle, [`Cone::pdf`] still
/// counts a direction as inside. A direction the cone drew at its very
/// edge is rounded to `f32` (about `6e-8` a component), which moved it up
/// to `1.9e-7` radians outward in a trial of 320,000 edge samples of
/// spheres' cones from `r / d = 1e-5` to `0.95`. A margin relative to the
/// bound (`1e-5` of it, as this was before) left 41 % of the edge samples
/// of a sphere at `r / d = 3e-3` outside, where the mixture would weigh
/// them as BSDF samples alone: fireflies. The shell this adds is where
/// the density is over-stated, so the light through it, about
/// `2 EDGE_ANGLE / theta_max` of the cone's, is missed: `1e-3` of it for
/// a cone of `1e-3` radians.
const EDGE_ANGLE: f32 = 5e-7;

/// The bound on `|w x axis|^2` of a cone whose `sin(theta_max) |axis|` is
/// `edge`, for `|axis| = length`, widened by [`EDGE_ANGLE`]:
/// `(edge + EDGE_ANGLE length)^2`.
fn widened_bound(edge: f32, length: f32) -> f32 {
    let widened = edge + EDGE_ANGLE * length;
    widened * widened
}

/// A cone of directions from a point, kept as what its sampling and
/// density need.
#[derive(Clone, Copy, Debug, Default)]
pub struct Cone {
    /// The axis, not necessarily unit (for a sphere: `c - p`).
    axis: Vec3,
    /// `(sin(theta_max) + EDGE_ANGLE)^2 |axis|^2`: the largest
    /// `|w x axis|^2` of a unit direction `w` counted as inside (for a
    /// sphere: `(r + EDGE_ANGLE d)^2`).
    bound: f32,
    /// `1 - cos(theta_max)`, without the cancellation of
    /// `1 - sqrt(1 - sin^2)` for a narrow cone.
    one_minus_cos_max: f32,
}

impl Cone {
    /// No directions (a placeholder in a fixed-size list).
    pub const EMPTY: Cone = Cone {
        axis: Vec3::ZERO,
        bound: 0.0,
        one_minus_cos_max: 0.0,
    };

    /// The cone of the sphere at `to_center` (from the point, squared
    /// length `d2`) of squared radius `r2`, for a point outside it
    /// (`d2 > r2`): `1 - cos(theta_max) = r^2 / (d (d + sqrt(d^2 - r^2)))`.
    pub fn of_sphere(to_center: Vec3, d2: f32, r2: f32) -> Self {
        let d = d2.sqrt();
        Cone {
            axis: to_center,
            bound: widened_bound(r2.sqrt(), d),
            one_minus_cos_max: r2 / (d * (d + (d2 - r2).sqrt())),
        }
    }

    /// The cone around the unit direction `axis` whose half-angle
    /// `theta_max`, below `pi / 2`, has the sine `sin_max` (in `(0, 1)`):
    /// `1 - cos = sin^2 / (1 + sqrt(1 - sin^2))`.
    pub fn around(axis: Vec3, sin_max: f32) -> Self {
        let sin2 = sin_max * sin_max;
        Cone {
            axis,
            bound: widened_bound(sin_max, 1.0),
            one_minus_cos_max: sin2 / (1.0 + (1.0 - sin2).sqrt()),
        }
    }

    /// The cone's solid angle, `2 pi (1 - cos(theta_max))`.
    #[cfg(test)]
    pub fn solid_angle(&self) -> f32 {
        1.0 / uniform_cone_pdf(self.one_minus_cos_max)
    }

    /// A direction (world space) uniform in the cone.
    pub fn sample(&self, u: Vec2) -> Vec3 {
        Frame::from_z(self.axis.normalize())
            .to_world(sample_uniform_cone(u, self.one_minus_cos_max))
            .normalize()
    }

    /// Density of [`Cone::sample`] for the unit direction `w` (world space).
    pub fn pdf(&self, w: Vec3) -> f32 {
        let inside = w.dot(self.axis) > 0.0 && w.cross(self.axis).length_squared() <= self.bound;
        if inside {
            uniform_cone_pdf(self.one_minus_cos_max)
        } else {
            0.0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cone_around_an_axis_holds_its_samples_with_its_density() {
        let axis = Vec3::new(0.3, -0.8, 0.2).normalize();
        // From the narrowest light image (`images::MIN_IMAGE_SINE`) up.
        for theta_max in [1e-2f32, 0.05, 0.4, 1.2] {
            let cone = Cone::around(axis, theta_max.sin());
            let solid_angle = 2.0 * std::f64::consts::PI * (1.0 - (theta_max as f64).cos());
            assert!((cone.solid_angle() as f64 / solid_angle - 1.0).abs() < 1e-4);
            // The edge too: u.x up to 1 - 1e-4.
            for i in 0..4096 {
                let u = Vec2::new(
                    1.0 - (i % 64) as f32 / 64.0 - 1e-4,
                    (i / 64) as f32 / 64.0 + 0.02,
                );
                let w = cone.sample(u);
                // Within the half-angle (by its sine: acos loses the small angles).
                assert!(w.dot(axis) > 0.0);
                assert!(w.cross(axis).length() <= theta_max.sin() * (1.0 + 1e-3) + 1e-6);
                assert!((cone.pdf(w) as f64 * solid_angle - 1.0).abs() < 1e-3);
            }
            // Just outside, and on the other side: not in the cone.
            let outside = Frame::from_z(axis).to_world(Vec3::new(
                (theta_max * 1.01).sin(),
                0.0,
                (theta_max * 1.01).cos(),
            ));
            assert_eq!(cone.pdf(outside), 0.0);
            assert_eq!(cone.pdf(-axis), 0.0);
        }
    }

    /// Samples at the very edge of cones (`u.x` just below 1) count as
    /// inside, spheres' cones and cones around an axis (light images,
    /// from the narrowest, `images::MIN_IMAGE_SINE`, up): with a margin of
    /// `1e-5` of the bound instead of [`EDGE_ANGLE`], rounding put 41 % of
    /// a small sphere's outside (`r / d = 3e-3`), and this test failed; so
    /// does the bound without its margin (checked by hand), and a cone
    /// around an axis whose bound is `(sin + EDGE_ANGLE) (sin -
    /// EDGE_ANGLE)` (checked with mutants).
    #[test]
    fn samples_at_the_edge_of_a_cone_count_as_inside() {
        use rand::Rng;
        let mut rng = crate::math::rng::sampler(3, 0);
        for i in 0..1000 {
            let axis = 10.0 * (Vec3::new(rng.gen(), rng.gen(), rng.gen()) - 0.5);
            let cone = if i % 2 == 0 {
                let r = axis.length() * (0.001 + 0.9 * rng.gen::<f32>());
                Cone::of_sphere(axis, axis.length_squared(), r * r)
            } else {
                Cone::around(axis.normalize(), 10f32.powf(-2.0 * rng.gen::<f32>()) * 0.9)
            };
            for k in 0..16 {
                let u = Vec2::new(crate::math::float::ONE_BELOW_ONE, (k as f32 + 0.5) / 16.0);
                let w = cone.sample(u);
                assert!(cone.pdf(w) > 0.0, "{cone:?}: {w} at u = {u}");
            }
        }
    }
}
