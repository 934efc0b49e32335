//! Writes a whole scene (its meshes, spheres, materials, area and point
//! lights and camera) as a COLLADA file in the course's dialect, so that a
//! course binary renders the project's own scenes: the checker
//! ([`crate::check`]) hands a student's binary these where the course's
//! files are missing.
//!
//! The file is Z-up like every course file: world points are written as
//! `G p` with `G (x, y, z) = (-x, z, y)`, which is its own inverse, so the
//! course's loader maps them back. Every transform is a node `<matrix>`
//! whose columns are written in file space:
//!
//! - area light: the loader reads the centre `T (0,0,0,1)`, the emitting
//!   direction `T (0,0,-1,1) - c` and the edges `T (-1,0,0,1) - c` and
//!   `T (0,1,0,1) - c`, so the columns are `-dim_x`, `dim_y`, `-direction`
//!   and the centre;
//! - camera: only `normalize(T (0,0,-1,1))` counts (translation included),
//!   so `T` translates by `G dir_to_camera + (0, 0, 1)`;
//! - point light and sphere: a translation to the position or centre.
//!
//! Each connected part of the mesh is wound so that the normals the
//! course rebuilds agree with the scene's: the course reverses them on an
//! open part's boundary ([`super::course_normals`]), so a wall or a pane
//! is written the other way round.
//!
//! Materials are CGL techniques (diffuse as `<phong>`, the only shader
//! whose colour the course reads). The mesh is
//! written as one `<geometry>` and one node per material, each with the
//! vertices its triangles use and one `<polylist>` (with `<vcount>`): the
//! course's loaders read only a geometry's first `<polylist>` (the 2023
//! starters' read nothing else: a `<triangles>` element loads as an empty
//! mesh, on which they crash; the 2025 starter's fall back to the first
//! `<triangles>`) and only a node's first `<instance_material>`. Normals are
//! not written: the course rebuilds them from the connectivity, within
//! each geometry. Every camera, light, material, geometry and node has a
//! `name` as well as an `id`: the course's loader copies both into
//! strings and crashes on a missing one (a null `const char*`).

use std::fmt::Write as _;
use std::io::{self, Write};

use glam::Vec3;

use super::normals::area_weighted_vertex_normals;
use super::{Light, Material, Scene};

/// The course's `G`, from world space to the file's Z-up space (and back).
fn to_file(p: Vec3) -> Vec3 {
    Vec3::new(-p.x, p.z, p.y)
}

/// A `<matrix>` with columns `x`, `y`, `z` and translation `t`, row major.
fn matrix(x: Vec3, y: Vec3, z: Vec3, t: Vec3) -> String {
    let rows = (0..3).map(|r| format!("{} {} {} {}", x[r], y[r], z[r], t[r]));
    format!(
        "<matrix>{} 0 0 0 1</matrix>",
        rows.collect::<Vec<_>>().join(" ")
    )
}

fn translation(t: Vec3) -> String {
    matrix(Vec3::X, Vec3::Y, Vec3::Z, t)
}

fn triple(c: Vec3) -> String {
    format!("{} {} {}", c.x, c.y, c.z)
}

