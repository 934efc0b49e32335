//! The table of direction samplers under test ([`families`]): every warp,
//! BSDF, light and environment sampler of the library, each with its
//! density and the grid its histogram is taken on.

use std::f64::consts::PI;

use glam::{Vec2, Vec3};
use pathtracer::bvh::BvhAccel;
use pathtracer::intersect::Ray;
use pathtracer::lights::{Light as SampledLight, LightConvention, LightPdf};
use pathtracer::materials::{Conductor, Diffuse, MicrofacetSampling};
use pathtracer::math::warp::{
    cosine_hemisphere_pdf, sample_cosine_hemisphere, sample_uniform_cone,
    sample_uniform_hemisphere, sample_uniform_sphere, uniform_cone_pdf, uniform_hemisphere_pdf,
    uniform_sphere_pdf,
};
use pathtracer::math::Frame;
use pathtracer::scene::{Light, Material, Scene};
use pathtracer::world::World;

use crate::common::{accel, diffuse, rect_corners, rect_light, SceneBuilder};

/// A sampler of unit directions with its density per steradian.
pub struct Family {
    pub name: String,
    /// A direction (world space) and the density the sampler reports for
    /// it, or `None` when the sampler gives nothing.
    pub sample: Box<dyn Fn(Vec2) -> Option<(Vec3, f64)>>,
    /// The density function, per steradian.
    pub pdf: Box<dyn Fn(Vec3) -> f64>,
    /// Frame of the histogram grid (its +Z is the grid's pole).
    pub frame: Frame,
    /// The grid covers `[cos_min, 1] x [0, 2 pi)`; unless `lossy`, the
    /// density vanishes for `cos theta < cos_min` in that frame.
    pub cos_min: f64,
    /// Whether the sampler may refuse draws and sample off the grid: the
    /// density is then a sub-density of the kept draws. A lossy family's
    /// grid is uniform in `theta` rather than `cos theta` (see
    /// [`radial`](crate::quadrature::radial)).
    pub lossy: bool,
}

/// The family of `Light::sample_li` / `Light::pdf_li` for `light` seen from `p`.
/// The grid's pole points at the light's centre (area light) or up (sky),
/// and `cos_min` bounds the light's extent (for a rectangle the largest
/// angle from the pole is at a corner, as the region within a cone is
/// convex on the light's plane).
fn light_family(name: &str, light: Light, p: Vec3) -> Family {
    let sampled = SampledLight::from_scene(&light, LightConvention::Physical);
    let queried = sampled.clone();
    let (frame, cos_min) = match light {
        Light::Area { center, .. } => {
            let axis = (center - p).normalize();
            let cos_min = rect_corners(&light)
                .iter()
                .map(|&q| (q - p).normalize().dot(axis) as f64)
                .fold(1.0, f64::min);
            (Frame::from_z(axis), (cos_min - 1e-3).max(-1.0))
        }
        _ => (Frame::from_z(Vec3::Y), 0.0),
    };
    Family {
        name: name.into(),
        sample: Box::new(move |u| {
            let s = sampled.sample_li(p, 0.5, u)?;
            match s.pdf {
                LightPdf::SolidAngle(pdf) => Some((s.wi, pdf as f64)),
                LightPdf::Delta => None,
            }
        }),
        pdf: Box::new(move |w| queried.pdf_li(p, w, None) as f64),
        frame,
        cos_min,
        lossy: false,
    }
}

/// `1 - cos(40 degrees)`: the cone of the cone family (the caustic
/// casters' sampler, `src/world/casters/cone.rs`).
const CONE_ONE_MINUS_COS: f32 = 0.233_955_55;

/// A warp of the unit square to directions around +Z with its density,
/// which vanishes below `cos_min`.
fn warp_family(name: &str, sample: fn(Vec2) -> Vec3, pdf: fn(Vec3) -> f32, cos_min: f64) -> Family {
    Family {
        name: name.into(),
        sample: Box::new(move |u| {
            let w = sample(u);
            Some((w, pdf(w) as f64))
        }),
        pdf: Box::new(move |w| pdf(w) as f64),
        frame: Frame::from_z(Vec3::Z),
        cos_min,
        lossy: false,
    }
}

