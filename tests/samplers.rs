//! Statistical tests of every direction sampler against its density.
//!
//! A table of sampler families ([`families`]) goes through the same
//! checks (design.md, "Testing"):
//!
//! 1. the density integrates to 1 over its domain (midpoint quadrature on a
//!    fine `(cos theta, phi)` grid, where `d omega = d cos(theta) d phi`);
//! 2. the density a sample reports equals the density function at the
//!    sampled direction;
//! 3. Pearson's chi-square goodness of fit: the histogram of sampled
//!    directions on a `(cos theta, phi)` grid in the family's frame against
//!    the expected counts `N * integral of pdf over the cell` (quadrature on
//!    a sub-grid), cells with expected count under 5 pooled. The expected
//!    counts are *not* renormalised, so a density off by a constant factor
//!    fails too.
//!
//! Lossy families (the microfacet conductor, which discards a direction
//! reflected below the surface) have a sub-density: its integral over the
//! sphere is the probability that a draw is kept, not 1. For them check 1
//! compares the integral over the whole sphere with the fraction of draws
//! kept (a z-test), and check 3 adds one cell for everything off the grid,
//! discarded draws included, whose expected count is `N` minus the grid's
//! (so lost draws are counted against the density too). Their grid is a
//! cap around the mirror direction whose radius scales with the roughness
//! (`4 alpha`), so that even the narrow lobe of `alpha = 0.01` spreads
//! over all its rings (about 2 % of the draws of a narrow lobe fall
//! outside the cap, in the extra cell).
//!
//! Seeds are fixed. The whole table is one test of significance
//! [`ALPHA`] = 1e-4, split evenly among the families (Bonferroni), so a
//! correct sampler fails it less than once in 10^4 seeds.
//! [`the_checks_reject_wrong_densities`] shows each check can fail: a pdf
//! off by a factor 1.1, the course's area-light pdf with `r` instead of
//! `r^2`, a cosine sampler checked against the uniform pdf. Checked once
//! by hand on the library too: a hemisphere warp with `z = sqrt(u1)` and an
//! area-light sample shifted by 5 % of a side both fail the chi-square test
//! (p = 0).

mod common;

use std::f64::consts::PI;

use common::{chi_square, rect_corners, rect_light, ALPHA};
use glam::{Vec2, Vec3};
use pathtracer::environment::{
    uv_to_direction, EnvironmentLight, EnvironmentMap, EnvironmentSampling,
};
use pathtracer::lights::{Light as SampledLight, LightConvention, LightPdf};
use pathtracer::materials::{Conductor, Diffuse, MicrofacetSampling};
use pathtracer::math::distribution::Distribution2D;
use pathtracer::math::rng::{next_2d, sampler};
use pathtracer::math::warp::{
    cosine_hemisphere_pdf, sample_cosine_hemisphere, sample_uniform_hemisphere,
    sample_uniform_sphere, uniform_hemisphere_pdf, uniform_sphere_pdf,
};
use pathtracer::math::Frame;
use pathtracer::scene::Light;

/// A sampler of unit directions with its density per steradian.
struct Family {
    name: String,
    /// A direction (world space) and the density the sampler reports for
    /// it, or `None` when the sampler gives nothing.
    sample: Box<dyn Fn(Vec2) -> Option<(Vec3, f64)>>,
    /// The density function, per steradian.
    pdf: Box<dyn Fn(Vec3) -> f64>,
    /// Frame of the histogram grid (its +Z is the grid's pole).
    frame: Frame,
    /// The grid covers `[cos_min, 1] x [0, 2 pi)`; unless `lossy`, the
    /// density vanishes for `cos theta < cos_min` in that frame.
    cos_min: f64,
    /// Whether the sampler may refuse draws and sample off the grid: the
    /// density is then a sub-density of the kept draws. A lossy family's
    /// grid is uniform in `theta` rather than `cos theta` (see
    /// [`radial`]).
    lossy: bool,
}

/// The radial grid coordinate of `w` and its `phi`: `cos theta` (rings of
/// equal solid angle), or for a lossy family `theta` itself, computed from
/// the local `x, y` so that it stays accurate near the pole. Rings uniform
/// in `theta` resolve a narrow lobe near its centre: the lobe of a grazing,
/// smooth conductor is a thin streak through the mirror direction, which
/// the innermost rings of equal solid angle (uniform in `theta^2`) blur.
fn radial(family: &Family, w: Vec3) -> (f64, f64) {
    if !family.lossy {
        return polar(&family.frame, w);
    }
    let l = family.frame.to_local(w).as_dvec3();
    let phi = l.y.atan2(l.x).rem_euclid(2.0 * PI);
    (l.x.hypot(l.y).atan2(l.z), phi)
}

