//! The course's path tracer as a correct student solution writes it: the
//! starter's functions, in the starter's order, one Rust function each.
//!
//! ```text
//! est_radiance_global_illumination(r) = zero_bounce_radiance(r)          (-o 1, or -m 0)
//!                                     + at_least_one_bounce_radiance(r)  (-m >= 1)
//! at_least_one_bounce_radiance(r, k) =
//!       one_bounce_radiance                     (not at a delta BSDF; -o 1, or k = m)
//!     + f |cos| / (pdf q) [ at_least_one_bounce_radiance(r', k + 1)
//!                           + zero_bounce_radiance(r') if the BSDF is a delta ]
//!                                                (k < m, and the coin comes up, q = 0.65
//!                                                 from the second vertex on, or
//!                                                 another of [`Choices`])
//! estimate_direct_lighting_hemisphere = 1/N sum f L_e(w_j) cos / (1 / 2 pi),
//!     N = (number of lights) x -l, L_e what the ray's first hit emits
//! estimate_direct_lighting_importance = sum over lights 1/N_l sum f L cos / pdf,
//!     N_l = 1 for a delta light, -l otherwise; samples from behind the
//!     surface skipped, shadow rays to the sample
//! ```
//!
//! What this computes differently from [`crate::global::PathTracer`]
//! (the project's default), and why, is the table of docs/14-course-image.md:
//! no multiple importance sampling; the lights weighted by the starter's
//! `sample_L` ([`crate::lights::LightConvention::Course`], set in the
//! [`World`] this runs on); the hemisphere estimator sees the scene's
//! geometry only (the lamp's mesh, not the area light, which is not
//! geometry in the course); a camera ray that escapes sees only the
//! environment map (`-e`), not the ambient sky; a mirror or glass at the
//! last vertex sends no ray; with [`Lamps::LightQuads`] (assignment 3-2)
//! each area light is its own quad emitting `L / A max(0, n . wo)` and the
//! lamp mesh emits nothing.
//!
//! The catalogue's mistakes ([`crate::mistakes`]) of parts 3 and 4 and
//! the rough metal's factor on `f` live here, each a branch on
//! [`StarterTracer::mistakes`] at the line a student would get wrong,
//! and those of parts 6 and 7 in the mistakes' own versions of the
//! starter's BSDFs, pdfs and environment light, called from here when
//! chosen; with none chosen, every branch takes the correct way.

use glam::Vec3;

use super::Choices;
use crate::intersect::{Hit, Intersector, Ray};
use crate::lights::Light;
use crate::materials::{Bsdf, BsdfSample};
use crate::math::{Frame, Rgb};
use crate::mistakes::{self, Mistake, Mistakes};
use crate::sampling::Sampler;
use crate::world::{ShadingPoint, World};

mod direct;

/// How direct light is estimated (`-H` or not).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StarterDirect {
    /// `estimate_direct_lighting_hemisphere` (`-H`).
    Hemisphere,
    /// `estimate_direct_lighting_importance`.
    Importance,
}

impl StarterDirect {
    /// The estimator `-H` (`hemisphere`) asks for.
    pub fn from_hemisphere(hemisphere: bool) -> Self {
        if hemisphere {
            StarterDirect::Hemisphere
        } else {
            StarterDirect::Importance
        }
    }
}

/// What the camera, mirrors, glass and `-H` see of a lamp.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lamps {
    /// Assignment 3-1: the scene's emissive meshes, with their radiance
    /// (in the course's boxes, the `light` mesh under the area light).
    MeshFaces,
    /// Assignment 3-2: the starter turns each area light into two
    /// triangles of its own that emit `radiance / area * max(0, n . wo)`,
    /// and the lamp mesh that stands in for it emits nothing (the 3-2
    /// starter's `AreaLight` constructor and its loader's
    /// `EmissionBSDF(radiance, 0)`; measured on the 3-2 starter, whose
    /// camera sees the quad, 0.8 x 0.6 in the course's boxes, where the
    /// lamp mesh is 0.6 x 0.8).
    LightQuads,
}

/// The course's path tracer (see the module docs).
#[derive(Clone, Copy, Debug)]
pub struct StarterTracer {
    pub direct: StarterDirect,
    /// `-l`: samples per area light (`ns_area_light`).
    pub light_samples: u32,
    /// `-m`: `max_ray_depth`.
    pub max_depth: u32,
    /// `-o 1`: `isAccumBounces`.
    pub accumulate: bool,
    pub lamps: Lamps,
    /// What the handout leaves open: roulette's `q` and first vertex, the
    /// adaptive stop rule.
    pub choices: Choices,
    /// The catalogue's mistakes to make (none: a correct solution).
    pub mistakes: Mistakes,
}

