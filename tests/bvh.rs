//! Both BVHs (part 2's binary one and the wide SIMD one) against the
//! linear scan: the same closest hit (same primitive, same `t` to the bit:
//! all run the same primitive test) on random rays over random scenes,
//! built-in scenes and the course scenes; `occluded` agrees with
//! `intersect`; `validate()` holds after every build, including
//! degenerate inputs.

mod common;

use common::*;
use glam::Vec3;
use pathtracer::bvh::{BvhAccel, WideBvhAccel};
use pathtracer::intersect::{Aabb, Intersector, LinearScan, Primitives, Ray};
use pathtracer::math::rng::{sampler, Sampler};
use pathtracer::raygen::Camera;
use pathtracer::scene::{builtin, Scene};
use proptest::prelude::*;
use rand::Rng;

/// Each BVH finds the linear scan's closest hit (computed once for all
/// of them). Where two primitives are hit at exactly the same `t` either
/// may be reported (the scan keeps the last in id order, the BVH the last
/// in traversal order).
fn assert_same_closest(prims: &Primitives, bvhs: &[&dyn Intersector], ray: &Ray) {
    let expected = LinearScan::new(prims).intersect(ray);
    for bvh in bvhs {
        match (expected, bvh.intersect(ray)) {
            (None, None) => {}
            (Some(a), Some(b)) if a.primitive == b.primitive => {
                assert_eq!(a, b, "same primitive, different record along {ray:?}")
            }
            (Some(a), Some(b)) => {
                let tie = prims.shapes[b.primitive as usize].intersect(ray, ray.t_max);
                assert!(
                    a.t == b.t && tie.map(|h| h.t) == Some(a.t),
                    "BVH {b:?} but linear scan {a:?} along {ray:?}"
                );
            }
            (a, b) => panic!("linear scan {a:?}, BVH {b:?} along {ray:?}"),
        }
    }
}

/// `occluded` (each BVH's and the linear scan's) is "intersect finds
/// something".
fn assert_occlusion_agrees(prims: &Primitives, bvhs: &[&dyn Intersector], ray: &Ray) {
    let linear = LinearScan::new(prims);
    let blocked = linear.intersect(ray).is_some();
    for bvh in bvhs {
        assert_eq!(bvh.occluded(ray), blocked, "BVH occluded along {ray:?}");
    }
    assert_eq!(
        linear.occluded(ray),
        blocked,
        "linear occluded along {ray:?}"
    );
}

/// A ray from outside `bounds` (a shell around it) aimed at a random point
/// inside it, or (one in four) a random ray starting inside.
fn random_ray(rng: &mut Sampler, bounds: &Aabb) -> Ray {
    let size = bounds.extent().length().max(1e-3);
    let target = random_point_in(rng, bounds);
    if rng.gen_range(0..4) == 0 {
        return Ray::new(target, random_unit(rng));
    }
    let origin = bounds.centroid() + random_unit(rng) * size * rng.gen_range(0.6..3.0);
    Ray::new(origin, (target - origin).normalize_or(Vec3::X))
}

/// Both BVHs over `prims`, validated.
struct Both {
    binary: BvhAccel,
    wide: WideBvhAccel,
}

impl Both {
    fn new(prims: &Primitives) -> Self {
        let binary = BvhAccel::new(prims.clone());
        binary.validate().expect("valid BVH");
        let wide = WideBvhAccel::new(prims.clone());
        wide.validate().expect("valid wide BVH");
        Both { binary, wide }
    }

    fn each(&self) -> [&dyn Intersector; 2] {
        [&self.binary, &self.wide]
    }
}

/// Builds both BVHs, validates them, and compares them with the linear
/// scan on `rays` random rays (half of them also with a random finite
/// `t_max` for the occlusion check).
fn check_scene(prims: Primitives, rays: usize, seed: u64) -> Both {
    let both = Both::new(&prims);
    let mut bounds = prims.bounds();
    if bounds.is_empty() {
        bounds = Aabb::from_points([-Vec3::ONE, Vec3::ONE]);
    }
    let size = bounds.extent().length();
    let mut rng = sampler(seed, 1);
    for i in 0..rays {
        let mut ray = random_ray(&mut rng, &bounds);
        assert_same_closest(&prims, &both.each(), &ray);
        if i % 2 == 0 {
            ray.t_max = rng.gen_range(0.0..3.0 * size.max(1e-3));
            assert_same_closest(&prims, &both.each(), &ray);
            assert_occlusion_agrees(&prims, &both.each(), &ray);
        }
    }
    both
}

