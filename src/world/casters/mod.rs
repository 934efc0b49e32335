//! Caustic casters: sampling the continuation of a path at a diffuse
//! vertex partly towards the scene's smooth spheres.
//!
//! A caustic on a diffuse surface is light that reached it through a
//! mirror, glass or a near-mirror conductor. A path tracer finds it only
//! one way: the direction sampled at the diffuse vertex must hit the
//! smooth object at the one place whose reflection (or refraction) leads
//! to a light. Light sampling at the diffuse vertex cannot help (the
//! light is seen through the object), and with cosine sampling the
//! object is a small target: the caustic is a rare event of large value,
//! the noise that dominates `CBspheres_microfacet_al_ag` and the glass
//! and mirror of `CBspheres` (docs/10, section 6).
//!
//! So at a diffuse vertex the continuation is drawn from a mixture
//! (defensive importance sampling, Hesterberg 1995; the one-sample model
//! of multiple importance sampling with the balance heuristic, Veach 1997,
//! section 9.2.4): with probability `1 - c` from the BSDF, with
//! probability `c / k` uniformly in the cone that each of the `k` casters
//! eligible at the vertex subtends (pbrt-v4, section 6.2.4: a sphere's
//! solid angle from a point outside it):
//!
//! ```text
//! p(wi) = (1 - c) p_bsdf(wi) + c / k  sum_j [wi in cone_j] / (2 pi (1 - cos theta_max,j))
//! cos theta_max,j = sqrt(1 - r_j^2 / d_j^2)
//! ```
//!
//! and the path's throughput takes `f |cos| / p(wi)`. This is unbiased
//! wherever the BSDF's own density is positive, since `p >= (1 - c)
//! p_bsdf`: the cones only add samples where caustics may be. The same
//! `p` is the BSDF strategy's density in multiple importance sampling
//! against light samples, at the vertex (`DirectLights`) and where the
//! ray finds an emitter (`found_emission`), since it is the density with
//! which the path chose the direction.
//!
//! A caster is a sphere whose material is a delta BSDF (mirror, glass,
//! refraction) or a conductor with `alpha <= SMOOTH_ALPHA`, or the sphere
//! that bounds a mirror-like mesh's triangles ([`meshes`]). It is
//! eligible at a vertex when the vertex is outside it and it is not
//! wholly below the vertex's tangent plane; both depend on the vertex
//! alone, so sampling and density agree. Only diffuse BSDFs mix: a glossy
//! lobe already samples where it reflects. A scene without casters (or
//! with more than [`MAX_CASTERS`], where the per-vertex loop would cost
//! more than it saves) renders exactly as without this module.
//!
//! A mirror sphere (or a conductor up to [`images::IMAGE_ALPHA`]) adds,
//! for each rectangle light, a narrower cone around the light's image in
//! it ([`images`]): the directions whose reflection reaches the light,
//! a small part of the sphere's cone. It is one more term of the sum,
//! uniform in the image's cone but restricted to its sphere's cone
//! `cone_s` (so that it need only be found for directions there:
//! [`Cones`]), a sub-density:
//!
//! ```text
//! p_image(wi) = [wi in image and in cone_s] / (2 pi (1 - cos phi))
//! ```
//!
//! or, where the vertex has no image, the sphere's own cone again.

pub mod cone;
pub mod cones;
pub mod images;
pub mod meshes;

pub use cone::Cone;
pub use cones::Cones;
pub use images::ImagedLight;

use glam::Vec3;

use crate::lights::LightSet;
use crate::scene::{Material, Scene};

/// Probability `c` of drawing the continuation from the casters' cones
/// when at least one is eligible. Each cone sample costs a longer path
/// (towards a sphere rather than, often, out of the scene), so `c` trades
/// that time against the caustics' variance: on
/// `CBspheres_microfacet_al_ag`, `0.25` was 1.33 times as efficient as no
/// casters and `0.5` 1.06 times (docs/10).
pub const CASTER_PROBABILITY: f32 = 0.25;

/// The largest Beckmann roughness of a conductor sphere that counts as a
/// caster: up to `0.3` (a lobe of about 17 degrees) the light a sphere
/// reflects onto a diffuse surface gathers in patches that cosine
/// sampling rarely finds. On `CBspheres_microfacet_al_ag` (spheres of
/// `alpha` 0.025 and 0.25) counting both gave 1.33 times the efficiency
/// of no casters, the smooth one alone 1.07 (docs/10).
pub const SMOOTH_ALPHA: f32 = 0.3;

/// The most casters: more smooth spheres than this and none are used;
/// mirror-like meshes take the slots the spheres leave.
pub const MAX_CASTERS: usize = 8;

