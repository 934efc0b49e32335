//! Colour: every channel of the estimators against its own closed form.
//! The other estimator tests use grey scenes and read luminance or one
//! channel, so a channel dropped, swapped or mixed with another passes
//! them; here albedos are coloured ([`ALBEDO`]) and so are the lights
//! ([`RADIANCE`]), their channels all different, so that swapping two
//! channels of either changes the answer in both.
//!
//! Each test traces one fixed ray many times with a fixed seed (the
//! independent sampler) and compares the mean of each channel with its
//! closed form through the confidence interval `mean +- z se`. The level
//! is shared by the whole file: [`ALPHA`] = 1e-4 divided among the
//! [`CHANNEL_COMPARISONS`] channel comparisons of all its tests
//! (Bonferroni), so a correct implementation fails the file less than
//! once in 10^4 seeds (z = 4.69). The sample counts keep every standard
//! error under 2 % of its channel (asserted), so a swapped or dropped
//! channel fails by many standard errors (8 to 900 in the checks named
//! below); where a channel's estimate is exact up to rounding, a
//! relative floor of 1e-4 or 1e-5 widens the interval.
//!
//! Every test was checked by hand to fail for a deliberately wrong
//! library (named in each test's comment; none is committed).

mod common;

use std::f64::consts::PI;

use common::{
    accel, assert_mean_matches, coloured_rect_light, polygon_irradiance, ray_towards, rect_corners,
    tracer, under_light_and_quad, MeanEstimate, SceneBuilder, ALPHA, HEMISPHERE, LIGHTS,
    LIGHTS_ALONE,
};
use glam::{DVec3, Vec3};
use pathtracer::global::{DirectStrategy, PathTracer, Roulette};
use pathtracer::intersect::{Intersector, Ray};
use pathtracer::sampling::IndependentSampler;
use pathtracer::scene::{Light, Material};
use pathtracer::world::World;

/// A coloured albedo: its products with [`RADIANCE`] (0.8, 0.6, 0.4)
/// differ from channel to channel.
const ALBEDO: [f32; 3] = [0.8, 0.3, 0.1];
/// A coloured light (radiance, or intensity for the point light).
const RADIANCE: [f32; 3] = [1.0, 2.0, 4.0];

/// Channel comparisons in this file: 6 direct estimates, 3 furnace
/// estimates and 3 integrating spheres, 3 channels each.
const CHANNEL_COMPARISONS: usize = 3 * (6 + 3 + 3);

/// The significance level of one channel comparison.
fn alpha() -> f64 {
    ALPHA / CHANNEL_COMPARISONS as f64
}

fn rgb(c: [f32; 3]) -> Vec3 {
    Vec3::from_array(c)
}

/// Per channel, the mean and standard error of `n` radiance estimates
/// along `ray` (one independent stream seeded by `seed`).
fn estimate_rgb<I: Intersector>(
    world: &World<I>,
    tracer: &PathTracer,
    ray: &Ray,
    n: usize,
    seed: u64,
) -> [MeanEstimate; 3] {
    let mut rng = IndependentSampler::from_stream(seed, 0);
    let samples: Vec<Vec3> = (0..n)
        .map(|_| {
            let l = tracer.radiance(world, ray, &mut rng);
            assert!(l.is_finite(), "non-finite radiance {l}");
            l
        })
        .collect();
    [0, 1, 2].map(|c| MeanEstimate::of(samples.iter().map(|l| l[c] as f64)))
}

/// Each channel's mean against its closed form, at [`alpha`] each; the
/// standard error is also checked to be under 2 % of the answer, so that
/// the test keeps its power to see a swapped channel.
fn assert_rgb_matches(label: &str, est: [MeanEstimate; 3], expected: [f64; 3], floor: f64) {
    for (c, name) in ["R", "G", "B"].into_iter().enumerate() {
        assert!(
            est[c].se <= 0.02 * expected[c],
            "{label}, {name}: se {:.2e} too large for {:.4}",
            est[c].se,
            expected[c]
        );
        let label = format!("{label}, channel {name}");
        assert_mean_matches(&label, est[c], expected[c], alpha(), floor * expected[c]);
    }
}

