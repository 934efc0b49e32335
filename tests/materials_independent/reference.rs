//! The answers the material tests compare against, written here in `f64`
//! from the textbook formulas and nothing of the library's: Fresnel from
//! Snell's law with the two indices apart (not their ratio), Schlick's
//! formula, the conductor's Fresnel equations with a complex index in
//! complex arithmetic (the library uses a real closed form), Beckmann's
//! `D` and Smith's `Lambda` with `statrs`'s `erf` (the library uses
//! `libm`'s `erfc`).

use std::f64::consts::PI;
use std::ops::{Add, Div, Mul, Sub};

use glam::DVec3;
use statrs::function::erf::erf;

/// Gold's complex index of refraction at red, green and blue (pbrt's
/// `metal-Au-eta` and `metal-Au-k` at about 650, 550 and 450 nm).
pub const GOLD_ETA: [f64; 3] = [0.143_119, 0.374_957, 1.442_48];
pub const GOLD_K: [f64; 3] = [3.983_16, 2.385_72, 1.603_22];

/// Reflectance of unpolarised light arriving at `cos_i` from the side of
/// index `n1` on the side of index `n2`: Snell's law
/// `n1 sin_i = n2 sin_t`, then
/// `r_s = (n1 cos_i - n2 cos_t) / (n1 cos_i + n2 cos_t)`,
/// `r_p = (n2 cos_i - n1 cos_t) / (n2 cos_i + n1 cos_t)`,
/// `R = (r_s^2 + r_p^2) / 2`; 1 past the critical angle.
pub fn snell_fresnel(n1: f64, n2: f64, cos_i: f64) -> f64 {
    let sin_t = n1 / n2 * (1.0 - cos_i * cos_i).max(0.0).sqrt();
    if sin_t >= 1.0 {
        return 1.0;
    }
    let cos_t = (1.0 - sin_t * sin_t).sqrt();
    let r_s = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
    let r_p = (n2 * cos_i - n1 * cos_t) / (n2 * cos_i + n1 * cos_t);
    0.5 * (r_s * r_s + r_p * r_p)
}

/// Schlick's approximation as the course's `GlassBSDF` writes it, at the
/// cosine on the side the light arrives from:
/// `R0 = ((n1 - n2) / (n1 + n2))^2`, `R = R0 + (1 - R0) (1 - cos_i)^5`;
/// 1 past the critical angle, where the course reflects everything.
pub fn schlick(n1: f64, n2: f64, cos_i: f64) -> f64 {
    if n1 / n2 * (1.0 - cos_i * cos_i).max(0.0).sqrt() >= 1.0 {
        return 1.0;
    }
    let r0 = ((n1 - n2) / (n1 + n2)).powi(2);
    r0 + (1.0 - r0) * (1.0 - cos_i).powi(5)
}

/// A complex number, just what the conductor's Fresnel equations need.
#[derive(Clone, Copy, Debug)]
pub struct C(pub f64, pub f64);

impl Add for C {
    type Output = C;
    fn add(self, o: C) -> C {
        C(self.0 + o.0, self.1 + o.1)
    }
}

impl Sub for C {
    type Output = C;
    fn sub(self, o: C) -> C {
        C(self.0 - o.0, self.1 - o.1)
    }
}

impl Mul for C {
    type Output = C;
    fn mul(self, o: C) -> C {
        C(self.0 * o.0 - self.1 * o.1, self.0 * o.1 + self.1 * o.0)
    }
}

impl Div for C {
    type Output = C;
    fn div(self, o: C) -> C {
        let d = o.norm2();
        C(
            (self.0 * o.0 + self.1 * o.1) / d,
            (self.1 * o.0 - self.0 * o.1) / d,
        )
    }
}

impl C {
    pub fn norm2(self) -> f64 {
        self.0 * self.0 + self.1 * self.1
    }

    /// The principal square root, from the polar form.
    pub fn sqrt(self) -> C {
        let (r, arg) = (self.norm2().sqrt().sqrt(), self.1.atan2(self.0) / 2.0);
        C(r * arg.cos(), r * arg.sin())
    }
}

