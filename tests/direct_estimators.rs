//! Direct lighting (depth 1) against closed forms and across estimators:
//! a rectangle light against Lambert's polygon formula, a tilted plane
//! under the ambient sky, and hemisphere against light sampling in the
//! Cornell box.
//!
//! Each test builds a small scene in code, traces one fixed ray many times
//! with a fixed seed and compares the mean luminance (grey scenes, so any
//! channel) with a closed form through the confidence interval
//! `mean +- z se`, or compares two estimators with a two-sample z-test, at
//! [`ALPHA`] = 1e-4 per test divided among its comparisons (Bonferroni;
//! the policy is in `tests/common/stats.rs`). A correct implementation
//! fails a test less than once in 10^4 seeds.
//!
//! Every test was checked once by hand to fail for a deliberately wrong
//! library (the variant is named in each test's comment; none is committed).

mod common;

use std::f64::consts::PI;

use common::{
    accel, assert_mean_matches, assert_means_agree, diffuse, estimate, polygon_irradiance,
    ray_towards, rect_corners, rect_light, tracer, under_light_and_quad, SceneBuilder, ALPHA,
    HEMISPHERE, LIGHTS,
};
use glam::{DVec3, Vec3};
use pathtracer::scene::builtin::cornell_box;
use pathtracer::scene::Light;
use pathtracer::world::World;

/// Radiance leaving a diffuse floor lit by a tilted rectangle equals
/// `a / pi * E` with `E` from Lambert's polygon formula, through three
/// estimators: light sampling of a `Light::Area`; uniform hemisphere
/// sampling of an emissive quad at the same place (a `Material::Emission`
/// mesh, no light, so not a stand-in); and light sampling in that
/// emissive-quad scene, which samples the quad's triangles as a light
/// (`lights::triangles`).
///
/// Closed form sanity: for a small light the formula tends to
/// `L A cos_l cos_x / r^2` (checked below). Checked by hand: the area-light
/// pdf off by a factor 1.1 fails the light-sampling comparison (10 % off,
/// about 40 standard errors), and the hemisphere pdf 1/(2 pi) replaced by
/// 1/(2.2 pi) fails the hemisphere one.
#[test]
fn rectangle_irradiance_matches_lamberts_formula() {
    let (radiance, albedo) = (4.0f32, 0.7f32);
    let light = rect_light(
        radiance,
        Vec3::new(0.3, 1.0, -0.2),
        Vec3::new(-0.25, -1.0, 0.15),
        0.8,
        0.5,
    );
    let corners = rect_corners(&light);
    let x = Vec3::ZERO;
    let eye = Vec3::new(-1.0, 1.0, 1.0);
    let ray = ray_towards(eye, x);
    let floor = |b: &mut SceneBuilder| {
        let m = b.material(diffuse(albedo));
        let s = 5.0;
        b.quad(
            m,
            [
                Vec3::new(-s, 0.0, -s),
                Vec3::new(s, 0.0, -s),
                Vec3::new(s, 0.0, s),
                Vec3::new(-s, 0.0, s),
            ],
        );
    };
    let e = polygon_irradiance(
        x.as_dvec3(),
        DVec3::Y,
        &corners.map(|c| c.as_dvec3()),
        radiance as f64,
    );
    let expected = albedo as f64 / PI * e;

    // The closed form itself: a tiny copy of the light far away.
    let tiny = rect_light(
        1.0,
        Vec3::new(0.0, 50.0, 30.0),
        Vec3::new(0.0, -1.0, -0.5),
        0.01,
        0.02,
    );
    let q = DVec3::new(0.0, 50.0, 30.0);
    let approx =
        0.01 * 0.02 * (q.normalize().dot(DVec3::new(0.0, 1.0, 0.5).normalize())) * q.normalize().y
            / q.length_squared();
    let exact = polygon_irradiance(
        DVec3::ZERO,
        DVec3::Y,
        &rect_corners(&tiny).map(|c| c.as_dvec3()),
        1.0,
    );
    assert!((exact / approx - 1.0).abs() < 1e-3, "{exact} vs {approx}");

    let (with_light, with_quad) =
        under_light_and_quad(floor, light, Vec3::splat(radiance), corners);

    let alpha = ALPHA / 3.0;
    let (a1, a2) = (accel(&with_light), accel(&with_quad));
    let (s1, s2) = (World::new(&with_light, &a1), World::new(&with_quad, &a2));
    assert_eq!(
        s2.lights.emissive_triangles().map_or(0, |t| t.len()),
        2,
        "the quad's triangles are sampled as a light"
    );
    let est = estimate(&s1, &tracer(LIGHTS, 1, false), &ray, 50_000, 1);
    assert_mean_matches("area light, light sampling", est, expected, alpha, 0.0);
    let est = estimate(&s2, &tracer(HEMISPHERE, 1, false), &ray, 300_000, 2);
    assert_mean_matches(
        "emissive quad, hemisphere sampling",
        est,
        expected,
        alpha,
        0.0,
    );
    let est = estimate(&s2, &tracer(LIGHTS, 1, false), &ray, 200_000, 3);
    assert_mean_matches(
        "emissive quad, sampled as a light",
        est,
        expected,
        alpha,
        0.0,
    );
}

