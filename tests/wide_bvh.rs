//! The wide BVH beyond the shared oracle tests of `tests/bvh.rs`: its SIMD
//! triangle test equals the scalar watertight test to the bit (random
//! rays, rays through vertices and along edges, rays in a triangle's
//! plane, axis-aligned cases that make edge functions exactly zero); rays
//! through the centre and spokes of a closed fan never slip through; the
//! Möller-Trumbore option goes through the scalar lanes and still agrees
//! with the linear scan; and renders through the wide BVH equal renders
//! through the binary one, pixel for pixel.

mod common;

use common::*;
use glam::Vec3;
use pathtracer::bvh::wide::leaf::{RayShear, TrianglePack};
use pathtracer::bvh::{BvhAccel, WideBvhAccel};
use pathtracer::cli::drivers::{render_lighting, render_normals};
use pathtracer::intersect::triangle::{TriangleHit, TriangleShape};
use pathtracer::intersect::{Intersector, LinearScan, Ray, Shape, TriangleTest};
use pathtracer::math::rng::{sampler, Sampler};
use pathtracer::raygen::Camera;
use pathtracer::render::RenderSettings;
use pathtracer::scene::builtin;
use pathtracer::world::World;
use proptest::prelude::*;
use rand::Rng;

/// The pack's answer is the scalar test's nearest lane, to the bit: the
/// lane it names gives the same hit by the scalar test, no other lane is
/// nearer, and it finds nothing only when no lane is hit.
fn assert_pack_equals_scalar(triangles: &[TriangleShape], ray: &Ray, t_max: f32) {
    let lanes: Vec<(u32, Shape)> = triangles
        .iter()
        .enumerate()
        .map(|(i, &t)| (i as u32, Shape::Triangle(t)))
        .collect();
    let pack = TrianglePack::new(&lanes);
    let scalar: Vec<_> = triangles.iter().map(|t| t.intersect(ray, t_max)).collect();
    let bits = |h: &pathtracer::intersect::triangle::TriangleHit| [h.t, h.u, h.v].map(f32::to_bits);
    match pack.intersect(&RayShear::new(ray), t_max) {
        None => assert!(
            scalar.iter().all(Option::is_none),
            "the pack missed {scalar:?} along {ray:?}"
        ),
        Some((lane, hit)) => {
            let expected = scalar[lane].expect("the scalar test hits the lane");
            assert_eq!(bits(&hit), bits(&expected), "lane {lane} along {ray:?}");
            for other in scalar.iter().flatten() {
                assert!(other.t >= hit.t, "a nearer lane {other:?} along {ray:?}");
            }
        }
    }
}

fn random_triangle(rng: &mut Sampler, scale: f32) -> TriangleShape {
    let c = random_point(rng, -scale, scale);
    let [p0, p1, p2] = [0; 3].map(|_| c + random_point(rng, -scale, scale) * 0.3);
    TriangleShape::new(p0, p1, p2)
}

/// Case `case`: `n` random triangles at one of three scales, and a ray
/// aimed at a random point, a vertex or a point on an edge of one of
/// them, or shot along its plane; returns them with the scale.
fn grazing_case(rng: &mut Sampler, case: usize, n: usize) -> (Vec<TriangleShape>, Ray, f32) {
    let scale = [1e-3f32, 1.0, 1e3][case % 3];
    let tris: Vec<TriangleShape> = (0..n).map(|_| random_triangle(rng, scale)).collect();
    let origin = random_point(rng, -3.0 * scale, 3.0 * scale);
    let t = &tris[rng.gen_range(0..n)];
    let s: f32 = rng.gen();
    let target = match case % 5 {
        0 => random_point(rng, -scale, scale),
        1 => t.p0,
        2 => t.p1 + s * (t.p2 - t.p1),
        3 => t.p0 + s * (t.p1 - t.p0),
        _ => t.p2,
    };
    let (origin, dir) = if case % 7 == 6 {
        let o = t.p0 + (t.p1 - t.p0) * 1.5 + (t.p2 - t.p0) * 0.25;
        (o, (t.p0 + s * (t.p2 - t.p1) - o).normalize_or(Vec3::X))
    } else {
        (origin, (target - origin).normalize_or(Vec3::Z))
    };
    (tris, Ray::new(origin, dir), scale)
}

#[test]
fn simd_triangle_test_equals_the_scalar_one_on_random_and_grazing_rays() {
    let mut rng = sampler(2013, 0);
    for case in 0..20_000 {
        let (tris, mut ray, scale) = grazing_case(&mut rng, case, 1 + case % 4);
        assert_pack_equals_scalar(&tris, &ray, f32::INFINITY);
        ray.t_min = rng.gen_range(0.0..scale);
        assert_pack_equals_scalar(&tris, &ray, rng.gen_range(0.0..6.0 * scale));
    }
}

