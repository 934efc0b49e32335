//! Property tests of triangle hits (the watertight test) against analytic
//! answers: `t`, the point, the barycentrics and the normal of a ray aimed
//! inside a triangle, the ray's `[t_min, t_max]` interval, and points just
//! outside an edge.
//!
//! Reference values are computed in `f64` from the same `f32` inputs, so a
//! tolerance only has to cover the rounding of the `f32` routine; each
//! tolerance is derived in a comment from the operations it covers, with
//! `u = 2^-24` the unit roundoff and `gamma(n) = n u / (1 - n u)`
//! (the bounds are in `tests/common/exact.rs`).

mod common;

use common::*;
use glam::Vec3;
use pathtracer::intersect::{Primitives, Ray};
use proptest::prelude::*;

proptest! {
    #![proptest_config(cases(1000))]

    /// A ray aimed at an interior point of a triangle hits it where the
    /// analytic answer says, and the hit record is consistent.
    #[test]
    fn triangle_hit_matches_the_analytic_answer(
        tri in triangle(10.0),
        (u, v) in interior_barycentrics(1e-3),
        origin in point(20.0),
        t_min_fraction in 0.0f32..0.9,
        t_max_factor in prop_oneof![Just(f32::INFINITY), 1.1f32..10.0],
    ) {
        let target = at_barycentric(&tri, u, v);
        let to_target = target - origin;
        let distance = to_target.length();
        let dir = to_target / distance;
        let n = plane_normal(&tri);
        let cos = dir.as_dvec3().dot(n).abs();
        prop_assume!(cos > 0.05 && distance > 1e-2);
        let ray = Ray {
            origin,
            dir,
            t_min: t_min_fraction * distance,
            t_max: t_max_factor * distance,
        };
        let prims = one_triangle(tri);

        // Barycentrics of the shape test: inside the closed triangle.
        let shape_hit = prims.shapes[0].intersect(&ray, ray.t_max);
        let shape_hit = shape_hit.expect("a ray aimed inside the triangle must hit");
        prop_assert!((0.0..=1.0).contains(&shape_hit.u), "{shape_hit:?}");
        prop_assert!((0.0..=1.0).contains(&shape_hit.v), "{shape_hit:?}");
        prop_assert!(shape_hit.u + shape_hit.v <= 1.0, "{shape_hit:?}");

        let hit = linear_hit(&prims, &ray).expect("the linear scan must find it too");
        assert_sane_hit(&hit, &ray);
        prop_assert_eq!(hit.primitive, 0);
        prop_assert_eq!(hit.t, shape_hit.t);

        // t against the exact plane crossing of this f32 ray.
        let t_exact = plane_t(&tri, &ray);
        let t_error = watertight_t_error(&tri, &ray);
        let t = f64::from(hit.t);
        prop_assert!((t - t_exact).abs() <= t_error, "t {t} exact {t_exact} error bound {t_error}");

        // t against |target - origin|: the f32 direction is off by about
        // gamma(4) in angle and gamma(3) in length, which moves the plane
        // crossing by at most L gamma(4) (1 + 1 / cos) along the ray.
        let length = f64::from(distance);
        let tol = t_error + length * g(8) * (1.0 + 1.0 / cos);
        prop_assert!((t - length).abs() <= tol, "t {t} |target - origin| {length} tol {tol}");

        // The point lies on the triangle's plane, within its error bound
        // (the exact barycentric combination of the computed u, v, w is on
        // the plane up to the rounding of w = 1 - u - v, covered by it).
        let off_plane = (hit.p.as_dvec3() - tri[0].as_dvec3()).dot(n).abs();
        let bound = n.abs().dot(hit.p_error.as_dvec3());
        prop_assert!(off_plane <= bound, "off the plane by {off_plane} > {bound}");
        // And the bound is tight: pbrt-v4's `gamma(7) (|w p0| + |u p1| +
        // |v p2|)` per axis, at most `gamma(7) max_k |p_k|` since the
        // weights sum to 1 (`gamma(8)` covers `w`'s rounding below 0). A
        // bound of the coordinates' size would push spawned rays past
        // nearby surfaces. Checked by hand: each `*` in the bound made `+`
        // fails here.
        for axis in 0..3 {
            let largest = tri.iter().map(|p| p[axis].abs()).fold(0.0, f32::max);
            let most = g(8) * f64::from(largest);
            let error = f64::from(hit.p_error[axis]);
            prop_assert!(error <= most, "axis {axis}: error bound {error} > {most}");
        }

        // The geometric normal follows the winding.
        prop_assert!(hit.ng.as_dvec3().dot(n) > 1.0 - 1e-5, "{:?} vs {n}", hit.ng);
    }

    /// The hit is bounded by the ray's interval; a point just outside an
    /// edge is missed.
    #[test]
    fn triangle_respects_interval_and_edges(
        tri in triangle(10.0),
        (u, v) in interior_barycentrics(1e-3),
        outside in -2.0f32..-0.01,
        edge in 0usize..3,
        origin in point(20.0),
    ) {
        let target = at_barycentric(&tri, u, v);
        let dir = (target - origin).normalize();
        let cos = dir.as_dvec3().dot(plane_normal(&tri)).abs();
        prop_assume!(cos > 0.05 && (target - origin).length() > 1e-2);
        let prims = one_triangle(tri);
        let t_exact = plane_t(&tri, &Ray::new(origin, dir)) as f32;
        // 10% is far beyond the error bound of `watertight_t_error`.
        let short = Ray { t_max: 0.9 * t_exact, ..Ray::new(origin, dir) };
        prop_assert!(linear_hit(&prims, &short).is_none());
        let late = Ray { t_min: 1.1 * t_exact, ..Ray::new(origin, dir) };
        prop_assert!(linear_hit(&prims, &late).is_none());

        // One barycentric clearly negative: outside the triangle.
        let w = 1.0 - u - v;
        let bary = match edge {
            0 => [outside, u + w - outside, v],
            1 => [w, outside, u + v - outside],
            _ => [w - outside + v, u, outside],
        };
        let aim = bary[0] * tri[0] + bary[1] * tri[1] + bary[2] * tri[2];
        let dir = (aim - origin).normalize();
        prop_assume!(dir.as_dvec3().dot(plane_normal(&tri)).abs() > 0.05);
        prop_assert!(linear_hit(&prims, &Ray::new(origin, dir)).is_none(), "hit outside an edge");
    }
}

