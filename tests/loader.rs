//! The COLLADA loader on the course's scene files and on a self-made scene.
//! Expected values were worked out by hand from the files (see each test).

mod common;

use glam::Vec3;
use pathtracer::scene::{collada, load, Light, Material, Scene};

use common::{course_file, course_scene, course_scenes, MINIMAL};

fn close(a: Vec3, b: Vec3, tol: f32) -> bool {
    (a - b).abs().max_element() <= tol
}

fn course(name: &str) -> Option<Scene> {
    course_scene(name)
}

/// The bounding box of every mesh vertex and sphere.
fn bounds(scene: &Scene) -> (Vec3, Vec3) {
    let mut lo = Vec3::splat(f32::INFINITY);
    let mut hi = -lo;
    for &p in &scene.mesh.positions {
        (lo, hi) = (lo.min(p), hi.max(p));
    }
    for s in &scene.spheres {
        (lo, hi) = (lo.min(s.center - s.radius), hi.max(s.center + s.radius));
    }
    (lo, hi)
}

/// Materials of the triangles whose vertices all satisfy `on`.
fn materials_where(scene: &Scene, on: impl Fn(Vec3) -> bool) -> Vec<Material> {
    let m = &scene.mesh;
    m.triangles
        .iter()
        .zip(&m.materials)
        .filter(|(t, _)| t.iter().all(|&v| on(m.positions[v as usize])))
        .map(|(_, &id)| scene.materials[id as usize])
        .collect()
}

#[test]
fn every_course_file_loads_with_its_primitive_counts() {
    // (file, triangles, spheres, lights, materials): counted by hand from
    // the polylist counts, sphere nodes, light nodes and materials used.
    let expected = [
        ("CBbunny.dae", 28_588, 0, 1, 7),
        ("CBempty.dae", 12, 0, 1, 6),
        ("CBspheres.dae", 12, 2, 1, 8),
        ("CBspheres_lambertian.dae", 12, 2, 1, 8),
        ("CBspheres_microfacet_al_ag.dae", 12, 2, 1, 8),
        ("bunny.dae", 33_696, 0, 1, 2),
        ("bunny_unlit.dae", 33_696, 0, 1, 2),
        ("cube.dae", 12, 0, 1, 1),
        ("plane.dae", 2, 0, 1, 1),
        ("teapot.dae", 2_464, 0, 1, 1),
    ];
    // Each expected file that is missing is named as skipped; every course
    // file found, expected or not, has to load.
    for (name, ..) in &expected {
        course_file(name);
    }
    let Some(files) = course_scenes() else { return };
    for path in files {
        let scene = load(&path).unwrap_or_else(|e| panic!("{e}"));
        let name = path.file_name().unwrap().to_str().unwrap();
        let m = &scene.mesh;
        assert_eq!(m.materials.len(), m.triangles.len());
        assert_eq!(m.normals.len(), m.positions.len());
        // A course file this test has no counts for still has to load.
        let Some(&(_, triangles, spheres, lights, materials)) =
            expected.iter().find(|e| e.0 == name)
        else {
            println!("{name}: loaded; no expected counts to compare");
            continue;
        };
        assert_eq!(m.triangles.len(), triangles, "{name} triangles");
        assert_eq!(scene.spheres.len(), spheres, "{name} spheres");
        assert_eq!(scene.lights.len(), lights, "{name} lights");
        assert_eq!(scene.materials.len(), materials, "{name} materials");
        assert!(scene.warnings.is_empty(), "{name}: {:?}", scene.warnings);
    }
}

