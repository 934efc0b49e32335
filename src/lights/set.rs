//! The light set of a render: every light of the scene behind the
//! [`Light`] interface, and for every primitive the way its emission is
//! counted, so that light is counted exactly once.
//!
//! Scene lights become [`Light`]s one to one. Emissive surfaces fall into
//! three roles ([`EmitterRole`]):
//!
//! - **stand-in**: the course's Cornell boxes hold an area light and, at the
//!   same place, an emissive `light` mesh. The light lights the scene; the
//!   mesh, the lamp's visible face, shows it to the camera and through
//!   delta bounces (a mirror, glass), where light sampling cannot reach,
//!   with the mesh's own radiance whatever the light's. A material is a
//!   stand-in when it is emissive and every triangle using it lies within
//!   reach of an area light ([`super::stand_ins`]): each
//!   vertex closer to the light's centre than the light's half-diagonal
//!   plus 10 % of it, and within 1 % of that diagonal of its plane.
//! - **sampled**: every other emissive triangle is a member of one more
//!   light, [`EmissiveTriangles`], sampled like an area light.
//! - **unsampled**: emissive spheres; no light samples them, so a ray that
//!   finds one always counts it.
//!
//! With the course's light convention (`--course-lights`) only the scene's
//! lights light the scene, as in the course's starter: every emitter that
//! stands in for no light is then shown to the camera but lights nothing.

use glam::Vec3;

use super::stand_ins::StandIns;
use super::{EmissiveTriangles, Light, LightChoice, LightChoiceRule, LightConvention, RectLight};
use crate::environment::EnvironmentLight;
use crate::math::Rgb;
use crate::scene::Scene;

/// How the emission of a primitive is counted when a ray hits it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EmitterRole {
    /// The surface emits nothing.
    Dark,
    /// Counted only after the camera or a delta bounce: it shows a light
    /// that light sampling covers everywhere else (the rectangle light
    /// `light` when it stands in for one).
    Shown { light: Option<u32> },
    /// Member `member` of light `light`, which samples it: counted with a
    /// multiple importance sampling weight.
    Sampled { light: u32, member: u32 },
    /// Nothing samples it: counted wherever a ray finds it.
    Unsampled,
}

/// The lights of a render and the roles of its emissive primitives.
#[derive(Clone, Debug, Default)]
pub struct LightSet {
    pub lights: Vec<Light>,
    /// Role of each primitive (triangles, then spheres); empty when
    /// nothing in the scene emits.
    roles: Vec<EmitterRole>,
    /// Indices of the rectangle lights, which rays test, and whether an
    /// emissive surface shows each to the camera.
    rects: Vec<(usize, bool)>,
    /// Indices of the lights at infinity that emit.
    infinite: Vec<usize>,
    /// Indices of the lights that emit (positive power): the ones direct
    /// lighting samples. A black light or the course's spot light is left
    /// out, so no sample or shadow ray is spent on it.
    lit: Vec<usize>,
    has_unsampled: bool,
    scene_radius: f32,
    /// Which lights direct lighting samples, as asked for and as decided.
    choice_rule: LightChoiceRule,
    choice: LightChoice,
}

impl LightSet {
    /// The lights of `scene` weighted by `convention`.
    pub fn new(scene: &Scene, convention: LightConvention) -> Self {
        let mut lights: Vec<Light> = scene
            .lights
            .iter()
            .map(|l| Light::from_scene(l, convention))
            .collect();
        let stand_ins = StandIns::of(scene);
        let stand_in = &stand_ins.materials;
        let emits = |m: usize| scene.materials[m].emission() != Rgb::ZERO;
        let course = convention == LightConvention::Course;
        let sampled: Vec<bool> = (0..scene.materials.len())
            .map(|m| emits(m) && !stand_in[m] && !course)
            .collect();
        let triangles = EmissiveTriangles::new(scene, &sampled);
        let triangle_count = scene.mesh.triangles.len();
        let mut roles = Vec::new();
        if (0..scene.materials.len()).any(emits) {
            let role_of_material = |m: u32| {
                let m = m as usize;
                match scene.materials.get(m) {
                    Some(_) if !emits(m) => EmitterRole::Dark,
                    Some(_) if stand_in[m] || course => EmitterRole::Shown { light: None },
                    Some(_) => EmitterRole::Unsampled,
                    None => EmitterRole::Dark,
                }
            };
            roles.extend(scene.mesh.materials.iter().map(|&m| role_of_material(m)));
            roles.extend(scene.spheres.iter().map(|s| role_of_material(s.material)));
            for (role, &light) in roles.iter_mut().zip(&stand_ins.triangle_light) {
                if let EmitterRole::Shown { light: shown } = role {
                    *shown = light;
                }
            }
            if !triangles.is_empty() {
                let light = lights.len() as u32;
                for (member, &t) in triangles.triangle_ids().iter().enumerate() {
                    roles[t as usize] = EmitterRole::Sampled {
                        light,
                        member: member as u32,
                    };
                }
            }
            // Sampled materials' triangles left out of the light (no area)
            // emit nothing anyone could see.
            for role in roles.iter_mut().take(triangle_count) {
                if *role == EmitterRole::Unsampled {
                    *role = EmitterRole::Dark;
                }
            }
        }
        if !triangles.is_empty() {
            lights.push(Light::Triangles(triangles));
        }
        let rects = (0..lights.len())
            .filter(|&i| matches!(lights[i], Light::Rect(_)))
            .map(|i| (i, stand_ins.lights[i]))
            .collect();
        LightSet {
            rects,
            infinite: Vec::new(),
            lit: Vec::new(),
            has_unsampled: roles.contains(&EmitterRole::Unsampled),
            roles,
            scene_radius: scene_radius(scene),
            lights,
            choice_rule: LightChoiceRule::default(),
            choice: LightChoice::default(),
        }
        .with_choice(LightChoiceRule::default())
    }

