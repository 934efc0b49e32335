//! The course's Möller-Trumbore test against the watertight test the
//! renderer uses: they agree away from edges, and only Möller-Trumbore lets
//! rays slip through a shared vertex of a closed mesh.

mod common;

use common::*;
use glam::Vec3;
use pathtracer::intersect::moller_trumbore::moller_trumbore;
use pathtracer::intersect::triangle::TriangleShape;
use pathtracer::intersect::{Intersector, LinearScan, Ray, TriangleTest};
use pathtracer::math::rng::sampler;
use proptest::prelude::*;

proptest! {
    #![proptest_config(cases(1000))]

    /// Away from the edges both tests find the same hit.
    #[test]
    fn agrees_with_the_watertight_test_inside_the_triangle(
        tri in triangle(10.0),
        (u, v) in interior_barycentrics(0.05),
        origin in point(30.0),
    ) {
        prop_assume!(well_shaped(&tri, 0.05));
        let aim = at_barycentric(&tri, u, v);
        prop_assume!((aim - origin).length() > 0.1);
        let ray = Ray::new(origin, (aim - origin).normalize());
        // Both tests lose accuracy in t as 1 / cos at grazing angles (the
        // plane crossing is ill-conditioned there); compare where it is not.
        let normal = (tri[1] - tri[0]).cross(tri[2] - tri[0]).normalize();
        prop_assume!(ray.dir.dot(normal).abs() > 0.05);
        let shape = TriangleShape::new(tri[0], tri[1], tri[2]);
        let mt = moller_trumbore(&shape, &ray, f32::INFINITY);
        let wt = shape.intersect(&ray, f32::INFINITY);
        let (Some(mt), Some(wt)) = (mt, wt) else {
            // Only a ray grazing the plane may be refused (by the watertight
            // test's t-error check).
            let cos = ray.dir.dot((tri[1] - tri[0]).cross(tri[2] - tri[0]).normalize());
            prop_assert!(cos.abs() < 1e-3, "missed: {mt:?} {wt:?}");
            return Ok(());
        };
        prop_assert!((mt.t - wt.t).abs() <= 1e-4 * wt.t.max(1.0), "{mt:?} {wt:?}");
        prop_assert!((mt.u - wt.u).abs() < 1e-3 && (mt.v - wt.v).abs() < 1e-3, "{mt:?} {wt:?}");
    }
}

/// Six small triangles around a shared centre vertex, seen from afar: rays
/// aimed exactly at the centre always hit with the watertight test, and
/// Möller-Trumbore loses some of them between the triangles.
#[test]
fn moller_trumbore_leaks_at_a_shared_vertex_and_the_watertight_test_does_not() {
    let mut rng = sampler(2013, 0);
    let (mut mt_misses, mut wt_misses, rays) = (0, 0, 4000);
    for _ in 0..rays {
        let centre = random_point(&mut rng, -10.0, 10.0);
        let normal = random_unit(&mut rng);
        let frame = pathtracer::math::Frame::from_z(normal);
        let ring: Vec<Vec3> = (0..6)
            .map(|i| {
                let a = i as f32 / 6.0 * std::f32::consts::TAU;
                centre + 0.01 * frame.to_world(Vec3::new(a.cos(), a.sin(), 0.0))
            })
            .collect();
        let fan: Vec<[Vec3; 3]> = (0..6)
            .map(|i| [centre, ring[i], ring[(i + 1) % 6]])
            .collect();
        // From 40 units away, on the side the normal faces, not grazing.
        let mut from = random_unit(&mut rng);
        if from.dot(normal) < 0.3 {
            from = (from + normal).normalize();
        }
        let ray = Ray::new(centre + 40.0 * from, -from);
        // Through the intersector part 1 runs, with each triangle test.
        let mut primitives = soup(&fan, &[]);
        wt_misses += LinearScan::new(&primitives).intersect(&ray).is_none() as usize;
        primitives.triangle_test = TriangleTest::MollerTrumbore;
        mt_misses += LinearScan::new(&primitives).intersect(&ray).is_none() as usize;
    }
    eprintln!("of {rays} rays at the shared vertex, Möller-Trumbore lost {mt_misses}, the watertight test {wt_misses}");
    assert_eq!(wt_misses, 0);
    assert!(mt_misses > 0, "expected Möller-Trumbore to leak somewhere");
}

/// The triangle's edges belong to it, as `0 <= u <= 1` says for `u`: a ray
/// through a point of an edge, where `v = 0`, `u = 0` or `u + v = 1` comes
/// out exactly in `f32`, hits. And a triangle so large that its determinant
/// overflows is refused, not hit at `t = 0` by a ray from its corner (with
/// `1 / det = 0`, `u`, `v` and `t` all come out 0). Checked by hand: the
/// edge tests `v < 0` made `v <= 0` and `u + v > 1` made `>= 1`, and the
/// guard `det == 0 || !det.is_finite()` made `&&`, each fail here.
#[test]
fn edges_belong_to_the_triangle_and_an_overflowing_determinant_is_refused() {
    let shape = TriangleShape::new(Vec3::ZERO, Vec3::X, Vec3::Y);
    let down = |x: f32, y: f32| Ray::new(Vec3::new(x, y, 1.0), -Vec3::Z);
    for (x, y, u, v) in [
        (0.5, 0.0, 0.5, 0.0),
        (0.0, 0.5, 0.0, 0.5),
        (0.5, 0.5, 0.5, 0.5),
    ] {
        let hit = moller_trumbore(&shape, &down(x, y), f32::INFINITY);
        let hit = hit.unwrap_or_else(|| panic!("missed the edge at ({x}, {y})"));
        assert_eq!((hit.t, hit.u, hit.v), (1.0, u, v));
    }
    assert!(moller_trumbore(&shape, &down(0.5, -1e-6), f32::INFINITY).is_none());

    let huge = TriangleShape::new(
        Vec3::ZERO,
        Vec3::new(1e20, 0.0, 0.0),
        Vec3::new(0.0, 1e20, 0.0),
    );
    let from_corner = Ray::new(Vec3::ZERO, Vec3::new(0.0, 0.6, -0.8));
    assert!(moller_trumbore(&huge, &from_corner, f32::INFINITY).is_none());
}
