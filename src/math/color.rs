//! Linear RGB colours and the quantities derived from them.

/// Linear RGB radiance, irradiance or reflectance, one `f32` per channel.
pub type Rgb = glam::Vec3;

/// The largest radiance (or intensity, or environment texel) a scene may
/// give, per channel. A render multiplies radiance by throughputs and
/// `1/pdf` factors and sums it over samples; keeping it below `1e15`
/// leaves 23 orders of magnitude before `f32::MAX` (3.4e38), where a
/// pixel would overflow to infinity. Real scenes stay far below: a sun
/// texel of a photographed sky is about `1e5`.
pub const MAX_RADIANCE: f32 = 1e15;

/// Luminance ("illuminance" in the course) of a linear Rec. 709 colour:
/// `Y = 0.2126 r + 0.7152 g + 0.0722 b`.
pub fn luminance(c: Rgb) -> f32 {
    0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z
}

/// The ratio maps' diverging colour for `log2(ratio) / 2` in `[-1, 1]`:
/// blue (a quarter) through white (equal) to red (four times); values
/// beyond the ends take the ends' colours.
pub fn ratio_colour(t: f32) -> Rgb {
    let t = t.clamp(-1.0, 1.0);
    if t < 0.0 {
        Rgb::new(1.0 + t, 1.0 + t, 1.0)
    } else {
        Rgb::new(1.0, 1.0 - t, 1.0 - t)
    }
}
