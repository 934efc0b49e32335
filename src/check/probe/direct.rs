//! The probes of the direct-lighting estimators (part 3):
//! `PathTracer::estimate_direct_lighting_hemisphere` and `_importance`,
//! each called many times at four points under one square area light
//! facing down (the driver's `light_quad`, `tracer`, `direct`), their
//! mean held to the light the point reflects. The points ([`POINTS`]):
//! two on a floor of triangles, each a hair (1e-9) under it as rounding
//! leaves a hit point (a shadow ray without the `EPS_F` offset meets the
//! floor: shadow acne); one in the air (nothing for acne, but a shadow
//! ray that reaches the light meets the light's own quad); one above the
//! light facing down onto its back (a one-sided light sends it nothing).
//!
//! A point `p` with normal `n` (albedo `rho`) under a light of radiance
//! `L` and area `A` reflects, by the rendering equation over the light's
//! area (`cos_i` at `p`, `cos_l` at the light, `d` the distance):
//!
//! ```text
//! L_out = rho / pi  L  integral cos_i |cos_l| / d^2 dA
//! ```
//!
//! which the hemisphere estimator's mean must be (its emitting triangles
//! glow on both sides, as the starter's comment warns). The importance
//! estimator divides each light sample by the pdf the course's
//! `AreaLight::sample_L` returns, `d^2 / (A cos_l)`, or, in the course's
//! own starter, `d / (A cos_l)` (its cosine taken with the unnormalised
//! `d`: cs184-format.md, section 8), so its mean is
//! `rho / pi L integral cos_i max(cos_l, 0) / d^k dA` with the `k` the
//! light's pdfs show (read from it first). The integrals are midpoint sums
//! ([`integral`]). Each mean is held to its value by [`means`]' z-test
//! per point and channel; a failure names the catalogued mistake whose
//! value passes the same test.

use std::f64::consts::PI;

use glam::DVec3;

use super::driver::Driver;
use super::geometry::{num, show, tokens};
use super::means::{self, always, fits, read, Moments, CALLS};
use super::verdict::{failure, Verdict};
use crate::mistakes::Mistake;

/// The light: radiance, centre, its two sides, the way it faces.
const RADIANCE: DVec3 = DVec3::new(2.0, 3.0, 4.0);
const CENTRE: DVec3 = DVec3::new(0.0, 0.0, 1.0);
const DX: DVec3 = DVec3::new(1.0, 0.0, 0.0);
const DY: DVec3 = DVec3::new(0.0, 1.0, 0.0);
const FACING: DVec3 = DVec3::new(0.0, 0.0, -1.0);
const ALBEDO: DVec3 = DVec3::new(0.5, 0.6, 0.7);
/// `ns_area_light`.
const NS: usize = 4;
/// The light's samples read to tell its pdf.
const LIGHT_SAMPLES: usize = 16;
/// Midpoint cells along each side of the light.
const CELLS: usize = 400;

/// A point probed: where, its normal, and whether it lies on the floor.
#[derive(Clone, Copy)]
pub struct Point {
    pub at: DVec3,
    pub normal: DVec3,
    pub on_floor: bool,
}

/// The points probed.
pub const POINTS: [Point; 4] = [
    Point {
        at: DVec3::new(0.1, 0.2, 0.0),
        normal: DVec3::Z,
        on_floor: true,
    },
    Point {
        at: DVec3::new(0.9, -0.6, 0.0),
        normal: DVec3::Z,
        on_floor: true,
    },
    Point {
        at: DVec3::new(0.3, 0.3, 0.5),
        normal: DVec3::Z,
        on_floor: false,
    },
    Point {
        at: DVec3::new(0.2, 0.1, 1.5),
        normal: DVec3::NEG_Z,
        on_floor: false,
    },
];

/// The floor: a 4 x 4 square of two triangles at `z = 0`.
const FLOOR: [[DVec3; 3]; 2] = [
    [
        DVec3::new(-2.0, -2.0, 0.0),
        DVec3::new(2.0, -2.0, 0.0),
        DVec3::new(2.0, 2.0, 0.0),
    ],
    [
        DVec3::new(-2.0, -2.0, 0.0),
        DVec3::new(2.0, 2.0, 0.0),
        DVec3::new(-2.0, 2.0, 0.0),
    ],
];

/// Which estimator.
#[derive(Clone, Copy, PartialEq)]
enum Estimator {
    Hemisphere,
    Importance,
}

/// `integral g(cos_i, cos_l, d) dA` over the light, seen from `p`
/// (`cos_l` negative where `p` sees the light's back).
pub fn integral(p: Point, g: impl Fn(f64, f64, f64) -> f64) -> f64 {
    let step = 1.0 / CELLS as f64;
    let area = DX.length() * DY.length();
    let mut sum = 0.0;
    for a in 0..CELLS {
        for b in 0..CELLS {
            let (u, v) = ((a as f64 + 0.5) * step - 0.5, (b as f64 + 0.5) * step - 0.5);
            let x = CENTRE + u * DX + v * DY;
            let to = x - p.at;
            let d = to.length();
            let (cos_i, cos_l) = (to.dot(p.normal) / d, -to.dot(FACING) / d);
            sum += g(cos_i, cos_l, d);
        }
    }
    sum * area * step * step
}

