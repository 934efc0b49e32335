//! Unit tests of what every material shares: the sample record.

use glam::Vec3;

use super::*;

/// A reflection sample exists only with a density that is positive and
/// finite: with 0 the estimator would divide by it, with infinity it
/// would weigh nothing, and a negative one is no density. Checked by
/// hand: `pdf > 0 && pdf.is_finite()` with `&&` made `||` or `>` made
/// `>=` fails here (found by the mutation run of `materials`).
#[test]
fn a_reflection_sample_needs_a_positive_finite_density() {
    let (f, wi) = (Rgb::new(0.2, 0.4, 0.6), Vec3::new(0.0, 0.6, 0.8));
    for pdf in [0.0, -0.0, -1.0, f32::INFINITY, f32::NAN] {
        assert!(BsdfSample::reflection(f, wi, pdf).is_none(), "pdf {pdf}");
    }
    let sample = BsdfSample::reflection(f, wi, 0.5).expect("a density of 0.5");
    assert_eq!((sample.f, sample.wi, sample.pdf()), (f, wi, 0.5));
    assert!(!sample.transmission && !sample.is_delta());
    assert_eq!(sample.eta, 1.0);
}

/// A sample's weight is `f |cos theta_i| / pdf`, and zero where the density
/// is not positive and finite (a record made by hand can hold any density;
/// a delta lobe's probability is its density here). Checked by hand: the
/// guard's `&&` made `||` or `>` made `>=` fails here.
#[test]
fn a_sample_weighs_f_cos_over_pdf_and_nothing_without_a_density() {
    let (f, wi) = (Rgb::new(0.2, 0.4, 0.6), Vec3::new(0.0, 0.6, -0.8));
    let sample = |density| BsdfSample {
        f,
        wi,
        density,
        transmission: true,
        eta: 1.5,
    };
    for (density, expected) in [(Density::SolidAngle(0.5), 1.6), (Density::Delta(0.25), 3.2)] {
        let weight = sample(density).weight();
        assert!(
            (weight - f * expected).abs().max_element() < 1e-6,
            "{weight:?}"
        );
    }
    for pdf in [0.0, -1.0, f32::INFINITY, f32::NAN] {
        for density in [Density::SolidAngle(pdf), Density::Delta(pdf)] {
            assert_eq!(sample(density).weight(), Rgb::ZERO, "{density:?}");
        }
    }
}

/// One BSDF of each kind, from the scene's materials.
fn every_kind() -> Vec<Bsdf> {
    let c = Rgb::new(0.2, 0.4, 0.6);
    let materials = [
        Material::Emission { radiance: c },
        Material::Diffuse { albedo: c },
        Material::Mirror { reflectance: c },
        Material::Refraction {
            transmittance: c,
            roughness: 0.0,
            ior: 1.5,
        },
        Material::Glass {
            reflectance: c,
            transmittance: c,
            roughness: 0.0,
            ior: 1.5,
        },
        Material::Microfacet {
            alpha: 0.3,
            eta: Rgb::new(0.2, 0.92, 1.1),
            k: Rgb::new(3.9, 2.45, 2.14),
        },
    ];
    let options = BsdfOptions::default();
    materials
        .iter()
        .map(|m| Bsdf::new(m, true, options))
        .collect()
}

/// `Bsdf::f` and `Bsdf::pdf` asked apart agree with `Bsdf::eval`, which
/// the renderer calls, for every kind and pairs of directions above,
/// across and below the surface; delta lobes and the black BSDF have
/// neither, and only the black one is black. Checked by hand: `pdf` made a
/// constant or either of its arms deleted, `f`'s conductor arm deleted and
/// `is_black` made `false` fail here (found by the mutation run of
/// `materials`: the renderer asks `eval` alone).
#[test]
fn f_and_pdf_apart_agree_with_eval_for_every_kind() {
    let directions = [
        Vec3::new(0.0, 0.0, 1.0),
        Vec3::new(0.6, 0.0, 0.8),
        Vec3::new(-0.48, 0.6, 0.64),
        Vec3::new(0.0, -0.6, -0.8),
    ];
    for bsdf in every_kind() {
        assert_eq!(bsdf.is_black(), matches!(bsdf, Bsdf::Black), "{bsdf:?}");
        let mut nonzero = 0;
        for wo in directions {
            for wi in directions {
                let (f, pdf) = bsdf.eval(wo, wi);
                assert_eq!((bsdf.f(wo, wi), bsdf.pdf(wo, wi)), (f, pdf), "{bsdf:?}");
                nonzero += usize::from(pdf > 0.0 && f.max_element() > 0.0);
            }
        }
        let smooth = matches!(bsdf, Bsdf::Diffuse(_) | Bsdf::Conductor(_));
        assert_eq!(
            nonzero > 0,
            smooth,
            "{bsdf:?}: {nonzero} pairs with f and pdf"
        );
    }
}

/// The diffuse BSDF reflects only between two directions above the
/// surface: `albedo / pi` there, 0 when either is below. Checked by hand:
/// `wo.z > 0 && wi.z > 0` made `||` fails here.
#[test]
fn diffuse_reflects_only_above_the_surface() {
    let albedo = Rgb::new(0.2, 0.4, 0.6);
    let diffuse = Diffuse { albedo };
    let (up, down) = (Vec3::new(0.6, 0.0, 0.8), Vec3::new(0.0, 0.6, -0.8));
    assert_eq!(diffuse.f(up, up), albedo / std::f32::consts::PI);
    for (wo, wi) in [(up, down), (down, up), (down, down)] {
        assert_eq!(diffuse.f(wo, wi), Rgb::ZERO, "{wo} {wi}");
    }
}