/// The conductor's reflectance at `cos_i` for the index `eta + i k`: the
/// same amplitudes as [`snell_fresnel`] (outside index 1) with a complex
/// index and a complex `cos_t = sqrt(1 - sin_i^2 / n^2)`.
pub fn conductor_fresnel(cos_i: f64, eta: f64, k: f64) -> f64 {
    let (n, ci, one) = (C(eta, k), C(cos_i, 0.0), C(1.0, 0.0));
    let cos_t = (one - C(1.0 - cos_i * cos_i, 0.0) / (n * n)).sqrt();
    let r_s = (ci - n * cos_t) / (ci + n * cos_t);
    let r_p = (n * ci - cos_t) / (n * ci + cos_t);
    0.5 * (r_s.norm2() + r_p.norm2())
}

/// Gold's reflectance per channel.
pub fn gold(cos_i: f64) -> DVec3 {
    DVec3::from_array(std::array::from_fn(|c| {
        conductor_fresnel(cos_i, GOLD_ETA[c], GOLD_K[c])
    }))
}

/// Beckmann's distribution of normals,
/// `D(h) = exp(-tan^2(theta_h) / alpha^2) / (pi alpha^2 cos^4(theta_h))`.
pub fn beckmann_d(alpha: f64, h: DVec3) -> f64 {
    let c2 = h.z * h.z;
    let tan2 = (h.x * h.x + h.y * h.y) / c2;
    (-tan2 / (alpha * alpha)).exp() / (PI * alpha * alpha * c2 * c2)
}

/// Smith's `Lambda` for Beckmann: with `a = 1 / (alpha tan(theta))`,
/// `(erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi))`; 0 at the normal.
pub fn smith_lambda(alpha: f64, w: DVec3) -> f64 {
    let tan = (w.x * w.x + w.y * w.y).sqrt() / w.z;
    if tan == 0.0 {
        return 0.0;
    }
    let a = 1.0 / (alpha * tan);
    0.5 * (erf(a) - 1.0) + (-a * a).exp() / (2.0 * a * PI.sqrt())
}

/// What the microfacet BRDF is made of for a pair of directions above the
/// surface: `D(h)`, `Lambda(wo)`, `Lambda(wi)` and `wo.h`.
pub struct Terms {
    pub d: f64,
    pub lambda_o: f64,
    pub lambda_i: f64,
    pub cos_oh: f64,
    pub cos_o: f64,
    pub cos_i: f64,
}

pub fn terms(alpha: f64, wo: DVec3, wi: DVec3) -> Option<Terms> {
    if wo.z <= 0.0 || wi.z <= 0.0 {
        return None;
    }
    let h = (wo + wi).normalize();
    Some(Terms {
        d: beckmann_d(alpha, h),
        lambda_o: smith_lambda(alpha, wo),
        lambda_i: smith_lambda(alpha, wi),
        cos_oh: wo.dot(h),
        cos_o: wo.z,
        cos_i: wi.z,
    })
}

impl Terms {
    /// The height-correlated `G = 1 / (1 + Lambda(wo) + Lambda(wi))`.
    pub fn g_correlated(&self) -> f64 {
        1.0 / (1.0 + self.lambda_o + self.lambda_i)
    }

    /// The separable `G = G1(wo) G1(wi)`.
    pub fn g_separable(&self) -> f64 {
        1.0 / ((1.0 + self.lambda_o) * (1.0 + self.lambda_i))
    }

    /// `F D G / (4 cos_o cos_i)` for a given `F` and `G`.
    pub fn f(&self, fresnel: DVec3, g: f64) -> DVec3 {
        fresnel * (self.d * g / (4.0 * self.cos_o * self.cos_i))
    }

    /// Gold's BRDF with `F(wo.h)` and the height-correlated `G`.
    pub fn gold_f(&self) -> DVec3 {
        self.f(gold(self.cos_oh), self.g_correlated())
    }
}
