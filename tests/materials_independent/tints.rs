//! Glass, mirror and refraction with a colour in each lobe: every channel
//! of a sampled weight is its tint times the expected scalar (the Fresnel
//! share from [`reference`](crate::reference), `1 / eta^2`), so a channel
//! dropped, swapped or taken from the other lobe fails. Built through
//! `Bsdf::new` from the scene's `Material`, seen from outside and inside.
//!
//! Tolerance: a weight is `f |cos| / pdf` in `f32`, the tint times a
//! product of a few roundings, and the Fresnel share is within
//! [`TOL`](crate::dielectric::TOL) of the reference's; 1e-5 relative to
//! the tint (or absolute, for shares), against changes of 0.25 and more
//! (the tints' channels differ by that much at least).

use glam::{Vec2, Vec3};
use pathtracer::materials::{Bsdf, BsdfOptions, Density, FresnelModel};
use pathtracer::scene::Material;

use crate::dielectric::{SIDES, TOL};
use crate::reference::{schlick, snell_fresnel};

const REFLECTANCE: Vec3 = Vec3::new(1.0, 0.5, 0.25);
const TRANSMITTANCE: Vec3 = Vec3::new(0.2, 0.6, 1.0);

fn close(got: Vec3, expected: Vec3) -> bool {
    (got - expected).abs().max_element() <= 1e-5 * expected.max_element().max(1.0)
}

/// `wo` at `degrees` from the normal, azimuth 1.1 rad.
fn at(degrees: f64) -> Vec3 {
    let (s, c) = degrees.to_radians().sin_cos();
    Vec3::new(
        (s * 1.1f64.cos()) as f32,
        (s * 1.1f64.sin()) as f32,
        c as f32,
    )
}

const ANGLES: [f64; 8] = [0.0, 15.0, 30.0, 40.0, 50.0, 65.0, 80.0, 88.0];

/// For both Fresnel models, entering and leaving glass of index 1.5 and
/// 2.4: the reflected sample (`uc = 0`) has probability `F`, weight `R` and
/// `f cos = R F` per channel; the transmitted one (`uc` just below 1, not
/// under total internal reflection) probability `1 - F`, weight
/// `T / eta^2` and `f cos = T (1 - F) / eta^2`; and the mean weight over
/// 4096 evenly spread `uc` is `R F + T (1 - F) / eta^2` per channel,
/// within the `1 / 4096` by which the count of reflections may miss `F`.
/// Checked against: the transmitted weight with `T`'s green channel for
/// its blue, reflectance and transmittance exchanged in `Bsdf::new`, the
/// lobes chosen the wrong way round (`uc < F` transmits), a fair coin
/// choosing the lobe while `f` and the probability still say `F` (each
/// sample's weight is right, the mean is not), and the glass taking exact
/// Fresnel when asked for Schlick.
#[test]
fn tinted_glass_weights_each_channel_by_its_lobe() {
    for fresnel in [FresnelModel::Exact, FresnelModel::Schlick] {
        let options = BsdfOptions {
            fresnel,
            ..BsdfOptions::default()
        };
        for (n1, n2) in SIDES {
            let material = Material::Glass {
                reflectance: REFLECTANCE,
                transmittance: TRANSMITTANCE,
                roughness: 0.0,
                ior: n1.max(n2) as f32,
            };
            let bsdf = Bsdf::new(&material, n1 < n2, options);
            let eta2 = (n2 / n1).powi(2) as f32;
            for degrees in ANGLES {
                let wo = at(degrees);
                let cos = f64::from(wo.z);
                let share = match fresnel {
                    FresnelModel::Exact => snell_fresnel(n1, n2, cos),
                    FresnelModel::Schlick => schlick(n1, n2, cos),
                } as f32;
                let label = format!("{fresnel:?}, n {n1} -> {n2}, {degrees} degrees");
                let r = bsdf.sample(wo, 0.0, Vec2::ZERO).unwrap();
                let Density::Delta(p) = r.density else {
                    panic!("{label}: {r:?}")
                };
                assert!(!r.transmission && r.wi == Vec3::new(-wo.x, -wo.y, wo.z));
                assert!(
                    f64::from((p - share).abs()) <= TOL,
                    "{label}: {p} vs {share}"
                );
                assert!(close(r.weight(), REFLECTANCE), "{label}: {r:?}");
                assert!(close(r.f * r.wi.z, REFLECTANCE * share), "{label}: {r:?}");
                let t = bsdf.sample(wo, 1.0 - f32::EPSILON, Vec2::ZERO).unwrap();
                if share < 1.0 {
                    assert!(t.transmission && t.wi.z < 0.0, "{label}: {t:?}");
                    assert!(f64::from((t.pdf() - (1.0 - share)).abs()) <= TOL);
                    assert!(close(t.weight(), TRANSMITTANCE / eta2), "{label}: {t:?}");
                    let f_cos = t.f * t.wi.z.abs();
                    assert!(
                        close(f_cos, TRANSMITTANCE * (1.0 - share) / eta2),
                        "{label}"
                    );
                } else {
                    assert!(!t.transmission && close(t.weight(), REFLECTANCE), "{label}");
                }
                let n = 4096;
                let mean = (0..n)
                    .map(|i| {
                        let uc = (i as f32 + 0.5) / n as f32;
                        bsdf.sample(wo, uc, Vec2::ZERO).unwrap().weight()
                    })
                    .sum::<Vec3>()
                    / n as f32;
                let expected = REFLECTANCE * share + TRANSMITTANCE * (1.0 - share) / eta2;
                let spread = (REFLECTANCE - TRANSMITTANCE / eta2).abs() / n as f32;
                assert!(
                    ((mean - expected).abs() - spread).max_element() <= 1e-5,
                    "{label}: mean weight {mean} vs {expected}"
                );
            }
        }
    }
}

