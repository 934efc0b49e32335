//! Every mistake of parts 6 and 7 in the catalogue
//! ([`pathtracer::mistakes`]) shows the symptom the catalogue names: the
//! built-in materials box (a mirror, a glass and a copper ball) and the
//! built-in environment scene (two balls on a floor under the built-in
//! sky), rendered small by the course's renderer with and without it.
//! Every test's comparisons share [`ALPHA`] = 1e-4.

mod common;
#[path = "mistakes_3_2/microfacet.rs"]
mod microfacet;

use common::*;
use glam::Vec3;
use pathtracer::course::{StarterDirect, StarterTracer};
use pathtracer::environment::{builtin_sky, EnvironmentLight, EnvironmentSampling};
use pathtracer::intersect::Ray;
use pathtracer::mistakes::{Mistake, Mistakes};
use pathtracer::scene::{builtin, Material};

use StarterDirect::Importance as L;

/// The pixels of the materials box that see the ball of centre `c`, radius 0.3.
fn ball(view: &CourseView, c: Vec3) -> Vec<usize> {
    view.pixels_seeing(|p| (p - c).length() < 0.31)
}

const MIRROR_BALL: Vec3 = Vec3::new(-0.5, 0.3, -0.4);
const GLASS_BALL: Vec3 = Vec3::new(0.45, 0.3, 0.3);

/// Part 6 at `-m 5`: `reflect-wrong-axis` darkens the mirror ball (its
/// rays go into it) and `refraction-ratio-inverted` brightens the glass
/// ball (its rim reflects the lamp-lit room); the factors are as measured here, far outside the noise.
#[test]
fn mirror_and_glass_mistakes_change_their_ball() {
    let view = CourseView::of(builtin::materials_box());
    let mirror = ball(&view, MIRROR_BALL);
    let glass = ball(&view, GLASS_BALL);
    assert!(mirror.len() > 40 && glass.len() > 40);
    let alpha = ALPHA / 2.0;
    let cases: [(Mistake, &[usize], std::ops::Range<f64>); 2] = [
        (Mistake::ReflectWrongAxis, &mirror, 0.0..0.8),
        (Mistake::RefractionRatioInverted, &glass, 1.1..3.0),
    ];
    for (k, (mistake, pixels, range)) in cases.into_iter().enumerate() {
        let seed = 400 + 10 * k as u64;
        let right = view.mean_over(&starter_tracer(&[], L, 1, 5, true), 256, pixels, seed);
        let wrong = view.mean_over(
            &starter_tracer(&[mistake], L, 1, 5, true),
            256,
            pixels,
            seed + 1,
        );
        assert_ratio_in(&mistake.to_string(), wrong, right, range, alpha);
    }
}

/// `no-eta-squared`: a closed glass ball seen from outside looks the same
/// (the factors entering and leaving cancel), but a floor seen through a
/// single refracting sheet of index 1.5 loses the starter's factor
/// `eta^2 = 2.25` (the course's convention; see `EtaScaling::Starter`).
#[test]
fn no_eta_squared_shows_only_through_one_surface() {
    let view = CourseView::of(builtin::materials_box());
    let glass = ball(&view, GLASS_BALL);
    let alpha = ALPHA / 2.0;
    let right = view.mean_over(&starter_tracer(&[], L, 1, 5, true), 64, &glass, 500);
    let wrong = view.mean_over(
        &starter_tracer(&[Mistake::NoEtaSquared], L, 1, 5, true),
        64,
        &glass,
        501,
    );
    assert_ratio("no-eta-squared, closed ball", wrong, right, 1.0, alpha);

    // A lit floor seen through a refracting sheet at y = 1 (index 1.5).
    let mut b = SceneBuilder::new();
    let floor = b.material(diffuse(0.5));
    b.floor(floor, 3.0);
    let sheet = b.material(Material::Refraction {
        transmittance: Vec3::ONE,
        roughness: 0.0,
        ior: 1.5,
    });
    b.quad(
        sheet,
        [
            Vec3::new(-3.0, 1.0, -3.0),
            Vec3::new(-3.0, 1.0, 3.0),
            Vec3::new(3.0, 1.0, 3.0),
            Vec3::new(3.0, 1.0, -3.0),
        ],
    );
    b.light(rect_light(
        4.0,
        Vec3::new(0.0, 0.6, 0.0),
        -Vec3::Y,
        0.5,
        0.5,
    ));
    let scene = b.finish();
    let bvh = accel(&scene);
    let world = pathtracer::world::World::with_options(&scene, &bvh, THREE_ONE.world_options());
    let ray = ray_towards(Vec3::new(0.3, 2.0, 0.4), Vec3::new(0.5, 0.0, 0.2));
    let through = |mistakes: &[Mistake], seed| {
        let t = StarterTracer {
            mistakes: Mistakes::of(mistakes),
            ..starter_tracer(&[], L, 1, 2, true)
        };
        along(&world, &t, &ray, 20_000, seed)
    };
    let (right, wrong) = (through(&[], 510), through(&[Mistake::NoEtaSquared], 511));
    assert_ratio(
        "no-eta-squared, one surface",
        wrong,
        right,
        1.0 / 2.25,
        alpha,
    );
}