/// Probes `estimate_direct_lighting_hemisphere`.
pub fn hemisphere(driver: &Driver) -> Verdict {
    probe(driver, Estimator::Hemisphere)
}

/// Probes `estimate_direct_lighting_importance`.
pub fn importance(driver: &Driver) -> Verdict {
    probe(driver, Estimator::Importance)
}

fn probe(driver: &Driver, which: Estimator) -> Verdict {
    let word = match which {
        Estimator::Hemisphere => "hemi",
        Estimator::Importance => "importance",
    };
    let mut commands = vec!["mesh_clear".to_owned()];
    commands.extend(FLOOR.iter().map(|t| {
        format!(
            "mesh_tri {} {} {} {} {} {}",
            tokens(t[0]),
            tokens(t[1]),
            tokens(t[2]),
            tokens(DVec3::Z),
            tokens(DVec3::Z),
            tokens(DVec3::Z)
        )
    }));
    commands.extend([
        format!(
            "light_quad {} {} {} {} {}",
            tokens(RADIANCE),
            tokens(CENTRE),
            tokens(DX),
            tokens(DY),
            tokens(FACING)
        ),
        format!("light_sample {} {LIGHT_SAMPLES}", tokens(POINTS[1].at)),
        format!("tracer {NS} 1 0"),
    ]);
    // The first `direct` command's index.
    let first = commands.len();
    for p in POINTS {
        // Seen from along the normal, tilted; a point on the floor a hair
        // under it.
        let back = (p.normal + DVec3::new(0.3, -0.2, 0.0)).normalize();
        let t = if p.on_floor {
            0.5 + 1e-9 / back.dot(p.normal)
        } else {
            0.5
        };
        commands.push(format!(
            "direct {word} {CALLS} {} {} {t:e} {} {}",
            tokens(p.at + 0.5 * back),
            tokens(-back),
            tokens(p.normal),
            tokens(ALBEDO)
        ));
    }
    let t = match driver.run(&format!("direct_{word}"), commands) {
        Ok(t) => t,
        Err(e) => return Verdict::Broken(e),
    };
    let k = match light_power(&t, first - 2) {
        Ok(k) => k,
        Err(v) => return v,
    };
    let own_quad = match t.exactly(first - 3, 1) {
        Ok(v) => v[0] == 1.0,
        Err(stop) => return Verdict::stopped(&stop, t.command(first - 3)),
    };
    // What the quad sends a hemisphere sample: the 3-1 starter's glows
    // both ways; the 3-2 starter's light makes its own, emitting
    // `L / A max(0, cos_l)`.
    let area = DX.length() * DY.length();
    let glow = move |cl: f64| {
        if own_quad {
            cl.max(0.0) / area
        } else {
            1.0
        }
    };
    let moments: Moments = match (first..first + POINTS.len())
        .map(|at| read(&t, at))
        .collect()
    {
        Ok(m) => m,
        Err(v) => return v,
    };
    if always(&moments, DVec3::ONE) {
        return Verdict::NotWritten(
            "it returns (1, 1, 1) every time, the starter's `return Vector3D(1.0);`".into(),
        );
    }
    let f = ALBEDO / PI * RADIANCE;
    let right: Vec<DVec3> = POINTS
        .iter()
        .map(|p| match which {
            Estimator::Hemisphere => {
                f * integral(*p, |ci, cl, d| ci * glow(cl) * cl.abs() / (d * d))
            }
            Estimator::Importance => f * integral(*p, |ci, cl, d| ci * cl.max(0.0) / d.powi(k)),
        })
        .collect();
    let z = means::z_critical(POINTS.len());
    if fits(&moments, &right) {
        return Verdict::Pass {
            cases: CALLS * POINTS.len(),
            note: Some(format!(
                "means {} on the floor, {} in the air, {} over the light's back, of {CALLS} calls each, as expected (largest |z| {} of {}){}",
                show(moments[0].0),
                show(moments[2].0),
                show(moments[3].0),
                num(means::largest(&moments, &right)),
                num(z),
                if which == Estimator::Importance && k == 1 {
                    " (with the starter's AreaLight pdf, d / (A cos_l))"
                } else {
                    ""
                }
            )),
        };
    }
    let mistake = suspects(which, k, &glow, &right)
        .into_iter()
        .find(|(_, values)| fits(&moments, values))
        .map(|(m, _)| m);
    let worst = means::worst(&moments, &right);
    let (mean, var) = moments[worst];
    let se = (var / CALLS as f64).max(DVec3::ZERO);
    let se = DVec3::new(se.x.sqrt(), se.y.sqrt(), se.z.sqrt());
    let ratio = mean / right[worst];
    Verdict::Fail(failure(
        format!(
            "{CALLS} calls at p = {} (normal {}, DiffuseBSDF{}{}) under a 1 x 1 area light of radiance {} facing down at z = 1, ns_area_light = {NS}",
            show(POINTS[worst].at),
            show(POINTS[worst].normal),
            show(ALBEDO),
            if POINTS[worst].on_floor {
                ", on a floor of triangles, 1e-9 under it as rounding leaves a hit"
            } else {
                ""
            },
            show(RADIANCE)
        ),
        format!(
            "a mean of {} (the light the point reflects), give or take {}",
            show(right[worst]),
            show(se * z)
        ),
        format!("a mean of {}", show(mean)),
        if right[worst] == DVec3::ZERO {
            "light reaches a point the light cannot reach: it faces the light's back, and an area light shines from its front only".to_owned()
        } else {
            format!(
                "the estimate's mean is not the light reflected ({} times it)",
                show(ratio)
            )
        },
        mistake,
    ))
}