/// The mirror's weight is its reflectance, channel by channel, in the
/// mirror direction with probability 1; refraction's is `T / eta^2`
/// entering or leaving, and `T` where total internal reflection turns it
/// back (the project's choice, documented in `refraction.rs`). Checked
/// against the mirror's reflectance with its channels reversed and
/// refraction's `1 / eta^2` left out.
#[test]
fn tinted_mirror_and_refraction_keep_their_channels() {
    let mirror = Bsdf::new(
        &Material::Mirror {
            reflectance: REFLECTANCE,
        },
        true,
        BsdfOptions::default(),
    );
    for degrees in ANGLES {
        let wo = at(degrees);
        let s = mirror.sample(wo, 0.5, Vec2::splat(0.5)).unwrap();
        assert_eq!(s.density, Density::Delta(1.0));
        assert!(!s.transmission && s.wi == Vec3::new(-wo.x, -wo.y, wo.z));
        assert!(close(s.weight(), REFLECTANCE), "{degrees}: {s:?}");
        assert!(close(s.f * s.wi.z, REFLECTANCE), "{degrees}: {s:?}");
    }
    for (n1, n2) in SIDES {
        let material = Material::Refraction {
            transmittance: TRANSMITTANCE,
            roughness: 0.0,
            ior: n1.max(n2) as f32,
        };
        let bsdf = Bsdf::new(&material, n1 < n2, BsdfOptions::default());
        for degrees in ANGLES {
            let s = bsdf.sample(at(degrees), 0.5, Vec2::splat(0.5)).unwrap();
            let label = format!("refraction, n {n1} -> {n2}, {degrees} degrees: {s:?}");
            let tir = n1 * degrees.to_radians().sin() > n2;
            assert_eq!(s.transmission, !tir, "{label}");
            let expected = if tir {
                TRANSMITTANCE
            } else {
                TRANSMITTANCE / (n2 / n1).powi(2) as f32
            };
            assert!(close(s.weight(), expected), "{label}");
        }
    }
}
