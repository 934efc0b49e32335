//! The exporter's round trips and the course loaders' needs.

use super::*;
use crate::scene::builtin;
use crate::scene::collada::load_str;

fn round_trip(scene: &Scene) -> Scene {
    let mut text = Vec::new();
    write_scene_dae(scene, &mut text).unwrap();
    load_str(std::str::from_utf8(&text).unwrap(), "exported.dae").unwrap()
}

fn close(a: Vec3, b: Vec3) -> bool {
    (a - b).length() <= 1e-5 * (1.0 + b.length())
}

/// The built-in boxes, written and read back by the course's rules
/// (the loader applies `G` and the node matrices): the same triangles
/// with the same materials and the same shading normals as the course
/// rebuilds them, spheres, lights and camera.
#[test]
fn the_built_in_boxes_load_back_as_they_were() {
    for scene in [
        builtin::cornell_box(),
        builtin::materials_box(),
        builtin::mesh_balls_box(),
    ] {
        let loaded = round_trip(&scene);
        assert!(loaded.warnings.is_empty(), "{:?}", loaded.warnings);
        // Each triangle's corners with their shading normals, in a fixed
        // order (the file may wind a part the other way: the normals
        // the course rebuilds are what must come back).
        let corners = |s: &Scene| -> Vec<(Vec<(Vec3, Vec3)>, Material)> {
            let mut v: Vec<_> = s
                .mesh
                .triangles
                .iter()
                .zip(&s.mesh.materials)
                .map(|(t, &m)| {
                    let mut c: Vec<(Vec3, Vec3)> = t
                        .iter()
                        .map(|&i| (s.mesh.positions[i as usize], s.mesh.normals[i as usize]))
                        .collect();
                    c.sort_by(|a, b| format!("{:?}", a.0).cmp(&format!("{:?}", b.0)));
                    (c, s.materials[m as usize])
                })
                .collect();
            v.sort_by(|a, b| format!("{a:?}").cmp(&format!("{b:?}")));
            v
        };
        let (a, b) = (corners(&loaded), corners(&scene));
        assert_eq!(a.len(), b.len());
        for ((pa, ma), (pb, mb)) in a.iter().zip(&b) {
            assert!(
                pa.iter()
                    .zip(pb)
                    .all(|(x, y)| close(x.0, y.0) && (x.1 - y.1).length() < 1e-4),
                "{pa:?} {pb:?}"
            );
            assert_eq!(ma, mb);
        }
        assert_eq!(loaded.spheres.len(), scene.spheres.len());
        for (s, t) in loaded.spheres.iter().zip(&scene.spheres) {
            assert!(close(s.center, t.center) && (s.radius - t.radius).abs() < 1e-6);
            assert_eq!(
                loaded.materials[s.material as usize],
                scene.materials[t.material as usize]
            );
        }
        assert_eq!(loaded.lights.len(), scene.lights.len());
        for (l, m) in loaded.lights.iter().zip(&scene.lights) {
            match (l, m) {
                (
                    Light::Area {
                        radiance: r1,
                        center: c1,
                        direction: d1,
                        dim_x: x1,
                        dim_y: y1,
                    },
                    Light::Area {
                        radiance: r2,
                        center: c2,
                        direction: d2,
                        dim_x: x2,
                        dim_y: y2,
                    },
                ) => {
                    assert_eq!(r1, r2);
                    assert!(close(*c1, *c2) && close(*d1, *d2));
                    assert!(close(*x1, *x2) && close(*y1, *y2), "{x1} {x2} {y1} {y2}");
                }
                _ => panic!("{l:?} against {m:?}"),
            }
        }
        let (c, d) = (loaded.camera, scene.camera);
        assert!(close(c.dir_to_camera, d.dir_to_camera), "{c:?} {d:?}");
        assert!((c.hfov_deg - d.hfov_deg).abs() < 1e-4 && (c.vfov_deg - d.vfov_deg).abs() < 1e-4);
    }
}

/// Every mesh geometry holds one `<polylist>` (the only element the
/// 2023 loaders read; they read a geometry's first), its `<vcount>`
/// one 3 a triangle, each mesh node binds one material, and every
/// element the course's loader names has a `name`.
#[test]
fn meshes_are_one_polylist_a_geometry_and_everything_is_named() {
    let scene = builtin::mesh_balls_box();
    let mut text = Vec::new();
    write_scene_dae(&scene, &mut text).unwrap();
    let text = String::from_utf8(text).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    let named = |n: roxmltree::Node, name: &str| n.has_tag_name(name);
    let meshes: Vec<_> = doc.descendants().filter(|n| named(*n, "mesh")).collect();
    assert_eq!(meshes.len(), used_materials(&scene).len());
    let mut triangles = 0;
    for mesh in meshes {
        assert!(!mesh.descendants().any(|n| named(n, "triangles")));
        let lists: Vec<_> = mesh.children().filter(|n| named(*n, "polylist")).collect();
        assert_eq!(lists.len(), 1);
        let count: usize = lists[0].attribute("count").unwrap().parse().unwrap();
        let vcount = lists[0].children().find(|n| named(*n, "vcount")).unwrap();
        let sizes: Vec<&str> = vcount.text().unwrap().split_whitespace().collect();
        assert_eq!(sizes.len(), count);
        assert!(sizes.iter().all(|s| *s == "3"));
        triangles += count;
    }
    assert_eq!(triangles, scene.mesh.triangles.len());
    for element in doc.descendants().filter(|n| {
        ["camera", "light", "material", "geometry", "node"]
            .iter()
            .any(|name| named(*n, name))
    }) {
        assert!(element.attribute("name").is_some(), "{element:?}");
    }
    for node in doc.descendants().filter(|n| named(*n, "instance_geometry")) {
        let bound = node
            .descendants()
            .filter(|n| named(*n, "instance_material"));
        assert_eq!(bound.count(), 1);
    }
}

/// What the course format cannot hold is refused before a byte is
/// written.
#[test]
fn what_the_format_cannot_hold_is_refused() {
    let mut scene = builtin::cornell_box();
    scene.lights.push(Light::Ambient {
        radiance: Vec3::ONE,
    });
    let mut text = Vec::new();
    let error = write_scene_dae(&scene, &mut text).unwrap_err();
    assert_eq!(error.kind(), io::ErrorKind::InvalidInput);
    assert!(error.to_string().contains("ambient"), "{error}");
    assert!(text.is_empty());
}