#[test]
fn cbspheres_lambertian_matches_the_format_doc() {
    let Some(scene) = course("CBspheres_lambertian.dae") else {
        return;
    };
    let [Light::Area {
        radiance,
        center,
        direction,
        dim_x,
        dim_y,
    }] = scene.lights[..]
    else {
        panic!("{:?}", scene.lights)
    };
    assert_eq!(radiance, Vec3::splat(10.0));
    assert!(close(center, Vec3::new(0.0, 1.49, 0.0), 1e-5), "{center}");
    assert!(close(direction, Vec3::NEG_Y, 1e-5), "{direction}");
    assert!((dim_x.length() - 0.6).abs() < 1e-5 && (dim_y.length() - 0.8).abs() < 1e-5);

    // Sphere1 at file (-0.4, 0.3, 0.3) and Sphere2 at (0.4, -0.3, 0.3), through G.
    let centers: Vec<Vec3> = scene.spheres.iter().map(|s| s.center).collect();
    assert!(
        close(centers[0], Vec3::new(0.4, 0.3, 0.3), 1e-5),
        "{centers:?}"
    );
    assert!(
        close(centers[1], Vec3::new(-0.4, 0.3, -0.3), 1e-5),
        "{centers:?}"
    );
    for s in &scene.spheres {
        assert!((s.radius - 0.3).abs() < 1e-6);
        let albedo = Vec3::splat(0.8);
        assert_eq!(
            scene.materials[s.material as usize],
            Material::Diffuse { albedo }
        );
    }

    // The emissive mesh `light` just below the ceiling, and the left wall.
    let light = materials_where(&scene, |p| (p.y - 1.49).abs() < 1e-4);
    let glow = Material::Emission {
        radiance: Vec3::splat(10.0),
    };
    assert_eq!(light, vec![glow; 2]);
    let left = materials_where(&scene, |p| (p.x + 1.0).abs() < 1e-4);
    assert_eq!(left.len(), 2);
    for m in left {
        let Material::Diffuse { albedo } = m else {
            panic!("{m:?}")
        };
        assert!(close(albedo, Vec3::new(0.6, 0.2, 0.2), 1e-6));
    }

    let (lo, hi) = bounds(&scene);
    assert!(close(lo, Vec3::new(-1.0, 0.0, -1.0), 1e-3), "{lo}");
    assert!(close(hi, Vec3::new(1.0, 1.5, 1.0), 1e-2), "{hi}");
    // The camera matrix `-1 0 0 0 0 0 1 3 0 1 0 0`: T(0,0,-1) = (0,2,0), G -> +Z.
    assert!(close(scene.camera.dir_to_camera, Vec3::Z, 1e-6));
    assert_eq!(scene.camera.hfov_deg, 49.13434);
    assert!((scene.camera.vfov_deg - 37.85).abs() < 0.01);
}

#[test]
fn cbbunny_camera_and_mirrored_walls() {
    let Some(scene) = course("CBbunny.dae") else {
        return;
    };
    // `1 0 0 0 0 0 -1 -3 0 1 0 0 0 0 0 1`: T(0,0,-1) = (0,-2,0), G -> -Z.
    assert!(close(scene.camera.dir_to_camera, Vec3::NEG_Z, 1e-6));
    // CBbunny's walls map (x,y,z) -> (-x, y, -z): the red wall is at +X.
    let right = materials_where(&scene, |p| (p.x - 1.0).abs() < 1e-4);
    let red = Material::Diffuse {
        albedo: Vec3::new(0.6, 0.2, 0.2),
    };
    assert!(
        right.len() == 2 && right.iter().all(|m| *m == red),
        "{right:?}"
    );
    let (lo, hi) = bounds(&scene);
    assert!(close(lo, Vec3::new(-1.0, 0.0, -1.0), 1e-3), "{lo}");
    assert!(close(hi, Vec3::new(1.0, 1.5, 1.0), 1e-3), "{hi}");
}

#[test]
fn cbspheres_mirror_and_glass() {
    let Some(scene) = course("CBspheres.dae") else {
        return;
    };
    let kinds: Vec<Material> = scene
        .spheres
        .iter()
        .map(|s| scene.materials[s.material as usize])
        .collect();
    let glass = Material::Glass {
        reflectance: Vec3::ONE,
        transmittance: Vec3::ONE,
        roughness: 0.0,
        ior: 1.45,
    };
    assert_eq!(
        kinds,
        vec![
            glass,
            Material::Mirror {
                reflectance: Vec3::ONE
            }
        ]
    );
}

#[test]
fn teapot_directional_bunny_ambient_cbempty_point() {
    if let Some(teapot) = course("teapot.dae") {
        // T = [0.707 0.5 0.5 1; -0.707 0.5 0.5 1; 0 -0.707 0.707 1.5]:
        // T(0,0,-1) = (0.5, 0.5, 0.793), G -> (-0.5, 0.793, 0.5).
        let expected = Vec3::new(-0.5, 1.5 - std::f32::consts::FRAC_1_SQRT_2, 0.5).normalize();
        assert!(
            matches!(teapot.lights[..], [Light::Directional { radiance, direction }]
                if radiance == Vec3::ONE && close(direction, expected, 1e-5)),
            "{:?}",
            teapot.lights
        );
    }
    if let Some(bunny) = course("bunny.dae") {
        let sky = Light::Ambient {
            radiance: Vec3::ONE,
        };
        assert_eq!(bunny.lights, vec![sky]);
    }
    if let Some(empty) = course("CBempty.dae") {
        // No CGL block: a point light of intensity 5 at T(0,0,0) = (0, 0.0043, 1.49).
        let at = Vec3::new(0.0, 1.49, 0.004315853);
        assert!(
            matches!(empty.lights[..], [Light::Point { intensity, position }]
                if intensity == Vec3::splat(5.0) && close(position, at, 1e-5)),
            "{:?}",
            empty.lights
        );
    }
}

