//! The probes of the base class's helpers `BSDF::reflect` and
//! `BSDF::refract` (part 6), and the exact directions the delta BSDFs'
//! probes ([`specular`](super::specular), [`glass`](super::glass)) compare
//! with, in the local frame (normal `(0, 0, 1)`, `wo` and `wi` both
//! leaving the surface):
//!
//! - `reflect(wo) = (-wo.x, -wo.y, wo.z)`, `wo` mirrored about the normal;
//! - `refract(wo)` by Snell's law with the handout's ratio
//!   `eta = n_i / n_t` along the ray: `1 / ior` when `wo.z > 0` (the ray
//!   enters the material from vacuum, the TODO's convention), `ior` when
//!   it leaves. With `cos^2 theta_t = 1 - eta^2 (1 - wo.z^2)`:
//!   `wi = (-eta wo.x, -eta wo.y, -sign(wo.z) cos theta_t)`, a unit vector
//!   on the other side; no direction (`false`) when `cos^2 theta_t < 0`,
//!   total internal reflection (only leaving).
//!
//! The inputs keep clear of the critical angle (`cos^2 theta_t` at least
//! 0.05 from 0), so rounding cannot decide total internal reflection.

use glam::DVec3;

use super::driver::Driver;
use super::geometry::{close, same_direction, show, tokens, vec_at};
use super::verdict::{failure, Cases, Failure, Verdict};
use crate::mistakes::Mistake;

/// Angles compared to this many radians; values to this relative error.
pub const ANGLE: f64 = 1e-6;
pub const REL: f64 = 1e-6;

/// `wo` mirrored about the normal.
pub fn reflect(wo: DVec3) -> DVec3 {
    // `+ 0.0` turns the -0 of a zero component into 0, for the report.
    DVec3::new(-wo.x, -wo.y, wo.z) + 0.0
}

/// `wo` mirrored through the tangent plane: `reflect-wrong-axis`.
pub fn wrong_axis(wo: DVec3) -> DVec3 {
    DVec3::new(wo.x, wo.y, -wo.z)
}

/// The handout's `eta = n_i / n_t` of a ray leaving along `-wo`:
/// `1 / ior` entering (`wo.z > 0`), `ior` leaving.
pub fn eta(wo: DVec3, ior: f64) -> f64 {
    if wo.z > 0.0 {
        1.0 / ior
    } else {
        ior
    }
}

/// `wo` refracted with the ratio `eta`, `None` under total internal
/// reflection.
pub fn refract_with(wo: DVec3, eta: f64) -> Option<DVec3> {
    let cos2 = 1.0 - eta * eta * (1.0 - wo.z * wo.z);
    (cos2 >= 0.0).then(|| DVec3::new(-eta * wo.x, -eta * wo.y, -wo.z.signum() * cos2.sqrt()) + 0.0)
}

/// `wo` refracted into (or out of) a material of index `ior`.
pub fn refract(wo: DVec3, ior: f64) -> Option<DVec3> {
    refract_with(wo, eta(wo, ior))
}

/// The same with the ratio upside down: `refraction-ratio-inverted`.
pub fn refract_inverted(wo: DVec3, ior: f64) -> Option<DVec3> {
    refract_with(wo, 1.0 / eta(wo, ior))
}

/// A unit direction from its polar angle (degrees, from `+z`) and azimuth.
pub fn polar(theta_deg: f64, phi_deg: f64) -> DVec3 {
    let (t, p) = (theta_deg.to_radians(), phi_deg.to_radians());
    DVec3::new(t.sin() * p.cos(), t.sin() * p.sin(), t.cos())
}

/// Whether `got` is `want` (direction and unit length).
pub fn same(got: DVec3, want: DVec3) -> bool {
    same_direction(got, want, ANGLE) && close(got.length(), 1.0, REL)
}

/// The directions `reflect` is asked about: above the surface from the
/// normal to grazing, then below it (the helper serves both sides).
fn reflect_inputs() -> Vec<DVec3> {
    vec![
        polar(0.0, 0.0),
        polar(30.0, 40.0),
        polar(60.0, 200.0),
        polar(85.0, 300.0),
        polar(120.0, 75.0),
        polar(160.0, 250.0),
    ]
}

/// Probes `BSDF::reflect`.
pub fn reflect_probe(driver: &Driver) -> Verdict {
    let inputs = reflect_inputs();
    let commands = inputs
        .iter()
        .map(|wo| format!("reflect {}", tokens(*wo)))
        .collect();
    let t = match driver.run("reflect", commands) {
        Ok(t) => t,
        Err(e) => return Verdict::Broken(e),
    };
    let mut cases = Cases::default();
    let mut stub_like = true;
    for (k, wo) in inputs.iter().enumerate() {
        let got = match t.exactly(k, 3) {
            Ok(v) => vec_at(&v, 0),
            Err(stop) => return Verdict::stopped(&stop, t.command(k)),
        };
        stub_like &= got.is_nan();
        let want = reflect(*wo);
        cases.record((!same(got, want)).then(|| {
            let flipped = same(got, wrong_axis(*wo)) && wo.z != 0.0;
            failure(
                format!("reflect(wo = {}, &wi)", show(*wo)),
                format!(
                    "*wi = {} (wo mirrored about the normal (0, 0, 1))",
                    show(want)
                ),
                format!("*wi = {}", show(got)),
                if flipped {
                    "wo is mirrored through the surface, (wo.x, wo.y, -wo.z): the ray heads into it"
                } else {
                    "*wi is not wo reflected about the normal (0, 0, 1)"
                },
                flipped.then_some(Mistake::ReflectWrongAxis),
            )
        }));
    }
    if stub_like {
        return Verdict::NotWritten("it never sets *wi, the starter's empty body".into());
    }
    cases.verdict(None)
}

