//! A ray-surface hit, and the one way to leave a surface: [`Hit::spawn_ray`].
//!
//! Leaving a surface: the computed hit point `p` is off the true surface by
//! at most `p_error` per axis. Moving the origin along the geometric normal
//! by `d = |n_g| . p_error` (then rounding away from the surface) puts it
//! on the correct side whatever the rounding, so the new ray cannot hit the
//! surface it starts on (pbrt-v4, section 6.8.6). The offset scales with
//! the magnitude of the coordinates, so it works from tiny to huge scenes.

use glam::Vec3;

use crate::math::float::next_float_towards;
use crate::scene::MaterialId;

use super::Ray;

/// Shadow rays stop this fraction short of their target, so a point sampled
/// on a light does not occlude itself.
pub const SHADOW_EPSILON: f32 = 1e-4;

/// Where and how a ray met a surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// Ray parameter of the hit, scene units.
    pub t: f32,
    /// The hit point, world space.
    pub p: Vec3,
    /// Per-axis bound on the absolute rounding error of `p`.
    pub p_error: Vec3,
    /// Shading normal: for triangles the barycentric interpolation of the
    /// course's vertex normals, for spheres the outward normal. Unit length.
    /// Not flipped towards the ray.
    pub n: Vec3,
    /// Geometric normal of the surface (triangle winding / sphere outward), unit length.
    pub ng: Vec3,
    /// The surface's material.
    pub material: MaterialId,
    /// Primitive id: triangle index, or number of triangles + sphere index.
    pub primitive: u32,
}

impl Hit {
    /// The hit point pushed off the surface to the side `w` points to.
    pub fn offset_origin(&self, w: Vec3) -> Vec3 {
        let d = self.ng.abs().dot(self.p_error);
        let offset = if w.dot(self.ng) < 0.0 {
            -d * self.ng
        } else {
            d * self.ng
        };
        let po = self.p + offset;
        // Round away from the surface, so the sum cannot fall back onto it.
        Vec3::new(
            next_float_towards(po.x, offset.x),
            next_float_towards(po.y, offset.y),
            next_float_towards(po.z, offset.z),
        )
    }

    /// A ray leaving the surface in the unit direction `wi`.
    #[doc(alias = "spawn_ray_from")]
    pub fn spawn_ray(&self, wi: Vec3) -> Ray {
        Ray::new(self.offset_origin(wi), wi)
    }

    /// The shadow ray towards a light sample in the unit direction `wi` at
    /// `distance` ([`Self::spawn_ray_to`] the sample's point), or along
    /// `wi` for ever when the light is at infinity.
    pub fn spawn_shadow_ray(&self, wi: Vec3, distance: f32) -> Ray {
        if distance.is_finite() {
            self.spawn_ray_to(self.p + distance * wi)
        } else {
            self.spawn_ray(wi)
        }
    }

    /// A (shadow) ray from the surface towards `target`, stopping just short of it.
    pub fn spawn_ray_to(&self, target: Vec3) -> Ray {
        let origin = self.offset_origin(target - self.p);
        let to_target = target - origin;
        let distance = to_target.length();
        Ray {
            origin,
            dir: to_target / distance,
            t_min: 0.0,
            t_max: distance * (1.0 - SHADOW_EPSILON),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A hit at `(1, 2, 3)` on a surface facing `+z`, its point known to a
    /// millionth.
    fn hit() -> Hit {
        Hit {
            t: 1.0,
            p: Vec3::new(1.0, 2.0, 3.0),
            p_error: Vec3::splat(1e-6),
            n: Vec3::Z,
            ng: Vec3::Z,
            material: 0,
            primitive: 0,
        }
    }

    /// A shadow ray towards a light sample `distance` away along `wi` runs
    /// along `wi` and stops `SHADOW_EPSILON` short of the sample; towards a
    /// light at infinity it never stops. Checked by hand: the target
    /// `p + distance wi` with its `+` made `-` or `*`, or its `*` made `+`
    /// or `/`, fails here, and so does `spawn_ray_to`'s stop
    /// `distance * (1 - SHADOW_EPSILON)` made `distance / (1 - ...)` or
    /// `distance * (1 + ...)`, which reaches past the sample (the
    /// direct-lighting tests, which the mutation run of `intersect` does not
    /// include, see these too).
    #[test]
    fn a_shadow_ray_runs_along_wi_and_stops_short_of_the_sample() {
        let hit = hit();
        let wi = Vec3::new(0.6, 0.0, 0.8);
        let ray = hit.spawn_shadow_ray(wi, 5.0);
        assert!((ray.dir - wi).abs().max_element() < 1e-6, "{ray:?}");
        let stop = 5.0 * (1.0 - SHADOW_EPSILON);
        assert!((ray.t_max - stop).abs() < 1e-5, "{ray:?}");
        assert!((ray.origin - hit.p).abs().max_element() < 1e-5, "{ray:?}");
        let to_infinity = hit.spawn_shadow_ray(wi, f32::INFINITY);
        assert_eq!(to_infinity.dir, wi);
        assert_eq!(to_infinity.t_max, f32::INFINITY);
    }
}
