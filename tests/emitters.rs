//! Sampling emissive triangles as lights (`lights::triangles`): the density
//! each sample reports is right, checked through an identity that holds
//! for any correct sampler, `E[1 / p(w)] = ∫ dω`, the solid angle of the
//! emitters (where the density is positive). For one triangle seen from
//! `x`, with `a, b, c` the vectors to its corners, the solid angle is given
//! by Van Oosterom and Strackee (IEEE Trans. Biomed. Eng. 30(2), 1983):
//!
//! ```text
//! tan(Ω / 2) = |a · (b × c)| / (|a||b||c| + (a·b)|c| + (a·c)|b| + (b·c)|a|)
//! ```
//!
//! With several triangles the power-proportional pick multiplies each
//! triangle's density by its pmf, so `E[1 / p]` is the sum of their solid
//! angles (as long as they do not overlap as seen from `x`). Tested at
//! alpha = 1e-4 split over the cases; fixed seeds.

mod common;

use common::*;
use glam::{DVec3, Vec3};
use pathtracer::lights::{EmissiveTriangles, LightPdf};
use pathtracer::math::rng::{next_2d, sampler};
use pathtracer::scene::normals::area_weighted_vertex_normals;
use pathtracer::scene::{Material, Scene, TriangleMesh};
use rand::Rng;

fn solid_angle(x: DVec3, corners: [DVec3; 3]) -> f64 {
    let [a, b, c] = corners.map(|p| p - x);
    let (la, lb, lc) = (a.length(), b.length(), c.length());
    let numerator = a.dot(b.cross(c)).abs();
    let denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    2.0 * numerator.atan2(denominator)
}

/// A triangle's corners and its (grey) radiance.
type Glowing = ([Vec3; 3], f32);

/// Emissive triangles with the given radiances (one material each).
fn emitters(triangles: &[Glowing]) -> Scene {
    let positions: Vec<Vec3> = triangles.iter().flat_map(|(t, _)| *t).collect();
    let indices: Vec<[u32; 3]> = (0..triangles.len() as u32)
        .map(|i| [3 * i, 3 * i + 1, 3 * i + 2])
        .collect();
    Scene {
        mesh: TriangleMesh {
            normals: area_weighted_vertex_normals(&positions, &indices),
            materials: (0..triangles.len() as u32).collect(),
            positions,
            triangles: indices,
        },
        materials: triangles
            .iter()
            .map(|&(_, l)| Material::Emission {
                radiance: Vec3::splat(l),
            })
            .collect(),
        ..Scene::default()
    }
}

#[test]
fn inverse_density_averages_to_the_solid_angle() {
    let cases: [(&str, Vec<Glowing>, Vec3); 3] = [
        (
            "one triangle, oblique",
            vec![(
                [
                    Vec3::new(-1.0, 2.0, 0.0),
                    Vec3::new(1.5, 2.5, 0.3),
                    Vec3::new(0.2, 2.2, 1.4),
                ],
                1.0,
            )],
            Vec3::new(0.1, 0.0, 0.2),
        ),
        (
            "one triangle, close and large, seen from its back",
            vec![(
                [
                    Vec3::new(-3.0, 0.5, -3.0),
                    Vec3::new(3.0, 0.5, -3.0),
                    Vec3::new(0.0, 0.5, 3.0),
                ],
                2.0,
            )],
            Vec3::new(0.3, 0.0, -0.4),
        ),
        (
            "three triangles of different power, apart",
            vec![
                (
                    [
                        Vec3::new(2.0, 1.0, 0.0),
                        Vec3::new(3.0, 1.0, 0.0),
                        Vec3::new(2.0, 2.0, 0.5),
                    ],
                    1.0,
                ),
                (
                    [
                        Vec3::new(-2.0, 1.0, 0.0),
                        Vec3::new(-4.0, 1.5, 0.0),
                        Vec3::new(-2.0, 3.0, 1.0),
                    ],
                    5.0,
                ),
                (
                    [
                        Vec3::new(0.0, -1.0, 3.0),
                        Vec3::new(0.5, -1.0, 4.0),
                        Vec3::new(-0.5, -2.0, 3.5),
                    ],
                    0.5,
                ),
            ],
            Vec3::ZERO,
        ),
    ];
    let alpha = ALPHA / cases.len() as f64;
    for (i, (label, triangles, x)) in cases.iter().enumerate() {
        let scene = emitters(triangles);
        let sampled = vec![true; scene.materials.len()];
        let set = EmissiveTriangles::new(&scene, &sampled);
        assert_eq!(set.len(), triangles.len());
        let expected: f64 = triangles
            .iter()
            .map(|(t, _)| solid_angle(x.as_dvec3(), t.map(|p| p.as_dvec3())))
            .sum();
        let mut rng = sampler(2024, i as u64);
        let inverse_densities = (0..200_000).map(|_| {
            let pick = rng.gen::<f32>();
            let sample = set
                .sample_li(*x, pick, next_2d(&mut rng))
                .expect("a sample");
            match sample.pdf {
                LightPdf::SolidAngle(p) => 1.0 / p as f64,
                LightPdf::Delta => panic!("emitters are not delta lights"),
            }
        });
        assert_mean_matches(
            label,
            MeanEstimate::of(inverse_densities),
            expected,
            alpha,
            0.0,
        );
    }
}

#[test]
fn brighter_triangles_are_picked_more_often() {
    let scene = emitters(&[
        ([Vec3::ZERO, Vec3::X, Vec3::Z], 1.0),
        (
            [
                Vec3::new(5.0, 0.0, 0.0),
                Vec3::new(6.0, 0.0, 0.0),
                Vec3::new(5.0, 0.0, 1.0),
            ],
            3.0,
        ),
    ]);
    let set = EmissiveTriangles::new(&scene, &[true, true]);
    let x = Vec3::new(2.5, 3.0, 0.3);
    let mut rng = sampler(7, 0);
    let n = 100_000;
    let bright = (0..n)
        .filter(|_| {
            let pick = rng.gen::<f32>();
            set.sample_li(x, pick, next_2d(&mut rng))
                .unwrap()
                .radiance
                .x
                > 2.0
        })
        .count();
    // Power ratio 1 : 3, so 3/4 of the picks; binomial se = sqrt(n p (1 - p)).
    let expected = 0.75 * n as f64;
    let se = (n as f64 * 0.75 * 0.25).sqrt();
    assert!(
        (bright as f64 - expected).abs() <= z_two_sided(ALPHA) * se,
        "{bright} of {n}"
    );
}
