//! Special functions the samplers need that the `libm` crate lacks.
//!
//! The inverse error function, `erfinv(y) = x` with `erf(x) = y`, turns a
//! uniform number into a Gaussian one, `x = erfinv(2 u - 1)` having density
//! `exp(-x^2) / sqrt(pi)`: the Beckmann distribution's slopes are drawn
//! this way ([`crate::materials::beckmann`]).

use std::f64::consts::FRAC_2_SQRT_PI;

/// `x.floor()`, exactly, without a call: on baseline x86-64 (no SSE4.1
/// `roundss`) `f32::floor` is a call into the C library, and the map
/// lookup makes two a ray (`perf`: 1.3 % of the glass bunny under a sun).
/// Floats of magnitude `2^23` or more are integers already, and a NaN
/// stays a NaN; below that, truncation towards zero is one step too high
/// for a negative non-integer.
#[inline(always)]
pub fn floor(x: f32) -> f32 {
    if x.abs() >= 8_388_608.0 || x.is_nan() {
        return x;
    }
    let t = x as i32 as f32;
    if t > x {
        t - 1.0
    } else {
        // The sign keeps -0.0 as the library gives it.
        t.copysign(x)
    }
}

/// `atan(t)` for `t` in `[0, 1]` (Abramowitz and Stegun 1964, formula
/// 4.4.49: `atan t = t (1 + a2 t^2 + ... + a16 t^16) + e`, `|e| <= 2e-8`).
fn atan_unit(t: f32) -> f32 {
    let t2 = t * t;
    let p = [
        0.002_866_225_7,
        -0.016_165_737,
        0.042_909_614,
        -0.075_289_64,
        0.106_562_64,
        -0.142_089,
        0.199_935_51,
        -0.333_331_45,
        1.0,
    ]
    .iter()
    .fold(0.0, |p, &c| c + p * t2);
    t * p
}

/// The angle of the point `(x, y)` from the +x axis, in `[-pi, pi]`, as
/// `f32::atan2` gives it to within a few units in the last place (`2e-7`
/// radians measured, `the_polynomial_atan2_matches_the_library`); 0 at
/// the origin. The argument is reduced to `[0, 1]` by
/// `atan(y/x) = pi/2 - atan(x/y)` and the quadrant's signs.
pub fn atan2(y: f32, x: f32) -> f32 {
    use std::f32::consts::{FRAC_PI_2, PI};
    let (ax, ay) = (x.abs(), y.abs());
    let (small, large) = if ay > ax { (ax, ay) } else { (ay, ax) };
    if large.is_nan() {
        return f32::NAN;
    }
    if large == 0.0 {
        // The origin (the library gives +-0 or +-pi by the zeros' signs;
        // a direction is never there).
        return 0.0;
    }
    let mut a = atan_unit(small / large);
    if ay > ax {
        a = FRAC_PI_2 - a;
    }
    if x < 0.0 {
        a = PI - a;
    }
    if y < 0.0 {
        -a
    } else {
        a
    }
}

/// The inverse error function on `(-1, 1)`, clamped to `|x| <= 6` at the
/// ends: [`erfinv_estimate`] refined by one Newton step on `libm::erf` to
/// double precision.
pub fn erfinv(y: f64) -> f64 {
    if y <= -1.0 {
        return -6.0;
    }
    if y >= 1.0 {
        return 6.0;
    }
    let mut x = erfinv_estimate(y);
    // The polynomial is good to about 1e-7; Newton's method squares the
    // error, so one step reaches double precision.
    let slope = FRAC_2_SQRT_PI * (-x * x).exp();
    if slope > 0.0 {
        x -= (libm::erf(x) - y) / slope;
    }
    x.clamp(-6.0, 6.0)
}

