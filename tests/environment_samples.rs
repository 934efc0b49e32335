//! The plan's map samples at a vertex (`DirectLights::estimate`):
//!
//! - drawn in a batch, so that their cache misses overlap, they are the
//!   samples drawn one at a time, to the bit;
//! - each sample's pair is moved into its own stratum of the map's rows
//!   (`sampling::strata`; an area light's samples are left as drawn), which
//!   gives the image of independent samples with less noise under a sun.
//!
//! Seeds are fixed; the one z-test is at `ALPHA`.

mod common;

use common::{
    accel, assert_means_agree, diffuse, lumpy_map, rect_light, sphere_on_floor, MeanEstimate,
    SceneBuilder, ALPHA,
};
use glam::{Vec2, Vec3};
use pathtracer::direct::DirectLights;
use pathtracer::environment::{EnvironmentLight, EnvironmentMap, EnvironmentSampling};
use pathtracer::intersect::{Intersector, Ray};
use pathtracer::math::{luminance, Rgb};
use pathtracer::sampling::strata::stratum_point;
use pathtracer::sampling::{IndependentSampler, Sampler};
use pathtracer::world::{ShadingPoint, World};

/// A sampler that logs the kind of each draw: 1 for a number, 2 for a pair.
struct Logged {
    inner: IndependentSampler,
    log: Vec<u8>,
}

impl Sampler for Logged {
    fn start_pixel_sample(&mut self, pixel: (u32, u32), index: u32) {
        self.inner.start_pixel_sample(pixel, index);
    }
    fn get_1d(&mut self) -> f32 {
        self.log.push(1);
        self.inner.get_1d()
    }
    fn get_2d(&mut self) -> Vec2 {
        self.log.push(2);
        self.inner.get_2d()
    }
}

/// A sampler that gives the numbers and pairs it holds, in order: a
/// number, then a pair.
struct Scripted {
    draws: std::vec::IntoIter<(f32, Vec2)>,
    pair: Vec2,
}

impl Sampler for Scripted {
    fn start_pixel_sample(&mut self, _: (u32, u32), _: u32) {}
    fn get_1d(&mut self) -> f32 {
        let (number, pair) = self.draws.next().expect("a scripted draw");
        self.pair = pair;
        number
    }
    fn get_2d(&mut self) -> Vec2 {
        self.pair
    }
}

/// The floor's shading point at `(0.6, 0, 0.4)`, seen from above.
fn floor_point<I: Intersector>(world: &World<I>) -> ShadingPoint {
    let origin = Vec3::new(0.3, 2.0, 1.5);
    let ray = Ray::new(origin, (Vec3::new(0.6, 0.0, 0.4) - origin).normalize());
    let hit = world
        .intersector
        .intersect(&ray)
        .expect("the ray meets the floor");
    world.shade_surface(hit, -ray.dir)
}

/// Light samples drawn in batches (their cache misses overlapped) are the
/// samples drawn one at a time: each sample draws its number and then its
/// pair, light after light (a rectangle, then the map), as before batches;
/// and the map's samples give the estimate of its samples one at a time
/// at the same points (each pair moved into its stratum), to the bit, for
/// counts within one batch and past it (without MIS, whose weight depends
/// on the count), while an area light's samples keep their pairs. Checked
/// to fail by hand: with the batch drawing all numbers before all pairs
/// the log differs; with a batch's strata restarted at `k = 0`, every
/// count past one batch gives another estimate; with area lights in
/// strata too (the rule's `&&` made `||`), the rectangle's estimate.
#[test]
fn batched_environment_samples_are_the_samples_one_at_a_time() {
    let mut builder = SceneBuilder::new();
    let floor = builder.material(diffuse(0.5));
    builder.floor(floor, 2.0);
    builder.light(rect_light(
        4.0,
        Vec3::new(0.0, 3.0, 0.0),
        -Vec3::Y,
        0.5,
        0.5,
    ));
    let scene = builder.finish();
    let env = EnvironmentLight::new(lumpy_map(), EnvironmentSampling::Importance);
    let lit = accel(&scene);
    let world = World::new(&scene, &lit).with_environment(Some(env));
    let with_mis = DirectLights {
        samples_per_light: 3,
        environment_samples: Some(11),
        mis: true,
    };
    let mut logged = Logged {
        inner: IndependentSampler::from_stream(5, 0),
        log: Vec::new(),
    };
    with_mis.estimate(&world, &floor_point(&world), &mut logged);
    let expected: Vec<u8> = [3, 11].iter().flat_map(|&n| [1, 2].repeat(n)).collect();
    assert_eq!(world.lights.lit().count(), 2);
    assert_eq!(logged.log, expected, "draws: 1 a number, 2 a pair");

    // The rectangle's samples (the map taken away) keep their pairs as
    // drawn: its three samples are three single samples from the stream.
    let rectangle = World::new(&scene, &lit);
    let point = floor_point(&rectangle);
    let three = DirectLights {
        samples_per_light: 3,
        environment_samples: None,
        mis: false,
    };
    let single = DirectLights {
        samples_per_light: 1,
        ..three
    };
    let mut a = IndependentSampler::from_stream(5, 1);
    let mut b = IndependentSampler::from_stream(5, 1);
    let got = three.estimate(&rectangle, &point, &mut a);
    let sum = (0..3).fold(Rgb::ZERO, |sum, _| {
        sum + single.estimate(&rectangle, &point, &mut b)
    });
    assert!(sum != Rgb::ZERO, "the rectangle lights the floor");
    assert_eq!(got, sum / 3.0, "an area light's samples");

    // The estimates, under the map alone.
    let scene = sphere_on_floor();
    let unlit = accel(&scene);
    let env = EnvironmentLight::new(lumpy_map(), EnvironmentSampling::Importance);
    let world = World::new(&scene, &unlit).with_environment(Some(env));
    let point = floor_point(&world);
    for n in [2, 8, 11, 19] {
        let batched = DirectLights {
            samples_per_light: 1,
            environment_samples: Some(n),
            mis: false,
        };
        let single = DirectLights {
            environment_samples: Some(1),
            ..batched
        };
        let mut a = IndependentSampler::from_stream(5, n as u64);
        let got = batched.estimate(&world, &point, &mut a);
        let mut b = IndependentSampler::from_stream(5, n as u64);
        let mut points = Scripted {
            draws: (0..n as usize)
                .map(|k| {
                    let (number, pair) = (b.get_1d(), b.get_2d());
                    (number, stratum_point(pair, k, n as usize))
                })
                .collect::<Vec<_>>()
                .into_iter(),
            pair: Vec2::ZERO,
        };
        let mut sum = Rgb::ZERO;
        for _ in 0..n {
            sum += single.estimate(&world, &point, &mut points);
        }
        assert!(sum != Rgb::ZERO, "the floor is lit");
        assert_eq!(got, sum / n as f32, "{n} samples");
    }
}

