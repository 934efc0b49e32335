//! What the lighting estimators share: a scene with its intersector, and a
//! hit prepared for shading (frame, BSDF, emission).

use glam::Vec3;

use super::emitters::EmissiveTriangles;
use super::lights::{sky_radiance, LightConvention};
use crate::intersect::{Hit, Intersector, Ray};
use crate::materials::Bsdf;
use crate::math::{Frame, Rgb};
use crate::scene::{Light, Material, Scene};

/// A scene as the lighting estimators see it: an intersector, materials,
/// lights, the emissive triangles light sampling samples, and which
/// emissive surfaces merely show a light to the camera.
pub struct SceneTracer<'a, I> {
    pub intersector: I,
    pub materials: &'a [Material],
    pub lights: &'a [Light],
    /// Emissive triangles that stand in for no light: light sampling
    /// samples them like an area light.
    pub emitters: EmissiveTriangles,
    /// Per material: an emissive surface standing in for one of
    /// [`Self::lights`] (see [`light_proxies`]).
    pub proxy: Vec<bool>,
    /// Per material: its triangles are in [`Self::emitters`].
    sampled: Vec<bool>,
    /// Primitive ids below this are triangles.
    triangle_count: u32,
    /// Whether some surface emits light that no light sampling covers:
    /// an emissive sphere that is not a stand-in.
    pub has_uncovered_emitters: bool,
    /// How light samples are weighted (physically, unless asked for the
    /// course's starter behaviour).
    pub light_convention: LightConvention,
}

impl<'a, I: Intersector> SceneTracer<'a, I> {
    pub fn new(scene: &'a Scene, intersector: I) -> Self {
        let proxy = light_proxies(scene);
        let emits = |m: usize| !proxy[m] && scene.materials[m].emission() != Rgb::ZERO;
        let sampled: Vec<bool> = (0..scene.materials.len()).map(emits).collect();
        let has_uncovered_emitters = scene.spheres.iter().any(|s| {
            let m = s.material as usize;
            m < sampled.len() && sampled[m]
        });
        SceneTracer {
            intersector,
            materials: &scene.materials,
            lights: &scene.lights,
            emitters: EmissiveTriangles::new(scene, &sampled),
            proxy,
            sampled,
            triangle_count: scene.mesh.triangles.len() as u32,
            has_uncovered_emitters,
            light_convention: LightConvention::Physical,
        }
    }

    /// The first surface along `ray`, prepared for shading towards the ray's origin.
    pub fn trace(&self, ray: &Ray) -> Option<ShadingPoint> {
        let hit = self.intersector.intersect(ray)?;
        let material = self
            .materials
            .get(hit.material as usize)
            .copied()
            .unwrap_or(Material::DEFAULT);
        Some(ShadingPoint::new(hit, -ray.dir, &material))
    }

    /// Radiance arriving along `ray` straight from an emitter: the emission
    /// of the first surface it hits, or the ambient sky if it escapes.
    pub fn emitted(&self, ray: &Ray) -> Rgb {
        match self.intersector.intersect(ray) {
            Some(hit) => self
                .materials
                .get(hit.material as usize)
                .map_or(Rgb::ZERO, Material::emission),
            None => self.sky(ray.dir),
        }
    }

    /// Light as the course's starter code computes it (`--course-lights`):
    /// its weighting of light samples ([`LightConvention::Course`]), and
    /// only `scene->lights` lighting the scene, so emitters that stand in
    /// for no light are seen by the camera but light nothing.
    pub fn with_course_lights(mut self) -> Self {
        self.light_convention = LightConvention::Course;
        self.emitters = EmissiveTriangles::default();
        self.has_uncovered_emitters = false;
        self
    }

    /// Radiance of the ambient sky along a ray that escapes.
    pub fn sky(&self, w: Vec3) -> Rgb {
        sky_radiance(self.lights, w)
    }

    /// Whether light sampling already counts the emission of `point`: it
    /// stands in for a scene light, or it is one of [`Self::emitters`].
    pub fn is_covered(&self, point: &ShadingPoint) -> bool {
        let m = point.hit.material as usize;
        let proxy = self.proxy.get(m).copied().unwrap_or(false);
        let sampled = self.sampled.get(m).copied().unwrap_or(false);
        proxy || (sampled && point.hit.primitive < self.triangle_count)
    }
}