/// The range of the radial grid coordinate, `[cos_min, 1]` or
/// `[0, acos(cos_min)]`.
fn radial_range(family: &Family) -> (f64, f64) {
    if family.lossy {
        (0.0, family.cos_min.clamp(-1.0, 1.0).acos())
    } else {
        (family.cos_min, 1.0)
    }
}

/// Midpoint-rule integral of `family.pdf` over `[r0, r1] x [p0, p1]` in
/// the family's radial coordinate and `phi`, `n x m` points.
fn integrate_radial(family: &Family, r: (f64, f64), p: (f64, f64), n: usize, m: usize) -> f64 {
    if !family.lossy {
        return integrate(family, r, p, n, m);
    }
    integrate_angle(family, r, p, n, m).0
}

/// [`integrate_radial`] of a lossy family over one cell of the histogram:
/// on `SUB` squared points, or on `4 SUB` squared for a cell the horizon
/// crosses (where the density drops to 0, some points are 0 and some are
/// not): the midpoint rule's error there, proportional to the point
/// spacing, would otherwise show in the chi-square statistic of a
/// grazing lobe cut by the horizon.
fn integrate_cell(family: &Family, r: (f64, f64), p: (f64, f64)) -> f64 {
    if !family.lossy {
        return integrate(family, r, p, SUB, SUB);
    }
    let (value, zeros) = integrate_angle(family, r, p, SUB, SUB);
    if zeros > 0 && zeros < SUB * SUB {
        integrate_angle(family, r, p, 4 * SUB, 4 * SUB).0
    } else {
        value
    }
}

/// Midpoint-rule integral over `[t0, t1] x [p0, p1]` in `(theta, phi)`,
/// and the number of points where the density is 0.
fn integrate_angle(
    family: &Family,
    r: (f64, f64),
    p: (f64, f64),
    n: usize,
    m: usize,
) -> (f64, usize) {
    // d omega = sin(theta) d theta d phi.
    let ((t0, t1), (p0, p1)) = (r, p);
    let (dt, dp) = ((t1 - t0) / n as f64, (p1 - p0) / m as f64);
    let mut sum = 0.0;
    let mut zeros = 0;
    for i in 0..n {
        let t = t0 + (i as f64 + 0.5) * dt;
        let (st, ct) = t.sin_cos();
        for j in 0..m {
            let (sp, cp) = (p0 + (j as f64 + 0.5) * dp).sin_cos();
            let w = family
                .frame
                .to_world(Vec3::new((st * cp) as f32, (st * sp) as f32, ct as f32));
            let pdf = (family.pdf)(w);
            zeros += usize::from(pdf == 0.0);
            sum += pdf * st;
        }
    }
    (sum * dt * dp, zeros)
}

/// `cos theta` and `phi` in `[0, 2 pi)` of `w` in `frame`.
fn polar(frame: &Frame, w: Vec3) -> (f64, f64) {
    let l = frame.to_local(w).normalize();
    let phi = (l.y as f64).atan2(l.x as f64).rem_euclid(2.0 * PI);
    ((l.z as f64).clamp(-1.0, 1.0), phi)
}

/// The world direction of `(cos theta, phi)` in `frame`.
fn direction(frame: &Frame, cos_theta: f64, phi: f64) -> Vec3 {
    let s = (1.0 - cos_theta * cos_theta).max(0.0).sqrt();
    frame.to_world(Vec3::new(
        (s * phi.cos()) as f32,
        (s * phi.sin()) as f32,
        cos_theta as f32,
    ))
}