/// A diffuse floor of albedo [`ALBEDO`] lit by a tilted rectangle of
/// radiance [`RADIANCE`]: `L_o = a / pi * E` per channel, with `E` from
/// Lambert's polygon formula (`tests/common/radiometry.rs`), through six
/// estimators. The rectangle is a `Light::Area` for light sampling
/// (alone at depth 1; at depth 2 weighted by MIS against the BSDF ray,
/// which finds the rectangle and then escapes: only the floor is there),
/// for hemisphere sampling and for BSDF sampling alone; and an emissive
/// quad at the same place, sampled by hemisphere rays and as a light (its
/// triangles) without MIS, at depth 2: the BSDF ray that then finds the
/// quad must add nothing, since the light sample counted it (the quad
/// reflects nothing, so nothing else comes back).
///
/// Checked by hand to fail when, in `src/direct/estimators.rs`,
/// `DirectLights::contribution` swaps the light's red and blue radiance
/// (`sample.radiance.zyx()`: 890 standard errors), when
/// `DirectHemisphere::estimate` drops the blue channel of what its rays
/// find (blue 0), when the path tracer swaps green and blue of the
/// throughput (`src/global/mod.rs`: the MIS case, 8.5 standard errors), and
/// when `found_emission` (`src/global/emission.rs`) drops the blue of a
/// rectangle light a BSDF ray crosses (the MIS case, 12 standard errors),
/// and when `emission_weight` (the same file) counts emission a BSDF ray
/// finds on a sampled emitter without MIS (the quad counted twice: the
/// standard error 1.7e-3 where the correct one is 6.3e-5, past the 2 %
/// of the answer the test allows).
#[test]
fn coloured_rectangle_light_on_a_coloured_floor() {
    let light = coloured_rect_light(
        rgb(RADIANCE),
        Vec3::new(0.3, 1.0, -0.2),
        Vec3::new(-0.25, -1.0, 0.15),
        0.8,
        0.5,
    );
    let corners = rect_corners(&light);
    let e_unit = polygon_irradiance(DVec3::ZERO, DVec3::Y, &corners.map(|c| c.as_dvec3()), 1.0);
    let expected: [f64; 3] = [0, 1, 2].map(|c| ALBEDO[c] as f64 / PI * RADIANCE[c] as f64 * e_unit);
    let ray = ray_towards(Vec3::new(-1.0, 1.0, 1.0), Vec3::ZERO);

    let floor = |b: &mut SceneBuilder| {
        let m = b.material(Material::Diffuse {
            albedo: rgb(ALBEDO),
        });
        b.floor(m, 5.0);
    };
    let (with_light, with_quad) = under_light_and_quad(floor, light, rgb(RADIANCE), corners);
    let (a1, a2) = (accel(&with_light), accel(&with_quad));
    let (s1, s2) = (World::new(&with_light, &a1), World::new(&with_quad, &a2));

    // (scene, label, strategy, depth, samples)
    let cases = [
        (&s1, "area light, light sampling", LIGHTS, 1, 20_000),
        (&s1, "area light, light sampling and MIS", LIGHTS, 2, 20_000),
        (&s1, "area light, hemisphere", HEMISPHERE, 1, 60_000),
        (
            &s1,
            "area light, BSDF sampling",
            DirectStrategy::BsdfOnly,
            1,
            60_000,
        ),
        (&s2, "emissive quad, hemisphere", HEMISPHERE, 1, 60_000),
        (
            &s2,
            "emissive quad, light sampling alone",
            LIGHTS_ALONE,
            2,
            20_000,
        ),
    ];
    for (k, &(world, label, strategy, depth, n)) in cases.iter().enumerate() {
        let est = estimate_rgb(
            world,
            &tracer(strategy, depth, false),
            &ray,
            n,
            60 + k as u64,
        );
        assert_rgb_matches(label, est, expected, 0.0);
    }
}