/// A diffuse plane of albedo `a` tilted by `beta` from horizontal under the
/// uniform ambient sky of radiance `L` (upper hemisphere only, nothing
/// else in the scene): the sky covers the part of the plane's hemisphere
/// above the horizon, whose projected solid angle is
/// `pi (1 + cos beta) / 2` (the isotropic-sky view factor, as in Liu and
/// Jordan 1963), so
///
/// ```text
/// L_o = a L (1 + cos beta) / 2     (a L for the horizontal plane).
/// ```
///
/// Estimated by light sampling of the `Light::Ambient` and by hemisphere
/// sampling (escaping rays see the sky). Checked by hand: a sky pdf of
/// 1/(2.2 pi) fails the light-sampling cases, a hemisphere pdf of
/// 1/(2.2 pi) the hemisphere ones, and a sky sampled around +Z instead of
/// +Y fails (light from below the horizon).
#[test]
fn plane_under_the_ambient_sky() {
    let (radiance, albedo) = (1.5f32, 0.6f32);
    let cases = [
        (0.0f32, LIGHTS),
        (0.0, HEMISPHERE),
        (60.0, LIGHTS),
        (60.0, HEMISPHERE),
    ];
    let alpha = ALPHA / cases.len() as f64;
    for (k, &(beta_deg, strategy)) in cases.iter().enumerate() {
        let beta = beta_deg.to_radians();
        let n = Vec3::new(beta.sin(), beta.cos(), 0.0);
        let (u, v) = (n.cross(Vec3::Z).normalize(), Vec3::Z);
        let s = 10.0;
        let mut b = SceneBuilder::new();
        let m = b.material(diffuse(albedo));
        b.quad(
            m,
            [-s * u - s * v, s * u - s * v, s * u + s * v, -s * u + s * v],
        )
        .light(Light::Ambient {
            radiance: Vec3::splat(radiance),
        });
        let scene = b.finish();
        let accel = accel(&scene);
        let st = World::new(&scene, &accel);
        let ray = ray_towards(2.0 * n + 0.5 * u + 0.3 * v, Vec3::ZERO);
        let est = estimate(
            &st,
            &tracer(strategy, 1, false),
            &ray,
            100_000,
            10 + k as u64,
        );
        let expected = (albedo * radiance) as f64 * (1.0 + (beta as f64).cos()) / 2.0;
        assert_mean_matches(
            &format!("sky-lit plane tilted {beta_deg} degrees, {strategy:?}"),
            est,
            expected,
            alpha,
            1e-5,
        );
    }
}

/// Hemisphere sampling and light sampling estimate the same direct light:
/// in the built-in Cornell box the area light has an emissive stand-in
/// quad at the same place (hemisphere rays hit it, light sampling samples
/// the light); three points, depth 1, two-sample z-tests. Bonferroni over
/// four comparisons: these three and the closed box of
/// `tests/global_estimators.rs`. Checked by hand: the area-light pdf off
/// by 1.1 fails (10 standard errors).
#[test]
fn hemisphere_and_light_sampling_agree() {
    let cornell = cornell_box();
    let cornell_accel = accel(&cornell);
    let cornell_tracer = World::new(&cornell, &cornell_accel);
    assert!(!cornell_tracer.lights.has_unsampled_emitters());

    let eye = Vec3::new(0.0, 0.75, 0.9);
    let alpha = ALPHA / 4.0;
    for (k, target) in [
        Vec3::new(0.2, 0.0, -0.3),
        Vec3::new(-0.4, 1.0, -1.0),
        Vec3::new(0.45, 0.55, 0.25),
    ]
    .into_iter()
    .enumerate()
    {
        let ray = ray_towards(eye, target);
        let seed = 30 + 2 * k as u64;
        let lights = estimate(
            &cornell_tracer,
            &tracer(LIGHTS, 1, false),
            &ray,
            40_000,
            seed,
        );
        let hemi = estimate(
            &cornell_tracer,
            &tracer(HEMISPHERE, 1, false),
            &ray,
            400_000,
            seed + 1,
        );
        assert_means_agree(
            &format!("Cornell box towards {target}"),
            lights,
            hemi,
            alpha,
        );
    }
}