/// The rough conductor's direction sampler for `wo` at `cos theta_o =
/// cos_o` (azimuth 2 rad, so that the visible-normal sampler's rotation is
/// exercised), gridded on a cap of radius `4 alpha` around the mirror
/// direction.
fn conductor_family(alpha: f32, cos_o: f32, sampling: MicrofacetSampling) -> Family {
    let sin_o = (1.0 - cos_o * cos_o).max(0.0).sqrt();
    let wo = Vec3::new(sin_o * 2f32.cos(), sin_o * 2f32.sin(), cos_o);
    let copper = Conductor::new(
        alpha,
        Vec3::new(0.2, 1.0, 1.2),
        Vec3::new(3.0, 2.5, 2.4),
        sampling,
    );
    Family {
        name: format!("conductor, {sampling:?}, alpha {alpha}, wo.z {cos_o}"),
        sample: Box::new(move |u| {
            let s = copper.sample(wo, u)?;
            Some((s.wi, s.pdf() as f64))
        }),
        pdf: Box::new(move |w| copper.pdf(wo, w) as f64),
        frame: Frame::from_z(Vec3::new(-wo.x, -wo.y, wo.z)),
        cos_min: (4.0 * f64::from(alpha)).min(PI).cos(),
        lossy: true,
    }
}

/// Conductor families: the three strategies, smooth to rough, normal to
/// grazing (`Auto` takes the half vector at `alpha` 0.01 up to `cos_o` 0.5
/// and at `alpha` 0.1 at normal incidence, the visible normals at the rest).
fn conductor_families() -> Vec<Family> {
    let mut families = Vec::new();
    for sampling in [
        MicrofacetSampling::HalfVector,
        MicrofacetSampling::VisibleNormals,
        MicrofacetSampling::Auto,
    ] {
        for alpha in [0.01, 0.1, 0.5, 1.0] {
            for cos_o in [1.0, 0.5, 0.05] {
                families.push(conductor_family(alpha, cos_o, sampling));
            }
        }
    }
    // The cosine-weighted baseline ignores the lobe; two roughnesses.
    for alpha in [0.1, 1.0] {
        for cos_o in [1.0, 0.5] {
            families.push(conductor_family(
                alpha,
                cos_o,
                MicrofacetSampling::CosineHemisphere,
            ));
        }
    }
    families
}

/// The path's continuation at a diffuse floor point under two caustic
/// casters (a mirror sphere and a smooth conductor, wholly above the
/// floor) lit by a rectangle light: the mixture of the cosine lobe, the
/// spheres' cones and the narrower cones around the light's image in
/// each (`World::sample_continuation`, `World::continuation_pdf`). The
/// family's 2D number chooses the branch and the cone and draws the
/// direction; the 1D number (the BSDF's lobe, unused by a diffuse one)
/// comes from its own fixed stream. It is lossy: an image's sample
/// outside its sphere's cone is refused (`Cones`), so the density is
/// that of the kept draws, and integrates to the kept fraction.
fn continuation_family() -> Family {
    let mut b = SceneBuilder::new();
    let floor = b.material(diffuse(0.7));
    let mirror = b.material(Material::Mirror {
        reflectance: Vec3::ONE,
    });
    let smooth = b.material(Material::Microfacet {
        alpha: 0.05,
        eta: Vec3::splat(0.2),
        k: Vec3::splat(3.0),
    });
    b.floor(floor, 3.0)
        .sphere(Vec3::new(0.5, 0.6, 0.2), 0.3, mirror)
        .sphere(Vec3::new(-0.8, 1.5, -0.4), 0.5, smooth)
        .light(rect_light(
            10.0,
            Vec3::new(-0.3, 2.5, 0.6),
            -Vec3::Y,
            0.8,
            0.6,
        ));
    // The world borrows the scene and its BVH for the family's lifetime.
    let scene: &'static Scene = Box::leak(Box::new(b.finish()));
    let bvh: &'static BvhAccel = Box::leak(Box::new(accel(scene)));
    let world: &'static World<&BvhAccel> = Box::leak(Box::new(World::new(scene, bvh)));
    assert_eq!(world.casters.spheres.len(), 2);
    let down = Ray::new(
        Vec3::new(0.0, 0.1, 0.0),
        Vec3::new(0.1, -1.0, 0.05).normalize(),
    );
    let point = world.trace(&down).expect("the ray meets the floor");
    // Both spheres' cones and both light images.
    assert_eq!(point.cones.len(), 4);
    let state = std::cell::Cell::new(0x9e37_79b9_7f4a_7c15u64);
    Family {
        name: "diffuse continuation with two caster cones and two light images".into(),
        sample: Box::new(move |u| {
            // SplitMix64 (Steele, Lea and Flood 2014) for the choice.
            let z = state.get().wrapping_add(0x9e37_79b9_7f4a_7c15);
            state.set(z);
            let z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            let z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            let uc = ((z ^ (z >> 31)) >> 40) as f32 / (1u64 << 24) as f32;
            let s = world.sample_continuation(&point, uc, u)?;
            Some((point.frame.to_world(s.wi), s.pdf() as f64))
        }),
        pdf: Box::new(move |w| {
            let bsdf_pdf = point.bsdf.pdf(point.wo, point.frame.to_local(w));
            world.continuation_pdf(&point, w, bsdf_pdf) as f64
        }),
        frame: point.frame,
        cos_min: 0.0,
        lossy: true,
    }
}