/// The effect of `material`, or why the course format cannot say it.
fn effect(material: &Material) -> Result<String, String> {
    let cgl =
        |body: String| format!(r#"<extra><technique profile="CGL">{body}</technique></extra>"#);
    Ok(match *material {
        Material::Diffuse { albedo } => format!(
            r#"<profile_COMMON><technique sid="common"><phong><diffuse><color>{} 1</color></diffuse></phong></technique></profile_COMMON>"#,
            triple(albedo)
        ),
        Material::Emission { radiance } => cgl(format!(
            "<emission><radiance>{}</radiance></emission>",
            triple(radiance)
        )),
        Material::Mirror { reflectance } => cgl(format!(
            "<mirror><reflectance>{}</reflectance></mirror>",
            triple(reflectance)
        )),
        Material::Glass {
            reflectance,
            transmittance,
            roughness,
            ior,
        } => cgl(format!(
            "<glass><reflectance>{}</reflectance><transmittance>{}</transmittance><roughness>{roughness}</roughness><ior>{ior}</ior></glass>",
            triple(reflectance),
            triple(transmittance)
        )),
        Material::Refraction {
            transmittance,
            roughness,
            ior,
        } => cgl(format!(
            "<refraction><transmittance>{}</transmittance><roughness>{roughness}</roughness><ior>{ior}</ior></refraction>",
            triple(transmittance)
        )),
        Material::Microfacet { alpha, eta, k } => cgl(format!(
            "<microfacet><alpha>{alpha}</alpha><eta>{}</eta><k>{}</k></microfacet>",
            triple(eta),
            triple(k)
        )),
        Material::EmissiveDiffuse { .. } => {
            return Err("an emissive diffuse material has no course equivalent".into())
        }
    })
}

/// The light's `<light>` body and its node's matrix.
fn light(light: &Light) -> Result<(String, String), String> {
    match *light {
        Light::Area {
            radiance,
            center,
            direction,
            dim_x,
            dim_y,
        } => Ok((
            format!(
                r#"<technique_common><point><color>{c}</color></point></technique_common><extra><technique profile="CGL"><area><color>{c}</color></area></technique></extra>"#,
                c = triple(radiance)
            ),
            matrix(
                -to_file(dim_x),
                to_file(dim_y),
                -to_file(direction),
                to_file(center),
            ),
        )),
        Light::Point {
            intensity,
            position,
        } => Ok((
            format!(
                "<technique_common><point><color>{}</color></point></technique_common>",
                triple(intensity)
            ),
            translation(to_file(position)),
        )),
        _ => Err(format!("a {} light is not written", light.kind())),
    }
}

/// Writes `scene` as a `.dae` document to `out`; an `InvalidInput` error
/// names what the course format cannot hold (an emissive diffuse material,
/// a directional, ambient or spot light), before anything is written.
pub fn write_scene_dae(scene: &Scene, out: &mut impl Write) -> io::Result<()> {
    let invalid = |e: String| io::Error::new(io::ErrorKind::InvalidInput, e);
    let effects: Vec<String> = scene
        .materials
        .iter()
        .map(effect)
        .collect::<Result<_, _>>()
        .map_err(invalid)?;
    let lights: Vec<(String, String)> = scene
        .lights
        .iter()
        .map(light)
        .collect::<Result<_, _>>()
        .map_err(invalid)?;
    let mut doc = String::from(
        r#"<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
<asset><up_axis>Z_UP</up_axis></asset>
"#,
    );
    let cam = &scene.camera;
    let _ = writeln!(
        doc,
        r#"<library_cameras><camera id="cam" name="cam"><optics><technique_common><perspective><xfov>{}</xfov><yfov>{}</yfov><znear>{}</znear><zfar>{}</zfar></perspective></technique_common></optics></camera></library_cameras>"#,
        cam.hfov_deg, cam.vfov_deg, cam.znear, cam.zfar
    );
    doc += "<library_lights>";
    for (i, (body, _)) in lights.iter().enumerate() {
        let _ = write!(
            doc,
            r#"<light id="light{i}" name="light{i}">{body}</light>"#
        );
    }
    doc += "</library_lights>\n<library_effects>";
    for (i, body) in effects.iter().enumerate() {
        let _ = write!(doc, r#"<effect id="fx{i}">{body}</effect>"#);
    }
    doc += "</library_effects>\n<library_materials>";
    for i in 0..effects.len() {
        let _ = write!(
            doc,
            r##"<material id="mat{i}" name="mat{i}"><instance_effect url="#fx{i}"/></material>"##
        );
    }
    doc += "</library_materials>\n<library_geometries>";
    let mesh_materials = used_materials(scene);
    write_mesh(scene, &mesh_materials, &mut doc);
    for (i, sphere) in scene.spheres.iter().enumerate() {
        let _ = write!(
            doc,
            r#"<geometry id="sphere{i}" name="sphere{i}"><extra><technique profile="CGL"><sphere><radius>{}</radius></sphere></technique></extra></geometry>"#,
            sphere.radius
        );
    }
    doc += "</library_geometries>\n<library_visual_scenes><visual_scene id=\"main\">\n";
    let camera_t = to_file(cam.dir_to_camera) + Vec3::Z;
    let _ = writeln!(
        doc,
        r##"<node id="camera" name="camera">{}<instance_camera url="#cam"/></node>"##,
        translation(camera_t)
    );
    for (i, (_, m)) in lights.iter().enumerate() {
        let _ = writeln!(
            doc,
            r##"<node id="light{i}-node" name="light{i}-node">{m}<instance_light url="#light{i}"/></node>"##
        );
    }
    let instance = |symbol: String, material: u32| {
        format!(r##"<instance_material symbol="{symbol}" target="#mat{material}"/>"##)
    };
    let bind = |instances: String| {
        format!("<bind_material><technique_common>{instances}</technique_common></bind_material>")
    };
    for &m in &mesh_materials {
        let _ = writeln!(
            doc,
            r##"<node id="mesh-m{m}-node" name="mesh-m{m}-node"><instance_geometry url="#mesh-m{m}">{}</instance_geometry></node>"##,
            bind(instance(format!("m{m}"), m))
        );
    }
    for (i, sphere) in scene.spheres.iter().enumerate() {
        let _ = writeln!(
            doc,
            r##"<node id="sphere{i}-node" name="sphere{i}-node">{}<instance_geometry url="#sphere{i}">{}</instance_geometry></node>"##,
            translation(to_file(sphere.center)),
            bind(instance(format!("s{i}"), sphere.material))
        );
    }
    doc += "</visual_scene></library_visual_scenes>\n<scene><instance_visual_scene url=\"#main\"/></scene>\n</COLLADA>\n";
    out.write_all(doc.as_bytes())
}

/// The materials the mesh's triangles use, in order.
fn used_materials(scene: &Scene) -> Vec<u32> {
    let mut used: Vec<u32> = scene.mesh.materials.clone();
    used.sort_unstable();
    used.dedup();
    used
}

/// The mesh: per material of `materials` (those its triangles use), a
/// geometry `mesh-m{material}` with the positions its triangles use, in
/// file space, and one `<polylist>` of them.
fn write_mesh(scene: &Scene, materials: &[u32], doc: &mut String) {
    let mesh = &scene.mesh;
    let positions = behind_their_lights(scene);
    let intended = if mesh.normals.len() == mesh.positions.len() {
        mesh.normals.clone()
    } else {
        area_weighted_vertex_normals(&mesh.positions, &mesh.triangles)
    };
    for &m in materials {
        let triangles: Vec<[u32; 3]> = mesh
            .triangles
            .iter()
            .zip(&mesh.materials)
            .filter(|(_, &tm)| tm == m)
            .map(|(t, _)| *t)
            .collect();
        let triangles = wound_for_the_course(&positions, &intended, &triangles);
        // The vertices these triangles use, numbered anew in order of use.
        let mut local = std::collections::HashMap::new();
        let mut used = Vec::new();
        let indices: Vec<u32> = triangles
            .iter()
            .flatten()
            .map(|&v| {
                *local.entry(v).or_insert_with(|| {
                    used.push(v);
                    used.len() as u32 - 1
                })
            })
            .collect();
        let n = used.len();
        let _ = write!(
            doc,
            r#"<geometry id="mesh-m{m}" name="mesh-m{m}"><mesh><source id="pos-m{m}"><float_array id="pos-m{m}-array" count="{}">"#,
            3 * n
        );
        for &v in &used {
            let _ = write!(doc, "{} ", triple(to_file(positions[v as usize])));
        }
        let _ = write!(
            doc,
            r##"</float_array><technique_common><accessor source="#pos-m{m}-array" count="{n}" stride="3"/></technique_common></source><vertices id="vtx-m{m}"><input semantic="POSITION" source="#pos-m{m}"/></vertices><polylist material="m{m}" count="{}"><input semantic="VERTEX" source="#vtx-m{m}" offset="0"/><vcount>"##,
            triangles.len()
        );
        doc.push_str(&"3 ".repeat(triangles.len()));
        doc.push_str("</vcount><p>");
        for v in indices {
            let _ = write!(doc, "{v} ");
        }
        doc.push_str("</p></polylist></mesh></geometry>");
    }
}

mod course_side;
pub use course_side::LAMP_SETBACK;
use course_side::{behind_their_lights, wound_for_the_course};

#[cfg(test)]
mod tests;
