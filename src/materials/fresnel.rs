//! Fresnel reflectance: the fraction of light a smooth interface reflects.
//!
//! All three take the cosine of the incident angle `cos_i >= 0`, measured
//! on the side the light arrives from, and the relative index of
//! refraction `eta = n_t / n_i` (the far side over the near side).
//!
//! - Dielectric, exact (unpolarised light, the mean of the two
//!   polarisations; Born and Wolf, *Principles of Optics*, section 1.5;
//!   pbrt-v4, section 9.3.5). With Snell's law
//!   `sin_t = sin_i / eta` and `cos_t = sqrt(1 - sin_t^2)`:
//!
//!   ```text
//!   r_par  = (eta cos_i - cos_t) / (eta cos_i + cos_t)
//!   r_perp = (cos_i - eta cos_t) / (cos_i + eta cos_t)
//!   F      = (r_par^2 + r_perp^2) / 2
//!   ```
//!
//!   and `F = 1` when `sin_t >= 1` (total internal reflection).
//! - Schlick's approximation (Schlick 1994, "An Inexpensive BRDF Model for
//!   Physically-based Rendering"), as the course writes it:
//!   `R0 = ((1 - eta) / (1 + eta))^2`, `F = R0 + (1 - R0) (1 - cos_i)^5`.
//!   The course evaluates it at the incident cosine on either side; it
//!   knows nothing of total internal reflection, so [`schlick`] reports
//!   it explicitly (`F = 1`).
//! - Conductor, exact: the same two amplitudes with the complex index
//!   `eta + i k` (pbrt-v4, section 9.3.6), where `cos_t` is complex too.
//!   Evaluated per colour channel in real arithmetic, by the closed form
//!   of the two reflectances (pbrt-v3's `FrConductor`; S. Lagarde,
//!   "Memo on Fresnel equations", 2013):
//!
//!   ```text
//!   t0 = eta^2 - k^2 - sin_i^2,    a^2 + b^2 = sqrt(t0^2 + 4 eta^2 k^2),    a = sqrt((a^2 + b^2 + t0) / 2)
//!   R_s = (a^2 + b^2 + cos_i^2 - 2 a cos_i) / (a^2 + b^2 + cos_i^2 + 2 a cos_i)
//!   R_p = R_s (cos_i^2 (a^2 + b^2) + sin_i^4 - 2 a cos_i sin_i^2) / (cos_i^2 (a^2 + b^2) + sin_i^4 + 2 a cos_i sin_i^2)
//!   F   = (R_s + R_p) / 2
//!   ```
//!
//!   A unit test checks it against the complex amplitudes in `f64`.

use crate::math::Rgb;

/// The cosine of the transmitted angle by Snell's law for `cos_i` and the
/// relative index `eta`, or `None` under total internal reflection.
pub fn refracted_cos(cos_i: f32, eta: f32) -> Option<f32> {
    let sin2_i = (1.0 - cos_i * cos_i).max(0.0);
    let sin2_t = sin2_i / (eta * eta);
    (sin2_t < 1.0).then(|| (1.0 - sin2_t).sqrt())
}

/// Exact Fresnel reflectance of a dielectric interface for unpolarised
/// light. `cos_i` in `[0, 1]`, `eta > 0`. 1 under total internal reflection.
#[doc(alias = "FrDielectric")]
pub fn dielectric(cos_i: f32, eta: f32) -> f32 {
    let cos_i = cos_i.clamp(0.0, 1.0);
    let Some(cos_t) = refracted_cos(cos_i, eta) else {
        return 1.0;
    };
    let r_par = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    let r_perp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    let f = 0.5 * (r_par * r_par + r_perp * r_perp);
    // At cos_i = cos_t = 0 (grazing, eta = 1) both quotients are 0 / 0.
    if f.is_nan() {
        1.0
    } else {
        f.min(1.0)
    }
}

/// Schlick's approximation of [`dielectric`], evaluated as the course does
/// at the incident cosine, and 1 under total internal reflection.
#[doc(alias = "reflectance")]
pub fn schlick(cos_i: f32, eta: f32) -> f32 {
    let cos_i = cos_i.clamp(0.0, 1.0);
    if refracted_cos(cos_i, eta).is_none() {
        return 1.0;
    }
    let r0 = ((1.0 - eta) / (1.0 + eta)).powi(2);
    r0 + (1.0 - r0) * (1.0 - cos_i).powi(5)
}