/// Every direction sampler of the library.
pub fn families() -> Vec<Family> {
    let diffuse = Diffuse {
        albedo: Vec3::splat(0.7),
    };
    let wo = Vec3::new(0.3, -0.2, 0.9).normalize();
    let mut families = vec![
        warp_family(
            "uniform hemisphere",
            sample_uniform_hemisphere,
            uniform_hemisphere_pdf,
            0.0,
        ),
        warp_family(
            "cosine hemisphere",
            sample_cosine_hemisphere,
            cosine_hemisphere_pdf,
            0.0,
        ),
        warp_family(
            "uniform cone of half-angle 40 degrees",
            |u| sample_uniform_cone(u, CONE_ONE_MINUS_COS),
            |w| {
                if w.z >= 1.0 - CONE_ONE_MINUS_COS {
                    uniform_cone_pdf(CONE_ONE_MINUS_COS)
                } else {
                    0.0
                }
            },
            1.0 - CONE_ONE_MINUS_COS as f64,
        ),
        warp_family(
            "uniform sphere",
            sample_uniform_sphere,
            |_| uniform_sphere_pdf(),
            -1.0,
        ),
        Family {
            name: "diffuse BSDF".into(),
            sample: Box::new(move |u| {
                let s = diffuse.sample(wo, u)?;
                Some((s.wi, s.pdf() as f64))
            }),
            pdf: Box::new(move |w| diffuse.pdf(wo, w) as f64),
            frame: Frame::from_z(Vec3::Z),
            cos_min: 0.0,
            lossy: false,
        },
        light_family(
            "area light, far and oblique",
            rect_light(
                1.0,
                Vec3::new(0.7, 2.0, -0.4),
                Vec3::new(-0.5, -1.0, 0.6),
                0.6,
                0.8,
            ),
            Vec3::new(0.1, 0.0, 0.2),
        ),
        light_family(
            "area light, near and large",
            rect_light(1.0, Vec3::new(0.2, 0.4, 0.1), -Vec3::Y, 1.5, 1.0),
            Vec3::ZERO,
        ),
        // A sheared light (a transform in the file can shear it): its
        // crossing test works in the edges' dual basis, whose cross terms
        // a rectangle's orthogonal edges set to zero.
        light_family(
            "area light, a parallelogram",
            Light::Area {
                radiance: Vec3::ONE,
                center: Vec3::new(0.3, 1.2, -0.2),
                direction: Vec3::new(0.2, -1.0, 0.1),
                dim_x: Vec3::new(1.2, 0.1, 0.0),
                dim_y: Vec3::new(0.8, -0.05, 0.9),
            },
            Vec3::new(-0.2, 0.0, 0.1),
        ),
        light_family(
            "ambient sky",
            Light::Ambient {
                radiance: Vec3::ONE,
            },
            Vec3::new(3.0, -1.0, 2.0),
        ),
    ];
    families.push(continuation_family());
    families.extend(conductor_families());
    families.extend(crate::environment_families::environment_families());
    families
}
