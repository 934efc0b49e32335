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
use pathtracer::intersect::Ray;
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