impl StarterTracer {
    /// Whether light that has bounced at vertex `k` is part of the image
    /// (`k = 0`: what the camera ray meets emits).
    fn counts(&self, k: u32) -> bool {
        self.accumulate
            || k == self.max_depth()
            || self.mistakes.has(Mistake::NoAccumulationSumsAll)
    }

    /// `-m` as the depth test reads it.
    fn max_depth(&self) -> u32 {
        if self.mistakes.has(Mistake::DepthOffByOne) {
            self.max_depth + 1
        } else {
            self.max_depth
        }
    }

    /// `bsdf->f(wo, wi)`.
    fn f(&self, bsdf: &Bsdf, wo: Vec3, wi: Vec3) -> Rgb {
        bsdf.f(starter_wo(bsdf, wo), wi) * self.f_factor(bsdf, wo, wi)
    }

    /// The hit as the starter shades it: `make_coord_space(o2w, isect.n)`,
    /// the frame's +Z the surface's own normal, never turned towards the
    /// viewer. A diffuse or rough surface seen from behind (`wo.z < 0`) is
    /// lit from its other side, through itself: the hemisphere sampler,
    /// `sample_f` and the test `wi.z < 0` all read +Z. A mirror or glass
    /// keeps the project's frame, turned to the viewer: its directions in
    /// the world are the same either way (reflection is symmetric in the
    /// normal's sign, and glass knows which side it is on from the
    /// geometric normal, as the starter's does from `wo.z`).
    fn shade<I: Intersector>(&self, world: &World<I>, hit: Hit, wo: Vec3) -> ShadingPoint {
        let mut point = world.shade_surface(hit, wo);
        if !point.bsdf.is_delta() && hit.n.dot(wo) < 0.0 {
            point.frame = Frame::from_z(hit.n);
            point.wo = point.frame.to_local(wo);
        }
        point
    }

    /// What a student's `f(wo, wi)` is times the right one: `pi` for a
    /// diffuse BRDF taken as its albedo; the rough metal's mistakes'
    /// factor (`mistakes::materials::microfacet_f_factor`).
    fn f_factor(&self, bsdf: &Bsdf, wo: Vec3, wi: Vec3) -> f32 {
        match bsdf {
            Bsdf::Diffuse(_) if self.mistakes.has(Mistake::BrdfIsAlbedo) => std::f32::consts::PI,
            Bsdf::Conductor(_) => mistakes::materials::microfacet_f_factor(wo, wi, self.mistakes),
            _ => 1.0,
        }
    }

    /// The factor a bounce from `wo` multiplies the light it brings by:
    /// `f cos / pdf`.
    fn bounce_weight(&self, bsdf: &Bsdf, wo: Vec3, sample: &BsdfSample) -> Rgb {
        let f = sample.f * self.f_factor(bsdf, wo, sample.wi);
        let density = mistakes::materials::microfacet_density(bsdf, wo, sample, self.mistakes);
        if self.mistakes.has(Mistake::ThroughputWithoutCosPdf) {
            f
        } else {
            BsdfSample {
                f,
                density,
                ..*sample
            }
            .weight()
        }
    }

    /// `cos(theta)` at the shading point for the local direction `wi`.
    fn cos_theta(&self, wi: Vec3) -> f32 {
        if self.mistakes.has(Mistake::NoCosine) {
            1.0
        } else {
            wi.z
        }
    }

    /// Divides a sample by its `pdf`.
    fn over_pdf(&self, value: Rgb, pdf: f32) -> Rgb {
        if self.mistakes.has(Mistake::NoPdf) {
            value
        } else {
            value / pdf
        }
    }

    /// Radiance along a camera ray.
    #[doc(alias = "est_radiance_global_illumination")]
    pub fn radiance<I: Intersector>(
        &self,
        world: &World<I>,
        ray: &Ray,
        sampler: &mut impl Sampler,
    ) -> Rgb {
        let Some(hit) = world.intersector.intersect(ray) else {
            return self.escaped_radiance(world, ray);
        };
        let mut l = Rgb::ZERO;
        if self.counts(0) {
            l += self.zero_bounce_radiance(world, ray, &hit);
        }
        if self.max_depth() >= 1 {
            l += self.at_least_one_bounce_radiance(world, ray, hit, 1, sampler);
        }
        l
    }

    /// What a ray that meets nothing sees: the environment map, and with
    /// [`Lamps::LightQuads`] a lamp's quad it crosses.
    fn escaped_radiance<I: Intersector>(&self, world: &World<I>, ray: &Ray) -> Rgb {
        let mut l = self.quads_radiance(world, ray, f32::INFINITY);
        for (_, light) in world.lights.infinite() {
            if let Light::Environment(env) = light {
                l += if mistakes::environment::any(self.mistakes) {
                    mistakes::environment::escaped_radiance(env, ray.dir, self.mistakes)
                } else {
                    env.escaped_radiance(ray.dir)
                };
            }
        }
        l
    }