/// The inverse error function to about `1e-7` relative, clamped to
/// `|x| <= 6`: Giles 2010, "Approximating the erfinv function" (GPU
/// Computing Gems), single-precision polynomials, here evaluated in `f64`.
/// A starting point for callers that refine it themselves.
pub fn erfinv_estimate(y: f64) -> f64 {
    if y <= -1.0 {
        return -6.0;
    }
    if y >= 1.0 {
        return 6.0;
    }
    let w = -((1.0 - y) * (1.0 + y)).ln();
    let p = if w < 5.0 {
        let w = w - 2.5;
        [
            2.810_226_36e-08,
            3.432_739_39e-07,
            -3.523_387_7e-06,
            -4.391_506_54e-06,
            2.185_808_7e-04,
            -1.253_725_03e-03,
            -4.177_681_64e-03,
            2.466_407_27e-01,
            1.501_409_41,
        ]
        .iter()
        .fold(0.0, |p, c| c + p * w)
    } else {
        let w = w.sqrt() - 3.0;
        [
            -2.002_142_57e-04,
            1.009_505_58e-04,
            1.349_343_22e-03,
            -3.673_428_44e-03,
            5.739_507_73e-03,
            -7.622_461_3e-03,
            9.438_870_47e-03,
            1.001_674_06,
            2.832_976_82,
        ]
        .iter()
        .fold(0.0, |p, c| c + p * w)
    };
    (p * y).clamp(-6.0, 6.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn erfinv_inverts_erf() {
        for i in -1000..=1000 {
            let y = i as f64 / 1000.5;
            let x = erfinv(y);
            assert!((libm::erf(x) - y).abs() < 1e-14, "{y}: {x}");
        }
        assert_eq!(erfinv(-1.0), -6.0);
        assert!(erfinv(1.0 - 1e-12) > 4.9);
    }

    /// Bit for bit the library's floor, around every integer step, at the
    /// ends of the fast range and beyond it, for zeros, infinities and NaN.
    #[test]
    fn the_fast_floor_is_the_library_floor() {
        use crate::math::float::{next_float_down, next_float_up};
        let mut values = vec![
            0.0f32,
            -0.0,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::MAX,
            f32::MIN,
        ];
        for k in -1000..=1000 {
            let x = k as f32 * 0.37;
            values.extend([
                x,
                next_float_up(x),
                next_float_down(x),
                k as f32,
                next_float_down(k as f32),
            ]);
        }
        for big in [8_388_607.5f32, 8_388_608.0, 8_388_609.0, 1e10, 3e9] {
            values.extend([big, -big, next_float_down(big), -next_float_down(big)]);
        }
        for x in values {
            assert_eq!(floor(x).to_bits(), x.floor().to_bits(), "floor({x})");
        }
        assert!(floor(f32::NAN).is_nan());
    }

    /// Against `f64::atan2` on 100,000 angles around the circle at radii
    /// from `1e-3` to `1e3`, the axes and the diagonals: within `3e-7`
    /// radians (half a unit in the last place of `pi` is `1.2e-7`). A
    /// wrong coefficient, quadrant or reduction fails by far more.
    #[test]
    fn the_polynomial_atan2_matches_the_library() {
        let mut worst = 0.0f64;
        let mut check = |y: f32, x: f32| {
            let exact = (y as f64).atan2(x as f64);
            let error = (atan2(y, x) as f64 - exact).abs();
            // -pi and pi are the same angle (a zero y's sign decides).
            let error = error.min((error - 2.0 * std::f64::consts::PI).abs());
            assert!(
                error <= 3e-7,
                "atan2({y}, {x}) = {} against {exact}",
                atan2(y, x)
            );
            worst = worst.max(error);
        };
        for k in 0..100_000 {
            let angle = (k as f64 + 0.5) / 100_000.0 * 2.0 * std::f64::consts::PI;
            let r = 10f64.powf((k % 7) as f64 - 3.0);
            check((r * angle.sin()) as f32, (r * angle.cos()) as f32);
        }
        for (y, x) in [
            (1.0, 0.0),
            (0.0, 1.0),
            (-1.0, 0.0),
            (0.0, -1.0),
            (1.0, 1.0),
            (-2.0, -2.0),
        ] {
            check(y, x);
        }
        assert!(worst > 0.0, "compared against something");
        assert_eq!(atan2(0.0, 0.0), 0.0);
        assert!(atan2(f32::NAN, 1.0).is_nan());
    }

    #[test]
    fn erfinv_estimate_is_within_its_stated_accuracy() {
        for i in -1000..=1000 {
            let y = i as f64 / 1000.5;
            let (estimate, exact) = (erfinv_estimate(y), erfinv(y));
            assert!(
                (estimate - exact).abs() <= 3e-7 * exact.abs().max(1e-3),
                "{y}: {estimate} vs {exact}"
            );
        }
    }
}