/// Midpoint-rule integral of `family.pdf` over `[c0, c1] x [p0, p1]` in
/// `(cos theta, phi)` with `n x m` points.
fn integrate(
    family: &Family,
    (c0, c1): (f64, f64),
    (p0, p1): (f64, f64),
    n: usize,
    m: usize,
) -> f64 {
    let (dc, dp) = ((c1 - c0) / n as f64, (p1 - p0) / m as f64);
    let mut sum = 0.0;
    for i in 0..n {
        let c = c0 + (i as f64 + 0.5) * dc;
        for j in 0..m {
            let p = p0 + (j as f64 + 0.5) * dp;
            sum += (family.pdf)(direction(&family.frame, c, p));
        }
    }
    sum * dc * dp
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

/// Conductor families: both strategies, smooth to rough, normal to grazing.
fn conductor_families() -> Vec<Family> {
    let mut families = Vec::new();
    for sampling in [
        MicrofacetSampling::HalfVector,
        MicrofacetSampling::VisibleNormals,
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
fn environment_families() -> Vec<Family> {
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

/// Every direction sampler of the library.
fn families() -> Vec<Family> {
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
        light_family(
            "ambient sky",
            Light::Ambient {
                radiance: Vec3::ONE,
            },
            Vec3::new(3.0, -1.0, 2.0),
        ),
    ];
    families.extend(conductor_families());
    families.extend(environment_families());
    families
}

/// Histogram grid: cells in `cos theta` and in `phi`, sub-grid points per
/// cell side for the expected counts, and samples per family.
const COS_CELLS: usize = 16;
const PHI_CELLS: usize = 32;
const SUB: usize = 32;
const SAMPLES: u64 = 400_000;

/// The chi-square test of `family` with `SAMPLES` draws from stream
/// `stream`: the p-value, plus draws the sampler refused and draws off the
/// grid (both must be 0), unless the family is lossy: those draws then
/// fill one more cell.
fn goodness_of_fit(family: &Family, stream: u64) -> (common::ChiSquare, u64) {
    let (c0, c1) = radial_range(family);
    let dc = (c1 - c0) / COS_CELLS as f64;
    let dp = 2.0 * PI / PHI_CELLS as f64;
    let mut observed = vec![0u64; COS_CELLS * PHI_CELLS];
    let mut refused = 0;
    let mut off_grid = 0;
    let mut rng = sampler(0x5A3D_1E55, stream);
    for _ in 0..SAMPLES {
        let Some((w, _)) = (family.sample)(next_2d(&mut rng)) else {
            refused += 1;
            continue;
        };
        let (c, p) = radial(family, w);
        if c < c0 || c > c1 {
            off_grid += 1;
            continue;
        }
        let i = (((c - c0) / dc) as usize).min(COS_CELLS - 1);
        let j = ((p / dp) as usize).min(PHI_CELLS - 1);
        observed[i * PHI_CELLS + j] += 1;
    }
    let mut expected = Vec::with_capacity(observed.len());
    for i in 0..COS_CELLS {
        let ci = c0 + i as f64 * dc;
        for j in 0..PHI_CELLS {
            let pj = j as f64 * dp;
            let cell = integrate_cell(family, (ci, ci + dc), (pj, pj + dp));
            expected.push(SAMPLES as f64 * cell);
        }
    }
    if !family.lossy {
        return (chi_square(&observed, &expected), refused + off_grid);
    }
    let on_grid: f64 = expected.iter().sum();
    observed.push(refused + off_grid);
    expected.push((SAMPLES as f64 - on_grid).max(0.0));
    (chi_square(&observed, &expected), 0)
}

/// The integral of a lossy family's density over the whole sphere: its
/// cap finely, then rings of doubling angular radius out to the south pole.
fn integrate_sphere(family: &Family) -> f64 {
    let (_, cap) = radial_range(family);
    let mut total = integrate_radial(family, (0.0, cap), (0.0, 2.0 * PI), 400, 400);
    let mut theta = cap;
    while theta < PI {
        let next = (2.0 * theta).min(PI);
        total += integrate_radial(family, (theta, next), (0.0, 2.0 * PI), 100, 400);
        theta = next;
    }
    total
}

/// The fraction of `n` draws from stream `stream` the sampler keeps, with
/// its binomial standard error.
fn kept_fraction(family: &Family, n: u64, stream: u64) -> (f64, f64) {
    let mut rng = sampler(0x0C0B_BEE5, stream);
    let kept = (0..n)
        .filter(|_| (family.sample)(next_2d(&mut rng)).is_some())
        .count() as f64
        / n as f64;
    (kept, (kept * (1.0 - kept) / n as f64).sqrt())
}

/// The lossy family's density integrates to its kept fraction: `Ok` with
/// both, or `Err` with a message.
fn check_lossy_mass(family: &Family, stream: u64, alpha: f64) -> Result<(f64, f64), String> {
    let total = integrate_sphere(family);
    let (kept, se) = kept_fraction(family, 100_000, stream);
    // Quadrature error of the midpoint rule across the horizon's cut: 2e-3.
    let limit = common::z_two_sided(alpha) * se + 2e-3;
    if (total - kept).abs() <= limit {
        Ok((total, kept))
    } else {
        Err(format!(
            "{}: the pdf integrates to {total} over the sphere, but {kept} of the draws are kept              (limit {limit:.2e})",
            family.name
        ))
    }
}

#[test]
fn every_density_integrates_to_one() {
    let families = families();
    let lossy = families.iter().filter(|f| f.lossy).count();
    for (stream, family) in families.iter().enumerate() {
        if family.lossy {
            let (total, kept) = check_lossy_mass(family, stream as u64, ALPHA / lossy as f64)
                .unwrap_or_else(|e| panic!("{e}"));
            eprintln!("{}: integral {total:.5}, kept {kept:.5}", family.name);
            continue;
        }
        // Where the density lives, finely; below cos_min, coarsely (it must be 0).
        let inside = integrate(family, (family.cos_min, 1.0), (0.0, 2.0 * PI), 1500, 1500);
        let outside = if family.cos_min > -1.0 {
            integrate(family, (-1.0, family.cos_min), (0.0, 2.0 * PI), 200, 400)
        } else {
            0.0
        };
        // Quadrature error: ~1e-6 for smooth densities, ~1e-3 along the
        // edge of an area light; a factor 1.1 is far outside.
        assert!(
            (inside - 1.0).abs() < 3e-3 && outside == 0.0,
            "{}: the pdf integrates to {inside} where it lives and {outside} elsewhere",
            family.name
        );
    }
}

#[test]
fn sampled_densities_equal_the_density_function() {
    for family in families() {
        let mut rng = sampler(17, 0);
        for _ in 0..10_000 {
            let Some((w, reported)) = (family.sample)(next_2d(&mut rng)) else {
                continue;
            };
            let evaluated = (family.pdf)(w);
            assert!(
                (reported - evaluated).abs() <= 1e-3 * evaluated.max(reported),
                "{}: sample reports pdf {reported} at {w}, pdf() says {evaluated}",
                family.name
            );
        }
    }
}

#[test]
fn every_sampler_matches_its_density_chi_square() {
    let families = families();
    let alpha = ALPHA / families.len() as f64;
    for (stream, family) in families.iter().enumerate() {
        let (test, lost) = goodness_of_fit(family, stream as u64);
        eprintln!(
            "{}: chi-square {:.1}, {} dof, p = {:.3e}",
            family.name, test.statistic, test.degrees_of_freedom, test.p_value
        );
        assert!(
            lost == 0 && test.p_value > alpha,
            "{}: chi-square {:.1} with {} degrees of freedom, p = {:.3e} (alpha {alpha:.1e}); \
             {lost} samples refused or off the grid",
            family.name,
            test.statistic,
            test.degrees_of_freedom,
            test.p_value,
        );
    }
}

/// The checks above have power: deliberately wrong densities fail them.
#[test]
fn the_checks_reject_wrong_densities() {
    let mut wrong = Vec::new();
    // Of the conductor families, those of alpha 0.1 (both strategies, every
    // angle) stand for the rest, to keep the run short.
    let sample_of_families = families()
        .into_iter()
        .filter(|f| !f.lossy || f.name.contains("alpha 0.1,"));
    for family in sample_of_families {
        let Family {
            name,
            sample,
            pdf,
            frame,
            cos_min,
            lossy,
        } = family;
        if name.starts_with("area light, far") {
            // The course's quirk: r / (A cos) instead of r^2 / (A cos).
            let light = rect_light(
                1.0,
                Vec3::new(0.7, 2.0, -0.4),
                Vec3::new(-0.5, -1.0, 0.6),
                0.6,
                0.8,
            );
            let p = Vec3::new(0.1, 0.0, 0.2);
            wrong.push(Family {
                name: "area light with the pdf's r^2 replaced by r".into(),
                sample,
                pdf: Box::new(move |w| {
                    let sampled = SampledLight::from_scene(&light, LightConvention::Physical);
                    let t = sampled.pdf_li(p, w, None) as f64;
                    // pdf = r^2 / (A cos): divide by r once.
                    let r = match light {
                        Light::Area {
                            center, direction, ..
                        } => (direction.dot(center - p) / direction.dot(w)) as f64,
                        _ => 1.0,
                    };
                    if t > 0.0 {
                        t / r
                    } else {
                        0.0
                    }
                }),
                frame,
                cos_min,
                lossy,
            });
        } else if name == "cosine hemisphere" {
            wrong.push(Family {
                name: "cosine samples against the uniform pdf".into(),
                sample,
                pdf: Box::new(|w| uniform_hemisphere_pdf(w) as f64),
                frame,
                cos_min,
                lossy,
            });
        } else {
            wrong.push(Family {
                name: format!("{name} with its pdf times 1.1"),
                sample,
                pdf: Box::new(move |w| 1.1 * pdf(w)),
                frame,
                cos_min,
                lossy,
            });
        }
    }
    let alpha = ALPHA / wrong.len() as f64;
    for (stream, family) in wrong.iter().enumerate() {
        let (test, _) = goodness_of_fit(family, 100 + stream as u64);
        eprintln!("{}: p = {:.3e}", family.name, test.p_value);
        assert!(
            test.p_value < alpha,
            "{}: the chi-square test should reject it, p = {:.3e}",
            family.name,
            test.p_value
        );
        if family.lossy {
            assert!(
                check_lossy_mass(family, 100 + stream as u64, alpha).is_err(),
                "{}: the mass check should reject it",
                family.name
            );
            continue;
        }
        let total = integrate(family, (family.cos_min, 1.0), (0.0, 2.0 * PI), 600, 600);
        if !family.name.starts_with("cosine samples") {
            assert!(
                (total - 1.0).abs() > 3e-2,
                "{}: integrates to {total}",
                family.name
            );
        }
    }
}
