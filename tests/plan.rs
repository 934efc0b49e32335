//! The render plan: what it decides for a scene, and that the integrator
//! it specialises estimates the same radiance as the general one
//! (two-sample z-tests, fixed seeds, [`ALPHA`] = 1e-4 over the file's
//! comparisons).

mod common;

use common::*;
use glam::Vec3;
use pathtracer::depth_of_field::ThinLens;
use pathtracer::environment::{EnvironmentLight, EnvironmentMap, EnvironmentSampling};
use pathtracer::glints::Decision;
use pathtracer::global::GLASS_SPLITS;
use pathtracer::lights::{LightConvention, LightSet};
use pathtracer::plan::Plan;
use pathtracer::scene::builtin::materials_box;
use pathtracer::scene::{Light, Material, Scene};
use pathtracer::world::World;

/// A diffuse floor under a wall, lit by a point light only.
fn point_lit() -> Scene {
    let mut b = SceneBuilder::new();
    let grey = b.material(diffuse(0.7));
    b.quad(
        grey,
        [
            Vec3::new(-2.0, 0.0, -2.0),
            Vec3::new(2.0, 0.0, -2.0),
            Vec3::new(2.0, 0.0, 2.0),
            Vec3::new(-2.0, 0.0, 2.0),
        ],
    );
    b.quad(
        grey,
        [
            Vec3::new(-2.0, 0.0, -1.0),
            Vec3::new(-2.0, 2.0, -1.0),
            Vec3::new(2.0, 2.0, -1.0),
            Vec3::new(2.0, 0.0, -1.0),
        ],
    );
    b.light(Light::Point {
        intensity: Vec3::splat(3.0),
        position: Vec3::new(0.3, 1.2, 0.4),
    });
    b.finish()
}

fn plan_of(scene: &Scene, max_depth: u32) -> Plan {
    let lights = LightSet::new(scene, LightConvention::Physical);
    Plan::new(
        scene,
        &lights,
        &tracer(LIGHTS, max_depth, true),
        &ThinLens::PINHOLE,
    )
}

#[test]
fn the_plan_names_what_the_scene_calls_for() {
    let point = plan_of(&point_lit(), 3);
    assert!(point.bsdfs.diffuse && !point.bsdfs.glossy && !point.bsdfs.delta);
    assert_eq!(point.light_kinds, vec!["point"]);
    assert!(
        point.light_sampling && !point.mis,
        "delta lights only: no MIS"
    );
    assert!(point.warnings.is_empty());
    assert!(point.lines.iter().all(|l| l.starts_with("plan: ")));

    let box_plan = plan_of(&materials_box(), 1);
    assert!(box_plan.bsdfs.diffuse && box_plan.bsdfs.glossy && box_plan.bsdfs.delta);
    assert!(box_plan.mis, "an area light and scattering surfaces");
    assert_eq!(box_plan.warnings.len(), 2, "{:?}", box_plan.warnings);
    assert!(plan_of(&materials_box(), 3).warnings.is_empty());

    // Nothing scatters non-delta: no light sampling at all.
    let mut mirrors = materials_box();
    for m in &mut mirrors.materials {
        if matches!(m, Material::Diffuse { .. } | Material::Microfacet { .. }) {
            *m = Material::Mirror {
                reflectance: Vec3::splat(0.9),
            };
        }
    }
    let p = plan_of(&mirrors, 5);
    assert!(!p.light_sampling && !p.mis && p.bsdfs.delta && !p.bsdfs.scatters());
}

/// The specialised integrator (MIS off where nothing else finds the
/// lights) and the general one agree: on the point-lit scene, where the
/// plan changes the integrator, at two points; and the plan leaves the
/// materials box's integrator as it is.
#[test]
fn the_specialised_integrator_agrees_with_the_general_one() {
    let scene = point_lit();
    let bvh = accel(&scene);
    let world = World::new(&scene, &bvh);
    let general = tracer(LIGHTS, 4, true);
    let plan = Plan::new(&scene, &world.lights, &general, &ThinLens::PINHOLE);
    let specialised = plan.specialise(&general);
    assert!(general.direct.mis() && !specialised.direct.mis());
    let eye = Vec3::new(0.0, 1.0, 2.5);
    for (i, target) in [Vec3::new(0.2, 0.0, 0.1), Vec3::new(-0.5, 0.8, -1.0)]
        .into_iter()
        .enumerate()
    {
        let ray = ray_towards(eye, target);
        let a = estimate(&world, &general, &ray, 50_000, 60 + i as u64);
        let b = estimate(&world, &specialised, &ray, 50_000, 70 + i as u64);
        assert_means_agree(&format!("point-lit point {i}"), a, b, ALPHA / 2.0);
    }
    let materials = materials_box();
    let bvh = accel(&materials);
    let world = World::new(&materials, &bvh);
    let plan = Plan::new(&materials, &world.lights, &general, &ThinLens::PINHOLE);
    assert!(plan.specialise(&general).direct.mis());
}

