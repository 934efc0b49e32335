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
        if distance.is_nan() || distance <= 0.0 {
            return None;
        }
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
        let pdf = self.area_pdf * distance_squared / cos_emitter;
        (cos_emitter > 0.0 && pdf > 0.0 && pdf.is_finite()).then_some(pdf)
    }
}
