//! The course's area light: a one-sided rectangle
//! `center + s dim_x + t dim_y`, `s, t` in `[-1/2, 1/2]`, of area
//! `A = |dim_x| |dim_y|`, emitting radiance `L` towards the side its unit
//! normal `n` points to.
//!
//! Sampling: a point `q` uniform on the rectangle, density `1 / A` per
//! area, seen from `p` at distance `r` under the light's cosine
//! `cos_l = n . (p - q) / r`:
//!
//! ```text
//! p_w = r^2 / (A cos_l)        (per steradian at p)
//! ```
//!
//! The density of a given direction (for multiple importance sampling)
//! intersects the ray with the rectangle: `p_w` at the point it crosses,
//! 0 if it misses or arrives from behind. Power: `Phi = pi A L`.
//!
//! The rectangle is not geometry: the camera does not see it (the course
//! files place an emissive mesh there for that), but a BSDF-sampled ray
//! meets it through [`RectLight::hit_distance`], so that both strategies
//! of multiple importance sampling can find every point of it.
//!
//! The course's starter weights a sample by `r^2 / (A r cos_l)` (it takes
//! the light's cosine from the unnormalised `q - p`); with
//! [`LightConvention::Course`] each sample is `r` times brighter, as there.

use glam::{Vec2, Vec3};

use super::{LightConvention, LightSample, SurfacePoint};
use crate::intersect::Ray;
use crate::math::Rgb;

/// The longer diagonal of the parallelogram with edges `a` and `b`:
/// `max(|a + b|, |a - b|)` (a rectangle's two are equal).
pub fn longer_diagonal(a: Vec3, b: Vec3) -> f32 {
    (a + b).length().max((a - b).length())
}

/// A one-sided rectangular area light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RectLight {
    pub radiance: Rgb,
    pub center: Vec3,
    /// Unit normal of the emitting side.
    pub normal: Vec3,
    pub dim_x: Vec3,
    pub dim_y: Vec3,
    pub convention: LightConvention,
}

impl RectLight {
    /// `|dim_x x dim_y|`: the area of the parallelogram the edges span
    /// (a rectangle's `|dim_x| |dim_y|`; a sheared transform gives a
    /// parallelogram, still sampled uniformly).
    pub fn area(&self) -> f32 {
        self.dim_x.cross(self.dim_y).length()
    }

    /// The longer diagonal of the rectangle.
    pub fn diagonal(&self) -> f32 {
        longer_diagonal(self.dim_x, self.dim_y)
    }

    /// A point uniform on the rectangle, seen from `p`.
    #[doc(alias = "sample_L")]
    pub fn sample_li(&self, p: Vec3, u: Vec2) -> Option<LightSample> {
        self.sample_sided(p, u, false)
    }

    /// [`Self::sample_li`] for a rectangle that emits from its back too
    /// when `two_sided` (the catalogue's `light-from-behind` mistake).
    pub fn sample_sided(&self, p: Vec3, u: Vec2, two_sided: bool) -> Option<LightSample> {
        // A light of no area (or a NaN one) gives an infinite or NaN
        // density, which `seen_from` refuses: no sample.
        let area = self.area();
        let q = self.center + (u.x - 0.5) * self.dim_x + (u.y - 0.5) * self.dim_y;
        let point = SurfacePoint {
            q,
            normal: self.normal,
            two_sided,
            radiance: self.radiance,
            area_pdf: 1.0 / area,
        };
        let mut sample = point.seen_from(p)?;
        sample.radiance *= self.convention.area_factor(sample.distance);
        Some(sample)
    }

