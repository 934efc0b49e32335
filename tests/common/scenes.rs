//! Small scenes built in code for the estimator tests, the path tracers
//! they compare, and the plumbing to average a path tracer's radiance
//! along one ray.

use glam::{Vec2, Vec3};
use pathtracer::bvh::BvhAccel;
use pathtracer::direct::{DirectHemisphere, DirectLights};
use pathtracer::environment::{uv_to_direction, EnvironmentMap};
use pathtracer::global::{DirectStrategy, PathTracer, Roulette};
use pathtracer::intersect::{Intersector, Primitives, Ray};
use pathtracer::math::Frame;
use pathtracer::math::{luminance, Rgb};
use pathtracer::sampling::IndependentSampler;
use pathtracer::scene::normals::area_weighted_vertex_normals;
use pathtracer::scene::{Light, Material, MaterialId, Scene, Sphere};
use pathtracer::world::World;

use super::stats::MeanEstimate;

/// Direct light by sampling each light once.
pub const LIGHTS: DirectStrategy = DirectStrategy::Lights(DirectLights {
    samples_per_light: 1,
    environment_samples: None,
    mis: true,
});
/// Direct light by sampling each light once, without MIS: emission a
/// BSDF ray finds on a sampled light is not counted.
pub const LIGHTS_ALONE: DirectStrategy = DirectStrategy::Lights(DirectLights {
    samples_per_light: 1,
    environment_samples: None,
    mis: false,
});
/// Direct light by one uniform hemisphere direction.
pub const HEMISPHERE: DirectStrategy = DirectStrategy::Hemisphere(DirectHemisphere { samples: 1 });

/// A path tracer that accumulates every bounce up to `max_depth`, with
/// the course's Russian roulette (`Roulette::Fixed`) when `russian_roulette`.
pub fn tracer(direct: DirectStrategy, max_depth: u32, russian_roulette: bool) -> PathTracer {
    let roulette = if russian_roulette {
        Roulette::Fixed
    } else {
        Roulette::Off
    };
    tracer_with(direct, max_depth, roulette)
}

/// A path tracer that accumulates every bounce up to `max_depth`, ending
/// paths by `roulette`.
pub fn tracer_with(direct: DirectStrategy, max_depth: u32, roulette: Roulette) -> PathTracer {
    PathTracer {
        direct,
        max_depth,
        accumulate: true,
        roulette,
        glass_splits: 0,
    }
}

/// The BVH over a scene's primitives.
pub fn accel(scene: &Scene) -> BvhAccel {
    BvhAccel::new(Primitives::from_scene(scene))
}

/// A grey diffuse material.
pub fn diffuse(albedo: f32) -> Material {
    Material::Diffuse {
        albedo: Vec3::splat(albedo),
    }
}

/// Clear glass of index 1.5 that reflects and refracts.
pub const GLASS: Material = Material::Glass {
    reflectance: Vec3::ONE,
    transmittance: Vec3::ONE,
    roughness: 0.0,
    ior: 1.5,
};

/// The mean luminance of a render's pixels.
pub fn image_mean(r: &pathtracer::render::Rendered) -> f64 {
    r.film
        .pixels
        .iter()
        .map(|&p| luminance(p) as f64)
        .sum::<f64>()
        / r.film.pixels.len() as f64
}

/// A grey emitter that reflects nothing.
pub fn emission(radiance: f32) -> Material {
    Material::Emission {
        radiance: Vec3::splat(radiance),
    }
}

/// The same scene twice, lit by one rectangle of radiance `radiance` at
/// `corners`: once as `light` (a light the renderer samples), once as an
/// emissive quad (triangles found by rays and sampled as emitters). The
/// rest of the scene is what `rest` adds.
pub fn under_light_and_quad(
    rest: impl Fn(&mut SceneBuilder),
    light: Light,
    radiance: Vec3,
    corners: [Vec3; 4],
) -> (Scene, Scene) {
    let mut with_light = SceneBuilder::new();
    rest(&mut with_light);
    with_light.light(light);
    let mut with_quad = SceneBuilder::new();
    rest(&mut with_quad);
    let lamp = with_quad.material(Material::Emission { radiance });
    with_quad.quad(lamp, corners);
    (with_light.finish(), with_quad.finish())
}

/// Builds a [`Scene`]: quads with their own vertices (so flat shading
/// normals), analytic spheres, lights.
#[derive(Default)]
pub struct SceneBuilder {
    scene: Scene,
}

