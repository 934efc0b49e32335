//! Unit tests of the mesh casters (`super`) and of how [`Casters`] takes
//! them in.

use glam::Vec3;

use crate::lights::LightSet;
use crate::scene::{Material, Scene};
use crate::world::casters::{CasterRule, Casters, MAX_CASTERS};

/// Each mirror-like material's triangles (a mirror's in two places, a
/// conductor's with `alpha` 0.025) become one caster, the sphere around
/// them centred on their box, showing no images; diffuse, glass and
/// rough conductor triangles none, nor a triangle whose material is not
/// in the scene; `off` none at all.
#[test]
fn mirror_like_meshes_cast_from_the_sphere_around_their_triangles() {
    let scene = Scene {
        materials: five_materials(),
        mesh: mesh_of(&[
            (0, unit_triangle(0.0)),
            (1, unit_triangle(10.0)),
            (2, unit_triangle(20.0)),
            // No vertex at a corner of its box: the radius is the
            // farthest vertex's distance, sqrt 2, not the box's half
            // diagonal, sqrt 3.
            (
                3,
                [
                    Vec3::new(30.0, 0.0, 1.0),
                    Vec3::new(31.0, 2.0, 0.0),
                    Vec3::new(32.0, 1.0, 2.0),
                ],
            ),
            (4, unit_triangle(40.0)),
            (99, unit_triangle(50.0)),
            // The mirror's second triangle, apart from its first: one
            // box for both.
            (
                1,
                [
                    Vec3::new(10.0, 0.0, 4.0),
                    Vec3::new(10.0, 0.0, 6.0),
                    Vec3::new(10.0, 2.0, 6.0),
                ],
            ),
        ]),
        lights: vec![light_above()],
        ..Scene::default()
    };
    let lights = LightSet::new(&scene, Default::default());
    let casters = Casters::new(&scene, &lights, CasterRule::Auto);
    // The mirror's box is [10, 11] x [0, 2] x [0, 6], its farthest
    // vertices (10, 0, 0) and (10, 2, 6) at sqrt(0.25 + 1 + 9) from the
    // centre.
    let expected = [
        (Vec3::new(10.5, 1.0, 3.0), 10.25f32.sqrt()),
        (Vec3::new(31.0, 1.0, 1.0), 2.0f32.sqrt()),
    ];
    assert_eq!(casters.spheres.len(), 2, "{casters:?}");
    assert_eq!(casters.meshes, 2);
    for (found, (center, radius)) in casters.spheres.iter().zip(expected) {
        assert!(found.center.abs_diff_eq(center, 1e-6), "{found:?}");
        assert!((found.radius - radius).abs() < 1e-6, "{found:?}");
        assert_eq!(found.image_spread, None);
    }
    assert_eq!(casters.images(), 0);
    assert_eq!(
        Casters::new(&scene, &lights, CasterRule::Spheres).spheres,
        casters.spheres
    );
    assert!(Casters::new(&scene, &lights, CasterRule::Off).is_empty());
}

/// Mesh casters take the slots the spheres leave: seven mirror spheres
/// and two mirror meshes give seven spheres and one mesh; nine spheres,
/// more than [`MAX_CASTERS`], none at all, meshes included.
#[test]
fn mesh_casters_take_the_slots_the_spheres_leave() {
    use crate::scene::Sphere;
    let with_spheres = |n: u32| Scene {
        materials: five_materials(),
        spheres: (0..n)
            .map(|i| Sphere {
                center: Vec3::new(i as f32, 5.0, 0.0),
                radius: 0.3,
                material: 1,
            })
            .collect(),
        mesh: mesh_of(&[(1, unit_triangle(0.0)), (3, unit_triangle(10.0))]),
        lights: vec![light_above()],
        ..Scene::default()
    };
    let scene = with_spheres(7);
    let lights = LightSet::new(&scene, Default::default());
    let casters = Casters::new(&scene, &lights, CasterRule::Auto);
    assert_eq!((casters.spheres.len(), casters.meshes), (MAX_CASTERS, 1));
    // The mesh comes last: the spheres keep their images.
    assert_eq!(casters.spheres[MAX_CASTERS - 1].image_spread, None);
    assert_eq!(casters.images(), 7);
    let scene = with_spheres(9);
    assert!(Casters::new(&scene, &lights, CasterRule::Auto).is_empty());
}

/// Diffuse, mirror, glass, a conductor with `alpha` 0.025, one with 0.2.
fn five_materials() -> Vec<Material> {
    let rgb = crate::math::Rgb::ONE;
    let conductor = |alpha| Material::Microfacet {
        alpha,
        eta: rgb,
        k: rgb,
    };
    vec![
        Material::Diffuse { albedo: rgb },
        Material::Mirror { reflectance: rgb },
        Material::Glass {
            reflectance: rgb,
            transmittance: rgb,
            roughness: 0.0,
            ior: 1.5,
        },
        conductor(0.025),
        conductor(0.2),
    ]
}

/// The right triangle with legs of 1 along x and y, at `(x, 0, 0)`.
fn unit_triangle(x: f32) -> [Vec3; 3] {
    [
        Vec3::new(x, 0.0, 0.0),
        Vec3::new(x + 1.0, 0.0, 0.0),
        Vec3::new(x, 1.0, 0.0),
    ]
}

/// A mesh of separate triangles, each with its material.
fn mesh_of(triangles: &[(u32, [Vec3; 3])]) -> crate::scene::TriangleMesh {
    let mut mesh = crate::scene::TriangleMesh::default();
    for &(material, corners) in triangles {
        let base = mesh.positions.len() as u32;
        mesh.positions.extend(corners);
        mesh.triangles.push([base, base + 1, base + 2]);
        mesh.materials.push(material);
    }
    mesh
}

/// A unit square light two above the origin, facing down.
pub(in crate::world::casters) fn light_above() -> crate::scene::Light {
    crate::scene::Light::Area {
        radiance: crate::math::Rgb::ONE,
        center: Vec3::new(0.0, 2.0, 0.0),
        direction: Vec3::NEG_Y,
        dim_x: Vec3::X,
        dim_y: Vec3::Z,
    }
}
