//! Floating-point helpers for robust geometry (pbrt-v4, section 6.8).

use glam::Vec3;

/// Half the distance between 1 and the next `f32`: the unit roundoff u.
pub const MACHINE_EPSILON: f32 = f32::EPSILON * 0.5;

/// The largest `f32` below 1, where a uniform number stretched back to
/// `[0, 1)` (after choosing a branch by it) is clamped.
pub const ONE_BELOW_ONE: f32 = 1.0 - MACHINE_EPSILON;

/// Conservative bound gamma(n) = n u / (1 - n u) on the relative error of
/// `n` chained floating-point operations (pbrt-v4, eq. 6.23).
pub const fn gamma(n: i32) -> f32 {
    (n as f32 * MACHINE_EPSILON) / (1.0 - n as f32 * MACHINE_EPSILON)
}

/// The smallest `f32` greater than `v` (identity for +inf and NaN).
pub fn next_float_up(v: f32) -> f32 {
    if v.is_infinite() && v > 0.0 || v.is_nan() {
        return v;
    }
    let v = if v == -0.0 { 0.0 } else { v };
    let bits = v.to_bits();
    let bits = if v >= 0.0 { bits + 1 } else { bits - 1 };
    f32::from_bits(bits)
}

/// The largest `f32` smaller than `v` (identity for -inf and NaN).
pub fn next_float_down(v: f32) -> f32 {
    if v.is_infinite() && v < 0.0 || v.is_nan() {
        return v;
    }
    let v = if v == 0.0 { -0.0 } else { v };
    let bits = v.to_bits();
    let bits = if v > 0.0 { bits - 1 } else { bits + 1 };
    f32::from_bits(bits)
}

/// `v` moved one `f32` away from zero-offset towards the sign of
/// `direction`: [`next_float_up`] for `direction > 0`, [`next_float_down`]
/// for `direction < 0`, `v` itself for `direction == 0`. For finite `v`,
/// without branches on the sign of `v` (the hot path of spawning rays):
/// with `s = ±1`, the next float towards `s` is `s * next_float_up(s v)`,
/// and on the bits of a non-negative-signed float stepping up adds 1, on a
/// negative one subtracts 1 (`-0` is made `+0` first by adding `0`).
#[inline(always)]
pub fn next_float_towards(v: f32, direction: f32) -> f32 {
    let s = 1.0f32.copysign(direction);
    let bits = (s * v + 0.0).to_bits() as i32;
    let up = f32::from_bits(bits.wrapping_add((bits >> 31) | 1) as u32);
    if direction == 0.0 {
        v
    } else {
        s * up
    }
}

/// The unit vector along `a x b`, or `None` when the cross product is zero
/// (parallel or zero vectors) or not finite. Where its squared length falls
/// below `f32::MIN_POSITIVE` (a triangle's edges shorter than about
/// `1e-10`) the squared length is subnormal and has lost its digits, so
/// glam's `normalize` would return a vector up to 1 % too long, or none;
/// there the cross product is first divided by its largest component.
/// Elsewhere the result is `normalize`'s, bit for bit.
pub fn unit_cross(a: Vec3, b: Vec3) -> Option<Vec3> {
    let c = a.cross(b);
    let length2 = c.length_squared();
    if length2 >= f32::MIN_POSITIVE && length2.is_finite() {
        return Some(c.normalize());
    }
    let largest = c.abs().max_element();
    (largest > 0.0 && largest.is_finite()).then(|| (c / largest).normalize())
}

/// `value` as a message shows it: `1e30` and `2e-7` rather than dozens of
/// digits, `0.25` and `1500` as they are, `NaN` and `inf` by name.
pub fn readable(value: f32) -> String {
    if value.is_finite() && value != 0.0 && !(1e-4..1e6).contains(&value.abs()) {
        format!("{value:e}")
    } else {
        format!("{value}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn next_float_towards_agrees_with_up_and_down() {
        let values = [-2.5f32, -0.0, 0.0, 1e-30, -1e-38, 1.0, 3.0e7, -7.25e5];
        for v in values {
            assert_eq!(
                next_float_towards(v, 0.5).to_bits(),
                next_float_up(v).to_bits()
            );
            assert_eq!(
                next_float_towards(v, -2.0).to_bits(),
                next_float_down(v).to_bits()
            );
            assert_eq!(next_float_towards(v, 0.0).to_bits(), v.to_bits());
        }
    }

    #[test]
    fn next_float_moves_by_one_ulp() {
        for v in [-2.5f32, -0.0, 0.0, 1e-30, 1.0, 3.0e7] {
            assert!(next_float_up(v) > v);
            assert!(next_float_down(v) < v);
            assert_eq!(
                next_float_down(next_float_up(v)),
                if v == 0.0 { 0.0 } else { v }
            );
        }
    }
    /// A cross product of tiny edges still gives a unit vector: at `1e-11`
    /// its squared length is subnormal and glam's `normalize` alone returns
    /// one about 1 % too long (checked: with `unit_cross` made
    /// `a.cross(b).try_normalize()`, this fails at `1e-10`). At ordinary
    /// sizes the result is `normalize`'s; parallel edges have none.
    #[test]
    fn unit_cross_is_unit_from_tiny_to_ordinary_edges() {
        for side in [1.0f32, 1e-5, 1e-10, 1e-11, 1e-13, 1e-15, 1e-18] {
            let (a, b) = (Vec3::new(side, 0.0, 0.0), Vec3::new(0.0, side, 0.0));
            assert_eq!(unit_cross(a, b), Some(Vec3::Z), "side {side}");
            assert_eq!(unit_cross(b, a), Some(-Vec3::Z), "side {side}");
        }
        let (a, b) = (Vec3::new(0.3, -1.2, 2.0), Vec3::new(4.0, 0.5, -0.7));
        assert_eq!(unit_cross(a, b), Some(a.cross(b).normalize()));
        let tilted = unit_cross(a * 1e-12, b * 1e-12).expect("tiny but not parallel");
        assert!(
            (tilted - a.cross(b).normalize()).length() < 1e-6,
            "{tilted}"
        );
        assert_eq!(unit_cross(a, 2.0 * a), None);
        assert_eq!(unit_cross(Vec3::ZERO, b), None);
        assert_eq!(unit_cross(a * 1e30, b * 1e30), None);
    }
}
