//! Hard cases of intersection: grazing rays and rays along edges,
//! zero-area triangles, rays starting on and inside spheres, huge and tiny
//! coordinates, and NaN/infinite rays. No panic, no NaN, and the obvious
//! answers where there are any; the linear scan and the BVH agree.

mod common;

use common::*;
use glam::Vec3;
use pathtracer::bvh::BvhAccel;
use pathtracer::intersect::Ray;
use rand::Rng;

/// Rays of every kind at `prims`: from `origins` towards `targets`, plus
/// rays with NaN and infinite components and odd intervals.
fn hard_rays(rng: &mut pathtracer::math::rng::Sampler, around: Vec3, size: f32) -> Vec<Ray> {
    let mut rays = Vec::new();
    for _ in 0..200 {
        let origin = around + random_point(rng, -2.0, 2.0) * size;
        let target = around + random_point(rng, -1.0, 1.0) * size;
        rays.push(Ray::new(origin, (target - origin).normalize()));
    }
    let (nan, inf) = (f32::NAN, f32::INFINITY);
    let good = Ray::new(around + Vec3::splat(2.0 * size), -Vec3::ONE.normalize());
    for v in [
        Vec3::new(nan, 0.0, 0.0),
        Vec3::splat(inf),
        Vec3::new(-inf, 1.0, 0.0),
    ] {
        rays.push(Ray { origin: v, ..good });
        rays.push(Ray { dir: v, ..good });
    }
    rays.push(Ray {
        dir: Vec3::ZERO,
        ..good
    });
    for (t_min, t_max) in [(nan, inf), (0.0, nan), (-inf, inf), (inf, inf), (1.0, 0.0)] {
        rays.push(Ray {
            t_min,
            t_max,
            ..good
        });
    }
    rays
}

/// Traces [`hard_rays`] through a scene made of `triangles` and `spheres`,
/// with a linear scan and a BVH; returns how many rays hit something.
fn trace_hard(triangles: &[[Vec3; 3]], spheres: &[(Vec3, f32)], around: Vec3, size: f32) -> usize {
    let prims = soup(triangles, spheres);
    let bvh = BvhAccel::new(prims.clone());
    bvh.validate().unwrap();
    let mut rng = pathtracer::math::rng::sampler(7, 0);
    hard_rays(&mut rng, around, size)
        .iter()
        .filter(|ray| {
            let hit = trace_both(&prims, &bvh, ray);
            if let Some(h) = &hit {
                if ray.origin.is_finite() && is_unit(ray.dir) && h.t.is_finite() {
                    // A ray meeting its preconditions (unit direction): a proper
                    // record (normals fall back to the geometric one, or to
                    // -dir for zero-area faces).
                    assert!(is_unit(h.n) && is_unit(h.ng), "{h:?} {ray:?}");
                }
                for spawned in [h.spawn_ray(ray.dir), h.spawn_ray_to(around)] {
                    trace_both(&prims, &bvh, &spawned);
                }
            }
            hit.is_some()
        })
        .count()
}

#[test]
fn grazing_rays_and_rays_along_edges() {
    let tri = [Vec3::ZERO, Vec3::X, Vec3::Y];
    let prims = one_triangle(tri);
    let bvh = BvhAccel::new(prims.clone());
    // In the plane: through the interior, along each edge, through vertices.
    let in_plane = [
        Ray::new(Vec3::new(-1.0, 0.25, 0.0), Vec3::X),
        Ray::new(Vec3::new(-1.0, 0.0, 0.0), Vec3::X),
        Ray::new(Vec3::new(0.0, -1.0, 0.0), Vec3::Y),
        Ray::new(
            Vec3::new(2.0, -1.0, 0.0),
            Vec3::new(-1.0, 1.0, 0.0).normalize(),
        ),
        Ray::new(
            Vec3::new(-1.0, -1.0, 0.0),
            Vec3::new(1.0, 1.0, 0.0).normalize(),
        ),
    ];
    for ray in &in_plane {
        // A ray in the plane meets the triangle in a segment of zero area:
        // the watertight test reports no hit (det = 0).
        assert!(trace_both(&prims, &bvh, ray).is_none(), "{ray:?}");
    }
    // Almost grazing rays aimed at the interior still hit it, down to a
    // slope of 1e-4. Below that the crossing along the ray is uncertain by
    // (position error ~ 1e-7) / slope, comparable to t itself, and the
    // conservative t > error-of-t check rightly refuses to certify it.
    for k in 1..=20 {
        let slope = 10f32.powi(-k);
        let dir = Vec3::new(1.0, 0.0, -slope).normalize();
        let ray = Ray::new(Vec3::new(0.25, 0.25, 0.0) - dir, dir);
        let hit = trace_both(&prims, &bvh, &ray);
        if k <= 4 {
            assert!(hit.is_some(), "grazing at slope {slope} missed");
        }
    }
    // Random triangles, random in-plane rays: whatever the answer, no NaN.
    let mut rng = pathtracer::math::rng::sampler(1, 0);
    for _ in 0..2000 {
        let tri = [0, 1, 2].map(|_| random_point(&mut rng, -5.0, 5.0));
        let (e1, e2) = (tri[1] - tri[0], tri[2] - tri[0]);
        let (a, b, c, d): (f32, f32, f32, f32) = (
            rng.gen(),
            rng.gen(),
            rng.gen::<f32>() - 0.5,
            rng.gen::<f32>() - 0.5,
        );
        let origin = tri[0] + (2.0 * a - 0.5) * e1 + (2.0 * b - 0.5) * e2;
        let dir = (c * e1 + d * e2).normalize();
        let prims = one_triangle(tri);
        let along_edge = Ray::new(tri[0] - e1, e1.normalize());
        for ray in [Ray::new(origin, dir), along_edge] {
            if let Some(hit) = linear_hit(&prims, &ray) {
                assert_sane_hit(&hit, &ray);
            }
        }
    }
}

