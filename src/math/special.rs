//! Special functions the samplers need that the `libm` crate lacks.
//!
//! The inverse error function, `erfinv(y) = x` with `erf(x) = y`, turns a
//! uniform number into a Gaussian one, `x = erfinv(2 u - 1)` having density
//! `exp(-x^2) / sqrt(pi)`: the Beckmann distribution's slopes are drawn
//! this way ([`crate::materials::beckmann`]).

use std::f64::consts::FRAC_2_SQRT_PI;

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
