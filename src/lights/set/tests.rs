//! Unit tests of the light set: stand-ins, roles, the scene's radius.
use super::*;
use crate::scene::builtin::cornell_box;
use crate::scene::{Light as SceneLight, Material};

#[test]
fn the_cornell_box_light_quad_stands_in_for_its_area_light() {
    let scene = cornell_box();
    let stand_ins = StandIns::of(&scene);
    let proxies = stand_ins.materials.clone();
    let emissive: Vec<bool> = scene
        .materials
        .iter()
        .map(|m| matches!(m, Material::Emission { .. }))
        .collect();
    assert_eq!(proxies, emissive, "exactly the emissive quad is a stand-in");
    assert!(proxies.iter().any(|&p| p));
    assert_eq!(stand_ins.lights, vec![true]);
    let set = LightSet::new(&scene, LightConvention::Physical);
    assert_eq!(set.lights.len(), 1, "the quad adds no light");
    let roles: Vec<EmitterRole> = (0..scene.mesh.triangles.len() as u32)
        .map(|t| set.role(t))
        .collect();
    let shown = EmitterRole::Shown { light: Some(0) };
    assert_eq!(roles.iter().filter(|&&r| r == shown).count(), 2);
    assert!(!roles
        .iter()
        .any(|r| matches!(r, EmitterRole::Sampled { .. })));
}

#[test]
fn an_emitter_without_a_light_is_sampled_as_one() {
    let mut scene = cornell_box();
    // A different radiance: the quad still shows the lamp (the
    // course's intent), and lights nothing itself.
    if let SceneLight::Area { radiance, .. } = &mut scene.lights[0] {
        *radiance *= 0.5;
    }
    let stand_ins = StandIns::of(&scene);
    assert!(stand_ins.materials.iter().any(|&p| p));
    assert_eq!(stand_ins.lights, vec![true]);
    // No area light at all: the quad lights the scene itself.
    scene.lights.clear();
    assert!(StandIns::of(&scene).materials.iter().all(|&p| !p));
    let set = LightSet::new(&scene, LightConvention::Physical);
    assert_eq!(
        set.emissive_triangles().map(EmissiveTriangles::len),
        Some(2)
    );
    assert!(!set.has_unsampled_emitters());
    let sampled = (0..scene.mesh.triangles.len() as u32)
        .filter(|&t| matches!(set.role(t), EmitterRole::Sampled { light: 0, .. }))
        .count();
    assert_eq!(sampled, 2);
    // The course's starter samples scene lights only: the quad is just shown.
    let course = LightSet::new(&scene, LightConvention::Course);
    assert!(course.lights.is_empty());
}

#[test]
fn two_lamps_may_share_one_stand_in_material() {
    let mut scene = cornell_box();
    let SceneLight::Area {
        radiance,
        center,
        direction,
        dim_x,
        dim_y,
    } = scene.lights[0]
    else {
        unreachable!()
    };
    // A second lamp, and a copy of the quad on it with the same material.
    let shift = Vec3::new(0.0, 0.0, 0.9);
    scene.lights.push(SceneLight::Area {
        radiance,
        center: center + shift,
        direction,
        dim_x,
        dim_y,
    });
    let mesh = &mut scene.mesh;
    let quad: Vec<usize> = (0..mesh.triangles.len())
        .filter(|&t| {
            matches!(
                scene.materials[mesh.materials[t] as usize],
                Material::Emission { .. }
            )
        })
        .collect();
    for t in quad {
        let base = mesh.positions.len() as u32;
        let corners = mesh.triangles[t];
        for v in corners {
            mesh.positions.push(mesh.positions[v as usize] + shift);
            mesh.normals.push(mesh.normals[v as usize]);
        }
        mesh.triangles.push([base, base + 1, base + 2]);
        mesh.materials.push(mesh.materials[t]);
    }
    let stand_ins = StandIns::of(&scene);
    assert_eq!(stand_ins.lights, vec![true, true]);
    let set = LightSet::new(&scene, LightConvention::Physical);
    assert_eq!(set.lights.len(), 2, "no light counted twice");
    assert!(set.emissive_triangles().is_none());
}

