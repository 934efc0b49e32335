//! The scene model: what a scene file describes, in world space, before any
//! acceleration structure is built.
//!
//! Conventions (see `docs/00-conventions.md`):
//! - world space is Y-up; the COLLADA loader has already applied every node
//!   matrix and the course's Z_UP map `(x, y, z) -> (-x, z, y)`;
//! - lengths are scene units, angles in the camera description are degrees;
//! - colours are linear RGB ([`Rgb`]), radiance in W/(sr m^2) per channel.

use glam::Vec3;

use crate::math::Rgb;

/// Index of a material in [`Scene::materials`].
pub type MaterialId = u32;

/// A whole scene: geometry, materials, lights and the camera description.
#[derive(Clone, Debug, Default)]
pub struct Scene {
    /// Where the scene came from (a file path or `built-in: NAME`), for messages.
    pub source: String,
    /// Every triangle mesh of the scene, merged into one.
    pub mesh: TriangleMesh,
    /// Analytic spheres.
    pub spheres: Vec<Sphere>,
    /// Materials referenced by [`TriangleMesh::materials`] and [`Sphere::material`].
    pub materials: Vec<Material>,
    /// Light sources (not counting emissive surfaces, which are materials).
    pub lights: Vec<Light>,
    /// The camera as the file describes it; the course re-places it
    /// (see [`crate::raygen::Camera::course_placement`]).
    pub camera: CameraInfo,
    /// Problems the loader tolerated (for example a 15-number matrix).
    pub warnings: Vec<String>,
}

/// Triangles sharing one vertex array. Meshes never share vertices with each
/// other, so merging several keeps each mesh's connectivity intact.
#[derive(Clone, Debug, Default)]
pub struct TriangleMesh {
    /// Vertex positions, world space.
    pub positions: Vec<Vec3>,
    /// Per-vertex shading normals (unit length, or zero for a vertex whose
    /// faces all have zero area), one per position. The course rebuilds
    /// them from connectivity: see [`crate::scene::normals`].
    pub normals: Vec<Vec3>,
    /// Vertex indices of each triangle, counter-clockwise as in the file.
    pub triangles: Vec<[u32; 3]>,
    /// Material of each triangle.
    pub materials: Vec<MaterialId>,
}

/// An analytic sphere.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    pub center: Vec3,
    pub radius: f32,
    pub material: MaterialId,
}

/// The BSDFs and emitters of the course: the `CGL` techniques the starter's
/// `ColladaParser::parse_material` reads (`src/scene/collada/collada.cpp`),
/// with the BSDFs of its `src/pathtracer/bsdf.h`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Material {
    /// Lambertian: f = albedo / pi.
    Diffuse { albedo: Rgb },
    /// Emits `radiance` from both sides, reflects nothing.
    Emission { radiance: Rgb },
    /// Lambertian reflection that also emits `radiance` from both sides.
    /// The course has no such material; test scenes use it for the
    /// furnace (a closed box whose walls reflect and glow).
    EmissiveDiffuse { albedo: Rgb, radiance: Rgb },
    /// Perfect specular reflection scaled by `reflectance`.
    Mirror { reflectance: Rgb },
    /// Fresnel-weighted choice of reflection and refraction.
    Glass {
        reflectance: Rgb,
        transmittance: Rgb,
        roughness: f32,
        ior: f32,
    },
    /// Perfect specular transmission only (Snell's law).
    Refraction {
        transmittance: Rgb,
        roughness: f32,
        ior: f32,
    },
    /// Beckmann microfacet conductor with complex index of refraction `eta + i k`.
    Microfacet { alpha: f32, eta: Rgb, k: Rgb },
}

impl Material {
    /// The course's default material: diffuse with albedo 0.5.
    pub const DEFAULT: Material = Material::Diffuse {
        albedo: Vec3::splat(0.5),
    };

    /// A short lower-case name of the material's kind, for `--info`.
    pub fn kind(&self) -> &'static str {
        match self {
            Material::Diffuse { .. } => "diffuse",
            Material::Emission { .. } => "emission",
            Material::EmissiveDiffuse { .. } => "emissive diffuse",
            Material::Mirror { .. } => "mirror",
            Material::Glass { .. } => "glass",
            Material::Refraction { .. } => "refraction",
            Material::Microfacet { .. } => "microfacet",
        }
    }

    /// Radiance emitted by a surface of this material (zero unless emissive).
    pub fn emission(&self) -> Rgb {
        match self {
            Material::Emission { radiance } | Material::EmissiveDiffuse { radiance, .. } => {
                *radiance
            }
            _ => Rgb::ZERO,
        }
    }
}

/// Light sources, in world space: the kinds the starter's
/// `ColladaParser::parse_light` reads, sampled as its `AreaLight::sample_L`,
/// `PointLight::sample_L`, ... do (`src/scene/light.cpp`; where this
/// project differs, see `docs/04-direct.md`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Light {
    /// One-sided rectangle `center + s * dim_x + t * dim_y`, s, t in
    /// [-1/2, 1/2], emitting `radiance` towards the side `direction` points to.
    Area {
        radiance: Rgb,
        center: Vec3,
        /// Unit normal of the emitting side.
        direction: Vec3,
        dim_x: Vec3,
        dim_y: Vec3,
    },
    /// Isotropic point source with radiant intensity `intensity` (W/sr).
    Point { intensity: Rgb, position: Vec3 },
    /// Light from infinitely far away; `direction` is the unit vector
    /// towards the light.
    Directional { radiance: Rgb, direction: Vec3 },
    /// A uniform sky of `radiance` over the hemisphere around +Y.
    Ambient { radiance: Rgb },
    /// A spot light: parsed, but it contributes nothing, as in the course.
    Spot {
        intensity: Rgb,
        position: Vec3,
        direction: Vec3,
    },
}

impl Light {
    /// A short lower-case name of the light's kind, for `--info`.
    pub fn kind(&self) -> &'static str {
        match self {
            Light::Area { .. } => "area",
            Light::Point { .. } => "point",
            Light::Directional { .. } => "directional",
            Light::Ambient { .. } => "ambient",
            Light::Spot { .. } => "spot",
        }
    }
}

/// The camera as the scene file describes it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraInfo {
    /// Unit vector from the view target towards the camera, world space.
    /// The course computes it as `normalize(G * T * (0, 0, -1, 1))`
    /// (translation included, a quirk of the course).
    pub dir_to_camera: Vec3,
    /// Horizontal field of view, degrees.
    pub hfov_deg: f32,
    /// Vertical field of view, degrees.
    pub vfov_deg: f32,
    /// Near clip distance, scene units.
    pub znear: f32,
    /// Far clip distance, scene units.
    pub zfar: f32,
}

impl Default for CameraInfo {
    /// The course's defaults when a file has no camera: looking along -Z
    /// (so the camera sits on +Z), hFov 50, vFov 35, znear 0.001, zfar 1000.
    fn default() -> Self {
        CameraInfo {
            dir_to_camera: Vec3::Z,
            hfov_deg: 50.0,
            vfov_deg: 35.0,
            znear: 0.001,
            zfar: 1000.0,
        }
    }
}