/// Exact Fresnel reflectance of a conductor with complex index `eta + i k`
/// (one channel), for `cos_i` in `[0, 1]`, in real arithmetic (see the
/// module docs): no complex division or square root.
#[inline]
fn conductor_channel(cos_i: f32, eta: f32, k: f32) -> f32 {
    // In f64: near grazing incidence on a weakly absorbing index, R_s's
    // numerator cancels (t1 and t2 both ~ 2 cos_i^2), which f32 loses.
    let (cos_i, eta, k) = (f64::from(cos_i), f64::from(eta), f64::from(k));
    let cos2 = cos_i * cos_i;
    let sin2 = 1.0 - cos2;
    let (eta2, k2) = (eta * eta, k * k);
    let t0 = eta2 - k2 - sin2;
    let a2_plus_b2 = (t0 * t0 + 4.0 * eta2 * k2).sqrt();
    let t1 = a2_plus_b2 + cos2;
    let a = (0.5 * (a2_plus_b2 + t0)).max(0.0).sqrt();
    let t2 = 2.0 * cos_i * a;
    let r_s = (t1 - t2) / (t1 + t2);
    let t3 = cos2 * a2_plus_b2 + sin2 * sin2;
    let t4 = t2 * sin2;
    let r_p = r_s * (t3 - t4) / (t3 + t4);
    let f = 0.5 * (r_p + r_s);
    if f.is_finite() {
        f.clamp(0.0, 1.0) as f32
    } else {
        1.0
    }
}