/// Marks, per material, the emissive surfaces that stand in for a light.
///
/// The course's Cornell boxes hold an area light and, at the same place,
/// an emissive `light` mesh of the same radiance. Light sampling already
/// counts the area light, so that mesh's emission may only be added where
/// nothing samples it: when the camera sees it (or, later, after a
/// specular bounce). A material is such a stand-in when it is emissive and
/// every triangle using it lies within reach of an area light of the same
/// radiance: each vertex closer to the light's centre than the light's
/// half-diagonal plus 10 % of it, and within 1 % of that diagonal of its plane.
/// Every other emissive surface lights the scene: triangles are sampled as
/// lights ([`super::emitters`]), spheres light it through the paths that hit them.
pub fn light_proxies(scene: &Scene) -> Vec<bool> {
    let mut proxy: Vec<bool> = scene
        .materials
        .iter()
        .map(|m| matches!(m, Material::Emission { .. }))
        .collect();
    for (corners, &material) in scene.mesh.triangles.iter().zip(&scene.mesh.materials) {
        let m = material as usize;
        let Some(&Material::Emission { radiance }) = scene.materials.get(m) else {
            continue;
        };
        let near_a_light = scene.lights.iter().any(|light| {
            let Light::Area {
                radiance: light_radiance,
                center,
                direction,
                dim_x,
                dim_y,
            } = *light
            else {
                return false;
            };
            let diagonal = (dim_x + dim_y).length().max((dim_x - dim_y).length());
            light_radiance == radiance
                && corners.iter().all(|&v| {
                    let q = scene.mesh.positions[v as usize] - center;
                    q.length() <= 0.55 * diagonal && q.dot(direction).abs() <= 0.01 * diagonal
                })
        });
        proxy[m] &= near_a_light;
    }
    // Spheres are never stand-ins.
    for sphere in &scene.spheres {
        if let Some(p) = proxy.get_mut(sphere.material as usize) {
            *p = false;
        }
    }
    let used = used_materials(scene);
    proxy.iter().zip(&used).map(|(&p, &u)| p && u).collect()
}

/// Per material, whether any triangle or sphere uses it.
fn used_materials(scene: &Scene) -> Vec<bool> {
    let mut used = vec![false; scene.materials.len()];
    let ids = scene
        .mesh
        .materials
        .iter()
        .chain(scene.spheres.iter().map(|s| &s.material));
    for &m in ids {
        if let Some(u) = used.get_mut(m as usize) {
            *u = true;
        }
    }
    used
}

/// A hit prepared for shading: the frame with the shading normal turned
/// towards the viewer (surfaces are two-sided), the outgoing direction in
/// that frame, the BSDF and the emitted radiance.
#[derive(Clone, Copy, Debug)]
pub struct ShadingPoint {
    pub hit: Hit,
    /// Local frame, +Z the shading normal on the viewer's side.
    pub frame: Frame,
    /// Direction towards the viewer, local frame.
    pub wo: Vec3,
    pub bsdf: Bsdf,
    /// Radiance emitted towards the viewer.
    pub emission: Rgb,
}

impl ShadingPoint {
    /// Prepares `hit` seen from the unit direction `wo` (world space).
    pub fn new(hit: Hit, wo: Vec3, material: &Material) -> Self {
        let n = if hit.n.dot(wo) < 0.0 { -hit.n } else { hit.n };
        let frame = Frame::from_z(n);
        let front_face = hit.ng.dot(wo) >= 0.0;
        let bsdf = Bsdf::new(material, front_face, Default::default());
        ShadingPoint {
            hit,
            frame,
            wo: frame.to_local(wo),
            bsdf,
            emission: material.emission(),
        }
    }
}

/// Light that reaches the camera straight from an emitter: the emission
/// of the first surface the camera ray hits.
#[doc(alias = "zero_bounce_radiance")]
pub fn zero_bounce(point: &ShadingPoint) -> Rgb {
    point.emission
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::builtin::cornell_box;

    #[test]
    fn the_cornell_box_light_quad_stands_in_for_its_area_light() {
        let scene = cornell_box();
        let proxies = light_proxies(&scene);
        let emissive: Vec<bool> = scene
            .materials
            .iter()
            .map(|m| matches!(m, Material::Emission { .. }))
            .collect();
        assert_eq!(proxies, emissive, "exactly the emissive quad is a stand-in");
        assert!(proxies.iter().any(|&p| p));
    }

    #[test]
    fn an_emitter_without_a_matching_light_is_not_a_stand_in() {
        let mut scene = cornell_box();
        // A different radiance, or no area light at all: the quad lights the scene itself.
        if let Light::Area { radiance, .. } = &mut scene.lights[0] {
            *radiance *= 2.0;
        }
        assert!(light_proxies(&scene).iter().all(|&p| !p));
        scene.lights.clear();
        assert!(light_proxies(&scene).iter().all(|&p| !p));
        let nothing = crate::intersect::Primitives::default();
        let accel = crate::intersect::LinearScan::new(&nothing);
        let tracer = SceneTracer::new(&scene, accel);
        // Light sampling then samples the quad's two triangles itself.
        assert_eq!(tracer.emitters.len(), 2);
        assert!(!tracer.has_uncovered_emitters);
    }
}
