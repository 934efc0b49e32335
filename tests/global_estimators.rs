//! Global illumination (several bounces) against closed forms and across
//! estimators: the integrating sphere, a convex object in an emissive
//! enclosure, Russian roulette on and off, hemisphere against light
//! sampling in a closed box at depth 4 (caustic casters on and off:
//! `tests/caustic_casters.rs`).
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
//!
//! One test counts rays instead: the last vertex's rules save time alone,
//! and only the number of rays traced shows them.

mod common;

use std::f64::consts::PI;
use std::sync::atomic::{AtomicUsize, Ordering};

use common::{
    accel, assert_mean_matches, assert_means_agree, diffuse, emission, estimate, ray_towards,
    rect_light, tracer, tracer_with, SceneBuilder, ALPHA, HEMISPHERE, LIGHTS, LIGHTS_ALONE,
};
use glam::{DVec3, Vec3};
use pathtracer::global::{PathTracer, Roulette, THROUGHPUT_ROULETTE_AFTER};
use pathtracer::intersect::{Intersector, PrimitiveHit, Primitives, Ray};
use pathtracer::sampling::IndependentSampler;
use pathtracer::scene::builtin::{cornell_box, COPPER_ETA, COPPER_K};
use pathtracer::scene::{Light, Material};
use pathtracer::world::World;

/// The integrating sphere complements the textbook furnace of
/// `tests/furnace.rs` (closed box, albedo `a`, emission `Le` everywhere,
/// `L = Le / (1 - a)`), which has no light: it checks light sampling of a
/// point light, with its 1/r^2, inside a closed diffuse enclosure. A
/// diffuse sphere of radius `R` and albedo `a` lit from inside by a point
/// light of intensity `I` at `c` has the same geometric series in closed
/// form.
///
/// Derivation. Inside a sphere, a cosine-distributed direction from any
/// wall point `x` hits the wall at a point `y` uniform in area: the density
/// per area is `cos_x cos_y / (pi r^2)` and on a sphere
/// `cos_x = cos_y = r / (2R)`, so it is `1 / (4 pi R^2)` (the constant form
/// factor of the integrating sphere; e.g. Goebel 1967, "Generalized
/// integrating-sphere theory"). Let `L_d(x) = (a / pi) I cos_x / |c - x|^2`
/// be the direct radiance (1/r^2 falloff, no occluder). All of the light's
/// power `4 pi I` reaches the wall, so the area mean of `L_d` is
/// `Lbar = (a / pi) I / R^2`. With `L_m` the radiance of paths with at most
/// `m` bounces, `L_m(x) = L_d(x) + a E_y[L_{m-1}(y)]` and the area means obey
/// `Lbar_k = Lbar + a Lbar_{k-1}`, hence
///
/// ```text
/// L_m(x) = L_d(x) + a Lbar (1 - a^(m-1)) / (1 - a)
/// ```
///
/// and, with the light at the centre (`L_d = Lbar = Le`) and `m -> inf`, the
/// furnace's `Le / (1 - a)`. Paths of exactly `m >= 2` bounces (`-o 0`)
/// carry `a^(m-1) Lbar`.
///
/// Here `R = 2` and the light is off centre so that every estimate has
/// variance except the `m = 1` case (one fixed ray, one shadow ray: exact
/// up to rounding, hence the 1e-5 relative floor). Checked by hand: the
/// test fails when the path tracer forgets to divide by the continuation
/// probability (RR case off by 9 %, 160 standard errors), and when the
/// point light drops its 1/r^2 (the course's quirk).
#[test]
fn furnace_integrating_sphere() {
    let radius = 2.0;
    let light_at = DVec3::new(0.6, -0.4, 0.2);
    let intensity = 4.0 * PI;
    let origin = DVec3::new(0.0, 0.2, 0.8);
    let dir = DVec3::new(0.6, 0.5, -0.3).normalize();
    // The wall point the camera ray hits: |o + t d| = R.
    let b = origin.dot(dir);
    let t = -b + (b * b - origin.length_squared() + radius * radius).sqrt();
    let x = origin + t * dir;
    let to_light = light_at - x;
    let cos_x = (-x / radius).dot(to_light.normalize());
    let ray = Ray::new(origin.as_vec3(), dir.as_vec3());

    // (albedo, max depth, accumulate, Russian roulette, samples)
    let cases = [
        (0.5, 1, true, false, 20_000),
        (0.5, 4, true, false, 100_000),
        (0.5, 4, true, true, 100_000),
        (0.8, 3, false, true, 100_000),
        (0.8, 60, true, false, 30_000),
        (0.8, 60, true, true, 200_000),
    ];
    let alpha = ALPHA / cases.len() as f64;
    for (k, &(a, m, accumulate, rr, n)) in cases.iter().enumerate() {
        let mut builder = SceneBuilder::new();
        let wall = builder.material(diffuse(a as f32));
        builder
            .sphere(Vec3::ZERO, radius as f32, wall)
            .light(Light::Point {
                intensity: Vec3::splat(intensity as f32),
                position: light_at.as_vec3(),
            });
        let scene = builder.finish();
        let accel = accel(&scene);
        let tracer_scene = World::new(&scene, &accel);
        let l_direct = a / PI * intensity * cos_x / to_light.length_squared();
        let l_bar = a / PI * intensity / (radius * radius);
        let expected = if accumulate {
            l_direct + a * l_bar * (1.0 - a.powi(m - 1)) / (1.0 - a)
        } else if m == 1 {
            l_direct
        } else {
            a.powi(m - 1) * l_bar
        };
        let pt = PathTracer {
            direct: LIGHTS,
            max_depth: m as u32,
            accumulate,
            roulette: if rr { Roulette::Fixed } else { Roulette::Off },
            glass_splits: 0,
        };
        let est = estimate(&tracer_scene, &pt, &ray, n, 100 + k as u64);
        assert_mean_matches(
            &format!("integrating sphere a {a}, m {m}, accumulate {accumulate}, RR {rr}"),
            est,
            expected,
            alpha,
            1e-5 * expected,
        );
    }
}

