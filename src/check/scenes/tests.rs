//! The check scenes' round trips through the course's format.

use super::*;

/// The specular box, written in the course's dialect and read back:
/// the same glass faces in the same places, each facing out of the
/// cube (the pane towards the camera), the two balls, no copper.
#[test]
fn the_specular_box_survives_the_course_format() {
    let scene = specular_box();
    let mut text = Vec::new();
    export_scene::write_scene_dae(&scene, &mut text).unwrap();
    let loaded =
        scene::collada::load_str(std::str::from_utf8(&text).unwrap(), "specular.dae").unwrap();
    assert!(loaded.warnings.is_empty(), "{:?}", loaded.warnings);
    let is = |s: &Scene, m: MaterialId, glass: bool| match s.materials[m as usize] {
        Material::Glass { .. } => glass,
        Material::Microfacet { .. } => panic!("a microfacet material is used"),
        _ => !glass,
    };
    // Each glass triangle's centroid and shading normal (as the course
    // rebuilds it from the file, the winding's where the box was built).
    let glass_faces = |s: &Scene| {
        s.mesh
            .triangles
            .iter()
            .zip(&s.mesh.materials)
            .filter(|(_, &m)| is(s, m, true))
            .map(|(t, _)| {
                let p = t.map(|i| s.mesh.positions[i as usize]);
                ((p[0] + p[1] + p[2]) / 3.0, s.mesh.normals[t[0] as usize])
            })
            .collect::<Vec<(Vec3, Vec3)>>()
    };
    let (a, b) = (glass_faces(&loaded), glass_faces(&scene));
    assert_eq!((a.len(), b.len()), (14, 14));
    for ((p, n), (q, m)) in a.iter().zip(&b) {
        assert!((*p - *q).length() < 1e-5 && (*n - *m).length() < 1e-4);
    }
    for (p, n) in &a[..12] {
        assert!((*p - CUBE_CENTRE).dot(*n) > 0.1, "{p} {n}");
    }
    assert!(a[12..].iter().all(|(_, n)| n.z > 0.999));
    assert_eq!(loaded.spheres.len(), 2);
    for s in &loaded.spheres {
        is(&loaded, s.material, false);
    }
}

/// The rough-metal box and the mesh box, written in the course's
/// dialect and read back: the same balls of copper (roughness, eta
/// and k), as many triangles of the same total area.
#[test]
fn the_microfacet_and_mesh_boxes_survive_the_course_format() {
    let round_trip = |scene: &Scene| {
        let mut text = Vec::new();
        export_scene::write_scene_dae(scene, &mut text).unwrap();
        let loaded =
            scene::collada::load_str(std::str::from_utf8(&text).unwrap(), "box.dae").unwrap();
        assert!(loaded.warnings.is_empty(), "{:?}", loaded.warnings);
        loaded
    };
    let metal = |s: &Scene| -> Vec<(f32, Vec3, Vec3)> {
        s.spheres
            .iter()
            .filter_map(|b| match s.materials[b.material as usize] {
                Material::Microfacet { alpha, eta, k } => Some((alpha, eta, k)),
                _ => None,
            })
            .collect()
    };
    let scene = microfacet_box();
    let metals = metal(&scene);
    assert_eq!(metals.len(), 2);
    assert_eq!(metal(&round_trip(&scene)), metals);
    let mesh = CheckScene::Mesh.own();
    let loaded = round_trip(&mesh);
    assert_eq!(loaded.mesh.triangles.len(), mesh.mesh.triangles.len());
    let area = |s: &Scene| -> f32 {
        s.mesh
            .triangles
            .iter()
            .map(|t| {
                let p = t.map(|i| s.mesh.positions[i as usize]);
                0.5 * (p[1] - p[0]).cross(p[2] - p[0]).length()
            })
            .sum()
    };
    assert!((area(&loaded) / area(&mesh) - 1.0).abs() < 1e-5);
    assert!(
        mesh.mesh.triangles.len() > 448,
        "two balls of 224 and the box"
    );
}

/// `--scenes` is searched with its subfolders (the course's `dae/` keeps
/// its scenes in folders such as `sky/`); a scene not found there is
/// replaced by the project's stand-in with a warning that names the
/// missing file.
#[test]
fn course_scenes_are_found_in_subfolders_and_a_stand_in_is_said() {
    let dir = tempfile::tempdir().unwrap();
    let dae = dir.path().join("dae");
    std::fs::create_dir_all(dae.join("sky")).unwrap();
    let mut text = Vec::new();
    export_scene::write_scene_dae(&builtin::cornell_box(), &mut text).unwrap();
    std::fs::write(dae.join("sky").join(COURSE_SCENE), &text).unwrap();
    let out = dir.path().join("out");
    let found = CheckScene::Lambertian.file(Some(&dae), &out).unwrap();
    assert_eq!(found.path, dae.join("sky").join(COURSE_SCENE));
    assert_eq!(found.warning, None);
    let stand_in = CheckScene::Microfacet.file(Some(&dae), &out).unwrap();
    assert_eq!(stand_in.path, out.join("scenes").join("microfacet-box.dae"));
    let warning = stand_in.warning.unwrap();
    assert!(
        warning.contains(COURSE_MICROFACET_SCENE) && warning.contains("stand-in"),
        "{warning}"
    );
    // The project's own scenes stand in for no course file: no warning.
    for own in [CheckScene::Specular, CheckScene::Mesh] {
        assert_eq!(own.file(Some(&dae), &out).unwrap().warning, None);
    }
}
