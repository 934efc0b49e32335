//! The probe of `MicrofacetBSDF::F` (part 6): the conductor's Fresnel
//! reflectance per channel from its `eta` and `k`, at
//! `c = cos theta_i = wi.z` (the function is declared on `wi`). The
//! handout's air-conductor form:
//!
//! ```text
//! R_s = ((eta^2 + k^2) - 2 eta c + c^2) / ((eta^2 + k^2) + 2 eta c + c^2)
//! R_p = ((eta^2 + k^2) c^2 - 2 eta c + 1) / ((eta^2 + k^2) c^2 + 2 eta c + 1)
//! F   = (R_s + R_p) / 2
//! ```
//!
//! The exact one (the two amplitudes with the complex index `eta + i k`,
//! pbrt-v3's `FrConductor`) is accepted too. Both give
//! `((eta - 1)^2 + k^2) / ((eta + 1)^2 + k^2)` at normal incidence.

use glam::DVec3;

use super::driver::Driver;
use super::geometry::{num, show, tokens, vec_at};
use super::microfacet::{near3, ETA, K};
use super::reflection::polar;
use super::verdict::{failure, Cases, Verdict};

/// The handout's air-conductor Fresnel reflectance at `cos`, per channel.
pub fn handout_fresnel(cos: f64, eta: DVec3, k: DVec3) -> DVec3 {
    let c = cos;
    let s = eta * eta + k * k;
    let rs = (s - 2.0 * eta * c + c * c) / (s + 2.0 * eta * c + c * c);
    let rp = (s * c * c - 2.0 * eta * c + 1.0) / (s * c * c + 2.0 * eta * c + 1.0);
    (rs + rp) / 2.0
}

/// The exact conductor Fresnel reflectance at `cos` (pbrt-v3's
/// `FrConductor`), per channel.
pub fn exact_fresnel(cos: f64, eta: DVec3, k: DVec3) -> DVec3 {
    let one = |eta: f64, k: f64| {
        let (c2, s2) = (cos * cos, 1.0 - cos * cos);
        let t0 = eta * eta - k * k - s2;
        let a2b2 = (t0 * t0 + 4.0 * eta * eta * k * k).sqrt();
        let a = (0.5 * (a2b2 + t0)).max(0.0).sqrt();
        let (t1, t2) = (a2b2 + c2, 2.0 * cos * a);
        let rs = (t1 - t2) / (t1 + t2);
        let (t3, t4) = (c2 * a2b2 + s2 * s2, t2 * s2);
        0.5 * (rs + rs * (t3 - t4) / (t3 + t4))
    };
    DVec3::new(one(eta.x, k.x), one(eta.y, k.y), one(eta.z, k.z))
}

/// Probes `MicrofacetBSDF::F`.
pub fn f_fresnel(driver: &Driver) -> Verdict {
    let gold = (
        DVec3::new(0.143119, 0.374957, 1.442479),
        DVec3::new(3.983160, 2.385721, 1.603215),
    );
    let metals = [(ETA, K), gold];
    let dirs = [
        polar(15.0, 30.0),
        polar(35.0, 130.0),
        polar(50.0, 210.0),
        polar(65.0, 300.0),
        polar(80.0, 80.0),
        polar(87.0, 170.0),
    ];
    let mut commands = Vec::new();
    for (eta, k) in metals {
        commands.push(format!("microfacet {} {} 0.3", tokens(eta), tokens(k)));
        commands.extend(dirs.iter().map(|w| format!("mf_F {}", tokens(*w))));
    }
    let t = match driver.run("microfacet_F", commands) {
        Ok(t) => t,
        Err(e) => return Verdict::Broken(e),
    };
    let mut cases = Cases::default();
    let mut stub_like = true;
    let mut exact = 0;
    for (m, (eta, k)) in metals.iter().enumerate() {
        for (j, wi) in dirs.iter().enumerate() {
            let i = m * (dirs.len() + 1) + 1 + j;
            let got = match t.exactly(i, 3) {
                Ok(v) => vec_at(&v, 0),
                Err(stop) => return Verdict::stopped(&stop, t.command(i)),
            };
            stub_like &= got == DVec3::ZERO;
            let want = handout_fresnel(wi.z, *eta, *k);
            let is_exact = near3(got, exact_fresnel(wi.z, *eta, *k));
            exact += usize::from(is_exact);
            cases.record((!near3(got, want) && !is_exact).then(|| {
                failure(
                    format!(
                        "F(wi = {}) with eta = {}, k = {}",
                        show(*wi),
                        show(*eta),
                        show(*k)
                    ),
                    format!(
                        "{} (the handout's (R_s + R_p) / 2 at cos theta_i = {})",
                        show(want),
                        num(wi.z)
                    ),
                    show(got),
                    "F is not the conductor's Fresnel reflectance from eta and k",
                    None,
                )
            }));
        }
    }
    if stub_like {
        return Verdict::NotWritten(
            "it returns black for every wi, the starter's `return Vector3D();`".into(),
        );
    }
    cases.verdict(
        (exact > 0).then(|| "the exact conductor Fresnel, not the handout's form".to_owned()),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_two_fresnels_agree_at_normal_incidence_and_differ_oblique() {
        let normal = ((ETA - 1.0) * (ETA - 1.0) + K * K) / ((ETA + 1.0) * (ETA + 1.0) + K * K);
        assert!(near3(handout_fresnel(1.0, ETA, K), normal));
        assert!(near3(exact_fresnel(1.0, ETA, K), normal));
        assert!(!near3(
            handout_fresnel(0.5, ETA, K),
            exact_fresnel(0.5, ETA, K)
        ));
    }
}