/// A convex diffuse object (albedo `a`) inside a closed emissive enclosure
/// of radiance `Le` (an emissive sphere, no light): every direction from
/// the object's surface meets the enclosure, which reflects nothing, so
/// `L_o = a Le` at any depth. Counting the enclosure's emission once or
/// twice is what this checks (light sampling picks it up through the
/// BSDF-sampled ray, hemisphere sampling through its own rays). Checked by
/// hand: letting the BSDF-sampled ray pick up emitters under hemisphere
/// sampling too (counting them twice) fails the depth-4 case, and a
/// hemisphere pdf of 1/(2.2 pi) the hemisphere cases.
#[test]
fn emissive_enclosure_lights_a_convex_object_once() {
    let (le, a) = (2.0f32, 0.6f32);
    let mut b = SceneBuilder::new();
    let inner = b.material(diffuse(a));
    let outer = b.material(emission(le));
    b.sphere(Vec3::ZERO, 1.0, inner)
        .sphere(Vec3::new(0.2, 0.0, 0.0), 3.0, outer);
    let scene = b.finish();
    let accel = accel(&scene);
    let st = World::new(&scene, &accel);
    let ray = ray_towards(Vec3::new(0.5, 1.5, 1.6), Vec3::ZERO);
    let cases = [(LIGHTS, 1), (LIGHTS, 4), (HEMISPHERE, 1), (HEMISPHERE, 4)];
    let alpha = ALPHA / cases.len() as f64;
    for (k, &(strategy, depth)) in cases.iter().enumerate() {
        let est = estimate(
            &st,
            &tracer(strategy, depth, true),
            &ray,
            50_000,
            20 + k as u64,
        );
        assert_mean_matches(
            &format!("enclosure, {strategy:?}, depth {depth}"),
            est,
            (a * le) as f64,
            alpha,
            1e-5,
        );
    }
}

