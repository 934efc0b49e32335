//! Linear RGB colours and the quantities derived from them.

/// Linear RGB radiance, irradiance or reflectance, one `f32` per channel.
pub type Rgb = glam::Vec3;

/// Luminance ("illuminance" in the course) of a linear Rec. 709 colour:
/// `Y = 0.2126 r + 0.7152 g + 0.0722 b`.
pub fn luminance(c: Rgb) -> f32 {
    0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z
}