/// `(wo, ior)` for `refract`: entering from vacuum at several angles and
/// indices, leaving below the critical angle, leaving beyond it.
pub fn refract_inputs() -> Vec<(DVec3, f64)> {
    vec![
        (polar(0.0, 0.0), 1.5),
        (polar(30.0, 40.0), 1.5),
        (polar(70.0, 160.0), 1.5),
        (polar(45.0, 290.0), 1.33),
        (polar(165.0, 20.0), 1.5),
        (polar(150.0, 230.0), 1.33),
        (polar(130.0, 100.0), 1.5),
        (polar(110.0, 330.0), 1.33),
    ]
}

/// Probes `BSDF::refract`.
pub fn refract_probe(driver: &Driver) -> Verdict {
    let inputs = refract_inputs();
    let commands = inputs
        .iter()
        .map(|(wo, ior)| format!("refract {} {ior}", tokens(*wo)))
        .collect();
    let t = match driver.run("refract", commands) {
        Ok(t) => t,
        Err(e) => return Verdict::Broken(e),
    };
    let mut cases = Cases::default();
    let mut stub_like = true;
    for (k, &(wo, ior)) in inputs.iter().enumerate() {
        let got = match t.exactly(k, 4) {
            Ok(v) => v,
            Err(stop) => return Verdict::stopped(&stop, t.command(k)),
        };
        let (ok, wi) = (got[0] == 1.0, vec_at(&got, 1));
        stub_like &= ok && wi.is_nan();
        cases.record(judge_refract(wo, ior, ok, wi));
    }
    if stub_like {
        return Verdict::NotWritten(
            "it returns true and never sets *wi, the starter's `return true;`".into(),
        );
    }
    cases.verdict(None)
}

/// One answer of `refract(wo, &wi, ior)`.
fn judge_refract(wo: DVec3, ior: f64, ok: bool, wi: DVec3) -> Option<Failure> {
    let side = if wo.z > 0.0 { "entering" } else { "leaving" };
    let input = format!(
        "refract(wo = {}, &wi, ior = {ior}), {side} (eta = {})",
        show(wo),
        super::geometry::num(eta(wo, ior))
    );
    let inverted = refract_inverted(wo, ior);
    let is_inverted = match inverted {
        Some(d) => ok && same(wi, d),
        None => !ok,
    };
    let said = if ok {
        format!("true, *wi = {}", show(wi))
    } else {
        "false".to_owned()
    };
    let fail = |expected: String, what: &str| {
        Some(failure(
            input.clone(),
            expected,
            said.clone(),
            if is_inverted {
                "Snell's law with the ratio of indices upside down (eta = ior entering, 1 / ior leaving)"
            } else {
                what
            },
            is_inverted.then_some(Mistake::RefractionRatioInverted),
        ))
    };
    match refract(wo, ior) {
        None if ok => fail(
            "false (total internal reflection)".into(),
            "true under total internal reflection: no direction refracts here",
        ),
        None => None,
        Some(want) => {
            let expected = format!("true, *wi = {}", show(want));
            if !ok {
                fail(expected, "false where the ray refracts")
            } else if same(wi, want) {
                None
            } else if same(wi, DVec3::new(want.x, want.y, -want.z)) {
                fail(expected, "*wi on the wrong side: it must cross the surface, wi.z of the sign opposite to wo.z")
            } else {
                fail(expected, "*wi is not the direction Snell's law gives (eta = 1 / ior entering, ior leaving)")
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn snells_law_with_the_handouts_ratio() {
        let wo = polar(30.0, 40.0);
        let wi = refract(wo, 1.5).unwrap();
        assert!(close(wi.length(), 1.0, 1e-15) && wi.z < 0.0);
        // sin(theta_t) = sin(theta_o) / 1.5 entering.
        let sin_t = (1.0 - wi.z * wi.z).sqrt();
        assert!(close(sin_t, 0.5 / 1.5, 1e-12));
        // Back out along -wi: the way it came.
        let back = refract(wi, 1.5).unwrap();
        assert!(same(back, wo));
        assert_eq!(refract(polar(130.0, 100.0), 1.5), None);
        assert_eq!(reflect(wo).z, wo.z);
    }

    #[test]
    fn the_inputs_keep_clear_of_the_critical_angle() {
        for (wo, ior) in refract_inputs() {
            for e in [eta(wo, ior), 1.0 / eta(wo, ior)] {
                let cos2 = 1.0 - e * e * (1.0 - wo.z * wo.z);
                assert!(cos2.abs() > 0.05, "{wo} {ior} {e}: {cos2}");
            }
        }
    }
}