impl SceneBuilder {
    pub fn new() -> Self {
        let mut b = SceneBuilder::default();
        b.scene.source = "test: built in code".into();
        b
    }

    pub fn material(&mut self, material: Material) -> MaterialId {
        self.scene.materials.push(material);
        (self.scene.materials.len() - 1) as MaterialId
    }

    /// A planar quad `a b c d` (two triangles, either winding: surfaces are two-sided).
    pub fn quad(&mut self, material: MaterialId, corners: [Vec3; 4]) -> &mut Self {
        let mesh = &mut self.scene.mesh;
        let base = mesh.positions.len() as u32;
        mesh.positions.extend(corners);
        for tri in [[0, 1, 2], [0, 2, 3]] {
            mesh.triangles.push(tri.map(|i| base + i));
            mesh.materials.push(material);
        }
        self
    }

    /// The square floor `y = 0`, `|x|, |z| <= half`, wound so that its
    /// normal points up (the course shades a surface by its own normal).
    pub fn floor(&mut self, material: MaterialId, half: f32) -> &mut Self {
        self.quad(
            material,
            [
                Vec3::new(-half, 0.0, -half),
                Vec3::new(-half, 0.0, half),
                Vec3::new(half, 0.0, half),
                Vec3::new(half, 0.0, -half),
            ],
        )
    }

    /// The six faces of the axis-aligned box `[lo, hi]` (12 triangles).
    pub fn closed_box(&mut self, material: MaterialId, lo: Vec3, hi: Vec3) -> &mut Self {
        let c = |x: bool, y: bool, z: bool| {
            Vec3::new(
                if x { hi.x } else { lo.x },
                if y { hi.y } else { lo.y },
                if z { hi.z } else { lo.z },
            )
        };
        let (f, t) = (false, true);
        self.quad(material, [c(f, f, f), c(t, f, f), c(t, f, t), c(f, f, t)]);
        self.quad(material, [c(f, t, f), c(f, t, t), c(t, t, t), c(t, t, f)]);
        self.quad(material, [c(f, f, f), c(f, t, f), c(t, t, f), c(t, f, f)]);
        self.quad(material, [c(f, f, t), c(t, f, t), c(t, t, t), c(f, t, t)]);
        self.quad(material, [c(f, f, f), c(f, f, t), c(f, t, t), c(f, t, f)]);
        self.quad(material, [c(t, f, f), c(t, t, f), c(t, t, t), c(t, f, t)])
    }

    /// One triangle with corners of its own, so that its vertex normals
    /// are its face normal.
    pub fn triangle(&mut self, material: MaterialId, corners: [Vec3; 3]) -> &mut Self {
        let mesh = &mut self.scene.mesh;
        let base = mesh.positions.len() as u32;
        mesh.positions.extend(corners);
        mesh.triangles.push([base, base + 1, base + 2]);
        mesh.materials.push(material);
        self
    }

    /// A closed sphere of flat facets around `center`: each of the eight
    /// faces of an octahedron cut into `n^2` triangles whose corners are
    /// pushed out to `radius` (`8 n^2` facets). Facets do not share
    /// corners, so each is shaded flat, and neighbours meet at an angle of
    /// about `pi / (2 n)`: a closed room without the right-angled edges
    /// and corners of a box.
    pub fn faceted_sphere(
        &mut self,
        material: MaterialId,
        center: Vec3,
        radius: f32,
        n: u32,
    ) -> &mut Self {
        for octant in 0..8u32 {
            let sign = |bit: u32| if octant & bit == 0 { 1.0 } else { -1.0 };
            let (a, b, c) = (sign(1) * Vec3::X, sign(2) * Vec3::Y, sign(4) * Vec3::Z);
            let point = |i: u32, j: u32| {
                let p = a * (n - i - j) as f32 + b * i as f32 + c * j as f32;
                center + radius * p.normalize()
            };
            for i in 0..n {
                for j in 0..n - i {
                    self.triangle(material, [point(i, j), point(i + 1, j), point(i, j + 1)]);
                    if i + j + 1 < n {
                        let upper = [point(i + 1, j), point(i + 1, j + 1), point(i, j + 1)];
                        self.triangle(material, upper);
                    }
                }
            }
        }
        self
    }

    pub fn sphere(&mut self, center: Vec3, radius: f32, material: MaterialId) -> &mut Self {
        self.scene.spheres.push(Sphere {
            center,
            radius,
            material,
        });
        self
    }