/// The mean luminance of `n` estimates of `tracer` along `ray` in `world`.
fn along<I: pathtracer::intersect::Intersector>(
    world: &pathtracer::world::World<I>,
    tracer: &StarterTracer,
    ray: &Ray,
    n: usize,
    seed: u64,
) -> Mean {
    let mut rng = pathtracer::sampling::IndependentSampler::from_stream(seed, 0);
    let e = MeanEstimate::of(
        (0..n).map(|_| pathtracer::math::luminance(tracer.radiance(world, ray, &mut rng)) as f64),
    );
    Mean {
        value: e.mean,
        se: e.se,
    }
}

/// `no-total-internal-reflection`: light inside a glass *ball* never meets
/// the critical angle (it leaves at the angle it entered), so balls look
/// the same; a glass block does not. A ray entering the top of a block of
/// index 1.5 at 50 degrees refracts to 30.7 and meets a side at 59.3,
/// beyond the critical 41.8: the right glass reflects it on towards the
/// lit floor beneath, the wrong one ends the path there (the ray's whole
/// light comes through that reflection here).
#[test]
fn no_total_internal_reflection_darkens_a_glass_block() {
    let view = CourseView::of(builtin::materials_box());
    let glass = ball(&view, GLASS_BALL);
    let alpha = ALPHA / 2.0;
    let right = view.mean_over(&starter_tracer(&[], L, 1, 5, true), 64, &glass, 520);
    let wrong = view.mean_over(
        &starter_tracer(&[Mistake::NoTotalInternalReflection], L, 1, 5, true),
        64,
        &glass,
        521,
    );
    assert_ratio(
        "no-total-internal-reflection, a ball",
        wrong,
        right,
        1.0,
        alpha,
    );

    let mut b = SceneBuilder::new();
    let floor = b.material(diffuse(0.5));
    b.floor(floor, 3.0);
    let glass = b.material(GLASS);
    b.closed_box(glass, Vec3::new(-0.5, 0.01, -0.5), Vec3::new(0.5, 1.0, 0.5));
    b.light(rect_light(
        6.0,
        Vec3::new(-1.5, 2.0, 0.0),
        -Vec3::Y,
        1.0,
        1.0,
    ));
    let scene = b.finish();
    let bvh = accel(&scene);
    let world = pathtracer::world::World::with_options(&scene, &bvh, THREE_ONE.world_options());
    // Into the top at 50 degrees from the normal, towards the +x side.
    let d = Vec3::new(50f32.to_radians().sin(), -50f32.to_radians().cos(), 0.0);
    let ray = Ray::new(Vec3::new(0.2, 1.0, 0.0) - d, d);
    let right = along(
        &world,
        &starter_tracer(&[], L, 1, 6, true),
        &ray,
        20_000,
        530,
    );
    let wrong = along(
        &world,
        &starter_tracer(&[Mistake::NoTotalInternalReflection], L, 1, 6, true),
        &ray,
        20_000,
        531,
    );
    assert_ratio_in(
        "no-total-internal-reflection, a block",
        wrong,
        right,
        f64::NEG_INFINITY..0.5,
        alpha,
    );
}

/// `schlick-r0-not-squared`: a glass sheet over nothing, seen at 30
/// degrees from its normal where it mirrors a lamp, shows the lamp by its
/// Fresnel reflectance alone: Schlick's `R0 + (1 - R0)(1 - cos)^5` with
/// `R0 = 0.04` for index 1.5, and with the square left out `R0 = 0.2`, so
/// about five times as bright (the ratio computed here from the formula).
#[test]
fn schlick_r0_not_squared_reflects_five_times_as_much() {
    let mut b = SceneBuilder::new();
    let glass = b.material(GLASS);
    b.floor(glass, 1.0);
    let lamp = b.material(Material::Emission {
        radiance: Vec3::splat(5.0),
    });
    // The lamp where the sheet mirrors the ray: up and to +x at 30 degrees.
    let (s, c) = (30f32.to_radians().sin(), 30f32.to_radians().cos());
    let at = Vec3::new(2.0 * s, 2.0 * c, 0.0);
    let (u, w) = (Vec3::new(c, -s, 0.0), Vec3::Z);
    b.quad(lamp, [at - u - w, at + u - w, at + u + w, at - u + w]);
    let scene = b.finish();
    let bvh = accel(&scene);
    let world = pathtracer::world::World::with_options(&scene, &bvh, THREE_ONE.world_options());
    let ray = Ray::new(Vec3::new(-2.0 * s, 2.0 * c, 0.0), Vec3::new(s, -c, 0.0));
    let schlick = |r0: f64| r0 + (1.0 - r0) * (1.0 - c as f64).powi(5);
    let factor = schlick(0.2) / schlick(0.04);
    let right = along(
        &world,
        &starter_tracer(&[], L, 1, 2, true),
        &ray,
        40_000,
        540,
    );
    let wrong = along(
        &world,
        &starter_tracer(&[Mistake::SchlickR0NotSquared], L, 1, 2, true),
        &ray,
        40_000,
        541,
    );
    assert!(
        (right.value / 5.0 - schlick(0.04)).abs() < 5.0 * right.se / 5.0,
        "{right:?}"
    );
    assert_ratio("schlick-r0-not-squared", wrong, right, factor, ALPHA);
}

