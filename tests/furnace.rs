//! The furnace test: inside a closed room whose walls reflect diffusely with
//! albedo `a` and emit `Le`, radiance is the same everywhere and in every
//! direction. Each bounce adds the walls' emission attenuated once more by
//! `a`, so a path tracer with at most `m` bounces must give
//!
//! ```text
//! L_m = Le (1 + a + a^2 + ... + a^m) = Le (1 - a^(m+1)) / (1 - a)  ->  Le / (1 - a)
//! ```
//!
//! With cosine-weighted sampling of a diffuse BSDF, `f cos / pdf = a`
//! exactly; the noise comes from sampling the glowing walls (as lights, or
//! by hemisphere rays) and from Russian roulette, and a confidence interval
//! absorbs it.
//!
//! An object that neither absorbs nor emits changes nothing in a furnace:
//! a perfect mirror sphere shows walls of radiance `Le / (1 - a)`, and so
//! does a glass sphere (reflectance and transmittance 1, exact Fresnel):
//! outside it `F L + (1 - F) L_inside / eta^2` with `L_inside = eta^2 L`,
//! which checks the `1 / eta^2` of radiance crossing the boundary.
//!
//! Russian roulette is checked with both rules, the course's fixed
//! `q = 0.65` and the throughput rule (`Roulette::Throughput`, whose `q`
//! also carries the `eta^2` of the glass sphere). Samples come from the
//! independent sampler: the intervals assume independent samples.
//!
//! Every comparison is a confidence interval at level `1 - ALPHA / k` for
//! the `k` comparisons of its test (Bonferroni), with fixed seeds.

mod common;

use common::{assert_mean_matches, MeanEstimate, SceneBuilder, ALPHA, GLASS};

use glam::Vec3;
use pathtracer::bvh::BvhAccel;
use pathtracer::direct::{DirectHemisphere, DirectLights};
use pathtracer::global::{DirectStrategy, PathTracer, Roulette};
use pathtracer::intersect::{Primitives, Ray};
use pathtracer::math::warp::sample_uniform_sphere;
use pathtracer::sampling::{IndependentSampler, Sampler};
use pathtracer::scene::{Material, Scene, Sphere};
use pathtracer::world::World;

/// The furnace: a closed faceted sphere of radius 0.5 around
/// `(0.5, 0.5, 0.5)`, 8 x 12^2 flat facets of one material.
///
/// Not a box: in a box, a light sample on the wall next to the shading
/// point's, near their shared edge, has `cos_x cos_y / r^2` growing as
/// `1 / r^2`. Light sampling alone then has an infinite variance, and
/// with MIS rare samples weigh far more than the rest (measured in the
/// box: variances uncertain by 26 % to 71 % at 4,000 to 20,000 samples,
/// and one seed 5.2 standard errors off). On a sphere `cos_x cos_y / r^2
/// = 1 / (4 R^2)` between any two points, so a light sample weighs nearly
/// the same wherever it lands; flat facets change that only next to a
/// facet's edge, where the neighbour is tilted by about `pi / 24`. Every
/// z-test asserts that its case's variance is known to 25 %
/// ([`common::HEAVY_TAIL`]); the worst case here is known to 15 %.
fn furnace(albedo: f32, radiance: f32) -> Scene {
    let mut b = SceneBuilder::new();
    let wall = b.material(Material::EmissiveDiffuse {
        albedo: Vec3::splat(albedo),
        radiance: Vec3::splat(radiance),
    });
    b.faceted_sphere(wall, Vec3::splat(0.5), 0.5, 12);
    b.finish()
}

/// Mean and standard error of `n` camera rays in random directions from
/// a point inside the box.
fn estimate(scene: &Scene, tracer: &PathTracer, n: usize, seed: u64) -> MeanEstimate {
    estimate_from(Vec3::new(0.3, 0.6, 0.45), scene, tracer, n, seed)
}

/// Mean and standard error of `n` camera rays in random directions from `origin`.
fn estimate_from(
    origin: Vec3,
    scene: &Scene,
    tracer: &PathTracer,
    n: usize,
    seed: u64,
) -> MeanEstimate {
    let accel = BvhAccel::new(Primitives::from_scene(scene));
    let view = World::new(scene, &accel);
    let mut rng = IndependentSampler::from_stream(seed, 0);
    MeanEstimate::of((0..n).map(|_| {
        let ray = Ray::new(origin, sample_uniform_sphere(rng.get_2d()));
        let l = tracer.radiance(&view, &ray, &mut rng);
        assert!(l.is_finite(), "non-finite radiance {l}");
        l.x as f64
    }))
}

fn geometric_sum(albedo: f64, radiance: f64, max_depth: u32) -> f64 {
    radiance * (1.0 - albedo.powi(max_depth as i32 + 1)) / (1.0 - albedo)
}

/// Paths of up to 200 bounces with Russian roulette: `a^201` is below
/// 1e-19, so the sum is the infinite one.
fn with_roulette(direct: DirectStrategy, roulette: Roulette) -> PathTracer {
    PathTracer {
        direct,
        max_depth: 200,
        accumulate: true,
        roulette,
        glass_splits: 0,
    }
}

/// Both rules of Russian roulette.
const ROULETTES: [Roulette; 2] = [Roulette::Fixed, Roulette::Throughput];

