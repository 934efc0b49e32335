//! Which emissive surfaces stand in for an area light.
//!
//! The course's Cornell boxes hold an area light and, at the same place,
//! an emissive `light` mesh: the light lights the scene, the mesh is the
//! lamp's visible face and shows it to the camera and through delta
//! bounces. That is the course's intent whatever the two radiances are
//! (a box whose quad has radiance 10 and whose light has 5 is lit by 5 and
//! shows a lamp of 10, as the course renders it): an emissive triangle
//! shows an area light when each corner lies within 0.55 of the light's
//! diagonal from its centre, and on the light's plane or up to 1 % of the
//! diagonal behind it (never in front, where it would shadow the light).
//! Its radiance is not compared: a rule that asked for equal radiance let
//! a brighter quad light the room besides the light. See [`super::set`] for how
//! the light set counts them.

use crate::math::Rgb;
use crate::scene::{Light as SceneLight, Material, Scene};

/// Which emissive surfaces stand in for an area light (see the module
/// docs): per material, whether it is a stand-in; per scene light, whether
/// some stand-in shows it; per triangle, the light it shows. A material is
/// a stand-in when each of its triangles shows some light (not
/// necessarily the same: two lamps may share one material). Spheres are
/// never stand-ins, and a material no primitive uses is not one.
pub struct StandIns {
    pub materials: Vec<bool>,
    pub lights: Vec<bool>,
    /// The light each triangle shows, if any (whatever its material).
    pub triangle_light: Vec<Option<u32>>,
}

impl StandIns {
    pub fn of(scene: &Scene) -> Self {
        let mut proxy: Vec<bool> = scene
            .materials
            .iter()
            .map(|m| matches!(m, Material::Emission { .. }))
            .collect();
        let mut used = vec![false; scene.materials.len()];
        let mut triangle_light = Vec::with_capacity(scene.mesh.triangles.len());
        for (corners, &material) in scene.mesh.triangles.iter().zip(&scene.mesh.materials) {
            let m = material as usize;
            if let Some(u) = used.get_mut(m) {
                *u = true;
            }
            let shown = match scene.materials.get(m) {
                Some(&Material::Emission { radiance }) if radiance != Rgb::ZERO => scene
                    .lights
                    .iter()
                    .position(|light| shows(scene, corners, light))
                    .map(|l| l as u32),
                _ => None,
            };
            if shown.is_none() {
                if let Some(p) = proxy.get_mut(m) {
                    *p = false;
                }
            }
            triangle_light.push(shown);
        }
        for sphere in &scene.spheres {
            if let Some(p) = proxy.get_mut(sphere.material as usize) {
                *p = false;
            }
        }
        let materials: Vec<bool> = proxy.iter().zip(&used).map(|(&p, &u)| p && u).collect();
        let mut lights = vec![false; scene.lights.len()];
        for (&light, &m) in triangle_light.iter().zip(&scene.mesh.materials) {
            if let (Some(l), Some(true)) = (light, materials.get(m as usize)) {
                lights[l as usize] = true;
            }
        }
        StandIns {
            materials,
            lights,
            triangle_light,
        }
    }
}