/// The plan's casters line counts each kind: the materials box's three
/// smooth spheres and the mirror's light image; with a mirror quad added,
/// the sphere around it too; the point-lit scene none.
#[test]
fn the_plan_names_the_caustic_casters() {
    use pathtracer::world::casters::{CasterRule, Casters};
    let casters_line = |scene: &Scene| {
        let lights = LightSet::new(scene, LightConvention::Physical);
        let plan = plan_of(scene, 5).with_casters(&Casters::new(scene, &lights, CasterRule::Auto));
        plan.lines
            .into_iter()
            .find(|l| l.starts_with("plan: caustic casters: "))
            .expect("a casters line")
    };
    let spheres = casters_line(&materials_box());
    assert!(
        spheres.contains(": 3 sphere(s) (mirror, glass"),
        "{spheres}"
    );
    assert!(spheres.contains("1 light image(s)"), "{spheres}");
    assert!(!spheres.contains("meshes"), "{spheres}");

    let mut with_mesh = materials_box();
    with_mesh.materials.push(Material::Mirror {
        reflectance: Vec3::ONE,
    });
    let mirror = (with_mesh.materials.len() - 1) as u32;
    let mesh = &mut with_mesh.mesh;
    let base = mesh.positions.len() as u32;
    mesh.positions.extend([
        Vec3::new(0.5, 0.0, -0.9),
        Vec3::new(0.9, 0.0, -0.9),
        Vec3::new(0.9, 0.6, -0.9),
    ]);
    mesh.normals.extend([Vec3::Z; 3]);
    mesh.triangles.push([base, base + 1, base + 2]);
    mesh.materials.push(mirror);
    let line = casters_line(&with_mesh);
    assert!(
        line.contains(": 3 sphere(s) (mirror, glass")
            && line.contains(", 1 sphere(s) around mirror-like meshes"),
        "{line}"
    );
    assert!(casters_line(&point_lit()).contains("none"));
}

/// Glass splits where the scene has glass: the materials box's glass
/// sphere gets [`GLASS_SPLITS`], which `specialise` puts in the tracer;
/// the point-lit scene, without glass, none; and a flag's number
/// replaces the plan's, line included.
#[test]
fn the_plan_splits_glass_where_the_scene_has_it() {
    let line = |plan: &Plan| {
        plan.lines
            .iter()
            .find(|l| l.starts_with("plan: glass splits: "))
            .expect("a glass splits line")
            .clone()
    };
    let glass = plan_of(&materials_box(), 5);
    assert!(glass.bsdfs.glass && glass.glass_splits == GLASS_SPLITS);
    let general = tracer(LIGHTS, 5, true);
    assert_eq!(general.glass_splits, 0);
    assert_eq!(glass.specialise(&general).glass_splits, GLASS_SPLITS);
    assert!(line(&glass).contains(&format!("glass splits: {GLASS_SPLITS} (the plan's)")));

    let plain = plan_of(&point_lit(), 5);
    assert!(!plain.bsdfs.glass && plain.glass_splits == 0);
    assert!(
        line(&plain).ends_with("none (no glass)"),
        "{}",
        line(&plain)
    );

    let coin = plan_of(&materials_box(), 5).with_glass_splits(Some(0));
    assert_eq!(coin.specialise(&general).glass_splits, 0);
    assert!(line(&coin).contains("none (asked)"), "{}", line(&coin));
    let four = plan_of(&materials_box(), 5).with_glass_splits(Some(4));
    assert_eq!(four.specialise(&general).glass_splits, 4);
    assert!(line(&four).contains("4 (asked)"), "{}", line(&four));
    let unasked = plan_of(&materials_box(), 5).with_glass_splits(None);
    assert_eq!(unasked.glass_splits, GLASS_SPLITS);
}

/// Glint samples where an environment map lights mirror or glass seen
/// through a pinhole: the materials box (mirror and glass spheres) under
/// a map; not without the map, not in the point-lit diffuse scene under
/// it, not through a thin lens, and not where the flags turn them off,
/// each line saying why.
#[test]
fn the_plan_samples_glints_where_a_map_lights_mirror_or_glass() {
    let map = || {
        let sky = EnvironmentMap::from_fn("sky", 16, 8, |_| Vec3::ONE).unwrap();
        EnvironmentLight::new(sky, EnvironmentSampling::Importance)
    };
    let plan = |scene: &Scene, environment: bool, lens: &ThinLens| {
        let mut lights = LightSet::new(scene, LightConvention::Physical);
        if environment {
            lights = lights.with_environment(map());
        }
        Plan::new(scene, &lights, &tracer(LIGHTS, 5, true), lens)
    };
    let line = |plan: &Plan| {
        plan.lines
            .iter()
            .find(|l| l.starts_with("plan: glint samples: "))
            .expect("a glint samples line")
            .clone()
    };
    let on = plan(&materials_box(), true, &ThinLens::PINHOLE);
    assert!(
        on.glints && line(&on).contains("samples: on"),
        "{}",
        line(&on)
    );
    let lens = ThinLens {
        radius: 0.05,
        focal_distance: 3.0,
    };
    for (plan, why) in [
        (
            plan(&materials_box(), false, &ThinLens::PINHOLE),
            "no environment map",
        ),
        (
            plan(&point_lit(), true, &ThinLens::PINHOLE),
            "no mirror or glass",
        ),
        (plan(&materials_box(), true, &lens), "a thin lens"),
        (
            on.clone()
                .with_glints(Decision::off_by_flags(false, 64, false)),
            "--glints off",
        ),
        (
            on.clone()
                .with_glints(Decision::off_by_flags(true, 8, false)),
            "-s below 16",
        ),
        (
            on.clone()
                .with_glints(Decision::off_by_flags(true, 64, true)),
            "-a",
        ),
    ] {
        assert!(!plan.glints, "{}", line(&plan));
        assert!(
            line(&plan).contains(&format!("off ({why}")),
            "{}",
            line(&plan)
        );
    }
    assert!(
        on.with_glints(Decision::off_by_flags(true, 16, false))
            .glints
    );
}