/// Integer corners and axis-aligned rays through vertices and along edges:
/// edge functions come out exactly zero, the `f64` recomputation runs,
/// and the lanes still agree with the scalar test.
#[test]
fn simd_triangle_test_equals_the_scalar_one_where_edge_functions_vanish() {
    let quad = |x: f32, y: f32| {
        let c = |dx: f32, dy: f32| Vec3::new(x + dx, y + dy, 0.0);
        [
            TriangleShape::new(c(0.0, 0.0), c(1.0, 0.0), c(1.0, 1.0)),
            TriangleShape::new(c(0.0, 0.0), c(1.0, 1.0), c(0.0, 1.0)),
        ]
    };
    let mut tris = quad(0.0, 0.0).to_vec();
    tris.extend(quad(1.0, 0.0));
    for i in 0..=8 {
        for j in 0..=4 {
            let (x, y) = (i as f32 * 0.25, j as f32 * 0.25);
            for dir in [Vec3::NEG_Z, Vec3::new(-0.0, 0.0, -1.0), Vec3::Z] {
                let ray = Ray::new(Vec3::new(x, y, 1.0), dir);
                assert_pack_equals_scalar(&tris, &ray, f32::INFINITY);
            }
            let along = Ray::new(Vec3::new(-1.0, y, 0.0), Vec3::X);
            assert_pack_equals_scalar(&tris, &along, f32::INFINITY);
        }
    }
}

/// The packs of `triangles`, four lanes each, ids in order.
fn packs_of(triangles: &[TriangleShape]) -> Vec<TrianglePack> {
    let lanes: Vec<(u32, Shape)> = triangles
        .iter()
        .enumerate()
        .map(|(i, &t)| (i as u32, Shape::Triangle(t)))
        .collect();
    lanes.chunks(4).map(TrianglePack::new).collect()
}

/// A leaf's packs tested two at a time in one AVX register give what
/// testing them one after the other gives, to the bit: the same pack,
/// the same lane (on a tie too: triangles copied into other lanes and
/// packs, and rays through the shared edges of a grid, where two
/// triangles report the same `t`), the same hit.
#[cfg(target_arch = "x86_64")]
#[test]
fn packs_two_at_a_time_equal_packs_one_at_a_time() {
    use pathtracer::bvh::wide::avx::Avx;
    use pathtracer::bvh::wide::node::{NodeTest, Sse};
    if !is_x86_feature_detected!("avx") {
        return;
    }
    let key = |(pack, lane, h): (usize, usize, TriangleHit)| {
        (pack, lane, [h.t, h.u, h.v].map(f32::to_bits))
    };
    let compare = |tris: &[TriangleShape], ray: &Ray, t_max: f32| {
        let (packs, shear) = (packs_of(tris), RayShear::new(ray));
        let one = Sse::packs_hit(&packs, &shear, t_max).map(key);
        assert_eq!(
            one,
            Avx::packs_hit(&packs, &shear, t_max).map(key),
            "{ray:?}"
        );
        one.is_some()
    };
    let mut rng = sampler(2014, 0);
    let mut hits = 0;
    for case in 0..20_000 {
        // Two to four packs: at least one pair.
        let n = 5 + case % 12;
        let (mut tris, mut ray, scale) = grazing_case(&mut rng, case, n);
        if case % 2 == 0 {
            tris[rng.gen_range(0..n)] = tris[rng.gen_range(0..n)];
        }
        hits += usize::from(compare(&tris, &ray, f32::INFINITY));
        ray.t_min = rng.gen_range(0.0..scale);
        compare(&tris, &ray, rng.gen_range(0.0..6.0 * scale));
    }
    assert!(hits > 5_000, "too few hits to compare: {hits}");
    let grid: Vec<TriangleShape> = (0..12)
        .map(|i| {
            let c = |dx: f32, dy: f32| Vec3::new((i / 2 % 3) as f32 + dx, (i / 6) as f32 + dy, 0.0);
            if i % 2 == 0 {
                TriangleShape::new(c(0.0, 0.0), c(1.0, 0.0), c(1.0, 1.0))
            } else {
                TriangleShape::new(c(0.0, 0.0), c(1.0, 1.0), c(0.0, 1.0))
            }
        })
        .collect();
    // Straight down onto the edge y = 1 shared by triangle 1 (pack 0,
    // lane 1) and triangle 6 (pack 1, lane 2): both report t = 1, and the
    // later pack wins, as when the packs are tested one after the other.
    let edge = Ray::new(Vec3::new(0.5, 1.0, 1.0), Vec3::NEG_Z);
    let (packs, shear) = (packs_of(&grid), RayShear::new(&edge));
    let alone = packs[0].intersect(&shear, f32::INFINITY);
    assert_eq!(alone.map(|(l, h)| (l, h.t)), Some((1, 1.0)), "the tie");
    for found in [
        Sse::packs_hit(&packs, &shear, f32::INFINITY),
        Avx::packs_hit(&packs, &shear, f32::INFINITY),
    ] {
        assert_eq!(found.map(|(p, l, h)| (p, l, h.t)), Some((1, 2, 1.0)));
    }
    for i in 0..=12 {
        for j in 0..=8 {
            let origin = Vec3::new(i as f32 * 0.25, j as f32 * 0.25, 1.0);
            for dir in [Vec3::NEG_Z, Vec3::new(-0.0, 0.0, -1.0), Vec3::Z] {
                compare(&grid, &Ray::new(origin, dir), f32::INFINITY);
            }
        }
    }
}

