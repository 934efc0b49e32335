//! The Beckmann microfacet distribution (isotropic, roughness `alpha`) in
//! the local frame (macro normal on +Z): its normal distribution `D`, the
//! Smith masking function, and two ways to sample a microfacet normal `h`.
//!
//! Normal distribution (Walter et al. 2007, "Microfacet Models for
//! Refraction through Rough Surfaces", eq. 25), normalised so that
//! `integral D(h) cos(theta_h) dh = 1` over the hemisphere:
//!
//! ```text
//! D(h) = exp(-tan^2(theta_h) / alpha^2) / (pi alpha^2 cos^4(theta_h))
//! ```
//!
//! Smith masking, exact form for Beckmann (Heitz 2014, "Understanding the
//! Masking-Shadowing Function in Microfacet-Based BRDFs", section 5.1,
//! eq. 72 and nearby), with `a = 1 / (alpha tan(theta))`:
//!
//! ```text
//! Lambda(w) = (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi))
//! G1(w)     = 1 / (1 + Lambda(w))
//! G(wo, wi) = 1 / (1 + Lambda(wo) + Lambda(wi))   (height-correlated)
//! ```
//!
//! We use this exact `Lambda` (with `erf` from the `libm` crate, evaluated
//! as `(exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2` to avoid cancellation) and
//! the height-correlated `G`, which Heitz 2014 (section 6) shows is more
//! accurate than the separable `G1(wo) G1(wi)`; no rational approximation
//! (Walter 2007, eq. 27, is one), so nothing here needs testing against an
//! approximation. The course handout's own `G1` formula is easy to mistype
//! and a known source of errors; the tests here check `Lambda` by its
//! defining property instead (Heitz 2014, eq. 9 with eq. 17): the projected
//! area of the visible microfacets equals the projected macro area,
//! `integral max(0, w.h) D(h) dh = w.z (1 + Lambda(w))`.
//!
//! Sampling `h`:
//!
//! - From `D(h) cos(theta_h)` (Walter 2007, eq. 28):
//!   `tan^2(theta_h) = -alpha^2 ln(1 - u1)`, `phi_h = 2 pi u2`; density
//!   `D(h) cos(theta_h)` per steradian of `h`.
//! - From the distribution of normals visible from `wo` (Heitz and d'Eon
//!   2014, "Importance Sampling Microfacet-Based BSDFs using the
//!   Distribution of Visible Normals"), density
//!   `D_wo(h) = G1(wo) max(0, wo.h) D(h) / wo.z`. Beckmann is invariant under
//!   stretching, so `wo` is stretched to the `alpha = 1` configuration, a
//!   microfacet slope is sampled there, and the slope is rotated back to
//!   `wo`'s azimuth and unstretched (the steps pbrt-v3 describes in its
//!   section 8.4.3). With `wo` at polar angle `theta` in the `xz` plane and
//!   slopes `(x, y)` of the normal `(-x, -y, 1)`, the visible slopes of the
//!   `alpha = 1` surface have density `G1 max(0, 1 - x tan(theta))
//!   exp(-x^2 - y^2) / pi`: `y` is independent of `x` with density
//!   `exp(-y^2) / sqrt(pi)`, drawn as `y = erfinv(2 u2 - 1)`; `x <= cot(theta)`
//!   has the CDF (times `2 cos(theta) / G1`)
//!
//!   ```text
//!   C(x) = cos(theta) (1 + erf(x)) + sin(theta) exp(-x^2) / sqrt(pi)
//!   ```
//!
//!   which we invert numerically (Newton's method kept inside a bisection
//!   bracket). The simpler closed-form visible-normal sampler of Heitz 2018
//!   ("Sampling the GGX Distribution of Visible Normals") relies on GGX being
//!   the distribution of normals of a stretched hemisphere; Beckmann is not,
//!   hence this 2014 method.

use std::f64::consts::PI;

use glam::{Vec2, Vec3};

use crate::math::special::{erfinv, erfinv_estimate};

/// The smallest roughness used: smaller values are clamped to it, so that a
/// near-mirror stays a (very narrow) finite lobe.
pub const MIN_ALPHA: f32 = 1e-4;

const SQRT_PI: f64 = 1.772_453_850_905_516;
/// The `a` past which `Lambda` is below `1e-18` (asymptotically
/// `exp(-a^2) / (4 a^3 sqrt(pi))`; at 6 about 3e-19), far below the `f32`
/// precision of the `1 + Lambda` it is added to.
const LAMBDA_NEGLIGIBLE: f64 = 6.0;

/// An isotropic Beckmann distribution of microfacet normals.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Beckmann {
    alpha: f32,
}

/// `tan^2(theta)` of a direction, from `sin^2 = x^2 + y^2` (accurate near the
/// pole); infinite at `cos(theta) = 0`.
fn tan2_theta(w: Vec3) -> f64 {
    let (x, y, z) = (f64::from(w.x), f64::from(w.y), f64::from(w.z));
    (x * x + y * y) / (z * z)
}