/// The most cones a vertex mixes: its casters', then light images in the
/// slots left (at least four; more are left out).
pub const MAX_CONES: usize = MAX_CASTERS + 4;

/// Whether a render samples towards caustic casters (`--casters`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum CasterRule {
    /// The scene's smooth spheres and mirror-like meshes, up to
    /// [`MAX_CASTERS`] in all, and the light images in the mirror-like
    /// spheres.
    #[default]
    Auto,
    /// The same casters' cones without light images: what the images
    /// add is the difference from [`CasterRule::Auto`].
    Spheres,
    /// None: the BSDF alone (the course's path tracer).
    Off,
}

/// A smooth sphere, or the sphere around a mirror-like mesh
/// ([`meshes`]), world space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Caster {
    pub center: Vec3,
    pub radius: f32,
    /// How much its reflection widens a light, if it shows light images
    /// ([`images::image_spread`]).
    pub image_spread: Option<f32>,
}

/// The scene's caustic casters.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Casters {
    /// The smooth spheres, then the spheres around mirror-like meshes.
    pub spheres: Vec<Caster>,
    /// How many of `spheres`, the last ones, bound meshes.
    pub meshes: usize,
    /// The lights whose images mirror-like casters show.
    pub lights: Vec<ImagedLight>,
}

impl Casters {
    /// The smooth spheres of `scene` (none if there are more than
    /// [`MAX_CASTERS`]), then the spheres around its mirror-like meshes in
    /// the slots they leave, under `rule`, with the images of the
    /// rectangle lights of `lights` in the mirror-like spheres.
    pub fn new(scene: &Scene, lights: &LightSet, rule: CasterRule) -> Self {
        if rule == CasterRule::Off {
            return Casters::default();
        }
        let smooth = |id: u32| match scene.materials.get(id as usize) {
            Some(
                Material::Mirror { .. } | Material::Glass { .. } | Material::Refraction { .. },
            ) => true,
            Some(Material::Microfacet { alpha, .. }) => *alpha <= SMOOTH_ALPHA,
            _ => false,
        };
        let mut spheres: Vec<Caster> = scene
            .spheres
            .iter()
            .filter(|s| s.radius > 0.0 && smooth(s.material))
            .map(|s| Caster {
                center: s.center,
                radius: s.radius,
                image_spread: scene
                    .materials
                    .get(s.material as usize)
                    .and_then(images::image_spread),
            })
            .collect();
        if spheres.len() > MAX_CASTERS {
            return Casters::default();
        }
        let mut meshes = meshes::mesh_casters(&scene.mesh, &scene.materials);
        meshes.truncate(MAX_CASTERS - spheres.len());
        let mirrors = spheres.iter().any(|s| s.image_spread.is_some());
        let mesh_count = meshes.len();
        spheres.extend(meshes);
        Casters {
            spheres,
            meshes: mesh_count,
            lights: if mirrors && rule == CasterRule::Auto {
                ImagedLight::of(lights)
            } else {
                Vec::new()
            },
        }
    }

    /// How many light images the casters can show: mirror-like casters
    /// times lights.
    pub fn images(&self) -> usize {
        let mirrors = self.spheres.iter().filter(|s| s.image_spread.is_some());
        mirrors.count() * self.lights.len()
    }

    pub fn is_empty(&self) -> bool {
        self.spheres.is_empty()
    }

    /// The cones of the casters eligible at `p`, whose tangent plane has
    /// the unit normal `n` on the side the continuation leaves: `p` is
    /// outside the sphere and the sphere reaches above the plane.
    pub fn cones(&self, p: Vec3, n: Vec3) -> Cones {
        let mut cones = Cones::at(p);
        // Each eligible caster's cone first, then the light images in the
        // slots left, so that images never take a caster's place.
        let mut members = [None; MAX_CASTERS];
        for (caster, member) in self.spheres.iter().zip(&mut members) {
            let to_center = caster.center - p;
            let d2 = to_center.length_squared();
            let r2 = caster.radius * caster.radius;
            // Outside, with a margin for the rounding of `d^2 - r^2`, and
            // some of the sphere above the plane.
            if d2 <= r2 * 1.0001 || to_center.dot(n) <= -caster.radius {
                continue;
            }
            *member = cones.push_sphere(Cone::of_sphere(to_center, d2, r2));
        }
        for (i, (caster, member)) in self.spheres.iter().zip(members).enumerate() {
            if let (Some(member), Some(_)) = (member, caster.image_spread) {
                for light in 0..self.lights.len() {
                    if !cones.push_image(member, i, light) {
                        return cones;
                    }
                }
            }
        }
        cones
    }
}

#[cfg(test)]
mod tests;
