//! What a light sample is, and the one place where an area density
//! becomes a density per steradian.

use glam::Vec3;

use crate::math::Rgb;

/// How a light sample was drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightPdf {
    /// From a delta distribution (point or directional light): the
    /// estimator uses the radiance without dividing by a density, and no
    /// other strategy can find the same light.
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
    /// density becomes a solid-angle one,
    ///
    /// ```text
    /// p_w = p_A r^2 / cos_e
    /// ```
    ///
    /// with `r = |q - p|` and `cos_e` the emitter's cosine towards `p`
    /// (`dA cos_e / r^2` is the solid angle `dA` subtends; pbrt-v4,
    /// section 4.2.3). `None` at zero distance or when `p` sees the back of
    /// a one-sided emitter.
    pub fn seen_from(&self, p: Vec3) -> Option<LightSample> {
        let to_light = self.q - p;
        let distance_squared = to_light.length_squared();
        let distance = distance_squared.sqrt();
        // At zero distance `wi` is NaN, and so is the density, which
        // `solid_angle_pdf` refuses.
        let wi = to_light / distance;
        let pdf = self.solid_angle_pdf(wi, distance_squared)?;
        Some(LightSample {
            radiance: self.radiance,
            wi,
            distance,
            pdf: LightPdf::SolidAngle(pdf),
        })
    }

    /// `p_A r^2 / cos_e` for the unit direction `wi` from a point to `q` at
    /// squared distance `distance_squared`, or `None` where nothing is
    /// emitted towards that point.
    pub fn solid_angle_pdf(&self, wi: Vec3, distance_squared: f32) -> Option<f32> {
        let facing = -self.normal.dot(wi);
        let cos_emitter = if self.two_sided { facing.abs() } else { facing };
        // The back of a one-sided emitter (cosine below 0) gives a
        // negative density, a grazing view (cosine 0) an infinite one.
        let pdf = self.area_pdf * distance_squared / cos_emitter;
        (pdf > 0.0 && pdf.is_finite()).then_some(pdf)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A point at `(0, 2, 0)` emitting downwards, chosen with density 1/4
    /// per unit area.
    fn lamp(two_sided: bool) -> SurfacePoint {
        SurfacePoint {
            q: Vec3::new(0.0, 2.0, 0.0),
            normal: Vec3::NEG_Y,
            two_sided,
            radiance: Rgb::new(1.0, 2.0, 3.0),
            area_pdf: 0.25,
        }
    }

    fn solid_angle(sample: LightSample) -> f32 {
        match sample.pdf {
            LightPdf::SolidAngle(pdf) => pdf,
            LightPdf::Delta => panic!("a surface point is no delta light"),
        }
    }

    // `p_A r^2 / cos_e` by numbers: straight below (r^2 = 4, cos 1) and
    // at 45 degrees (r^2 = 8, cos 1/sqrt(2)). Fails if a factor is
    // dropped, inverted or added to, or the cosine's sign is lost.
    #[test]
    fn an_area_density_becomes_p_a_r2_over_cos_per_steradian() {
        let below = lamp(false).seen_from(Vec3::ZERO).unwrap();
        assert_eq!(below.wi, Vec3::Y);
        assert_eq!(below.distance, 2.0);
        assert_eq!(below.radiance, Rgb::new(1.0, 2.0, 3.0));
        assert!((solid_angle(below) - 1.0).abs() < 1e-6);
        let oblique = lamp(false).seen_from(Vec3::new(2.0, 0.0, 0.0)).unwrap();
        assert!((oblique.distance - 8f32.sqrt()).abs() < 1e-6);
        assert!((solid_angle(oblique) - 2.0 * 2f32.sqrt()).abs() < 1e-5);
    }

    // From above, the one-sided lamp's back shows nothing, the two-sided
    // one's the same density as from below. At the point itself, and
    // along the emitting plane (cos 0: an infinite density), there is no
    // sample. Fails if `abs` goes, or a guard is turned or dropped.
    #[test]
    fn a_back_a_point_on_the_light_and_a_grazing_view_give_no_sample() {
        let above = Vec3::new(0.0, 4.0, 0.0);
        assert_eq!(lamp(false).seen_from(above), None);
        let back = lamp(true).seen_from(above).unwrap();
        assert!((solid_angle(back) - 1.0).abs() < 1e-6);
        assert_eq!(back.wi, Vec3::NEG_Y);
        assert_eq!(lamp(true).seen_from(lamp(true).q), None);
        assert_eq!(lamp(true).seen_from(Vec3::new(3.0, 2.0, 0.0)), None);
        let nowhere = SurfacePoint {
            area_pdf: 0.0,
            ..lamp(true)
        };
        assert_eq!(nowhere.seen_from(Vec3::ZERO), None);
    }
}