/// The coloured furnace: a closed box whose walls reflect diffusely with
/// albedo `a` = [`ALBEDO`] and emit `Le` = [`RADIANCE`] (every channel its
/// own geometric series, so the colour products of every bounce matter):
///
/// ```text
/// L_m = Le (1 + a + ... + a^m) = Le (1 - a^(m+1)) / (1 - a)  ->  Le / (1 - a)
/// ```
///
/// At `m = 3` without Russian roulette by hemisphere sampling and by BSDF
/// sampling alone (exact up to rounding: `f cos / pdf = a` and every ray
/// finds `Le`), the infinite sum by BSDF sampling with the throughput
/// rule, whose `q` follows the coloured throughput, and `m = 12` with the
/// course's fixed rule, which acts from the second vertex (the throughput
/// rule acts only after 8 bounces, where green and blue bring almost
/// nothing). Light sampling is left
/// to the integrating spheres below: in a box, light samples on a wall
/// next to a vertex near an edge make the estimator's variance infinite
/// (the integrand grows as `1 / distance^2` to the edge), so its
/// confidence interval would not hold.
///
/// Checked by hand to fail when the path tracer (`src/global/mod.rs`)
/// multiplies the throughput by the BSDF weight with its green and blue
/// swapped (`weight.xzy()`: 69 standard errors), when it divides only the
/// red channel by the roulette's `q` (`PathWeight::survived`: the fixed
/// rule's case, 203; the throughput rule's, 340 when it started after 5
/// bounces, no longer sees it), and when
/// `DirectHemisphere::estimate` drops the blue channel. (The roulette's
/// `q` reading one channel instead of the maximum is not wrong: any `q`
/// keeps the mean, and here red is the maximum anyway.)
#[test]
fn coloured_furnace_sums_each_channel_s_bounces() {
    let mut b = SceneBuilder::new();
    let wall = b.material(Material::EmissiveDiffuse {
        albedo: rgb(ALBEDO),
        radiance: rgb(RADIANCE),
    });
    b.closed_box(wall, Vec3::ZERO, Vec3::ONE);
    let scene = b.finish();
    let accel = accel(&scene);
    let world = World::new(&scene, &accel);
    let ray = ray_towards(Vec3::new(0.3, 0.6, 0.45), Vec3::new(1.0, 0.4, 0.7));
    let sum = |m: Option<i32>| -> [f64; 3] {
        [0, 1, 2].map(|c| {
            let (a, le) = (ALBEDO[c] as f64, RADIANCE[c] as f64);
            le * (1.0 - m.map_or(0.0, |m| a.powi(m + 1))) / (1.0 - a)
        })
    };
    let bsdf = DirectStrategy::BsdfOnly;
    // (label, strategy, depth, roulette, samples)
    let cases = [
        ("hemisphere, m = 3", HEMISPHERE, 3, Roulette::Off, 20_000),
        ("BSDF sampling, m = 3", bsdf, 3, Roulette::Off, 1_000),
        (
            "BSDF sampling, throughput roulette",
            bsdf,
            200,
            Roulette::Throughput,
            40_000,
        ),
        (
            "BSDF sampling, the course's roulette, m = 12",
            bsdf,
            12,
            Roulette::Fixed,
            40_000,
        ),
    ];
    for (k, &(label, direct, max_depth, roulette, n)) in cases.iter().enumerate() {
        let tracer = PathTracer {
            direct,
            max_depth,
            accumulate: true,
            roulette,
            glass_splits: 0,
        };
        let expected = sum((max_depth < 200).then_some(max_depth as i32));
        let est = estimate_rgb(&world, &tracer, &ray, n, 70 + k as u64);
        assert_rgb_matches(label, est, expected, 1e-4);
    }
}