/// The power `k` of the distance in the pdfs the light returns
/// (`d^k / (A cos_l)`), read from the `light_sample` answers.
fn light_power(t: &super::driver::Transcript, at: usize) -> Result<i32, Verdict> {
    let v = t
        .exactly(at, LIGHT_SAMPLES * 8)
        .map_err(|stop| Verdict::stopped(&stop, t.command(at)))?;
    let area = DX.length() * DY.length();
    for k in [2, 1] {
        let all = v.chunks(8).all(|s| {
            let (wi, d, pdf) = (DVec3::new(s[0], s[1], s[2]), s[3], s[4]);
            let cos_l = wi.dot(FACING).abs();
            (pdf - d.powi(k) / (area * cos_l)).abs() <= 1e-9 * pdf.abs().max(1.0)
        });
        if all {
            return Ok(k);
        }
    }
    Err(Verdict::Broken(
        "the tree's AreaLight::sample_L returns pdfs of neither d^2 / (A cos) nor the starter's d / (A cos): the probe cannot tell what the estimate should be".into(),
    ))
}

/// The catalogued mistakes of the estimator and the means they make.
fn suspects(
    which: Estimator,
    k: i32,
    glow: &dyn Fn(f64) -> f64,
    right: &[DVec3],
) -> Vec<(Mistake, Vec<DVec3>)> {
    let f = ALBEDO / PI * RADIANCE;
    let each = |g: &dyn Fn(f64, f64, f64) -> f64| -> Vec<DVec3> {
        POINTS.iter().map(|p| f * integral(*p, g)).collect()
    };
    let scaled = |s: f64| right.iter().map(|r| *r * s).collect::<Vec<_>>();
    match which {
        Estimator::Hemisphere => vec![
            (
                Mistake::NoCosine,
                each(&|_, cl, d| glow(cl) * cl.abs() / (d * d)),
            ),
            (Mistake::NoPdf, scaled(1.0 / (2.0 * PI))),
            (Mistake::HemispherePdfOneOverPi, scaled(0.5)),
        ],
        Estimator::Importance => {
            // Shadow acne blocks the floor's points alone.
            let acne = POINTS
                .iter()
                .zip(right)
                .map(|(p, r)| if p.on_floor { DVec3::ZERO } else { *r })
                .collect();
            vec![
                (Mistake::NoCosine, each(&|_, cl, d| cl.max(0.0) / d.powi(k))),
                (
                    Mistake::NoPdf,
                    each(&|ci, cl, _| if cl > 0.0 { ci } else { 0.0 }),
                ),
                (Mistake::LightSamplesNotAveraged, scaled(NS as f64)),
                (Mistake::ShadowRayReachesLight, scaled(0.0)),
                (Mistake::ShadowAcne, acne),
                (
                    Mistake::LightFromBehind,
                    each(&|ci, cl, d| ci * cl.abs() / d.powi(k)),
                ),
            ]
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Under a large light close above, the point sees nearly the whole
    /// hemisphere: `integral cos_i cos_l / d^2 dA` tends to pi. Here, the
    /// exact form factor of a square above its centre (Howell's catalogue,
    /// C-10, four rectangles with a corner over the point) checks the sum.
    #[test]
    fn the_integral_matches_the_form_factor() {
        let p = Point {
            at: DVec3::ZERO,
            normal: DVec3::Z,
            on_floor: true,
        };
        let sum = integral(p, |ci, cl, d| ci * cl / (d * d));
        // F = 1/(2 pi) [A/sqrt(1+A^2) atan(B/sqrt(1+A^2)) + B/sqrt(1+B^2)
        // atan(A/sqrt(1+B^2))], A = B = 0.5 (half side over height), four
        // times; the integral is pi F.
        let a: f64 = 0.5;
        let s = (1.0 + a * a).sqrt();
        let corner = (a / s * (a / s).atan() * 2.0) / (2.0 * PI);
        let want = PI * 4.0 * corner;
        assert!((sum - want).abs() < 1e-5 * want, "{sum} {want}");
    }
}