/// The environment scene under the built-in sky.
fn sky_view() -> CourseView {
    let mut view = CourseView::of(builtin::environment_spheres());
    let sky = builtin_sky().expect("the built-in sky");
    view.environment = Some(EnvironmentLight::new(sky, EnvironmentSampling::Importance));
    view
}

/// Part 7 at `-m 1 -o 0` (the map's direct light alone): without the
/// `2 pi^2` the image is `1 / (2 pi^2)` of the right one; without
/// `sin(theta)` it is brighter (every density is too small by `sin`).
#[test]
fn environment_pdf_mistakes_bias_the_direct_light() {
    let view = sky_view();
    // The balls and the floor: camera rays that escape see the map itself.
    let surfaces = view.pixels_seeing(|_| true);
    let alpha = ALPHA / 2.0;
    // 128 samples: the handout's texel weights leave the cells beside the
    // sun, which the bilinear lookup lights, rarely sampled (fireflies).
    let right = view.mean_over(&starter_tracer(&[], L, 1, 1, false), 128, &surfaces, 600);
    let no_jacobian = view.mean_over(
        &starter_tracer(&[Mistake::EnvPdfNoJacobian], L, 1, 1, false),
        128,
        &surfaces,
        601,
    );
    let two_pi_squared = 2.0 * std::f64::consts::PI.powi(2);
    assert_ratio(
        "env-pdf-no-jacobian",
        no_jacobian,
        right,
        1.0 / two_pi_squared,
        alpha,
    );
    let no_sin = view.mean_over(
        &starter_tracer(&[Mistake::EnvPdfNoSin], L, 1, 1, false),
        128,
        &surfaces,
        602,
    );
    assert_ratio_in("env-pdf-no-sin", no_sin, right, 1.05..3.0, alpha);
}

/// `env-map-u-flipped` and `env-map-v-flipped`: a camera ray that escapes
/// sees the map at the mirrored direction (`z` or `y` negated), and the
/// scene is lit from there: with the sky upside down the floor, lit by
/// the ground's half of the map, darkens.
#[test]
fn environment_flips_mirror_the_map() {
    let view = sky_view();
    let env = view.environment.clone().unwrap();
    let dirs = [
        Vec3::new(0.3, 0.5, -0.8),
        Vec3::new(-0.7, 0.2, 0.4),
        Vec3::new(0.1, -0.6, 0.5),
    ];
    let (scene, bvh) = (
        builtin::environment_spheres(),
        accel(&builtin::environment_spheres()),
    );
    let world = pathtracer::world::World::with_options(&scene, &bvh, THREE_ONE.world_options())
        .with_environment(Some(env.clone()));
    for (mistake, mirror) in [
        (Mistake::EnvMapUFlipped, Vec3::new(1.0, 1.0, -1.0)),
        (Mistake::EnvMapVFlipped, Vec3::new(1.0, -1.0, 1.0)),
    ] {
        let t = StarterTracer {
            mistakes: Mistakes::of(&[mistake]),
            ..starter_tracer(&[], L, 1, 0, true)
        };
        for d in dirs {
            let d = d.normalize();
            // From far away, so that the ray escapes past the scene.
            let ray = Ray::new(-20.0 * d.cross(Vec3::Y).normalize() + 30.0 * Vec3::Y, d);
            let mut rng = pathtracer::sampling::IndependentSampler::from_stream(1, 0);
            let seen = t.radiance(&world, &ray, &mut rng);
            assert_eq!(seen, env.escaped_radiance(d * mirror), "{mistake}, {d}");
        }
    }
    let floor = view.pixels_seeing(|p| p.y < 1e-3);
    let right = view.mean_over(&starter_tracer(&[], L, 1, 1, false), 32, &floor, 610);
    let upside_down = view.mean_over(
        &starter_tracer(&[Mistake::EnvMapVFlipped], L, 1, 1, false),
        32,
        &floor,
        611,
    );
    assert_ratio_in(
        "env-map-v-flipped, the floor",
        upside_down,
        right,
        0.0..0.7,
        ALPHA / 2.0,
    );
}

const THREE_ONE: pathtracer::course::CourseExact = pathtracer::course::CourseExact {
    assignment: pathtracer::course::Assignment::PathTracer1,
};