    /// Where the ray from `p` along the unit `wi` crosses the rectangle's
    /// emitting side: the distance, or `None`.
    pub fn crossing(&self, p: Vec3, wi: Vec3) -> Option<f32> {
        let denom = self.normal.dot(wi);
        if denom.is_nan() || denom >= 0.0 {
            return None;
        }
        let t = self.normal.dot(self.center - p) / denom;
        // Coordinates of the crossing in the edges' basis (dual basis, so
        // that a parallelogram is handled as well as a rectangle).
        let local = p + t * wi - self.center;
        let (a, b) = (self.dim_x, self.dim_y);
        let (aa, ab, bb) = (a.dot(a), a.dot(b), b.dot(b));
        let det = aa * bb - ab * ab;
        let (la, lb) = (local.dot(a), local.dot(b));
        let s_coord = (bb * la - ab * lb) / det;
        let t_coord = (aa * lb - ab * la) / det;
        let inside = s_coord.abs() <= 0.5 && t_coord.abs() <= 0.5;
        (t > 0.0 && t.is_finite() && inside).then_some(t)
    }

    /// The distance at which `ray` meets the emitting side within its
    /// interval, if it does.
    pub fn hit_distance(&self, ray: &Ray) -> Option<f32> {
        self.crossing(ray.origin, ray.dir)
            .filter(|&t| t >= ray.t_min && t <= ray.t_max)
    }

    /// Density per steradian with which [`Self::sample_li`] picks `wi` from `p`.
    pub fn pdf_li(&self, p: Vec3, wi: Vec3) -> f32 {
        // A crossing has the light's cosine `-n . wi` positive and an area
        // (`det = |dim_x x dim_y|^2` is positive, or nothing is inside).
        let Some(t) = self.crossing(p, wi) else {
            return 0.0;
        };
        t * t / (self.area() * -self.normal.dot(wi))
    }

    /// Radiance the light sends along a ray that meets it at distance `t`,
    /// as the BSDF side of multiple importance sampling counts it against
    /// light samples: the course's convention scales it as it scales
    /// samples, so that MIS under `--course-lights` gives the course's
    /// image (the camera, `-H` and BSDF sampling alone see
    /// [`Self::radiance`]).
    pub fn radiance_at(&self, t: f32) -> Rgb {
        self.radiance * self.convention.area_factor(t)
    }