impl Beckmann {
    /// The distribution of roughness `alpha`, clamped to `[MIN_ALPHA, inf)`.
    pub fn new(alpha: f32) -> Self {
        Beckmann {
            alpha: alpha.max(MIN_ALPHA),
        }
    }

    pub fn alpha(&self) -> f32 {
        self.alpha
    }

    /// The normal distribution `D(h)` (0 for `h.z <= 0`). It depends on
    /// `h`'s direction only: `h` need not be of unit length (`wo + wi`
    /// will do).
    pub fn d(&self, h: Vec3) -> f32 {
        if h.z <= 0.0 {
            return 0.0;
        }
        let a2 = f64::from(self.alpha).powi(2);
        let cos2 = f64::from(h.z).powi(2) / f64::from(h.length_squared());
        let d = (-tan2_theta(h) / a2).exp() / (PI * a2 * cos2 * cos2);
        if d.is_finite() {
            d as f32
        } else {
            0.0
        }
    }

    /// Smith's `Lambda(w)` for a direction above the surface (`w.z > 0`);
    /// infinite at `w.z <= 0`.
    pub fn lambda(&self, w: Vec3) -> f32 {
        if w.z <= 0.0 {
            return f32::INFINITY;
        }
        let tan2 = tan2_theta(w);
        if tan2 == 0.0 {
            return 0.0;
        }
        let a = 1.0 / (f64::from(self.alpha) * tan2.sqrt());
        // Past a = 6, Lambda < 1e-18: 1 + Lambda rounds to 1 in f32, where
        // every caller adds it, so skip erfc and exp (most directions of a
        // smooth surface: a = cot(theta) / alpha).
        if a > LAMBDA_NEGLIGIBLE {
            return 0.0;
        }
        // (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)), without cancellation.
        let lambda = 0.5 * ((-a * a).exp() / (a * SQRT_PI) - libm::erfc(a));
        lambda.max(0.0) as f32
    }

    /// The course starter's `Lambda` (`bsdf.h`), in f64: with
    /// `a = 1 / (alpha tan(theta))`,
    /// `Lambda = (erf(a) - 1 + exp(-a^2) / (a pi)) / 2`, where the exact
    /// Beckmann `Lambda` ([`Self::lambda`]) has `a sqrt(pi)`. It is smaller
    /// than the exact one everywhere (at `a = 0.3`, 0.149 against 0.524),
    /// and negative past `a = 0.530` (down to -0.024 near `a = 1`), where
    /// the starter's `G` exceeds 1. 0 at the normal, infinite below the
    /// surface.
    pub fn starter_lambda(&self, w: Vec3) -> f64 {
        if w.z <= 0.0 {
            return f64::INFINITY;
        }
        let tan2 = tan2_theta(w);
        if tan2 == 0.0 {
            return 0.0;
        }
        let a = 1.0 / (f64::from(self.alpha) * tan2.sqrt());
        0.5 * ((-a * a).exp() / (a * PI) - libm::erfc(a))
    }

    /// Smith's masking function `G1(w) = 1 / (1 + Lambda(w))`.
    pub fn g1(&self, w: Vec3) -> f32 {
        1.0 / (1.0 + self.lambda(w))
    }

    /// Height-correlated masking-shadowing `1 / (1 + Lambda(wo) + Lambda(wi))`.
    pub fn g(&self, wo: Vec3, wi: Vec3) -> f32 {
        1.0 / (1.0 + self.lambda(wo) + self.lambda(wi))
    }

    /// A normal drawn from `D(h) cos(theta_h)` (Walter 2007, eq. 28).
    pub fn sample_h(&self, u: Vec2) -> Vec3 {
        let a2 = f64::from(self.alpha).powi(2);
        let tan2 = -a2 * (1.0 - f64::from(u.x)).ln();
        let cos = 1.0 / (1.0 + tan2).sqrt();
        let sin = (tan2 / (1.0 + tan2)).sqrt();
        let phi = 2.0 * PI * f64::from(u.y);
        Vec3::new(
            (sin * phi.cos()) as f32,
            (sin * phi.sin()) as f32,
            cos as f32,
        )
    }

    /// Density of [`Beckmann::sample_h`], per steradian of `h`.
    pub fn pdf_h(&self, h: Vec3) -> f32 {
        self.d(h) * h.z.max(0.0)
    }