/// Exact Fresnel reflectance of a conductor, per channel, from the real
/// part `eta` and the extinction coefficient `k` of its index of refraction.
#[doc(alias = "FrComplex")]
pub fn conductor(cos_i: f32, eta: Rgb, k: Rgb) -> Rgb {
    let cos_i = cos_i.clamp(0.0, 1.0);
    Rgb::new(
        conductor_channel(cos_i, eta.x, k.x),
        conductor_channel(cos_i, eta.y, k.y),
        conductor_channel(cos_i, eta.z, k.z),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A complex number, just enough for the conductor's Fresnel equations.
    #[derive(Clone, Copy, Debug, PartialEq)]
    struct Complex {
        re: f64,
        im: f64,
    }

    impl Complex {
        fn new(re: f64, im: f64) -> Self {
            Complex { re, im }
        }

        fn add(self, o: Complex) -> Complex {
            Complex::new(self.re + o.re, self.im + o.im)
        }

        fn sub(self, o: Complex) -> Complex {
            Complex::new(self.re - o.re, self.im - o.im)
        }

        fn mul(self, o: Complex) -> Complex {
            Complex::new(
                self.re * o.re - self.im * o.im,
                self.re * o.im + self.im * o.re,
            )
        }

        fn norm_sqr(self) -> f64 {
            self.re * self.re + self.im * self.im
        }

        fn div(self, o: Complex) -> Complex {
            let d = o.norm_sqr();
            Complex::new(
                (self.re * o.re + self.im * o.im) / d,
                (self.im * o.re - self.re * o.im) / d,
            )
        }

        /// The principal square root (non-negative real part).
        fn sqrt(self) -> Complex {
            let r = self.norm_sqr().sqrt();
            if r == 0.0 {
                return Complex::new(0.0, 0.0);
            }
            let re = (0.5 * (r + self.re)).max(0.0).sqrt();
            let im = (0.5 * (r - self.re)).max(0.0).sqrt().copysign(self.im);
            Complex::new(re, im)
        }
    }

    /// The textbook form the closed form comes from: the dielectric's two
    /// amplitudes with the complex index `n = eta + i k` and a complex
    /// `cos_t`, in `f64`.
    fn conductor_reference(cos_i: f32, eta: f32, k: f32) -> f64 {
        let cos_i = f64::from(cos_i.clamp(0.0, 1.0));
        let n = Complex::new(f64::from(eta), f64::from(k));
        let one = Complex::new(1.0, 0.0);
        let ci = Complex::new(cos_i, 0.0);
        // Snell's law with a complex index: sin_t^2 = sin_i^2 / n^2.
        let sin2_t = Complex::new(1.0 - cos_i * cos_i, 0.0).div(n.mul(n));
        let ct = one.sub(sin2_t).sqrt();
        let r_par = n.mul(ci).sub(ct).div(n.mul(ci).add(ct));
        let r_perp = ci.sub(n.mul(ct)).div(ci.add(n.mul(ct)));
        let f = 0.5 * (r_par.norm_sqr() + r_perp.norm_sqr());
        // 0 / 0 at grazing incidence on an index of 1: all is reflected.
        if f.is_finite() {
            f
        } else {
            1.0
        }
    }

    #[test]
    fn the_closed_form_equals_the_complex_amplitudes() {
        // Metals of the course's scenes and pbrt's tables, a dielectric
        // (k = 0) and an absorbing dielectric; grazing to normal.
        let indices = [
            (0.059193, 4.1283),
            (1.3352, 7.3398),
            (0.2, 3.0),
            (1.5, 0.0),
            (1.0, 0.0),
            (2.4, 0.5),
            (0.33228, 3.1646),
        ];
        for (eta, k) in indices {
            for i in 0..=1000 {
                let c = i as f32 / 1000.0;
                let fast = conductor_channel(c, eta, k);
                let exact = conductor_reference(c, eta, k);
                assert!(
                    (f64::from(fast) - exact).abs() < 2e-6,
                    "eta {eta} k {k} cos {c}: {fast} vs {exact}"
                );
            }
        }
    }

    #[test]
    fn normal_incidence_gives_r0() {
        for eta in [1.33f32, 1.5, 2.4, 1.0 / 1.5] {
            let r0 = ((eta - 1.0) / (eta + 1.0)).powi(2);
            assert!((dielectric(1.0, eta) - r0).abs() < 1e-6, "{eta}");
            assert!((schlick(1.0, eta) - r0).abs() < 1e-6, "{eta}");
        }
        // A conductor with k = 0 is a dielectric seen from outside.
        let c = conductor(1.0, Rgb::splat(1.5), Rgb::ZERO);
        assert!((c.x - 0.04).abs() < 1e-6, "{c}");
        // |n - 1|^2 / |n + 1|^2 with n = eta + i k.
        let (eta, k) = (0.2f32, 3.0f32);
        let expected = ((eta - 1.0).powi(2) + k * k) / ((eta + 1.0).powi(2) + k * k);
        let c = conductor(1.0, Rgb::splat(eta), Rgb::splat(k));
        assert!((c.x - expected).abs() < 1e-6, "{c} {expected}");
    }

    #[test]
    fn grazing_incidence_reflects_everything() {
        for eta in [1.5f32, 1.0 / 1.5, 1.0001] {
            assert!(dielectric(0.0, eta) > 0.999, "{eta}");
            assert!(dielectric(1e-4, eta) >= dielectric(1e-2, eta), "{eta}");
            assert!(schlick(0.0, eta) > 0.999, "{eta}");
        }
        let c = conductor(0.0, Rgb::new(0.2, 1.0, 1.2), Rgb::new(3.0, 2.5, 2.4));
        assert!(c.min_element() > 0.999, "{c}");
    }

    #[test]
    fn total_internal_reflection_beyond_the_critical_angle() {
        let eta = 1.0f32 / 1.5;
        let critical = eta.asin(); // sin_i = eta
        let beyond = (critical + 0.01).cos();
        let before = (critical - 0.01).cos();
        assert_eq!(dielectric(beyond, eta), 1.0);
        assert_eq!(schlick(beyond, eta), 1.0);
        assert!(dielectric(before, eta) < 1.0);
        assert!(refracted_cos(beyond, eta).is_none());
    }

    #[test]
    fn index_one_reflects_nothing_and_values_stay_in_range() {
        for i in 0..=100 {
            let c = i as f32 / 100.0;
            if c > 0.0 {
                assert!(dielectric(c, 1.0) < 1e-6);
            }
            for eta in [1.2f32, 1.0 / 1.2, 2.5] {
                let f = dielectric(c, eta);
                assert!((0.0..=1.0).contains(&f), "{c} {eta} {f}");
            }
            let f = conductor(c, Rgb::new(0.14, 0.37, 1.44), Rgb::new(4.0, 2.4, 1.6));
            assert!(f.min_element() >= 0.0 && f.max_element() <= 1.0);
        }
    }
}