#[test]
fn zero_area_triangles() {
    let p = Vec3::new(0.3, -0.2, 0.1);
    let e = Vec3::new(0.5, 0.25, -0.125);
    let degenerate = [
        [p, p + e, p + 2.0 * e],
        [p, p + e, p + 0.5 * e],
        [p, p, p + e],
        [p, p + e, p + e],
        [p, p, p],
        [Vec3::ZERO; 3],
    ];
    let hits = trace_hard(&degenerate, &[], p, 1.0);
    assert_eq!(hits, 0, "a zero-area triangle was hit");
    // Mixed with a proper triangle, the proper one is still found.
    let mut with_proper = degenerate.to_vec();
    with_proper.push([
        Vec3::new(-1.0, -1.0, 0.0),
        Vec3::new(1.0, -1.0, 0.0),
        Vec3::Y,
    ]);
    assert!(trace_hard(&with_proper, &[], Vec3::ZERO, 1.0) > 0);
}

#[test]
fn rays_starting_on_and_inside_spheres() {
    let mut rng = pathtracer::math::rng::sampler(2, 0);
    for _ in 0..2000 {
        let center = random_point(&mut rng, -10.0, 10.0);
        let radius = 10f32.powf(rng.gen_range(-3.0..3.0));
        let prims = one_sphere(center, radius);
        let w = random_unit(&mut rng);
        let dir = random_unit(&mut rng);
        // On the surface (as well as f32 allows): a hit, if any, is sane.
        let on = Ray::new(center + radius * w, dir);
        if let Some(hit) = linear_hit(&prims, &on) {
            assert_sane_hit(&hit, &on);
        }
        // Exactly at the centre and anywhere inside: the far side at r.
        for origin in [center, center + 0.5 * radius * w] {
            let ray = Ray::new(origin, dir);
            let hit = linear_hit(&prims, &ray).expect("inside a sphere: always a hit");
            assert_sane_hit(&hit, &ray);
            assert_on_sphere(&hit, center, radius);
        }
    }
}

#[test]
fn huge_and_tiny_coordinates() {
    for exponent in [-38, -30, -20, -10, 10, 20, 30, 38] {
        let s = 10f32.powi(exponent);
        let tri = [
            Vec3::new(-1.0, -1.0, 0.0),
            Vec3::new(1.0, -1.0, 0.0),
            Vec3::Y,
        ]
        .map(|p| p * s);
        let spheres = [
            (Vec3::new(0.0, 0.0, -2.0) * s, 0.5 * s),
            (Vec3::splat(3.0 * s), s),
        ];
        let near = trace_hard(&[tri], &spheres, Vec3::ZERO, s);
        // Far from the origin as well.
        let offset = Vec3::new(3.0e38, -1.0e38, 2.0e30);
        let moved = tri.map(|p| p + offset);
        let far = trace_hard(&[moved], &[(offset, s)], offset, s);
        // Where products of coordinates fit in f32 (|x| below about 1e19)
        // rays find the geometry, 2 to 62 of the ~200 here; beyond, the
        // squared lengths overflow and everything is missed, cleanly.
        if exponent <= 10 {
            assert!(
                near > 0 && far > 0,
                "scale 1e{exponent}: {near} and {far} hits"
            );
        }
    }
}

#[test]
fn nan_and_infinite_rays_do_not_panic() {
    let mut rng = pathtracer::math::rng::sampler(3, 0);
    let triangles: Vec<[Vec3; 3]> = (0..50)
        .map(|_| [0, 1, 2].map(|_| random_point(&mut rng, -5.0, 5.0)))
        .collect();
    let spheres = [(Vec3::ZERO, 1.0), (Vec3::splat(3.0), 0.5)];
    assert!(trace_hard(&triangles, &spheres, Vec3::ZERO, 5.0) > 0);
    // Spawning with a NaN or zero direction does not panic either.
    let prims = soup(&triangles, &spheres);
    let ray = Ray::new(Vec3::new(0.0, 0.0, 10.0), -Vec3::Z);
    let hit = linear_hit(&prims, &ray).expect("the unit sphere is in the way");
    for w in [Vec3::NAN, Vec3::ZERO, Vec3::INFINITY] {
        let _ = linear_hit(&prims, &hit.spawn_ray(w));
        let _ = linear_hit(&prims, &hit.spawn_ray_to(w));
        let _ = linear_hit(&prims, &hit.spawn_ray_to(hit.p));
    }
}