/// A sky of radiance 0.05 and a sun of 8 x 4 texels holding about 60 %
/// of the map's light, about 53 degrees from the zenith. (A sun of one texel
/// would do less for the strata: its bilinear radiance over cells of
/// constant density varies more within the sun than the count of samples
/// that find it does.)
fn sun_map() -> EnvironmentMap {
    let mut texels = vec![Rgb::splat(0.05); 128 * 64];
    for j in 17..21 {
        for i in 68..76 {
            texels[j * 128 + i] = Rgb::new(15.0, 14.0, 13.0);
        }
    }
    EnvironmentMap::new("sun", 128, 64, texels).unwrap()
}

/// Four map samples at a vertex in strata have the mean of four
/// independent ones and, under a sun holding most of the light, less
/// variance: independent samples find the sun a binomial number of times
/// (a variance of 0.95 here), strata a number that only the two strata
/// its rows' ends cut can change (0.40). 20,000 estimates each at the
/// floor's point, without MIS (whose light half alone is weighted by the
/// count); measured: the strata's standard error 0.69 of the independent
/// samples' (both known to 1 %), 0.71 with the strata's taken at its
/// upper bound, as the test takes it. Checked to fail by hand: with the strata
/// removed (`stratum_point` returning its pair) the ratio is 1; with `k`
/// dropped (every sample in the first stratum) the means differ.
#[test]
fn strata_lower_the_noise_of_a_sun_not_the_mean() {
    let scene = sphere_on_floor();
    let unlit = accel(&scene);
    let env = EnvironmentLight::new(sun_map(), EnvironmentSampling::Importance);
    let world = World::new(&scene, &unlit).with_environment(Some(env));
    let point = floor_point(&world);
    let four = DirectLights {
        samples_per_light: 1,
        environment_samples: Some(4),
        mis: false,
    };
    let one = DirectLights {
        environment_samples: Some(1),
        ..four
    };
    let n = 20_000;
    let strata = MeanEstimate::of((0..n).map(|k| {
        let mut rng = IndependentSampler::from_stream(71, k);
        luminance(four.estimate(&world, &point, &mut rng)) as f64
    }));
    // The same count, each sample its own numbers: four one-sample
    // estimates averaged.
    let independent = MeanEstimate::of((0..n).map(|k| {
        let mut rng = IndependentSampler::from_stream(72, k);
        let sum: Rgb = (0..4)
            .map(|_| one.estimate(&world, &point, &mut rng))
            .fold(Rgb::ZERO, |a, b| a + b);
        luminance(sum / 4.0) as f64
    }));
    assert!(strata.mean > 0.0);
    assert_means_agree("strata vs independent", strata, independent, ALPHA);
    // The strata's error at its upper bound, the other's as estimated:
    // the comparison leans against the claim.
    independent.held_se("independent");
    let ratio = strata.held_se("strata") / independent.se;
    assert!(ratio < 0.8, "standard error ratio {ratio}");
}
