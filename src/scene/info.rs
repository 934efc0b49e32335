//! `--info`: a one-item-per-line summary of a loaded scene.
//!
//! Always includes exactly these three lines (format fixed for scripts):
//!
//! ```text
//! triangles: N
//! spheres: N
//! camera: position (x, y, z) direction (x, y, z) hfov H vfov V
//! ```

use std::collections::BTreeMap;
use std::fmt::Write;

use glam::Vec3;

use super::{Light, Scene};
use crate::raygen::Camera;

fn vec(v: Vec3) -> String {
    format!("({:.4}, {:.4}, {:.4})", v.x, v.y, v.z)
}

/// Counts of each kind, as `kind N, kind N` sorted by kind.
fn counts<'a>(kinds: impl Iterator<Item = &'a str>) -> String {
    let mut map = BTreeMap::new();
    for k in kinds {
        *map.entry(k).or_insert(0) += 1;
    }
    map.iter()
        .map(|(k, n)| format!("{k} {n}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The summary; `camera` is the placed camera for the requested size.
pub fn describe(scene: &Scene, camera: &Camera) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "scene: {}", scene.source);
    let _ = writeln!(out, "triangles: {}", scene.mesh.triangles.len());
    let _ = writeln!(out, "spheres: {}", scene.spheres.len());
    let _ = writeln!(out, "vertices: {}", scene.mesh.positions.len());
    let _ = writeln!(
        out,
        "camera: position {} direction {} hfov {:.2} vfov {:.2}",
        vec(camera.position),
        vec(camera.view_direction()),
        camera.hfov_deg,
        camera.vfov_deg
    );
    let _ = writeln!(
        out,
        "lights: {} ({})",
        scene.lights.len(),
        counts(scene.lights.iter().map(Light::kind))
    );
    for light in &scene.lights {
        let line = match *light {
            Light::Area {
                radiance,
                center,
                direction,
                dim_x,
                dim_y,
            } => format!(
                "area radiance {} centre {} direction {} size {:.4} x {:.4}",
                vec(radiance),
                vec(center),
                vec(direction),
                dim_x.length(),
                dim_y.length()
            ),
            Light::Point {
                intensity,
                position,
            } => {
                format!(
                    "point intensity {} position {}",
                    vec(intensity),
                    vec(position)
                )
            }
            Light::Directional {
                radiance,
                direction,
            } => {
                format!(
                    "directional radiance {} towards {}",
                    vec(radiance),
                    vec(direction)
                )
            }
            Light::Ambient { radiance } => format!("ambient radiance {}", vec(radiance)),
            Light::Spot {
                intensity,
                position,
                ..
            } => {
                format!(
                    "spot intensity {} position {} (contributes nothing, as in the course)",
                    vec(intensity),
                    vec(position)
                )
            }
        };
        let _ = writeln!(out, "light: {line}");
    }
    let _ = writeln!(
        out,
        "materials: {} ({})",
        scene.materials.len(),
        counts(scene.materials.iter().map(|m| m.kind()))
    );
    for warning in &scene.warnings {
        let _ = writeln!(out, "warning: {warning}");
    }
    out
}