    /// A normal drawn from the normals visible from `wo` (`wo.z > 0`;
    /// from `wo` at or below the surface, which sees none, the macro
    /// normal, of density 0 by [`Self::pdf_visible`]).
    pub fn sample_visible(&self, wo: Vec3, u: Vec2) -> Vec3 {
        if wo.z <= 0.0 || wo.z.is_nan() {
            return Vec3::Z;
        }
        let alpha = f64::from(self.alpha);
        // Stretch to alpha = 1.
        let (sx, sy, sz) = (
            alpha * f64::from(wo.x),
            alpha * f64::from(wo.y),
            f64::from(wo.z),
        );
        // Plain square roots: the components are at most 1 in size, so
        // `hypot`'s guard against overflow buys nothing here, at a cost.
        let r = (sx * sx + sy * sy).sqrt();
        let (cos_phi, sin_phi) = if r > 0.0 {
            (sx / r, sy / r)
        } else {
            (1.0, 0.0)
        };
        // (sz, r) is (cos(theta), sin(theta)) times the stretched length,
        // and only their ratio counts: no need to normalise.
        let (x, y) = sample_unit_slopes(sz, r, u);
        // Rotate to wo's azimuth, unstretch, and turn the slopes into a normal.
        let mx = alpha * (cos_phi * x - sin_phi * y);
        let my = alpha * (sin_phi * x + cos_phi * y);
        let n = (mx * mx + my * my + 1.0).sqrt();
        Vec3::new((-mx / n) as f32, (-my / n) as f32, (1.0 / n) as f32)
    }

    /// Density of [`Beckmann::sample_visible`], per steradian of `h`:
    /// `G1(wo) max(0, wo.h) D(h) / wo.z`.
    pub fn pdf_visible(&self, wo: Vec3, h: Vec3) -> f32 {
        if wo.z <= 0.0 {
            return 0.0;
        }
        let p = f64::from(self.g1(wo)) * f64::from(wo.dot(h).max(0.0)) * f64::from(self.d(h))
            / f64::from(wo.z);
        p as f32
    }
}

/// How closely [`sample_unit_slopes`] solves `C(x) = u C(top)`, relative
/// to `C(x)`. The normal is returned in `f32` (relative rounding
/// `6e-8`), so solving to `1e-8` loses nothing the caller keeps; `1e-13`
/// took twice the Newton steps for digits the `f32` drops.
const SLOPE_TOLERANCE: f64 = 1e-8;

/// The slopes `(x, y)` of a normal visible from the direction at polar
/// angle `theta` (azimuth 0) on the `alpha = 1` Beckmann surface, given
/// `(cos(theta), sin(theta))` up to a common positive factor: `C` and its
/// target scale with it, so the slope depends on `cot(theta)` alone.
fn sample_unit_slopes(cos_theta: f64, sin_theta: f64, u: Vec2) -> (f64, f64) {
    let (x, _steps) = visible_slope_x(cos_theta, sin_theta, u.x);
    (x, erfinv(2.0 * f64::from(u.y) - 1.0))
}

/// The `x` with `C(x) = u C(top)` (the module doc's `C`, `top` the least
/// of `cot(theta)` and 6), and how many Newton or bisection steps found it.
fn visible_slope_x(cos_theta: f64, sin_theta: f64, u: f32) -> (f64, u32) {
    // C(x) as in the module doc, increasing on (-inf, cot(theta)], and its
    // derivative; both need exp(-x^2), computed once for the pair.
    let cdf = |x: f64, gauss: f64| cos_theta * (1.0 + libm::erf(x)) + sin_theta * gauss / SQRT_PI;
    let density = |x: f64, gauss: f64| 2.0 * (cos_theta - x * sin_theta) * gauss / SQRT_PI;
    // Beyond |x| = 6 the CDF changes by less than 1e-15 of its range. At
    // normal incidence (`sin = 0`) `cot` is infinite.
    let cot = cos_theta / sin_theta;
    let (mut lo, mut hi) = (-6.0f64, cot.min(6.0));
    // C(6) is 2 cos(theta) to the last bit when cot(theta) >= 6: erf(6)
    // rounds to 1, and sin(theta) exp(-36) / sqrt(pi) < 1e-17 cos(theta).
    let top = if cot >= 6.0 {
        2.0 * cos_theta
    } else {
        cdf(hi, (-hi * hi).exp())
    };
    let target = f64::from(u).clamp(0.0, 1.0) * top;
    // Start from the normal-incidence answer, erfinv(2 u - 1), to the
    // polynomial's 1e-7: the Newton steps below refine it anyway.
    let mut x = erfinv_estimate(2.0 * f64::from(u) - 1.0).clamp(lo, hi);
    for step in 0..64 {
        let gauss = (-x * x).exp();
        let err = cdf(x, gauss) - target;
        if err.abs() <= SLOPE_TOLERANCE * target.max(1e-300) {
            return (x, step);
        }
        if err > 0.0 {
            hi = x;
        } else {
            lo = x;
        }
        let newton = x - err / density(x, gauss);
        x = if newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if hi - lo < 1e-9 {
            return (x, step + 1);
        }
    }
    (x, 64)
}

#[cfg(test)]
mod tests;