/// Several samples an estimate, and lights chosen by power. Two
/// rectangles of different radiance light a diffuse floor, whose radiance
/// is then `a / pi (E_1 + E_2)` (Lambert's formula for each); for light
/// sampling a point light of intensity `I` at `r` adds `a / pi I cos /
/// |r|^2`. Estimated by
/// light sampling with 3 samples a light (each light's mean of its 3), by
/// light sampling with 3 samples in all, each of a light chosen in
/// proportion to its power (weighted `1 / (P(l) p)`), and by 4 hemisphere
/// directions over the two rectangles as emissive quads. The other tests
/// take one sample, where a sum and a mean agree.
///
/// Checked by hand: the hemisphere's `sum / n` as `sum * n` (4 times too
/// bright), each light's `sum / samples` as `sum * samples`, the
/// by-power branch subtracting its samples instead of adding them, and a
/// delta light's weight `1 / P(l)` as `P(l)` each fail.
#[test]
fn several_samples_and_lights_chosen_by_power() {
    use pathtracer::direct::{DirectHemisphere, DirectLights};
    use pathtracer::global::DirectStrategy;
    use pathtracer::lights::LightChoiceRule;
    use pathtracer::world::WorldOptions;

    let albedo = 0.6f32;
    let lamps = [
        rect_light(
            4.0,
            Vec3::new(0.3, 1.0, -0.2),
            Vec3::new(-0.25, -1.0, 0.15),
            0.8,
            0.5,
        ),
        rect_light(
            1.5,
            Vec3::new(-0.5, 0.9, -0.6),
            Vec3::new(0.5, -0.9, 0.6),
            0.6,
            0.6,
        ),
    ];
    let radiances = [4.0f32, 1.5];
    let expected: f64 = lamps
        .iter()
        .zip(radiances)
        .map(|(lamp, l)| {
            let corners = rect_corners(lamp).map(|c| c.as_dvec3());
            albedo as f64 / PI * polygon_irradiance(DVec3::ZERO, DVec3::Y, &corners, l as f64)
        })
        .sum();
    // A point light too, where light sampling alone sees it.
    let (intensity, bulb) = (0.8f32, Vec3::new(0.2, 1.2, 0.4));
    let r = bulb.as_dvec3();
    let from_bulb = albedo as f64 / PI * intensity as f64 * r.y / r.length().powi(3);
    let ray = ray_towards(Vec3::new(-1.0, 1.0, 1.0), Vec3::ZERO);
    let floor = |b: &mut SceneBuilder| {
        let m = b.material(diffuse(albedo));
        b.floor(m, 5.0);
    };
    let mut with_lights = SceneBuilder::new();
    floor(&mut with_lights);
    with_lights.light(Light::Point {
        intensity: Vec3::splat(intensity),
        position: bulb,
    });
    let mut with_quads = SceneBuilder::new();
    floor(&mut with_quads);
    for (lamp, l) in lamps.into_iter().zip(radiances) {
        let glow = with_quads.material(common::emission(l));
        with_quads.quad(glow, rect_corners(&lamp));
        with_lights.light(lamp);
    }
    let (with_lights, with_quads) = (with_lights.finish(), with_quads.finish());
    let (a1, a2) = (accel(&with_lights), accel(&with_quads));
    let every = World::new(&with_lights, &a1);
    let by_power = World::with_options(
        &with_lights,
        &a1,
        WorldOptions {
            light_choice: LightChoiceRule::ByPower,
            ..WorldOptions::default()
        },
    );
    let quads = World::new(&with_quads, &a2);
    let three = DirectStrategy::Lights(DirectLights {
        samples_per_light: 3,
        environment_samples: None,
        mis: false,
    });
    let four = DirectStrategy::Hemisphere(DirectHemisphere { samples: 4 });
    let alpha = ALPHA / 3.0;
    let lit = expected + from_bulb;
    let est = estimate(&every, &tracer(three, 1, false), &ray, 30_000, 41);
    assert_mean_matches("3 samples a light", est, lit, alpha, 0.0);
    let est = estimate(&by_power, &tracer(three, 1, false), &ray, 30_000, 42);
    assert_mean_matches("3 samples of lights chosen by power", est, lit, alpha, 0.0);
    let est = estimate(&quads, &tracer(four, 1, false), &ray, 100_000, 43);
    assert_mean_matches("4 hemisphere directions", est, expected, alpha, 0.0);
}