/// The shading normal is the barycentric blend of the vertex normals,
/// `normalize(w n0 + u n1 + v n2)`, at three points of a triangle whose
/// vertex normals all differ; `vertex_normals` gives them back, and nothing
/// for a sphere. Checked by hand: either `+` of the blend made `-` or `*`,
/// and `vertex_normals` made `None` or zeros, fail here.
#[test]
fn shading_normals_blend_the_vertex_normals() {
    let tri = [Vec3::ZERO, Vec3::X, Vec3::Y];
    let mut scene = soup_scene(&[tri], &[(Vec3::new(5.0, 0.0, 0.0), 1.0)]);
    let normals = [
        Vec3::new(0.6, 0.0, 0.8),
        Vec3::new(0.0, 0.6, 0.8),
        Vec3::new(-0.48, -0.6, 0.64),
    ];
    scene.mesh.normals = normals.to_vec();
    let prims = Primitives::from_scene(&scene);
    assert_eq!(prims.vertex_normals(0), Some(normals));
    assert_eq!(prims.vertex_normals(1), None);
    for (u, v) in [(0.2f32, 0.3f32), (0.5, 0.25), (0.1, 0.8)] {
        let w = 1.0 - u - v;
        let ray = Ray::new(Vec3::new(u, v, 1.0), -Vec3::Z);
        let hit = linear_hit(&prims, &ray).expect("aimed inside");
        let blend = (f64::from(w) * normals[0].as_dvec3()
            + f64::from(u) * normals[1].as_dvec3()
            + f64::from(v) * normals[2].as_dvec3())
        .normalize();
        let off = (hit.n.as_dvec3() - blend).length();
        assert!(off < 1e-5, "at ({u}, {v}): {:?}, expected {blend}", hit.n);
    }
}

/// Triangles of sides `1e-10` to `1e-14`, hit from as close: their
/// edges' cross product has a subnormal squared length, yet the geometric
/// normal is the winding's, of unit length. Before `unit_cross` it came
/// out 1 % too long at `1e-11` and, from `1e-12` on, not at all: the
/// fallback then faced the ray, the wrong side for this winding (checked
/// by hand with `finish_hit`'s `unit_cross` made glam's
/// `normalize_or(-ray.dir)`).
#[test]
fn tiny_triangles_get_the_unit_normal_of_their_winding() {
    for side in [1e-10f32, 1e-11, 1e-12, 1e-13, 1e-14] {
        let tri = [
            Vec3::ZERO,
            Vec3::new(0.0, side, 0.0),
            Vec3::new(side, 0.0, 0.0),
        ];
        let ray = Ray::new(Vec3::new(0.25 * side, 0.25 * side, side), -Vec3::Z);
        let hit = linear_hit(&one_triangle(tri), &ray);
        let hit = hit.unwrap_or_else(|| panic!("the watertight test hits at side {side}"));
        assert_sane_hit(&hit, &ray);
        assert_eq!(hit.ng, -Vec3::Z, "side {side}");
    }
}

/// A ray through a point of an edge, or through a corner, hits, whichever
/// way the triangle is wound and from either side: the edge functions are
/// zero there and of one sign elsewhere, negative for one winding, positive
/// for the other. Checked by hand: `e0 > 0` in the test for mixed signs
/// made `e0 >= 0`, which refuses the edge where `e0 = 0` when the others
/// are negative, fails here.
#[test]
fn edges_and_corners_belong_to_the_triangle_either_way_round() {
    let points = [
        (0.5, 0.0),
        (0.0, 0.5),
        (0.5, 0.5),
        (0.0, 0.0),
        (1.0, 0.0),
        (0.0, 1.0),
    ];
    for tri in [
        [Vec3::ZERO, Vec3::X, Vec3::Y],
        [Vec3::ZERO, Vec3::Y, Vec3::X],
    ] {
        let prims = one_triangle(tri);
        for (x, y) in points {
            for side in [1.0f32, -1.0] {
                let ray = Ray::new(Vec3::new(x, y, side), Vec3::new(0.0, 0.0, -side));
                let hit = linear_hit(&prims, &ray);
                let hit =
                    hit.unwrap_or_else(|| panic!("missed ({x}, {y}) from z = {side} in {tri:?}"));
                assert_eq!(hit.t, 1.0);
            }
        }
    }
}