    /// Radiant power, `pi A L` per channel.
    pub fn power(&self) -> Rgb {
        std::f32::consts::PI * self.area() * self.radiance
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A light at `center` emitting upwards (+Y), with edges `a` and `b`
    /// in the plane `y = center.y`.
    fn facing_up(center: Vec3, a: Vec3, b: Vec3) -> RectLight {
        RectLight {
            radiance: Rgb::splat(1.0),
            center,
            normal: Vec3::Y,
            dim_x: a,
            dim_y: b,
            convention: LightConvention::Physical,
        }
    }

    // Fails if either diagonal's `+` or `-` changes, or the longer one is
    // not the one taken: a sheared light's diagonals differ, and which is
    // longer depends on the shear's sign.
    #[test]
    fn the_diagonal_is_the_parallelograms_longer_one() {
        let a = Vec3::new(2.0, 0.0, 0.0);
        let long = 10f32.sqrt();
        let sheared = facing_up(Vec3::ZERO, a, Vec3::new(0.0, 0.0, 1.0) + Vec3::X);
        assert!((sheared.diagonal() - long).abs() < 1e-6);
        let other_way = facing_up(Vec3::ZERO, a, Vec3::new(0.0, 0.0, 1.0) - Vec3::X);
        assert!((other_way.diagonal() - long).abs() < 1e-6);
        let square = facing_up(Vec3::ZERO, Vec3::X, Vec3::Z);
        assert!((square.diagonal() - 2f32.sqrt()).abs() < 1e-6);
        assert!((sheared.area() - 2.0).abs() < 1e-6);
    }

    // `u` runs along the edges: `q = center + (u.x - 1/2) dim_x + (u.y -
    // 1/2) dim_y`, so `u = (0, 0)` is the corner `center - (dim_x + dim_y)
    // / 2` (a sign flipped in either term would sample the same
    // distribution, mirrored: only this catches it). A light without area
    // gives no sample.
    #[test]
    fn the_sample_point_runs_along_the_edges_from_the_lower_corner() {
        let light = facing_up(Vec3::new(0.0, -1.0, 0.0), Vec3::X * 2.0, Vec3::Z);
        for (u, expected) in [
            (Vec2::ZERO, Vec3::new(-1.0, -1.0, -0.5)),
            (Vec2::new(1.0, 0.0), Vec3::new(1.0, -1.0, -0.5)),
            (Vec2::new(0.25, 1.0), Vec3::new(-0.5, -1.0, 0.5)),
        ] {
            let s = light.sample_li(Vec3::ZERO, u).unwrap();
            let q = s.wi * s.distance;
            assert!((q - expected).length() < 1e-6, "{u}: {q}");
        }
        let flat = facing_up(Vec3::NEG_Y, Vec3::X, Vec3::X * 2.0);
        assert_eq!(flat.sample_li(Vec3::ZERO, Vec2::splat(0.5)), None);
    }

    // A ray from one unit above the light's centre meets it at `t = 1`
    // exactly: the interval's ends count (`>=` and `<=`), and past them
    // it misses. Fails with either comparison turned or made strict.
    #[test]
    fn a_ray_meets_the_light_within_its_interval_ends_included() {
        let light = facing_up(Vec3::ZERO, Vec3::X, Vec3::Z);
        let ray = |t_min: f32, t_max: f32| Ray {
            origin: Vec3::Y,
            dir: Vec3::NEG_Y,
            t_min,
            t_max,
        };
        assert_eq!(light.hit_distance(&ray(0.0, f32::INFINITY)), Some(1.0));
        assert_eq!(light.hit_distance(&ray(1.0, 2.0)), Some(1.0));
        assert_eq!(light.hit_distance(&ray(0.0, 1.0)), Some(1.0));
        assert_eq!(light.hit_distance(&ray(1.001, 2.0)), None);
        assert_eq!(light.hit_distance(&ray(0.0, 0.999)), None);
        // From below, the light's back: nothing. From a point on the light
        // itself (`t = 0`): nothing either.
        let below = Ray::new(Vec3::NEG_Y, Vec3::Y);
        assert_eq!(light.hit_distance(&below), None);
        assert_eq!(light.crossing(Vec3::new(0.1, 0.0, 0.2), Vec3::NEG_Y), None);
    }

    // Where the ray crosses the plane decides: inside the parallelogram,
    // not merely inside its bounding rectangle. Fails if a cross term of
    // the dual basis (`ab`) changes, which a rectangle's orthogonal edges
    // cannot show.
    #[test]
    fn a_sheared_light_is_met_only_inside_its_parallelogram() {
        let light = facing_up(Vec3::ZERO, Vec3::X * 2.0, Vec3::new(1.0, 0.0, 1.0));
        let from = Vec3::new(0.0, 1.0, 0.0);
        let towards = |x: f32, z: f32| (Vec3::new(x, 0.0, z) - from).normalize();
        // Points `s a + t b` for `|s|, |t| < 1/2` and just outside.
        for (s, t, inside) in [
            (0.45, 0.45, true),
            (-0.45, 0.45, true),
            (0.45, -0.45, true),
            (0.0, 0.0, true),
            (0.55, 0.0, false),
            (0.0, 0.55, false),
            (-0.3, -0.55, false),
        ] {
            let q = s * light.dim_x + t * light.dim_y;
            let crossing = light.crossing(from, towards(q.x, q.z));
            assert_eq!(crossing.is_some(), inside, "s {s}, t {t}");
            if let Some(distance) = crossing {
                assert!(
                    (distance - (q - from).length()).abs() < 1e-5,
                    "s {s}, t {t}"
                );
            }
        }
        // Inside the bounding box of the parallelogram, outside it: a
        // rectangle test with the edges' lengths would take it.
        let q = Vec3::new(-1.4, 0.0, 0.45);
        assert!(light.crossing(from, towards(q.x, q.z)).is_none());
    }
}