/// Whether a triangle lies on the area light `light`, whatever the two
/// radiances: each corner within 0.55 of the light's diagonal
/// from its centre, and on the light's plane or behind it (up to 1 % of
/// the diagonal; not in front, where it would block the light's shadow
/// rays while BSDF rays that hit it count the light).
fn shows(scene: &Scene, corners: &[u32; 3], light: &SceneLight) -> bool {
    let SceneLight::Area {
        center,
        direction,
        dim_x,
        dim_y,
        ..
    } = *light
    else {
        return false;
    };
    let diagonal = crate::lights::rect::longer_diagonal(dim_x, dim_y);
    corners.iter().all(|&v| {
        let q = scene.mesh.positions[v as usize] - center;
        let in_front = q.dot(direction);
        q.length() <= 0.55 * diagonal && in_front <= 1e-4 * diagonal && in_front >= -0.01 * diagonal
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::builtin::cornell_box;
    use glam::Vec3;

    /// The Cornell box with its lamp's quad moved by `moved(q)`, `q` a
    /// corner relative to the light's centre, in units of the light's
    /// diagonal and along its emitting direction: what `StandIns::of`
    /// says of it (does the quad show the light?).
    fn shows_after(moved: impl Fn(Vec3, Vec3, f32) -> Vec3) -> bool {
        // The box twice its size: its lamp's diagonal is 1, where a bound's
        // `* diagonal` made `/ diagonal` would not show.
        let mut scene = cornell_box();
        for p in &mut scene.mesh.positions {
            *p *= 2.0;
        }
        let SceneLight::Area {
            center,
            direction,
            dim_x,
            dim_y,
            ..
        } = &mut scene.lights[0]
        else {
            unreachable!("the box's light is an area light")
        };
        (*center, *dim_x, *dim_y) = (*center * 2.0, *dim_x * 2.0, *dim_y * 2.0);
        let diagonal = crate::lights::rect::longer_diagonal(*dim_x, *dim_y);
        let (center, direction) = (*center, *direction);
        let mut quad = Vec::new();
        for (t, &m) in scene.mesh.triangles.iter().zip(&scene.mesh.materials) {
            if matches!(scene.materials[m as usize], Material::Emission { .. }) {
                quad.extend(t.iter().map(|&v| v as usize));
            }
        }
        quad.sort_unstable();
        quad.dedup();
        assert_eq!(quad.len(), 4, "the lamp is one quad");
        for v in quad {
            let q = scene.mesh.positions[v] - center;
            scene.mesh.positions[v] = center + moved(q, direction, diagonal);
        }
        let stand_ins = StandIns::of(&scene);
        assert_eq!(stand_ins.materials.iter().any(|&m| m), stand_ins.lights[0]);
        stand_ins.lights[0]
    }

    // Each fails with a mutant of `shows`' bounds: the 0.55 of the
    // diagonal, the 1 % behind the light, the 1e-4 in front of it, or a
    // comparison turned around.
    #[test]
    fn a_quad_on_its_lamp_or_just_behind_it_stands_in_for_it() {
        assert!(shows_after(|q, _, _| q));
        // Behind the light by 0.9 % of its diagonal, or in front by 5e-5:
        // within the tolerances.
        assert!(shows_after(|q, d, diag| q - 0.009 * diag * d));
        assert!(shows_after(|q, d, diag| q + 5e-5 * diag * d));
        // Grown until its corners lie 0.54 of the diagonal from the centre.
        assert!(shows_after(|q, _, diag| q.normalize() * 0.54 * diag));
    }

    // A quad that emits nothing shows no lamp, wherever it lies: it is a
    // surface like any other. Fails if the radiance guard is dropped.
    #[test]
    fn a_black_quad_on_its_lamp_does_not_stand_in_for_it() {
        let mut scene = cornell_box();
        for m in &mut scene.materials {
            if let Material::Emission { radiance } = m {
                *radiance = Rgb::ZERO;
            }
        }
        let stand_ins = StandIns::of(&scene);
        assert_eq!(stand_ins.lights, vec![false]);
        assert!(stand_ins.materials.iter().all(|&m| !m));
        assert!(stand_ins.triangle_light.iter().all(Option::is_none));
    }

    #[test]
    fn a_quad_too_far_behind_in_front_or_too_large_does_not() {
        assert!(!shows_after(|q, d, diag| q - 0.011 * diag * d));
        // 0.5 % of the diagonal towards the room: it would shadow the lamp.
        assert!(!shows_after(|q, d, diag| q + 0.005 * diag * d));
        assert!(!shows_after(|q, d, diag| q + 2e-4 * diag * d));
        assert!(!shows_after(|q, _, diag| q.normalize() * 0.56 * diag));
    }
}