/// The strategies whose estimators are bounded in a closed room. Light
/// sampling *alone* is not among them: a light sample on a facet next to
/// the shading point's, near their shared edge, weighs `f Le cos_x cos_y
/// / (r^2 p_A)`, which grows as `1 / r^2`, and its square is not
/// integrable. Seen here: one sample of 4,000 at 19.3 where the rest lie
/// within 1.87 to 2.29 (m = 12, 48^2 facets an octant), a variance that
/// no sample size pins down. With MIS the light sample's weight `f Le
/// cos_x / (p_light + p_bsdf)` is at most `a Le`, so it is bounded.
/// `tests/colour.rs` checks light sampling alone in an integrating sphere
/// around a rectangle light, where the light keeps its distance.
fn strategies() -> [(&'static str, DirectStrategy); 3] {
    [
        (
            "light sampling with MIS",
            DirectStrategy::Lights(DirectLights {
                samples_per_light: 1,
                environment_samples: None,
                mis: true,
            }),
        ),
        (
            "hemisphere sampling",
            DirectStrategy::Hemisphere(DirectHemisphere { samples: 1 }),
        ),
        ("BSDF sampling alone", DirectStrategy::BsdfOnly),
    ]
}

#[test]
fn furnace_without_russian_roulette_sums_m_bounces() {
    for (albedo, max_depth) in [(0.5, 12), (0.8, 30)] {
        let scene = furnace(albedo as f32, 1.0);
        let expected = geometric_sum(albedo, 1.0, max_depth);
        for (name, direct) in strategies() {
            let tracer = PathTracer {
                direct,
                max_depth,
                accumulate: true,
                roulette: Roulette::Off,
                glass_splits: 0,
            };
            let label = format!("{name}, a = {albedo}, m = {max_depth}");
            let est = estimate(&scene, &tracer, 4000, 7);
            assert_mean_matches(&label, est, expected, ALPHA / 6.0, 1e-4 * expected);
        }
    }
}

/// Albedos 0.5 and 0.7, not higher: with the course's fixed `q = 0.65`
/// a path that survives `k` bounces weighs `(a / q)^k` with probability
/// `q^k`, so the estimator's fourth moment sums `(a^4 / q^3)^k`, which
/// diverges for `a > q^(3/4) = 0.72`. Its variance is then known only
/// roughly (uncertain by 23 % at `a = 0.8` and 20,000 samples), and the
/// interval would not keep its stated rate. 80,000 samples, because
/// where the throughput rule starts late (after 8 bounces) its few
/// survivors make most of the variance (BSDF sampling finds `Le` at every
/// bounce, so nothing else varies): at 20,000 the variance of BSDF
/// sampling alone at `a = 0.5` was uncertain by 32 %.
#[test]
fn furnace_with_russian_roulette_reaches_le_over_one_minus_a() {
    for albedo in [0.5, 0.7] {
        let scene = furnace(albedo as f32, 1.0);
        let expected = 1.0 / (1.0 - albedo);
        for (name, direct) in strategies() {
            for roulette in ROULETTES {
                let tracer = with_roulette(direct, roulette);
                let est = estimate(&scene, &tracer, 80_000, 11);
                assert!(est.se > 0.0, "Russian roulette adds noise");
                let label = format!("{name}, a = {albedo}, roulette {roulette:?}");
                assert_mean_matches(&label, est, expected, ALPHA / 12.0, 0.0);
            }
        }
    }
}

#[test]
fn only_the_m_th_bounce_with_o_0() {
    let (albedo, max_depth) = (0.8f64, 5);
    let scene = furnace(albedo as f32, 1.0);
    let expected = albedo.powi(max_depth as i32);
    for (name, direct) in strategies() {
        let tracer = PathTracer {
            direct,
            max_depth,
            accumulate: false,
            roulette: Roulette::Off,
            glass_splits: 0,
        };
        let est = estimate(&scene, &tracer, 4000, 13);
        assert_mean_matches(name, est, expected, ALPHA / 3.0, 1e-4 * expected);
    }
}

/// A perfect mirror sphere and a clear glass sphere (exact Fresnel) are
/// invisible in the furnace: every strategy, Russian roulette on, finds
/// `Le / (1 - a)` from outside, and `eta^2 Le / (1 - a)` from inside the
/// glass, where radiance is `eta^2` times brighter (`L / n^2` is invariant
/// along a ray; Veach 1997, section 5.2). Checked by hand: glass without
/// the `1 / eta^2` still passes from outside (the factors of entering and
/// leaving cancel) but fails from inside (by hundreds of standard errors).
#[test]
fn mirror_and_glass_spheres_are_invisible_in_a_furnace() {
    let albedo = 0.5f64;
    let expected = 1.0 / (1.0 - albedo);
    let objects = [
        (
            "mirror sphere",
            Material::Mirror {
                reflectance: Vec3::ONE,
            },
        ),
        ("glass sphere", GLASS),
    ];
    for (object, material) in objects {
        let mut scene = furnace(albedo as f32, 1.0);
        scene.materials.push(material);
        scene.spheres.push(Sphere {
            center: Vec3::new(0.55, 0.45, 0.5),
            radius: 0.25,
            material: 1,
        });
        for (name, direct) in strategies() {
            for roulette in ROULETTES {
                let tracer = with_roulette(direct, roulette);
                let est = estimate(&scene, &tracer, 20_000, 17);
                let label = format!("{object}, {name}, roulette {roulette:?}");
                assert_mean_matches(&label, est, expected, ALPHA / 18.0, 0.0);
                if object == "glass sphere" {
                    let inside =
                        estimate_from(scene.spheres[0].center, &scene, &tracer, 20_000, 19);
                    let label = format!("inside the {object}, {name}, roulette {roulette:?}");
                    assert_mean_matches(&label, inside, 2.25 * expected, ALPHA / 18.0, 0.0);
                }
            }
        }
    }
}