    /// The same set with its lights chosen by `rule` ([`LightChoice`]).
    /// Also finds the lights that emit and those at infinity among them:
    /// called after every change to [`Self::lights`].
    pub fn with_choice(mut self, rule: LightChoiceRule) -> Self {
        let radius = self.scene_radius;
        self.lit = (0..self.lights.len())
            .filter(|&i| self.lights[i].power(radius).max_element() > 0.0)
            .collect();
        self.infinite = self
            .lit
            .iter()
            .copied()
            .filter(|&i| self.lights[i].is_infinite())
            .collect();
        self.choice_rule = rule;
        self.choice = LightChoice::new(rule, &self.lights, radius);
        self
    }

    /// The lights that emit, with their indices: what direct lighting samples.
    pub fn lit(&self) -> impl Iterator<Item = (usize, &Light)> + '_ {
        self.lit.iter().map(|&i| (i, &self.lights[i]))
    }

    /// How direct lighting chooses the lights it samples.
    pub fn choice(&self) -> &LightChoice {
        &self.choice
    }

    /// The same set with the environment light `environment` added, at
    /// infinity: escaping rays see it, direct lighting samples it.
    pub fn with_environment(mut self, environment: EnvironmentLight) -> Self {
        self.lights.push(Light::Environment(environment));
        let rule = self.choice_rule;
        self.with_choice(rule)
    }

    /// How the emission of primitive `primitive` is counted.
    pub fn role(&self, primitive: u32) -> EmitterRole {
        self.roles
            .get(primitive as usize)
            .copied()
            .unwrap_or(EmitterRole::Dark)
    }

    /// The rectangle lights, with their indices and whether a stand-in
    /// shows them.
    pub fn rects(&self) -> impl Iterator<Item = (usize, &RectLight, bool)> + '_ {
        self.rects
            .iter()
            .filter_map(|&(i, shown)| match &self.lights[i] {
                Light::Rect(r) => Some((i, r, shown)),
                _ => None,
            })
    }

    /// The lights at infinity that emit, with their indices.
    pub fn infinite(&self) -> impl Iterator<Item = (usize, &Light)> + '_ {
        self.infinite.iter().map(|&i| (i, &self.lights[i]))
    }

    /// Whether some surface emits light that no light samples.
    pub fn has_unsampled_emitters(&self) -> bool {
        self.has_unsampled
    }

    /// Radius of a sphere around the scene's geometry, for the power of
    /// lights at infinity.
    pub fn scene_radius(&self) -> f32 {
        self.scene_radius
    }

    /// The emissive triangles sampled as a light, if any.
    pub fn emissive_triangles(&self) -> Option<&EmissiveTriangles> {
        self.lights.iter().find_map(|l| match l {
            Light::Triangles(t) => Some(t),
            _ => None,
        })
    }
}

/// Half the diagonal of the box around the scene's vertices and spheres.
fn scene_radius(scene: &Scene) -> f32 {
    let mut lo = Vec3::splat(f32::INFINITY);
    let mut hi = Vec3::splat(f32::NEG_INFINITY);
    for &p in &scene.mesh.positions {
        lo = lo.min(p);
        hi = hi.max(p);
    }
    for s in &scene.spheres {
        lo = lo.min(s.center - Vec3::splat(s.radius));
        hi = hi.max(s.center + Vec3::splat(s.radius));
    }
    let r = 0.5 * (hi - lo).length();
    if r.is_finite() {
        r
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests;