// Half the diagonal of the box around vertices and spheres: two vertices
// span (0,0,0)-(2,4,4), a sphere at (5,0,0) of radius 1 stretches it to
// (0,-1,-1)-(6,4,4): 0.5 * |(6,5,5)| = 0.5 * sqrt(86). Fails if the
// spheres are left out, the box's corners are taken otherwise, or the
// half becomes another factor.
#[test]
fn the_scene_radius_is_half_the_diagonal_of_its_box_spheres_included() {
    let mut scene = Scene::default();
    scene.mesh.positions = vec![Vec3::ZERO, Vec3::new(2.0, 4.0, 4.0)];
    assert!((scene_radius(&scene) - 3.0).abs() < 1e-6);
    scene.spheres.push(crate::scene::Sphere {
        center: Vec3::new(5.0, 0.0, 0.0),
        radius: 1.0,
        material: 0,
    });
    assert!((scene_radius(&scene) - 0.5 * 86f32.sqrt()).abs() < 1e-6);
    let set = LightSet::new(&scene, LightConvention::Physical);
    assert_eq!(set.scene_radius(), scene_radius(&scene));
    // Nothing at all: no box, radius 0 (not infinite or NaN).
    assert_eq!(scene_radius(&Scene::default()), 0.0);
}

// Which lights direct lighting samples (`lit`: positive power), which
// lie at infinity among them, and which are rectangles that rays test.
// Fails if a black light or the spot light is sampled, a light at
// infinity is missed, or a rectangle is not listed.
#[test]
fn the_set_samples_the_lights_that_emit_and_lists_each_kind() {
    let mut scene = cornell_box();
    scene.lights.push(SceneLight::Point {
        intensity: Vec3::ZERO,
        position: Vec3::ZERO,
    });
    scene.lights.push(SceneLight::Spot {
        intensity: Vec3::ONE,
        position: Vec3::ZERO,
        direction: Vec3::NEG_Y,
    });
    scene.lights.push(SceneLight::Directional {
        radiance: Vec3::ONE,
        direction: Vec3::Y,
    });
    scene.lights.push(SceneLight::Ambient {
        radiance: Vec3::ZERO,
    });
    let set = LightSet::new(&scene, LightConvention::Physical);
    let lit: Vec<usize> = set.lit().map(|(i, _)| i).collect();
    assert_eq!(lit, vec![0, 3], "the area and directional lights");
    let infinite: Vec<usize> = set.infinite().map(|(i, _)| i).collect();
    assert_eq!(infinite, vec![3], "the black sky is not sampled or seen");
    let rects: Vec<(usize, bool)> = set.rects().map(|(i, _, shown)| (i, shown)).collect();
    assert_eq!(rects, vec![(0, true)], "the box's lamp, shown by its quad");
    assert!(set.emissive_triangles().is_none());
    assert!(!set.has_unsampled_emitters());
}

// The rule asked for is the one used (`choice`), an environment joins the
// lit lights at infinity, and an emissive sphere, which no light samples,
// is reported. Fails if `choice` gives the default, `with_environment`
// loses the set, or `has_unsampled_emitters` is always false.
#[test]
fn a_rule_an_environment_and_an_emissive_sphere_are_taken_into_account() {
    use crate::environment::{EnvironmentLight, EnvironmentMap, EnvironmentSampling};
    let scene = cornell_box();
    let set = LightSet::new(&scene, LightConvention::Physical);
    assert_eq!(set.choice(), &LightChoice::EveryLight);
    let by_power = set.clone().with_choice(LightChoiceRule::ByPower);
    assert!(matches!(by_power.choice(), LightChoice::ByPower(_)));

    let map = EnvironmentMap::from_fn("sky", 8, 4, |d| Rgb::splat(1.0 + d.y)).unwrap();
    let lit =
        by_power.with_environment(EnvironmentLight::new(map, EnvironmentSampling::Importance));
    assert_eq!(lit.lights.len(), 2);
    assert_eq!(lit.lit().map(|(i, _)| i).collect::<Vec<_>>(), vec![0, 1]);
    assert_eq!(
        lit.infinite()
            .map(|(i, l)| (i, l.kind()))
            .collect::<Vec<_>>(),
        vec![(1, "environment")]
    );
    assert!(
        matches!(lit.choice(), LightChoice::ByPower(_)),
        "the rule is kept"
    );

    assert!(!set.has_unsampled_emitters());
    let mut glowing = scene.clone();
    glowing.materials.push(Material::Emission {
        radiance: Rgb::splat(2.0),
    });
    glowing.spheres.push(crate::scene::Sphere {
        center: Vec3::new(0.0, 0.5, 0.0),
        radius: 0.1,
        material: (glowing.materials.len() - 1) as u32,
    });
    let with_sphere = LightSet::new(&glowing, LightConvention::Physical);
    assert!(with_sphere.has_unsampled_emitters());
    // Primitives are the triangles, then the spheres: the new one is last.
    let sphere = (glowing.mesh.triangles.len() + glowing.spheres.len() - 1) as u32;
    assert_eq!(with_sphere.role(sphere), EmitterRole::Unsampled);
}
