//! The scene as the renderer sees it: an intersector over the scene's
//! primitives, the materials, the light set, and hits prepared for
//! shading ([`ShadingPoint`]). Every part from 3 on renders through a [`World`].

pub mod shading_point;

pub use shading_point::ShadingPoint;

use crate::environment::EnvironmentLight;
use glam::Vec3;

use crate::intersect::{Hit, Intersector, Ray};
use crate::lights::{LightChoiceRule, LightConvention, LightSet};
use crate::materials::BsdfOptions;
use crate::scene::{Material, Scene};

/// Choices about the scene's appearance that a render makes once.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WorldOptions {
    /// How light samples are weighted (`--course-lights`).
    pub light_convention: LightConvention,
    /// Fresnel model and microfacet sampling for every BSDF.
    pub bsdf: BsdfOptions,
    /// Which lights direct lighting samples (`--light-choice`).
    pub light_choice: LightChoiceRule,
}

/// A scene ready to be traced: intersector, materials and lights.
pub struct World<'a, I> {
    pub intersector: I,
    pub materials: &'a [Material],
    pub lights: LightSet,
    pub bsdf_options: BsdfOptions,
}

impl<'a, I: Intersector> World<'a, I> {
    /// `scene` with its lights weighted physically and default BSDF options.
    pub fn new(scene: &'a Scene, intersector: I) -> Self {
        Self::with_options(scene, intersector, WorldOptions::default())
    }

    pub fn with_options(scene: &'a Scene, intersector: I, options: WorldOptions) -> Self {
        World {
            intersector,
            materials: &scene.materials,
            lights: LightSet::new(scene, options.light_convention)
                .with_choice(options.light_choice),
            bsdf_options: options.bsdf,
        }
    }

    /// The same world lit also by `environment`, if any (`-e`).
    pub fn with_environment(mut self, environment: Option<EnvironmentLight>) -> Self {
        if let Some(environment) = environment {
            self.lights = std::mem::take(&mut self.lights).with_environment(environment);
        }
        self
    }

    /// The first surface along `ray`, prepared for shading towards the ray's origin.
    pub fn trace(&self, ray: &Ray) -> Option<ShadingPoint> {
        let hit = self.intersector.intersect(ray)?;
        Some(self.shade(hit, -ray.dir))
    }

    /// The material of `hit` (the course's default for an unknown id).
    pub fn material(&self, hit: &Hit) -> Material {
        self.materials
            .get(hit.material as usize)
            .copied()
            .unwrap_or(Material::DEFAULT)
    }

    /// `hit` prepared for shading towards the unit direction `wo`.
    pub fn shade(&self, hit: Hit, wo: Vec3) -> ShadingPoint {
        let material = self.material(&hit);
        ShadingPoint::new(hit, wo, &material, self.bsdf_options)
    }
}