/// Whole paths (depth 4, no Russian roulette) of hemisphere and light
/// sampling agree in a closed box lit by an emissive quad that no light
/// covers, so light sampling picks the quad up through the BSDF-sampled
/// ray. Two-sample z-test; Bonferroni over four comparisons: this one and
/// the three Cornell-box points of `tests/direct_estimators.rs`. Checked
/// by hand: counting uncovered emitters twice fails.
#[test]
fn hemisphere_and_light_sampling_agree_in_a_closed_box() {
    let mut b = SceneBuilder::new();
    let wall = b.material(diffuse(0.6));
    let lamp = b.material(emission(5.0));
    let ball = b.material(diffuse(0.8));
    b.closed_box(wall, Vec3::splat(-1.0), Vec3::splat(1.0))
        .quad(
            lamp,
            [
                Vec3::new(-0.3, 0.9, -0.2),
                Vec3::new(0.3, 0.9, -0.2),
                Vec3::new(0.3, 0.9, 0.2),
                Vec3::new(-0.3, 0.9, 0.2),
            ],
        )
        .sphere(Vec3::new(0.3, -0.6, 0.1), 0.4, ball);
    let closed = b.finish();
    let closed_accel = accel(&closed);
    let closed_tracer = World::new(&closed, &closed_accel);

    let alpha = ALPHA / 4.0;
    let ray = ray_towards(Vec3::new(-0.5, 0.2, 0.8), Vec3::new(0.2, -1.0, -0.4));
    let lights = estimate(&closed_tracer, &tracer(LIGHTS, 4, false), &ray, 100_000, 40);
    let hemi = estimate(
        &closed_tracer,
        &tracer(HEMISPHERE, 4, false),
        &ray,
        100_000,
        41,
    );
    assert_means_agree(
        "closed box lit by an emissive quad, depth 4",
        lights,
        hemi,
        alpha,
    );
}

/// Russian roulette changes the variance, not the mean: two points of the
/// Cornell box at depth 13 with roulette off, and on by each rule (the
/// course's fixed `q` from the second vertex, the throughput rule after
/// [`THROUGHPUT_ROULETTE_AFTER`] bounces, so depth 13 gives it four
/// vertices to act on), two-sample z-tests.
/// Checked by hand: not dividing by the continuation probability fails
/// (the fixed roulette's estimate drops by 6 %, 50 standard errors).
#[test]
fn russian_roulette_on_and_off_agree() {
    let cornell = cornell_box();
    let cornell_accel = accel(&cornell);
    let st = World::new(&cornell, &cornell_accel);
    let eye = Vec3::new(0.0, 0.75, 0.9);
    let targets = [Vec3::new(0.2, 0.0, -0.3), Vec3::new(-1.0, 0.5, -0.5)];
    let rules = [Roulette::Fixed, Roulette::Throughput];
    const DEPTH: u32 = 13;
    const { assert!(DEPTH > THROUGHPUT_ROULETTE_AFTER + 2) };
    let alpha = ALPHA / (targets.len() * rules.len()) as f64;
    for (k, target) in targets.into_iter().enumerate() {
        let ray = ray_towards(eye, target);
        let seed = 50 + 3 * k as u64;
        let off = estimate(&st, &tracer(LIGHTS, DEPTH, false), &ray, 60_000, seed);
        for (r, rule) in rules.into_iter().enumerate() {
            let on = estimate(
                &st,
                &tracer_with(LIGHTS, DEPTH, rule),
                &ray,
                120_000,
                seed + 1 + r as u64,
            );
            assert_means_agree(
                &format!("Cornell box towards {target}, roulette off and {rule:?}"),
                off,
                on,
                alpha,
            );
        }
    }
}