/// A diffuse sphere of radius `R` and coloured albedo `a` = [`ALBEDO`] lit
/// from inside by a coloured light: per channel, paths of at most `m`
/// bounces bring (derivation in `tests/global_estimators.rs`,
/// `furnace_integrating_sphere`: a cosine-distributed direction from the
/// wall meets the wall uniformly in area)
///
/// ```text
/// L_m(x) = L_d(x) + a Lbar (1 - a^(m-1)) / (1 - a),   Lbar = (a / pi) Phi / (4 pi R^2)
/// ```
///
/// with `L_d` the direct radiance at the camera ray's wall point `x` and
/// `Phi` the light's power, all of which reaches the wall: a coloured
/// light times a coloured albedo to the power of each bounce. Two lights:
/// a point light of intensity [`RADIANCE`] (`Phi = 4 pi I`,
/// `L_d = (a / pi) I cos_x / r^2`), light sampling; and a rectangle light
/// of radiance [`RADIANCE`] (`Phi = pi L A`, `L_d` by Lambert's formula;
/// rectangle lights are not geometry, so it blocks nothing), by light
/// sampling with MIS (the BSDF rays that cross it weighted against the
/// light samples) and by hemisphere sampling. `m = 4`, no Russian roulette.
///
/// Checked by hand to fail when the point light's sample swaps its red
/// and green intensity (`src/lights/point.rs`: 370 standard errors), when
/// the path tracer swaps green and blue of the throughput (as for the
/// furnace: 900), when the rectangle light's emission found by a BSDF ray
/// (`found_emission`, `src/global/emission.rs`) drops its blue channel
/// (8.7), and when light sampling swaps the light's red and blue.
#[test]
fn coloured_lights_in_a_coloured_integrating_sphere() {
    let radius = 2.0f64;
    let origin = DVec3::new(0.0, 0.2, 0.8);
    let dir = DVec3::new(0.6, 0.5, -0.3).normalize();
    let b = origin.dot(dir);
    let t = -b + (b * b - origin.length_squared() + radius * radius).sqrt();
    let x = origin + t * dir;
    let normal = -x / radius;
    let ray = Ray::new(origin.as_vec3(), dir.as_vec3());
    let m = 4;
    let point_at = DVec3::new(0.6, -0.4, 0.2);
    let rect_at = DVec3::new(0.2, -0.1, -0.2);
    let rect = coloured_rect_light(
        rgb(RADIANCE),
        rect_at.as_vec3(),
        (x - rect_at).as_vec3(),
        1.0,
        0.8,
    );
    let Light::Area {
        direction,
        dim_x,
        dim_y,
        ..
    } = rect
    else {
        unreachable!()
    };
    let corners = rect_corners(&rect).map(|c| c.as_dvec3());
    // The camera ray starts in front of the rectangle and moves away from
    // its plane, so it never sees the light.
    let facing = direction.as_dvec3();
    assert!((origin - rect_at).dot(facing) > 0.0 && dir.dot(facing) > 0.0);
    assert!(corners
        .iter()
        .all(|c| c.length() < radius && (x - c).dot(facing) > 0.0));
    let area = (dim_x.length() * dim_y.length()) as f64;
    // Per unit radiance or intensity: (irradiance at x, power).
    let to_point = point_at - x;
    let point_unit = (
        normal.dot(to_point.normalize()) / to_point.length_squared(),
        4.0 * PI,
    );
    let rect_unit = (polygon_irradiance(x, normal, &corners, 1.0), PI * area);
    let expected = |(e, phi): (f64, f64)| {
        [0, 1, 2].map(|c| {
            let (a, l) = (ALBEDO[c] as f64, RADIANCE[c] as f64);
            let l_bar = a / PI * l * phi / (4.0 * PI * radius * radius);
            a / PI * l * e + a * l_bar * (1.0 - a.powi(m - 1)) / (1.0 - a)
        })
    };
    let sphere_with = |light: Light| {
        let mut builder = SceneBuilder::new();
        let wall = builder.material(Material::Diffuse {
            albedo: rgb(ALBEDO),
        });
        builder.sphere(Vec3::ZERO, radius as f32, wall).light(light);
        builder.finish()
    };
    let point_scene = sphere_with(Light::Point {
        intensity: rgb(RADIANCE),
        position: point_at.as_vec3(),
    });
    let rect_scene = sphere_with(rect);
    let (pa, ra) = (accel(&point_scene), accel(&rect_scene));
    let (point_world, rect_world) = (World::new(&point_scene, &pa), World::new(&rect_scene, &ra));
    // (label, world, unit answer, strategy, samples)
    let cases = [
        (
            "point light, light sampling",
            &point_world,
            point_unit,
            LIGHTS,
            20_000,
        ),
        (
            "rectangle, light sampling and MIS",
            &rect_world,
            rect_unit,
            LIGHTS,
            20_000,
        ),
        (
            "rectangle, hemisphere",
            &rect_world,
            rect_unit,
            HEMISPHERE,
            160_000,
        ),
    ];
    for (k, &(label, world, unit, strategy, n)) in cases.iter().enumerate() {
        let est = estimate_rgb(
            world,
            &tracer(strategy, m as u32, false),
            &ray,
            n,
            80 + k as u64,
        );
        assert_rgb_matches(label, est, expected(unit), 1e-5);
    }
}
