//! The scenes the checks render, and the files handed to the student's
//! binary.
//!
//! - [`CheckScene::Lambertian`] (parts 3 to 5 and 8): the course's
//!   `CBspheres_lambertian.dae` where one is found (`--scenes DIR`, else
//!   `CS184_SCENES`), else the project's own Cornell box
//!   ([`builtin::cornell_box`]);
//! - [`CheckScene::Mesh`] (part 2): always the project's Cornell box with
//!   balls of triangles ([`builtin::mesh_balls_box`]): its coarse smooth
//!   normals show permuted barycentrics, its nested balls a traversal that
//!   stops at the first hit or keeps `max_t`. The course's `CBbunny.dae`
//!   shows neither whatever the student's tree: its triangles are about a
//!   pixel each, with nearly equal vertex normals, and what shows through
//!   a wrong traversal depends on the tree. Measured on a C++ solution:
//!   with the bunny none of the three was named; with this box each is,
//!   fitting (misfit 0.1 a cell), the next suspect at 1.1 or more;
//! - [`CheckScene::Specular`] (part 6): always the project's own box of
//!   mirror and glass, [`specular_box`]. The course's `CBspheres.dae`
//!   holds a mirror ball and a glass ball only, and in a closed ball two
//!   of part 6's mistakes cannot show: the `1 / eta^2` of the radiance
//!   entering cancels the `eta^2` of it leaving, and light inside a ball
//!   never meets the critical angle. This box adds a glass cube turned
//!   45 degrees (light entering one face meets the next at about 62
//!   degrees, past the critical 41.8: total internal reflection) and a
//!   single glass pane across the box's opening (light crosses it once,
//!   so the starter's `eta^2` shows: what lies behind it is
//!   `ior^2 = 2.25` times as bright in a correct 3-2 solution);
//! - [`CheckScene::Microfacet`] (part 6's rough metal): the course's
//!   `CBspheres_microfacet_al_ag.dae` where one is found, else the
//!   project's Cornell box with copper balls ([`microfacet_box`]);
//! - [`CheckScene::Sky`] (part 7): two diffuse balls on a floor, no
//!   light but the sky of [`super::sky`], written beside the scene as
//!   `sky-balls.exr` and given with `-e`.
//!
//! Each is written in the course's dialect ([`export_scene`]) into the
//! output folder and read back by the project's loader, so that the
//! reference renders what the student's binary reads.

use std::path::{Path, PathBuf};

use glam::Vec3;

use super::battery::Stage;
use crate::course::{Assignment, CourseExact};
use crate::environment::{EnvironmentLight, EnvironmentMap, EnvironmentSampling};
use crate::scene::{self, builtin, course_files, export_scene, Material, MaterialId, Scene};

/// Which scene a check renders.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CheckScene {
    /// Diffuse balls in a Cornell box.
    Lambertian,
    /// A mesh in a Cornell box: the course's bunny, or the project's
    /// balls of triangles.
    Mesh,
    /// A mirror ball, a glass ball, a glass cube and a glass pane in a
    /// Cornell box ([`specular_box`]).
    Specular,
    /// Rough metal balls in a Cornell box ([`microfacet_box`]), or the
    /// course's aluminium and silver ones.
    Microfacet,
    /// Diffuse balls on a floor lit by an environment map alone
    /// ([`sky_balls`], [`super::sky`]).
    Sky,
    /// The Cornell box whose every wall and ball glows a colour of its own,
    /// without light ([`glowing_box`]): at `-m 0` an image of which
    /// surface each camera ray hits first.
    Glowing,
}

/// The course scene [`CheckScene::Lambertian`] prefers.
pub const COURSE_SCENE: &str = "CBspheres_lambertian.dae";

/// The course scene [`CheckScene::Microfacet`] prefers.
pub const COURSE_MICROFACET_SCENE: &str = "CBspheres_microfacet_al_ag.dae";

impl CheckScene {
    /// Every one, in the battery's order.
    pub const ALL: [CheckScene; 6] = [
        CheckScene::Glowing,
        CheckScene::Lambertian,
        CheckScene::Mesh,
        CheckScene::Specular,
        CheckScene::Microfacet,
        CheckScene::Sky,
    ];

