//! Part 1's glowing box, and the probe made of it that tells a 3-2
//! binary from a 3-1 one.

use std::path::{Path, PathBuf};

use super::write_own;
use crate::scene::{builtin, Material, MaterialId, Scene};

/// Part 1's scene ([`super::CheckScene::Glowing`]), and with the box's own
/// camera the one that tells a 3-2 binary from a 3-1 one
/// ([`write_lamp_probe`]): the Cornell box with each wall, the lamp and each ball emitting a
/// colour of its own (at most 0.6, below the tone map's white), and no
/// light, seen from the front right. At `-m 0` a 3-1 binary renders which
/// surface each camera ray meets first: the field of view, the camera's frame, triangles and
/// spheres, the nearest hit. The 3-2 starter's loader makes every
/// emissive surface emit nothing (its `EmissionBSDF` is given the
/// direction 0 and emits `radiance * max(0, dir . wo)`), so a 3-2 binary
/// renders it black.
pub fn glowing_box() -> Scene {
    let mut scene = builtin::cornell_box();
    scene.lights.clear();
    // Seen from the front right, not along -z: a camera frame left out
    // (rays in camera space) shows.
    scene.camera.dir_to_camera = glam::Vec3::new(0.4, 0.2, 1.0).normalize();
    // Each quad of the box (two triangles) and each ball its own colour.
    let quads = scene.mesh.triangles.len().div_ceil(2);
    let colour = |k: usize| {
        let hue = k as f32 * 0.618_034;
        let channel =
            |shift: f32| 0.05 + 0.55 * (0.5 + 0.5 * (std::f32::consts::TAU * (hue + shift)).cos());
        crate::math::Rgb::new(channel(0.0), channel(1.0 / 3.0), channel(2.0 / 3.0))
    };
    scene.materials = (0..quads + scene.spheres.len())
        .map(|k| Material::Emission {
            radiance: colour(k),
        })
        .collect();
    for (t, m) in scene.mesh.materials.iter_mut().enumerate() {
        *m = (t / 2) as MaterialId;
    }
    for (k, sphere) in scene.spheres.iter_mut().enumerate() {
        sphere.material = (quads + k) as MaterialId;
    }
    scene
}

/// The scene that tells a 3-2 binary from a 3-1 one
/// ([`crate::check::Student::renders_lamps_as_quads`]): [`glowing_box`] seen as
/// the Cornell box is, so that a camera a 3-1 binary gets wrong misses
/// the same in it as in the lit box; written into
/// `out/scenes/lamp-probe.dae`.
pub fn write_lamp_probe(out: &Path) -> Result<PathBuf, String> {
    let mut scene = glowing_box();
    scene.camera = builtin::cornell_box().camera;
    write_own(&scene, out, "lamp-probe.dae")
}