/// A random scene of `triangles` triangles and `spheres` spheres, in one of
/// three layouts: small triangles scattered in a box, large overlapping
/// triangles, or clusters of tiny triangles far apart.
fn random_scene(seed: u64, triangles: usize, spheres: usize, layout: u8) -> Primitives {
    let mut rng = sampler(seed, 0);
    let mut tris = Vec::with_capacity(triangles);
    let centres: Vec<Vec3> = (0..4)
        .map(|_| random_point(&mut rng, -100.0, 100.0))
        .collect();
    for _ in 0..triangles {
        let (centre, size) = match layout {
            0 => (random_point(&mut rng, -10.0, 10.0), 1.0),
            1 => (random_point(&mut rng, -2.0, 2.0), 8.0),
            _ => {
                let c = centres[rng.gen_range(0..centres.len())];
                (c + random_point(&mut rng, -0.5, 0.5), 0.05)
            }
        };
        tris.push([0, 1, 2].map(|_| centre + random_point(&mut rng, -size, size)));
    }
    let spheres: Vec<(Vec3, f32)> = (0..spheres)
        .map(|_| {
            (
                random_point(&mut rng, -10.0, 10.0),
                rng.gen_range(0.05..3.0),
            )
        })
        .collect();
    soup(&tris, &spheres)
}

proptest! {
    #![proptest_config(cases(200))]

    #[test]
    fn bvh_matches_linear_scan_on_random_scenes(
        seed in any::<u64>(),
        triangles in 0usize..300,
        spheres in prop_oneof![Just(0usize), 0usize..20],
        layout in 0u8..3,
    ) {
        check_scene(random_scene(seed, triangles, spheres, layout), 64, seed);
    }
}

#[test]
fn degenerate_inputs_build_valid_trees() {
    let tri = [Vec3::ZERO, Vec3::X, Vec3::Y];
    let point = Vec3::new(0.5, -0.25, 2.0);
    let line: Vec<[Vec3; 3]> = (0..500)
        .map(|i| tri.map(|p| p * 0.1 + Vec3::X * i as f32))
        .collect();
    let cases: Vec<(&str, Primitives)> = vec![
        ("empty", soup(&[], &[])),
        ("one triangle", soup(&[tri], &[])),
        ("one sphere", soup(&[], &[(Vec3::ZERO, 1.0)])),
        ("1000 identical triangles", soup(&[tri; 1000], &[])),
        (
            "1000 zero-area triangles at one point",
            soup(&[[point; 3]; 1000], &[]),
        ),
        ("triangles in a line", soup(&line, &[])),
        (
            "spheres only",
            soup(&[], &[(Vec3::ZERO, 1.0), (Vec3::X, 0.5), (Vec3::Y, 2.0)]),
        ),
        ("1000 identical spheres", soup(&[], &[(point, 0.5); 1000])),
    ];
    for (name, prims) in cases {
        println!("{name}: {} primitives", prims.len());
        check_scene(prims, 200, 5);
    }
}

#[test]
fn many_duplicates_stay_within_the_depth_limit() {
    let tri = [Vec3::ZERO, Vec3::X, Vec3::Y];
    let mut tris = vec![tri; 50_000];
    tris.extend([[Vec3::splat(3.0); 3]; 20_000]);
    let both = check_scene(soup(&tris, &[]), 20, 6);
    let (_, depth) = both.binary.bvh.leaf_stats();
    assert!(depth <= pathtracer::bvh::MAX_DEPTH, "depth {depth}");
    let (_, wide_depth, _) = both.wide.wide.leaf_stats();
    assert!(wide_depth <= depth, "wide depth {wide_depth}");
}

