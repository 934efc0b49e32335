//! The families of [`crate::families`] that sample a 2D piecewise-constant
//! distribution: the distribution itself, carried to the sphere by an
//! equal-area map, and the environment light on a map with a gradient, a
//! bright lobe and a black band, by importance and uniformly.

use std::f64::consts::PI;

use glam::{Vec2, Vec3};
use pathtracer::environment::{
    uv_to_direction, EnvironmentLight, EnvironmentMap, EnvironmentSampling,
};
use pathtracer::lights::LightPdf;
use pathtracer::math::distribution::Distribution2D;
use pathtracer::math::Frame;

use crate::families::Family;

/// A 2D distribution of `width x height` cells of `f(i, j)`, carried to
/// the sphere by the equal-area map `z = 1 - 2 v`, `phi = 2 pi u` (whose
/// Jacobian is the constant `4 pi`), so that the direction tests check its
/// sampler and density: `p(w) = p(u, v) / (4 pi)`.
fn distribution_family(
    name: &str,
    width: usize,
    height: usize,
    f: impl Fn(usize, usize) -> f32,
) -> Family {
    let func: Vec<f32> = (0..width * height)
        .map(|k| f(k % width, k / width))
        .collect();
    let d = std::rc::Rc::new(Distribution2D::new(&func, width, height));
    let queried = d.clone();
    let to_sphere = |uv: Vec2| {
        let z = 1.0 - 2.0 * uv.y;
        let r = (1.0 - z * z).max(0.0).sqrt();
        let phi = 2.0 * std::f32::consts::PI * uv.x;
        Vec3::new(r * phi.cos(), r * phi.sin(), z)
    };
    let to_square = |w: Vec3| {
        let phi = (w.y as f64).atan2(w.x as f64).rem_euclid(2.0 * PI);
        Vec2::new((phi / (2.0 * PI)) as f32, 0.5 * (1.0 - w.z))
    };
    Family {
        name: name.into(),
        sample: Box::new(move |u| {
            let s = d.sample(u);
            Some((to_sphere(s.x), s.pdf as f64 / (4.0 * PI)))
        }),
        pdf: Box::new(move |w| queried.pdf(to_square(w)) as f64 / (4.0 * PI)),
        frame: Frame::from_z(Vec3::Z),
        cos_min: -1.0,
        lossy: false,
    }
}

/// The environment light's sampler on `map`, with its grid's pole on +Y
/// and its `phi` the map's (local x = -X, y = +Z), so that the grid's
/// sectors fall on the map's columns (the density jumps only between
/// cells, and the quadrature of the expected counts then meets those
/// jumps only between rows).
fn environment_family(name: &str, map: EnvironmentMap, sampling: EnvironmentSampling) -> Family {
    let light = EnvironmentLight::new(map, sampling);
    let queried = light.clone();
    Family {
        name: name.into(),
        sample: Box::new(move |u| {
            let s = light.sample_li(u)?;
            match s.pdf {
                LightPdf::SolidAngle(pdf) => Some((s.wi, pdf as f64)),
                LightPdf::Delta => None,
            }
        }),
        pdf: Box::new(move |w| queried.pdf_li(w) as f64),
        frame: Frame {
            x: -Vec3::X,
            y: Vec3::Z,
            z: Vec3::Y,
        },
        cos_min: -1.0,
        lossy: false,
    }
}

/// A 64 x 32 map: a gradient, a bright lobe, and a black band.
fn lumpy_map() -> EnvironmentMap {
    let lobe = Vec3::new(0.5, 0.6, -0.62).normalize();
    let texels = (0..64 * 32)
        .map(|k| {
            let (i, j) = (k % 64, k / 64);
            let d = uv_to_direction(Vec2::new((i as f32 + 0.5) / 64.0, (j as f32 + 0.5) / 32.0));
            if j == 10 || j == 11 {
                return Vec3::ZERO;
            }
            Vec3::new(0.3, 0.5, 0.8) * (1.0 + d.y)
                + Vec3::splat(30.0 * (-(1.0 - d.dot(lobe)) / 0.05).exp())
        })
        .collect();
    EnvironmentMap::new("lumpy", 64, 32, texels).unwrap()
}

/// The distributions and environment samplers.
pub fn environment_families() -> Vec<Family> {
    vec![
        distribution_family("2D distribution, 24 x 12, empty cells", 24, 12, |i, j| {
            if (i + j) % 5 == 0 {
                0.0
            } else {
                1.0 + ((i * 7 + j * 3) % 11) as f32
            }
        }),
        distribution_family("2D distribution, 1 x 3", 1, 3, |_, j| [2.0, 0.0, 1.0][j]),
        environment_family(
            "environment, lumpy map, importance",
            lumpy_map(),
            EnvironmentSampling::Importance,
        ),
        environment_family(
            "environment, lumpy map, uniform",
            lumpy_map(),
            EnvironmentSampling::Uniform,
        ),
    ]
}
