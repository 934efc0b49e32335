//! Perfect specular directions in the local frame (normal on +Z, the
//! outgoing direction `wo` on the +Z side).
//!
//! - Reflection: `wi = 2 (wo . n) n - wo = (-wo.x, -wo.y, wo.z)`.
//! - Refraction by Snell's law into a side of relative index `eta`
//!   (the far side's index over the near side's): `sin_t = sin_i / eta`,
//!   `wi = -wo / eta + (cos_i / eta - cos_t) n`, which has `wi.z = -cos_t`
//!   (pbrt-v4, section 9.3.2).
//!
//! Delta lobes carry their weight in the sample: a BSDF that reflects the
//! fraction `R` of the light into one direction has `f = R / |cos_i|` there,
//! so that every estimator keeps the textbook form `f |cos| / pdf`
//! (pbrt-v4's convention, section 9.2.3).

use glam::Vec3;

use super::fresnel::refracted_cos;

/// The mirror direction of `wo` about the normal `+Z`.
pub fn reflect(wo: Vec3) -> Vec3 {
    Vec3::new(-wo.x, -wo.y, wo.z)
}

/// The direction refracted from `wo` (with `wo.z >= 0`) into the side of
/// relative index `eta`, below the surface; `None` under total internal
/// reflection.
pub fn refract(wo: Vec3, eta: f32) -> Option<Vec3> {
    let cos_i = wo.z.clamp(0.0, 1.0);
    let cos_t = refracted_cos(cos_i, eta)?;
    Some(Vec3::new(-wo.x / eta, -wo.y / eta, -cos_t))
}

#[cfg(test)]
mod tests {
    use super::*;

    // `wo` has both `x` and `y`, so that a slip in either (`-wo.y / eta`
    // made `-wo.y % eta`, missed while `wo.y` was 0) leaves the plane of
    // incidence or the unit sphere.
    #[test]
    fn refraction_obeys_snells_law_in_the_plane_of_incidence_and_stays_unit() {
        let wo = Vec3::new(0.48, 0.36, 0.8);
        for eta in [1.5f32, 1.0, 1.0 / 1.2] {
            let wi = refract(wo, eta).unwrap();
            assert!((wi.length() - 1.0).abs() < 1e-6);
            let sin_i = (1.0 - wo.z * wo.z).sqrt();
            let sin_t = (1.0 - wi.z * wi.z).sqrt();
            assert!((sin_i - eta * sin_t).abs() < 1e-6, "{eta}");
            // Opposite azimuth: `wi.xy` is a positive multiple of `-wo.xy`.
            assert!(wi.z < 0.0 && wi.x < 0.0 && wi.y < 0.0, "{eta}: {wi}");
            assert!((wi.x * wo.y - wi.y * wo.x).abs() < 1e-6, "{eta}: {wi}");
        }
        assert_eq!(refract(wo, 1.0).unwrap(), -wo, "index 1 goes straight on");
        assert!(refract(Vec3::new(0.9, 0.0, 0.436), 1.0 / 1.5).is_none());
        assert_eq!(reflect(wo), Vec3::new(-0.48, -0.36, 0.8));
    }
}