#[test]
fn bumpy_sphere_matches_linear_scan() {
    let prims = Primitives::from_scene(&builtin::bumpy_sphere(64, 32));
    check_scene(prims, 2000, 8);
}

#[test]
fn cornell_box_matches_linear_scan() {
    let scene = builtin::cornell_box();
    let prims = Primitives::from_scene(&scene);
    let both = check_scene(prims.clone(), 2000, 9);
    check_camera_rays(&scene, &prims, &both);
}

/// The course camera's rays over a coarse grid agree too.
fn check_camera_rays(scene: &Scene, prims: &Primitives, both: &Both) {
    let (width, height) = (48, 36);
    let camera = Camera::course_placement(&scene.camera, &prims.bounds(), width, height);
    for j in 0..height {
        for i in 0..width {
            let x = (i as f32 + 0.5) / width as f32;
            let y = (j as f32 + 0.5) / height as f32;
            assert_same_closest(prims, &both.each(), &camera.ray(x, y));
        }
    }
}

/// Every course scene that is present: BVH against linear scan on one to
/// three thousand random rays and the camera's rays. Skipped (saying so) where
/// the scenes are absent.
#[test]
fn course_scenes_match_linear_scan() {
    let Some(files) = common::course_scenes() else {
        return;
    };
    let mut seen = Vec::new();
    for (index, path) in files.iter().enumerate() {
        // The course ships some scenes twice under two names (bunny.dae,
        // bunny_unlit.dae): one check each is enough.
        let text = std::fs::read(path).unwrap();
        if seen.contains(&text) {
            println!("{}: the same file as one checked above", path.display());
            continue;
        }
        seen.push(text);
        let scene = pathtracer::scene::load(path).unwrap_or_else(|e| panic!("{e}"));
        let prims = Primitives::from_scene(&scene);
        // A few thousand random rays on small scenes, fewer on the meshes
        // (each checked ray costs a linear scan over every primitive).
        let rays = (40_000_000 / prims.len().max(1)).clamp(1000, 3000);
        let both = check_scene(prims.clone(), rays, 100 + index as u64);
        check_camera_rays(&scene, &prims, &both);
        println!("{}: {} primitives agree", path.display(), prims.len());
    }
}

/// Rays that do not move along an axis (direction component exactly ±0)
/// and run exactly along box planes: the slab test meets 0 · inf = NaN
/// there, and the BVH must still find what the linear scan finds.
#[test]
fn axis_parallel_rays_along_box_planes_agree_with_the_linear_scan() {
    // A floor of 8 x 8 unit squares in z = 0, two triangles each.
    let mut triangles = Vec::new();
    for i in 0..8 {
        for j in 0..8 {
            let (x, y) = (i as f32, j as f32);
            let c = |dx: f32, dy: f32| Vec3::new(x + dx, y + dy, 0.0);
            triangles.push([c(0.0, 0.0), c(1.0, 0.0), c(1.0, 1.0)]);
            triangles.push([c(0.0, 0.0), c(1.0, 1.0), c(0.0, 1.0)]);
        }
    }
    let primitives = soup(&triangles, &[]);
    let both = Both::new(&primitives);
    let mut checked = 0;
    for i in 0..=16 {
        for j in 0..=16 {
            let (x, y) = (i as f32 * 0.5, j as f32 * 0.5);
            for dir in [Vec3::new(0.0, 0.0, -1.0), Vec3::new(-0.0, -0.0, -1.0)] {
                let ray = Ray::new(Vec3::new(x, y, 5.0), dir);
                for bvh in both.each() {
                    assert!(
                        bvh.intersect(&ray).is_some(),
                        "a BVH missed the floor at ({x}, {y})"
                    );
                }
                assert_same_closest(&primitives, &both.each(), &ray);
                assert_occlusion_agrees(&primitives, &both.each(), &ray);
                checked += 1;
            }
            // Above the floor, along a row of box planes.
            let along = Ray::new(Vec3::new(-1.0, y, 0.5), Vec3::new(1.0, 0.0, 0.0));
            assert_same_closest(&primitives, &both.each(), &along);
        }
    }
    assert_eq!(checked, 17 * 17 * 2);
}