    /// Light emitted by the surface `ray` meets at `hit` towards the ray's
    /// origin: `isect.bsdf->get_emission()`.
    pub fn zero_bounce_radiance<I: Intersector>(
        &self,
        world: &World<I>,
        ray: &Ray,
        hit: &Hit,
    ) -> Rgb {
        match self.lamps {
            Lamps::MeshFaces => world.material(hit).emission(),
            // The 3-2 starter's loader gives every emissive surface the
            // emission direction 0 (`EmissionBSDF(radiance, 0)`, emitting
            // `radiance max(0, dir . wo)`): only the lights' quads glow.
            Lamps::LightQuads => self.quads_radiance(world, ray, hit.t),
        }
    }

    /// With [`Lamps::LightQuads`], the light of the area lights' quads that
    /// `ray` crosses before `t_max`: `L / A max(0, n . wo)`.
    fn quads_radiance<I: Intersector>(&self, world: &World<I>, ray: &Ray, t_max: f32) -> Rgb {
        if self.lamps != Lamps::LightQuads {
            return Rgb::ZERO;
        }
        let mut l = Rgb::ZERO;
        for (_, rect, _) in world.lights.rects() {
            if rect.hit_distance(ray).is_some_and(|t| t <= t_max) {
                let cos = rect.normal.dot(-ray.dir).max(0.0);
                l += rect.radiance * (cos / rect.area());
            }
        }
        l
    }

    /// Direct light at `point`, by `-H` or by the lights.
    pub fn one_bounce_radiance<I: Intersector>(
        &self,
        world: &World<I>,
        point: &ShadingPoint,
        sampler: &mut impl Sampler,
    ) -> Rgb {
        match self.direct {
            StarterDirect::Hemisphere => self.direct_hemisphere(world, point, sampler),
            StarterDirect::Importance => self.direct_importance(world, point, sampler),
        }
    }

    /// The light of paths of one bounce or more from vertex `k` (1 for the
    /// camera ray's hit) at `hit`, which `ray` found.
    pub fn at_least_one_bounce_radiance<I: Intersector>(
        &self,
        world: &World<I>,
        ray: &Ray,
        hit: Hit,
        k: u32,
        sampler: &mut impl Sampler,
    ) -> Rgb {
        let point = self.shade(world, hit, -ray.dir);
        if point.bsdf.is_black() {
            return Rgb::ZERO;
        }
        let delta = point.bsdf.is_delta();
        let mut l = Rgb::ZERO;
        if !delta && self.counts(k) {
            l += self.one_bounce_radiance(world, &point, sampler);
        }
        if k >= self.max_depth() {
            return l;
        }
        let q = self.choices.continue_probability_at(k);
        if q < 1.0 && sampler.get_1d() >= q {
            return l;
        }
        let (uc, u) = (sampler.get_1d(), sampler.get_2d());
        let sample = mistakes::materials::sample_specular(&point.bsdf, point.wo, uc, self.mistakes)
            .unwrap_or_else(|| point.bsdf.sample(starter_wo(&point.bsdf, point.wo), uc, u));
        let Some(sample) = sample else {
            return l;
        };
        let next_ray = point.hit.spawn_ray(point.frame.to_world(sample.wi));
        let incoming = match world.intersector.intersect(&next_ray) {
            Some(next) => {
                let shown = if delta || self.mistakes.has(Mistake::EmissionEveryBounce) {
                    self.zero_bounce_radiance(world, &next_ray, &next)
                } else {
                    Rgb::ZERO
                };
                shown + self.at_least_one_bounce_radiance(world, &next_ray, next, k + 1, sampler)
            }
            None if delta => self.escaped_radiance(world, &next_ray),
            None => Rgb::ZERO,
        };
        let q_divided = if self.mistakes.has(Mistake::RouletteNotDivided) {
            1.0
        } else {
            q
        };
        l + self.bounce_weight(&point.bsdf, point.wo, &sample) * incoming / q_divided
    }
}

/// `wo` as the starter's BSDF reads it: `DiffuseBSDF`'s `f` and `sample_f`
/// ignore `wo`, so a diffuse surface seen from behind reflects as from the
/// front (the project's [`crate::materials::Diffuse`] wants `wo.z > 0`);
/// a rough conductor's `f` is 0 below its surface, as the project's.
fn starter_wo(bsdf: &Bsdf, wo: Vec3) -> Vec3 {
    match bsdf {
        Bsdf::Diffuse(_) => Vec3::new(wo.x, wo.y, wo.z.abs()),
        _ => wo,
    }
}