    pub fn light(&mut self, light: Light) -> &mut Self {
        self.scene.lights.push(light);
        self
    }

    pub fn finish(mut self) -> Scene {
        let mesh = &mut self.scene.mesh;
        mesh.normals = area_weighted_vertex_normals(&mesh.positions, &mesh.triangles);
        self.scene
    }
}

/// A rectangular area light of `radiance` centred at `center`, facing
/// `facing` (normalised here), with sides `sx` and `sy`.
pub fn rect_light(radiance: f32, center: Vec3, facing: Vec3, sx: f32, sy: f32) -> Light {
    coloured_rect_light(Vec3::splat(radiance), center, facing, sx, sy)
}

/// [`rect_light`] of RGB radiance `radiance`.
pub fn coloured_rect_light(radiance: Vec3, center: Vec3, facing: Vec3, sx: f32, sy: f32) -> Light {
    let direction = facing.normalize();
    let frame = Frame::from_z(direction);
    Light::Area {
        radiance,
        center,
        direction,
        dim_x: sx * frame.to_world(Vec3::X),
        dim_y: sy * frame.to_world(Vec3::Y),
    }
}

/// The corners of an area light, in order around it.
pub fn rect_corners(light: &Light) -> [Vec3; 4] {
    let Light::Area {
        center,
        dim_x,
        dim_y,
        ..
    } = *light
    else {
        panic!("not an area light: {light:?}");
    };
    [(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)]
        .map(|(s, t)| center + s * dim_x + t * dim_y)
}

/// The ray from `origin` towards `target`.
pub fn ray_towards(origin: Vec3, target: Vec3) -> Ray {
    Ray::new(origin, (target - origin).normalize())
}

/// The luminance of `n` independent radiance estimates along `ray`
/// (one random stream per call, seeded by `seed`, through the
/// independent sampler: the standard error assumes independent samples):
/// their mean and its standard error. Panics on a non-finite sample.
pub fn estimate<I: Intersector>(
    scene: &World<I>,
    tracer: &PathTracer,
    ray: &Ray,
    n: usize,
    seed: u64,
) -> MeanEstimate {
    let mut rng = IndependentSampler::from_stream(seed, 0);
    MeanEstimate::of((0..n).map(|_| {
        let l = tracer.radiance(scene, ray, &mut rng);
        assert!(l.is_finite(), "non-finite radiance {l}");
        luminance(l) as f64
    }))
}

/// A bright lobe, a gradient, and a black band (rows 10 and 11 of 32)
/// whose neighbours are bright.
pub fn lumpy_map() -> EnvironmentMap {
    let lobe = Vec3::new(0.5, 0.6, -0.62).normalize();
    let texels = (0..64 * 32)
        .map(|k| {
            let (i, j) = (k % 64, k / 64);
            if j == 10 || j == 11 {
                return Rgb::ZERO;
            }
            let uv = Vec2::new((i as f32 + 0.5) / 64.0, (j as f32 + 0.5) / 32.0);
            let d = uv_to_direction(uv);
            let gradient = Rgb::new(0.3, 0.5, 0.8) * (1.0 + d.y);
            let spot = 30.0 * (-(1.0 - d.dot(lobe)) / 0.05).exp();
            let band = if j == 9 || j == 12 { 8.0 } else { 0.0 };
            gradient + Rgb::new(1.0, 0.9, 0.7) * (spot + band)
        })
        .collect();
    EnvironmentMap::new("lumpy", 64, 32, texels).unwrap()
}

/// A sphere of radius 0.5 resting on a floor quad.
pub fn sphere_on_floor() -> Scene {
    ball_on_floor(diffuse(0.8))
}

/// [`sphere_on_floor`] with the sphere made of `ball`.
pub fn ball_on_floor(ball: Material) -> Scene {
    let mut b = SceneBuilder::new();
    let floor = b.material(diffuse(0.5));
    let ball = b.material(ball);
    b.quad(
        floor,
        [
            Vec3::new(-2.0, 0.0, 2.0),
            Vec3::new(2.0, 0.0, 2.0),
            Vec3::new(2.0, 0.0, -2.0),
            Vec3::new(-2.0, 0.0, -2.0),
        ],
    );
    b.sphere(Vec3::new(0.0, 0.5, 0.0), 0.5, ball);
    b.finish()
}
