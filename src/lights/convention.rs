//! How light samples are weighted: correctly, or as the course's starter
//! code does (`--course-lights`), to compare with the course's images.
//!
//! The convention lives inside each light's sample, so every estimator
//! that uses the sample (light sampling alone or with multiple importance
//! sampling) sees the same value.

/// The weighting of area and point light samples.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LightConvention {
    /// Area lights with the solid-angle pdf `r^2 / (A cos_l)`, point lights
    /// falling off as `1 / r^2`.
    #[default]
    Physical,
    /// The course's starter (`AreaLight::sample_L`, `PointLight::sample_L`):
    /// its area light takes the light's cosine from the unnormalised vector
    /// `q - p`, so its pdf is `r^2 / (A r cos_l)` and each sample is `r`
    /// times too bright; its point light returns the intensity without
    /// `1 / r^2`, so `r^2` times too bright.
    Course,
}

impl LightConvention {
    /// Factor on an area light's sample taken at distance `r`.
    pub fn area_factor(self, r: f32) -> f32 {
        match self {
            LightConvention::Physical => 1.0,
            LightConvention::Course => r,
        }
    }

    /// Factor on a point light's sample taken at distance `r`.
    pub fn point_factor(self, r: f32) -> f32 {
        match self {
            LightConvention::Physical => 1.0,
            LightConvention::Course => r * r,
        }
    }
}
