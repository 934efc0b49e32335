//! Writes a triangle mesh as a COLLADA file in the course's dialect, so a
//! generated mesh (the scale benchmark's bumpy sphere of up to 10 million
//! triangles) can be rendered by `pathtracer` like any course scene.
//!
//! The file is Y-up (no axis map), with one `<triangles>` element of
//! vertex positions (the loader rebuilds the normals from connectivity,
//! as the course does), one diffuse material, a point light and a camera
//! whose course viewing direction ([`crate::scene::collada`]'s camera
//! module) is `dir_to_camera`.

use std::io::{self, Write};

use glam::Vec3;

use super::TriangleMesh;

/// What the file shows besides the mesh.
#[derive(Clone, Copy, Debug)]
pub struct ExportView {
    /// Direction from the scene towards the camera (the course re-places
    /// the camera along it to frame the scene).
    pub dir_to_camera: Vec3,
    /// Horizontal field of view, degrees.
    pub hfov_deg: f32,
    /// Position and intensity (W/sr per channel) of the point light.
    pub light_position: Vec3,
    pub light_intensity: f32,
    /// Albedo of the mesh's diffuse material.
    pub albedo: f32,
}

/// Writes `mesh` (positions and triangles; normals and materials are
/// not written) and `view` as a `.dae` document to `out`.
pub fn write_dae(mesh: &TriangleMesh, view: &ExportView, out: &mut impl Write) -> io::Result<()> {
    let (nv, nt) = (mesh.positions.len(), mesh.triangles.len());
    let [lx, ly, lz] = view.light_position.to_array();
    // T * (0, 0, -1, 1) must be the direction: translate by it plus +Z.
    let [cx, cy, cz] = (view.dir_to_camera + Vec3::Z).to_array();
    let (l, a) = (view.light_intensity, view.albedo);
    writeln!(out, r#"<?xml version="1.0" encoding="utf-8"?>"#)?;
    writeln!(
        out,
        r#"<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">"#
    )?;
    writeln!(out, "<asset><up_axis>Y_UP</up_axis></asset>")?;
    writeln!(
        out,
        r#"<library_cameras><camera id="cam"><optics><technique_common><perspective><xfov>{}</xfov><aspect_ratio>1.3333</aspect_ratio></perspective></technique_common></optics></camera></library_cameras>"#,
        view.hfov_deg
    )?;
    writeln!(
        out,
        r#"<library_lights><light id="lamp"><technique_common><point><color>{l} {l} {l}</color></point></technique_common></light></library_lights>"#
    )?;
    writeln!(
        out,
        r#"<library_effects><effect id="fx"><profile_COMMON><technique sid="common"><phong><diffuse><color>{a} {a} {a} 1</color></diffuse></phong></technique></profile_COMMON></effect></library_effects>"#
    )?;
    writeln!(
        out,
        r##"<library_materials><material id="mat"><instance_effect url="#fx"/></material></library_materials>"##
    )?;
    writeln!(out, r#"<library_geometries><geometry id="mesh"><mesh>"#)?;
    write!(
        out,
        r#"<source id="pos"><float_array id="pos-array" count="{}">"#,
        3 * nv
    )?;
    for p in &mesh.positions {
        write!(out, "{} {} {} ", p.x, p.y, p.z)?;
    }
    writeln!(out, "</float_array>")?;
    writeln!(
        out,
        r##"<technique_common><accessor source="#pos-array" count="{nv}" stride="3"/></technique_common></source>"##
    )?;
    writeln!(
        out,
        r##"<vertices id="vtx"><input semantic="POSITION" source="#pos"/></vertices>"##
    )?;
    write!(
        out,
        r##"<triangles material="skin" count="{nt}"><input semantic="VERTEX" source="#vtx" offset="0"/><p>"##
    )?;
    for [i, j, k] in &mesh.triangles {
        write!(out, "{i} {j} {k} ")?;
    }
    writeln!(
        out,
        "</p></triangles></mesh></geometry></library_geometries>"
    )?;
    writeln!(out, r#"<library_visual_scenes><visual_scene id="main">"#)?;
    writeln!(
        out,
        r##"<node id="camera-node"><matrix>1 0 0 {cx} 0 1 0 {cy} 0 0 1 {cz} 0 0 0 1</matrix><instance_camera url="#cam"/></node>"##
    )?;
    writeln!(
        out,
        r##"<node id="lamp-node"><matrix>1 0 0 {lx} 0 1 0 {ly} 0 0 1 {lz} 0 0 0 1</matrix><instance_light url="#lamp"/></node>"##
    )?;
    writeln!(
        out,
        r##"<node id="mesh-node"><instance_geometry url="#mesh"><bind_material><technique_common><instance_material symbol="skin" target="#mat"/></technique_common></bind_material></instance_geometry></node>"##
    )?;
    writeln!(out, "</visual_scene></library_visual_scenes>")?;
    writeln!(
        out,
        r##"<scene><instance_visual_scene url="#main"/></scene></COLLADA>"##
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::builtin::bumpy_sphere;
    use crate::scene::collada::load_str;
    use crate::scene::Light;

    /// Written and read back: the same positions, triangles, light and
    /// viewing direction.
    #[test]
    fn a_written_mesh_loads_back() {
        let scene = bumpy_sphere(16, 8);
        let view = ExportView {
            dir_to_camera: Vec3::new(0.0, 0.6, 0.8),
            hfov_deg: 40.0,
            light_position: Vec3::new(2.0, 3.0, 4.0),
            light_intensity: 30.0,
            albedo: 0.6,
        };
        let mut text = Vec::new();
        write_dae(&scene.mesh, &view, &mut text).unwrap();
        let loaded = load_str(std::str::from_utf8(&text).unwrap(), "test.dae").unwrap();
        assert_eq!(loaded.mesh.positions, scene.mesh.positions);
        assert_eq!(loaded.mesh.triangles, scene.mesh.triangles);
        assert!((loaded.camera.dir_to_camera - view.dir_to_camera).length() < 1e-6);
        assert!(matches!(
            loaded.lights.as_slice(),
            [Light::Point { position, .. }] if *position == view.light_position
        ));
    }
}