/// An intersector that counts the closest-hit searches and the shadow
/// rays it is asked for (atomics: an intersector is shared between
/// threads, `Sync`).
struct Counting<I> {
    inner: I,
    nearest: AtomicUsize,
    occluded: AtomicUsize,
}

impl<I: Intersector> Intersector for Counting<I> {
    fn primitives(&self) -> &Primitives {
        self.inner.primitives()
    }

    fn nearest(&self, ray: &Ray) -> Option<PrimitiveHit> {
        self.nearest.fetch_add(1, Ordering::Relaxed);
        self.inner.nearest(ray)
    }

    fn occluded(&self, ray: &Ray) -> bool {
        self.occluded.fetch_add(1, Ordering::Relaxed);
        self.inner.occluded(ray)
    }
}

/// The last vertex traces no continuation ray where what it would find
/// cannot count or is counted otherwise: where it is diffuse and a light
/// samples every emitter, it takes its direct light from light samples
/// alone (docs/05-global.md); without MIS, what a BSDF ray finds on a
/// sampled light never counts. At depth 1 each path to a diffuse floor
/// under a rectangle light traces its camera ray and one shadow ray; to a
/// rough conductor it traces the continuation ray too, whose emission is
/// the BSDF side of MIS, unless MIS is off. What this saves is time alone
/// (the image is the same in expectation), so no estimator test can see
/// it. Checked by mutants: `lights_alone_at_last` made `false` (the floor
/// traces 2,000 rays) or `true` (the conductor with MIS traces 1,000), and
/// `last_ray_can_count` made `true` (the conductor without MIS traces
/// about 2,000). The same holds for shadow rays: a light sample whose BSDF
/// value is 0 traces none (`DirectLights::contribution`'s early return,
/// whose `||` made `&&` traces 1,000 under a floor lit from below).
#[test]
fn the_last_vertex_traces_no_ray_that_cannot_count() {
    let paths = 1000;
    let copper = Material::Microfacet {
        alpha: 0.3,
        eta: COPPER_ETA,
        k: COPPER_K,
    };
    // The material, the strategy, whether the last ray is traced, and
    // whether the light hangs above the floor (or lies under it, facing
    // up, where no light sample can light the floor).
    let cases = [
        (diffuse(0.5), LIGHTS, false, true),
        (copper, LIGHTS, true, true),
        (copper, LIGHTS_ALONE, false, true),
        (diffuse(0.5), LIGHTS, false, false),
    ];
    for (material, direct, continues, above) in cases {
        let mut b = SceneBuilder::new();
        let floor = b.material(material);
        let (y, facing) = if above {
            (1.0, -Vec3::Y)
        } else {
            (-1.0, Vec3::Y)
        };
        b.floor(floor, 2.0)
            .light(rect_light(5.0, Vec3::new(0.0, y, 0.0), facing, 0.5, 0.5));
        let scene = b.finish();
        let counting = Counting {
            inner: accel(&scene),
            nearest: AtomicUsize::new(0),
            occluded: AtomicUsize::new(0),
        };
        let world = World::new(&scene, &counting);
        let ray = ray_towards(Vec3::new(0.0, 0.8, 1.0), Vec3::new(0.2, 0.0, 0.1));
        let mut sampler = IndependentSampler::from_stream(5, 0);
        for _ in 0..paths {
            tracer(direct, 1, false).radiance(&world, &ray, &mut sampler);
        }
        let rays = counting.nearest.load(Ordering::Relaxed);
        let shadow_rays = counting.occluded.load(Ordering::Relaxed);
        // One light sample a path, and no shadow ray for a sample that
        // cannot light the floor (its BSDF value is 0).
        let expected = if above { paths } else { 0 };
        assert_eq!(shadow_rays, expected, "shadow rays, light above: {above}");
        if continues {
            // A sample below the surface is dropped: most are traced.
            assert!(rays > paths * 3 / 2, "{rays} rays for {paths} paths");
        } else {
            assert_eq!(rays, paths, "the camera rays alone: {direct:?}");
        }
    }
}
