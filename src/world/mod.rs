//! The scene as the renderer sees it: an intersector over the scene's
//! primitives, the materials, the light set, and hits prepared for
//! shading ([`ShadingPoint`]), and how a path continues from a surface
//! ([`World::sample_continuation`]: the BSDF, mixed at diffuse vertices
//! with directions towards caustic casters, [`casters`]). Every part from
//! 3 on renders through a [`World`].

pub mod casters;
pub mod shading_point;

pub use casters::{CasterRule, Casters};
pub use shading_point::ShadingPoint;

use crate::environment::EnvironmentLight;
use glam::{Vec2, Vec3};

use crate::intersect::{Hit, Intersector, Ray};
use crate::lights::{Light, LightChoiceRule, LightConvention, LightSet};
use crate::materials::{Bsdf, BsdfOptions, BsdfSample, Density};
use crate::math::float::ONE_BELOW_ONE;
use crate::plan::{light_samples, BsdfKinds};
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
    /// Whether diffuse vertices sample towards caustic casters (`--casters`).
    pub casters: CasterRule,
}

impl WorldOptions {
    /// The scene's lights as a world with these options samples them (its
    /// convention and its choice of lights): what `--info` reports and
    /// the render uses.
    pub fn lights(&self, scene: &Scene) -> LightSet {
        LightSet::new(scene, self.light_convention).with_choice(self.light_choice)
    }
}

/// A scene ready to be traced: intersector, materials and lights.
pub struct World<'a, I> {
    pub intersector: I,
    pub materials: &'a [Material],
    pub lights: LightSet,
    pub bsdf_options: BsdfOptions,
    /// Smooth spheres that diffuse vertices sample towards.
    pub casters: Casters,
    /// Whether some surface casts caustics
    /// ([`crate::plan::BsdfKinds::casts_caustics`]).
    pub caustics: bool,
}

impl<'a, I: Intersector> World<'a, I> {
    /// `scene` with its lights weighted physically and default BSDF options.
    pub fn new(scene: &'a Scene, intersector: I) -> Self {
        Self::with_options(scene, intersector, WorldOptions::default())
    }

    pub fn with_options(scene: &'a Scene, intersector: I, options: WorldOptions) -> Self {
        let lights = options.lights(scene);
        World {
            intersector,
            materials: &scene.materials,
            casters: Casters::new(scene, &lights, options.casters),
            caustics: BsdfKinds::of(scene).casts_caustics(),
            lights,
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
        let mut point = self.shade_surface(hit, wo);
        self.add_caster_cones(&mut point);
        point
    }

    /// [`World::shade`] without the caster cones, which only the
    /// continuation and its density read: for a vertex where the path
    /// ends (then [`World::add_caster_cones`] if it goes on after all).
    pub fn shade_surface(&self, hit: Hit, wo: Vec3) -> ShadingPoint {
        let material = self.material(&hit);
        ShadingPoint::new(hit, wo, &material, self.bsdf_options)
    }

    /// Fills in the cones of the casters that `point`'s continuation
    /// mixes in ([`World::sample_continuation`]).
    ///
    /// Only a diffuse BSDF mixes in cones, one that reflects only:
    /// [`World::sample_continuation`] relies on it. Elsewhere the point
    /// keeps [`casters::Cones::NONE`], untouched (the list is a few
    /// hundred bytes, and every vertex of every scene comes here).
    pub fn add_caster_cones(&self, point: &mut ShadingPoint) {
        if !self.casters.is_empty() && matches!(point.bsdf, Bsdf::Diffuse(_)) {
            point.cones = self.casters.cones(point.hit.p, point.frame.z);
        }
    }

    /// The direction a path takes from `point`, from `uc` and `u` in
    /// `[0, 1)`. Without eligible casters it is the BSDF's sample (`uc`
    /// its lobe, `u` the direction). With casters, `u.x < c` chooses the
    /// cones, else the BSDF (`uc` its lobe), and `u.x` is stretched back
    /// to `[0, 1)` within the branch taken (and within the cone taken,
    /// [`casters::Cones::sample`]): so each branch's directions keep the
    /// stratification of the sampler's 2D points, as a separate uniform
    /// number for the choice would not. The sample's density is the
    /// mixture's ([`World::continuation_pdf`]), so its weight
    /// `f |cos| / p` is the path's. `None` where the path ends: the BSDF
    /// gives no sample, or a cone's direction is refused (below the
    /// surface, or a light image's outside its sphere's cone).
    pub fn sample_continuation(
        &self,
        point: &ShadingPoint,
        uc: f32,
        u: Vec2,
    ) -> Option<BsdfSample> {
        let cones = &point.cones;
        if cones.is_empty() {
            return point.bsdf.sample(point.wo, uc, u);
        }
        let c = casters::CASTER_PROBABILITY;
        let (mut sample, wi_world, bsdf_pdf) = if u.x < c {
            let wi_world = cones.sample(Vec2::new(u.x / c, u.y), &self.casters)?;
            let wi = point.frame.to_local(wi_world);
            // Only diffuse BSDFs mix in cones (`add_caster_cones`), and they
            // reflect only: a cone direction below the surface carries
            // nothing (f = 0), and ends the path; so does a NaN one.
            if wi.z <= 0.0 || wi.z.is_nan() {
                return None;
            }
            let (f, bsdf_pdf) = point.bsdf.eval(point.wo, wi);
            (BsdfSample::reflection(f, wi, 1.0)?, wi_world, bsdf_pdf)
        } else {
            let stretched = ((u.x - c) / (1.0 - c)).min(ONE_BELOW_ONE);
            let sample = point.bsdf.sample(point.wo, uc, Vec2::new(stretched, u.y))?;
            (sample, point.frame.to_world(sample.wi), sample.pdf())
        };
        sample.density = Density::SolidAngle(cones.mixture_pdf(bsdf_pdf, wi_world, &self.casters));
        Some(sample)
    }

    /// Density per steradian of [`World::sample_continuation`] at `point`
    /// for the unit direction `wi_world` (world space), given the BSDF's
    /// own density `bsdf_pdf` there.
    pub fn continuation_pdf(&self, point: &ShadingPoint, wi_world: Vec3, bsdf_pdf: f32) -> f32 {
        if point.cones.is_empty() {
            bsdf_pdf
        } else {
            point.cones.mixture_pdf(bsdf_pdf, wi_world, &self.casters)
        }
    }

    /// Whether light sampling at a vertex of BSDF `bsdf` splits the
    /// environment map's samples ([`crate::plan::light_samples`]: at a
    /// conductor from `smallest_split_alpha` up, at a diffuse vertex only
    /// where nothing in the scene casts caustics); true without a map,
    /// where nothing is split anyway.
    pub fn splits_map(&self, bsdf: &Bsdf) -> bool {
        self.lights.infinite().all(|(_, light)| match light {
            Light::Environment(map) => light_samples::splits_map(bsdf, map, self.caustics),
            _ => true,
        })
    }
}
