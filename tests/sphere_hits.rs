//! Property tests of sphere hits against the exact roots: from outside
//! aimed at the centre, from inside (the far side), and lines passing the
//! centre at more than the radius (a miss).
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

    /// From outside, aimed at the centre: hit at `|o - c| - r`.
    #[test]
    fn sphere_hit_from_outside(
        center in point(100.0),
        radius in 0.01f32..50.0,
        w in unit_vector(),
        k in 1.01f32..100.0,
    ) {
        let origin = center + w * (k * radius);
        let dir = (center - origin).normalize();
        let ray = Ray::new(origin, dir);
        let hit = linear_hit(&one_sphere(center, radius), &ray).expect("aimed at the centre");
        assert_sane_hit(&hit, &ray);
        let expected = (origin.as_dvec3() - center.as_dvec3()).length() - f64::from(radius);
        let tol = sphere_t_tolerance(&ray, center, radius, expected);
        let t = f64::from(hit.t);
        prop_assert!((t - expected).abs() <= tol, "t {t} expected {expected} tol {tol}");
        assert_on_sphere(&hit, center, radius);
        prop_assert!(hit.ng.dot(dir) < 0.0, "front side faces the ray");
    }

    /// From inside: the far side, at distance r from the centre.
    #[test]
    fn sphere_hit_from_inside(
        center in point(100.0),
        radius in 0.01f32..50.0,
        w in unit_vector(),
        k in 0.0f32..0.99,
        dir in unit_vector(),
    ) {
        let origin = center + w * (k * radius);
        let ray = Ray::new(origin, dir);
        let hit = linear_hit(&one_sphere(center, radius), &ray).expect("inside: always a hit");
        assert_sane_hit(&hit, &ray);
        let (_, far) = sphere_roots(&ray, center, radius).expect("the exact ray meets it");
        let tol = sphere_t_tolerance(&ray, center, radius, far);
        let t = f64::from(hit.t);
        prop_assert!((t - far).abs() <= tol, "t {t} far root {far} tol {tol}");
        assert_on_sphere(&hit, center, radius);
        prop_assert!(hit.ng.dot(dir) > 0.0, "leaving through the far side");
    }

    /// A line passing the centre at more than r misses, wherever the
    /// origin sits on it.
    #[test]
    fn sphere_missed_by_more_than_radius(
        center in point(100.0),
        radius in 0.01f32..50.0,
        dir in unit_vector(),
        side in unit_vector(),
        k in 1.01f32..10.0,
        along in -20.0f32..20.0,
    ) {
        let side = side - side.dot(dir) * dir;
        prop_assume!(side.length() > 0.1);
        let origin = center + side.normalize() * (k * radius) - dir * (along * radius);
        let ray = Ray::new(origin, dir);
        // The actual f32 line must clear the sphere by more than the
        // rounding of `disc = r^2 - |perp|^2` (see `sphere_t_tolerance`).
        let f = origin.as_dvec3() - center.as_dvec3();
        let d = dir.as_dvec3();
        let perp2 = (f - f.dot(d) / d.length_squared() * d).length_squared();
        let r2 = f64::from(radius).powi(2);
        prop_assume!(perp2 - r2 > g(16) * (f.length_squared() + r2));
        prop_assert!(linear_hit(&one_sphere(center, radius), &ray).is_none());
    }
}