    /// The file name it is written to in `out/scenes/`.
    fn file_name(self) -> &'static str {
        match self {
            CheckScene::Lambertian => "cornell-box.dae",
            CheckScene::Mesh => "mesh-balls-box.dae",
            CheckScene::Specular => "specular-box.dae",
            CheckScene::Microfacet => "microfacet-box.dae",
            CheckScene::Sky => "sky-balls.dae",
            CheckScene::Glowing => "glowing-box.dae",
        }
    }

    /// The project's own scene.
    fn own(self) -> Scene {
        match self {
            CheckScene::Lambertian => builtin::cornell_box(),
            CheckScene::Mesh => builtin::mesh_balls_box(),
            CheckScene::Specular => specular_box(),
            CheckScene::Microfacet => microfacet_box(),
            CheckScene::Sky => sky_balls(),
            CheckScene::Glowing => glowing_box(),
        }
    }

    /// The course's scene this one stands in for, used where found.
    fn course_file(self) -> Option<&'static str> {
        match self {
            CheckScene::Lambertian => Some(COURSE_SCENE),
            CheckScene::Microfacet => Some(COURSE_MICROFACET_SCENE),
            CheckScene::Mesh | CheckScene::Specular | CheckScene::Sky | CheckScene::Glowing => None,
        }
    }

    /// The environment map's file beside the scene file `scene_file`, for
    /// the scene lit by one.
    pub fn environment_file(self, scene_file: &Path) -> Option<PathBuf> {
        (self == CheckScene::Sky).then(|| scene_file.with_extension("exr"))
    }

    /// The stage of the scene `scene` read from `file` (with
    /// [`Stage::remembering`] when `remember`), lit by its environment
    /// map as the course's 3-2 solution samples it, read back from its
    /// file.
    pub fn stage(self, file: &Path, scene: Scene, remember: bool) -> Result<Stage, String> {
        let stage = if remember {
            Stage::remembering(scene)
        } else {
            Stage::new(scene)
        };
        let Some(map_file) = self.environment_file(file) else {
            return Ok(stage);
        };
        let map = EnvironmentMap::load(&map_file).map_err(|e| e.to_string())?;
        let weights = CourseExact {
            assignment: Assignment::PathTracer2,
        }
        .environment_weights();
        Ok(stage.lit_by(EnvironmentLight::with_weights(
            map,
            EnvironmentSampling::Importance,
            weights,
        )))
    }

    /// The scene file to give the student, the scene as this project
    /// loads it, and a warning when a stand-in is used for a course scene
    /// that was not found: for [`CheckScene::Lambertian`] and
    /// [`CheckScene::Microfacet`] the course's
    /// file found anywhere under `scenes` (the course's `dae/` keeps its
    /// scenes in subfolders) when there, else the project's own written
    /// to `out/scenes/`.
    pub fn file(self, scenes: Option<&Path>, out: &Path) -> Result<SceneFile, String> {
        let root = scenes.map(Path::to_path_buf);
        let mut warning = None;
        if let Some(name) = self.course_file() {
            if let Some(path) = root
                .as_ref()
                .and_then(|r| course_files::find_in(std::slice::from_ref(r), name))
            {
                let loaded = scene::load(&path).map_err(|e| e.to_string())?;
                return Ok(SceneFile {
                    path,
                    scene: loaded,
                    warning,
                });
            }
            warning = Some(match &root {
                Some(r) => format!(
                    "{name} is not under {} (nor its subfolders): the checks use the project's stand-in, {}",
                    r.display(),
                    self.file_name()
                ),
                None => format!(
                    "no folder of course scenes to find {name} in: the checks use the project's stand-in, {}",
                    self.file_name()
                ),
            });
        }
        let path = write_own(&self.own(), out, self.file_name())?;
        if let Some(map_file) = self.environment_file(&path) {
            super::sky::write_exr(&map_file)?;
        }
        let loaded = scene::load(&path).map_err(|e| e.to_string())?;
        Ok(SceneFile {
            path,
            scene: loaded,
            warning,
        })
    }
}

/// Writes `scene` in the course's dialect as `out/scenes/name`.
pub(super) fn write_own(scene: &Scene, out: &Path, name: &str) -> Result<PathBuf, String> {
    let folder = out.join("scenes");
    std::fs::create_dir_all(&folder).map_err(|e| format!("{}: {e}", folder.display()))?;
    let path = folder.join(name);
    let mut text = Vec::new();
    export_scene::write_scene_dae(scene, &mut text).map_err(|e| e.to_string())?;
    std::fs::write(&path, text).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(path)
}

/// A check's scene: the file the student's binary reads and the scene
/// as this project loads it from there.
pub struct SceneFile {
    pub path: PathBuf,
    pub scene: Scene,
    /// Set when the project's stand-in replaces a course scene not found.
    pub warning: Option<String>,
}

/// The centre of [`specular_box`]'s glass cube (on the floor, lifted by
/// 0.01 so that its bottom is not the floor's plane) and its side.
pub const CUBE_CENTRE: Vec3 = Vec3::new(-0.05, 0.16, 0.65);
pub const CUBE_SIDE: f32 = 0.3;

/// [`specular_box`]'s pane, at `z = 0.99` across the box's opening:
/// `x` and `y` ranges (the upper right of the image).
pub const PANE_X: (f32, f32) = (0.02, 0.98);
pub const PANE_Y: (f32, f32) = (0.8, 1.48);