#[test]
fn cube_without_bound_material_gets_the_default() {
    let Some(scene) = course("cube.dae") else {
        return;
    };
    assert_eq!(scene.materials, vec![Material::DEFAULT]);
}

#[test]
fn a_fifteen_number_camera_matrix_loads_with_a_warning() {
    let Some(path) = course_file("CBspheres.dae") else {
        return;
    };
    let text = std::fs::read_to_string(path).unwrap();
    let full = "-1 0 0 0 0 0 1 3 0 1 0 0 0 0 0 1</matrix>";
    assert_eq!(text.matches(full).count(), 1);
    let short = text.replace(full, "-1 0 0 0 0 0 1 3 0 1 0 0 0 0 0</matrix>");
    let scene = collada::load_str(&short, "CBspheres-15.dae").unwrap();
    assert_eq!(scene.warnings.len(), 1, "{:?}", scene.warnings);
    assert!(
        scene.warnings[0].contains("node[id=Camera]/matrix"),
        "{:?}",
        scene.warnings
    );
    // Only w changes, and the course ignores it: same direction as before.
    assert!(close(scene.camera.dir_to_camera, Vec3::Z, 1e-6));
}

#[test]
fn the_minimal_scene_loads_as_computed_by_hand() {
    let scene = collada::load_str(MINIMAL, "minimal.dae").unwrap_or_else(|e| panic!("{e}"));
    assert!(scene.warnings.is_empty(), "{:?}", scene.warnings);
    let red = Material::Diffuse {
        albedo: Vec3::new(0.7, 0.1, 0.1),
    };
    let glow = Material::Emission {
        radiance: Vec3::splat(3.0),
    };
    assert_eq!(scene.materials, vec![red, glow]);
    let m = &scene.mesh;
    // The quad 0 1 2 3 fans into (0,1,2), (0,2,3); then 0 1 4; then 2 3 4.
    assert_eq!(
        m.triangles,
        vec![[0, 1, 2], [0, 2, 3], [0, 1, 4], [2, 3, 4]]
    );
    assert_eq!(m.materials, vec![0, 0, 0, 1]);
    assert!(close(m.positions[4], Vec3::new(-3.0, 2.0, 1.0), 1e-6));
    assert!(m.normals.iter().all(|n| (n.length() - 1.0).abs() < 1e-5));
    let [ball] = scene.spheres[..] else { panic!() };
    assert!(close(ball.center, Vec3::new(0.0, 2.0, 0.0), 1e-6));
    assert_eq!((ball.radius, ball.material), (1.0, 0));
    let point = Light::Point {
        intensity: Vec3::splat(2.0),
        position: Vec3::new(0.0, 2.0, 0.0),
    };
    assert_eq!(scene.lights, vec![point]);
    let cam = scene.camera;
    assert!(close(cam.dir_to_camera, Vec3::NEG_Z, 1e-6));
    let vfov = 2.0 * ((20f32).to_radians().tan() / 1.5).atan().to_degrees();
    assert_eq!((cam.hfov_deg, cam.znear, cam.zfar), (40.0, 0.1, 50.0));
    assert!((cam.vfov_deg - vfov).abs() < 1e-4);
}

#[test]
fn without_a_scene_element_the_first_visual_scene_is_used() {
    let text = common::corrupt(
        r##"<scene><instance_visual_scene url="#main"/></scene>"##,
        "",
    );
    let scene = collada::load_str(&text, "minimal.dae").unwrap();
    assert_eq!((scene.mesh.triangles.len(), scene.spheres.len()), (4, 1));
}

#[test]
fn an_unbound_symbol_warns_and_uses_the_default_material() {
    let text = common::corrupt(r#"symbol="shine""#, r#"symbol="sheen""#);
    let scene = collada::load_str(&text, "minimal.dae").unwrap();
    assert_eq!(
        scene.materials[scene.mesh.materials[3] as usize],
        Material::DEFAULT
    );
    assert!(scene.warnings.len() == 1 && scene.warnings[0].contains("\"shine\""));
}