proptest! {
    #![proptest_config(cases(300))]

    /// A closed planar fan through the wide BVH: a ray aimed at the centre
    /// vertex or a point on a spoke always hits a face.
    #[test]
    fn fan_through_the_wide_bvh_is_watertight(
        centre in point(100.0),
        normal in unit_vector(),
        axis in unit_vector(),
        spokes in 3usize..12,
        radius in 1e-3f32..10.0,
        from in unit_vector(),
        along in 0.0f32..1.0,
        spoke in 0usize..12,
    ) {
        prop_assume!(normal.cross(axis).length() > 0.1 && from.dot(normal).abs() > 0.05);
        let x = (axis - axis.dot(normal) * normal).normalize();
        let y = normal.cross(x);
        let ring: Vec<Vec3> = (0..spokes)
            .map(|i| {
                let a = i as f32 / spokes as f32 * std::f32::consts::TAU;
                centre + radius * (a.cos() * x + a.sin() * y)
            })
            .collect();
        let tris: Vec<[Vec3; 3]> =
            (0..spokes).map(|i| [centre, ring[i], ring[(i + 1) % spokes]]).collect();
        let prims = soup(&tris, &[]);
        let wide = WideBvhAccel::new(prims.clone());
        wide.validate().unwrap();
        let target = centre + along * (ring[spoke % spokes] - centre);
        let origin = target + from * radius * 3.0;
        let ray = Ray::new(origin, (target - origin).normalize());
        prop_assert!(wide.intersect(&ray).is_some(), "slipped through at {target}");
        prop_assert!(wide.occluded(&ray));
    }
}

#[test]
fn moller_trumbore_option_agrees_with_the_linear_scan() {
    let mut prims = pathtracer::intersect::Primitives::from_scene(&builtin::cornell_box());
    prims.triangle_test = TriangleTest::MollerTrumbore;
    let wide = WideBvhAccel::new(prims.clone());
    wide.validate().unwrap();
    let linear = LinearScan::new(&prims);
    let bounds = prims.bounds();
    let mut rng = sampler(7, 0);
    for _ in 0..2000 {
        let target = random_point_in(&mut rng, &bounds);
        let origin = random_point_in(&mut rng, &bounds);
        let ray = Ray::new(origin, (target - origin).normalize_or(Vec3::X));
        let (a, b) = (linear.intersect(&ray), wide.intersect(&ray));
        assert_eq!(a.map(|h| h.t), b.map(|h| h.t), "along {ray:?}");
        assert_eq!(linear.occluded(&ray), wide.occluded(&ray));
    }
}

/// Normal shading and a path-traced render of the Cornell box (spheres
/// included) through both BVHs: the same pixels, bit for bit, since the
/// hits are the same.
#[test]
fn renders_through_the_wide_bvh_equal_renders_through_the_binary_one() {
    let scene = builtin::cornell_box();
    let prims = pathtracer::intersect::Primitives::from_scene(&scene);
    let binary = BvhAccel::new(prims.clone());
    let wide = WideBvhAccel::new(prims.clone());
    let settings = RenderSettings {
        width: 48,
        height: 36,
        samples_per_pixel: 4,
        threads: Some(2),
        seed: 11,
        ..RenderSettings::default()
    };
    let camera = Camera::course_placement(&scene.camera, &prims.bounds(), 48, 36);
    let pixels = |r: pathtracer::render::Rendered| {
        r.film
            .pixels
            .iter()
            .map(|p| format!("{p:?}"))
            .collect::<Vec<_>>()
    };
    assert_eq!(
        pixels(render_normals(&binary, &camera, &settings)),
        pixels(render_normals(&wide, &camera, &settings))
    );
    let tracer = tracer(LIGHTS, 4, true);
    let render = |accel: &dyn Intersector| {
        let world = World::new(&scene, accel);
        pixels(render_lighting(&world, &tracer, &camera, &settings, None))
    };
    assert_eq!(render(&binary), render(&wide));
}

/// Traversal is safe for any ray: one whose origin or direction is not
/// finite meets nothing (in a release build; a debug build's assertion
/// says that no caller should send one).
#[test]
#[cfg_attr(debug_assertions, should_panic(expected = "not finite"))]
fn a_ray_that_is_not_finite_meets_nothing() {
    let scene = pathtracer::scene::builtin::cornell_box();
    let accel = WideBvhAccel::new(pathtracer::intersect::Primitives::from_scene(&scene));
    let origins = [
        Vec3::new(0.0, 0.7, 3.0),
        Vec3::splat(f32::NAN),
        Vec3::splat(f32::INFINITY),
    ];
    let dirs = [
        Vec3::NAN,
        Vec3::new(f32::INFINITY, 0.0, -1.0),
        Vec3::new(0.0, 0.0, -1.0),
    ];
    for (origin, dir) in origins.into_iter().zip(dirs) {
        let ray = Ray::new(origin, dir);
        assert!(accel.nearest(&ray).is_none(), "{ray:?}");
        assert!(!accel.occluded(&ray), "{ray:?}");
    }
}