/// The box of part 6's check of mirror and glass:
/// [`builtin::materials_box`] without its copper ball (a student may
/// check mirror and glass before writing the rough metal, which has a
/// check and a scene of its own, [`microfacet_box`]), with a glass
/// cube of side [`CUBE_SIDE`] turned 45 degrees about `y` at
/// [`CUBE_CENTRE`] (between the balls, in front) and a glass pane
/// ([`PANE_X`], [`PANE_Y`]) facing the camera across the opening. Every
/// face of the cube and the pane has corners of its own, so the course's
/// normals, rebuilt from connectivity, are the faces' own; each is wound
/// counter-clockwise seen from outside, so its normal points out (the
/// pane's towards the camera: rays from the camera enter the glass).
pub fn specular_box() -> Scene {
    let mut scene = builtin::materials_box();
    let materials = scene.materials.clone();
    scene
        .spheres
        .retain(|s| !matches!(materials[s.material as usize], Material::Microfacet { .. }));
    let glass = materials
        .iter()
        .position(|m| matches!(m, Material::Glass { .. }))
        .expect("the materials box has glass") as MaterialId;
    // The unit cube's faces, counter-clockwise seen from outside.
    let corner = |x: bool, y: bool, z: bool| {
        let s = |b: bool| if b { 1.0 } else { -1.0 };
        Vec3::new(s(x), s(y), s(z))
    };
    let (f, t) = (false, true);
    let faces = [
        [
            corner(f, f, f),
            corner(t, f, f),
            corner(t, f, t),
            corner(f, f, t),
        ],
        [
            corner(f, t, f),
            corner(f, t, t),
            corner(t, t, t),
            corner(t, t, f),
        ],
        [
            corner(f, f, f),
            corner(f, t, f),
            corner(t, t, f),
            corner(t, f, f),
        ],
        [
            corner(f, f, t),
            corner(t, f, t),
            corner(t, t, t),
            corner(f, t, t),
        ],
        [
            corner(f, f, f),
            corner(f, f, t),
            corner(f, t, t),
            corner(f, t, f),
        ],
        [
            corner(t, f, f),
            corner(t, t, f),
            corner(t, t, t),
            corner(t, f, t),
        ],
    ];
    let turn = glam::Quat::from_rotation_y(std::f32::consts::FRAC_PI_4);
    for face in faces {
        let placed = face.map(|p| CUBE_CENTRE + turn * (0.5 * CUBE_SIDE * p));
        push_quad(&mut scene, glass, placed);
    }
    let (x0, x1) = PANE_X;
    let (y0, y1) = PANE_Y;
    let z = 0.99;
    let pane = [
        Vec3::new(x0, y0, z),
        Vec3::new(x1, y0, z),
        Vec3::new(x1, y1, z),
        Vec3::new(x0, y1, z),
    ];
    push_quad(&mut scene, glass, pane);
    scene.mesh.normals =
        scene::normals::area_weighted_vertex_normals(&scene.mesh.positions, &scene.mesh.triangles);
    scene.source = "check: specular-box".into();
    scene
}

/// The box of part 6's check of the rough metal: [`builtin::cornell_box`]
/// with its balls made of the materials box's copper, Beckmann roughness
/// 0.15 (left, back) and 0.4 (right, front): a sharp and a broad lobe,
/// each reflecting the lit walls (what a wrong `sample_f` changes) and
/// the lamp's highlight (what a wrong `f` changes).
pub fn microfacet_box() -> Scene {
    let (eta, k) = (builtin::COPPER_ETA, builtin::COPPER_K);
    let mut scene = builtin::cornell_box();
    let balls: Vec<MaterialId> = scene.spheres.iter().map(|s| s.material).collect();
    for (material, alpha) in balls.into_iter().zip([0.15, 0.4]) {
        scene.materials[material as usize] = Material::Microfacet { alpha, eta, k };
    }
    scene.source = "check: microfacet-box".into();
    scene
}

/// Part 7's scene: [`builtin::environment_spheres`] (a floor and two
/// balls of radius 0.5, no light) with both balls diffuse (its copper
/// ball made white, albedo 0.75, for the reason [`specular_box`] has no
/// copper).
pub fn sky_balls() -> Scene {
    let mut scene = builtin::environment_spheres();
    for m in &mut scene.materials {
        if matches!(m, Material::Microfacet { .. }) {
            *m = Material::Diffuse {
                albedo: Vec3::splat(0.75),
            };
        }
    }
    scene.source = "check: sky-balls".into();
    scene
}

/// Two triangles over four corners of their own, in order around the quad.
fn push_quad(scene: &mut Scene, material: MaterialId, corners: [Vec3; 4]) {
    let mesh = &mut scene.mesh;
    let base = mesh.positions.len() as u32;
    mesh.positions.extend(corners);
    mesh.triangles.push([base, base + 1, base + 2]);
    mesh.triangles.push([base, base + 2, base + 3]);
    mesh.materials.extend([material, material]);
}

mod glowing;
pub use glowing::{glowing_box, write_lamp_probe};

#[cfg(test)]
mod tests;
