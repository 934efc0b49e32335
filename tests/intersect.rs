//! Property tests of part 1's intersection routines against analytic
//! answers: triangles (Möller-Trumbore), spheres, leaving a surface with
//! `Hit::spawn_ray` / `spawn_ray_to`, watertight shared edges, and hard
//! numerical cases.
//!
//! Reference values are computed in `f64` from the same `f32` inputs, so a
//! tolerance only has to cover the rounding of the `f32` routine; each
//! tolerance is derived in a comment from the operations it covers, with
//! `u = 2^-24` the unit roundoff and `gamma(n) = n u / (1 - n u)`.

mod common;

use common::*;
use glam::{DVec3, Vec3};
use pathtracer::intersect::{Hit, Intersector, LinearScan, Primitives, Ray};
use pathtracer::math::float::gamma;
use proptest::prelude::*;

fn g(n: i32) -> f64 {
    f64::from(gamma(n))
}

/// `(|b_y c_z| + |b_z c_y|, ...)`: the bound on the rounding error of each
/// component of `b x c`, divided by `gamma(2)`, for non-negative inputs.
fn cross_abs(b: DVec3, c: DVec3) -> DVec3 {
    DVec3::new(
        b.y * c.z + b.z * c.y,
        b.z * c.x + b.x * c.z,
        b.x * c.y + b.y * c.x,
    )
}

/// The exact `t` at which the `f32` ray meets the plane of the `f32`
/// triangle, in double precision.
fn plane_t(tri: &[Vec3; 3], ray: &Ray) -> f64 {
    let n = plane_normal(tri);
    (tri[0].as_dvec3() - ray.origin.as_dvec3()).dot(n) / ray.dir.as_dvec3().dot(n)
}

/// Bound on the relative error of Möller-Trumbore's `t = num / det` with
/// `num = e2 . (s x e1)`, `det = e1 . (d x e2)`.
///
/// A triple product `a . (b x c)` evaluated in floating point is off by at
/// most `gamma(5) A . (B x' C)` with `A = |a|` componentwise and `x'` the
/// cross product with both terms added ([`cross_abs`]): `gamma(2)` for the
/// cross product, `gamma(3)` for the dot product. The inputs are rounded
/// too: `e1 = p1 - p0`, `e2 = p2 - p0` and `s = o - p0` each carry a
/// relative error `u` per component, which adds `u` per rounded factor.
/// So `|err num| <= gamma(8) N'` (three rounded factors) and
/// `|err det| <= gamma(7) D'` (two), and the quotient adds `u`:
/// `|err t| / |t| <= gamma(8) N' / |num| + gamma(7) D' / |det| + gamma(1)`
/// to first order; the bound is doubled to cover second-order terms.
fn mt_relative_error(tri: &[Vec3; 3], ray: &Ray) -> f64 {
    let [p0, p1, p2] = tri.map(|p| p.as_dvec3());
    let (e1, e2) = (p1 - p0, p2 - p0);
    let s = ray.origin.as_dvec3() - p0;
    let d = ray.dir.as_dvec3();
    let num = e2.dot(s.cross(e1));
    let det = e1.dot(d.cross(e2));
    let num_abs = e2.abs().dot(cross_abs(s.abs(), e1.abs()));
    let det_abs = e1.abs().dot(cross_abs(d.abs(), e2.abs()));
    2.0 * (g(8) * num_abs / num.abs() + g(7) * det_abs / det.abs() + g(1))
}

fn one_triangle(tri: [Vec3; 3]) -> Primitives {
    soup(&[tri], &[])
}

fn one_sphere(center: Vec3, radius: f32) -> Primitives {
    soup(&[], &[(center, radius)])
}

/// `10^x`.
fn pow10(x: f32) -> f32 {
    10f32.powf(x)
}

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
        let rel = mt_relative_error(&tri, &ray);
        let t = f64::from(hit.t);
        prop_assert!((t - t_exact).abs() <= rel * t_exact, "t {t} exact {t_exact} rel {rel}");

        // t against |target - origin|: the f32 direction is off by about
        // gamma(4) in angle and gamma(3) in length, which moves the plane
        // crossing by at most L gamma(4) (1 + 1 / cos) along the ray.
        let length = f64::from(distance);
        let tol = rel * t_exact + length * g(8) * (1.0 + 1.0 / cos);
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
        // 10% is far beyond the error bound of `mt_relative_error`.
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

/// Bound on the absolute error of the sphere routine's root `t` for a ray
/// with `f = o - c`, `q = -b - sign(b) sqrt(disc)` (exact values).
///
/// `f` is rounded (`u`), `b = f.d` (`gamma(3) |f|`),
/// `disc = r^2 - |f - b d|^2` and `c = f.f - r^2` each carry at most
/// `gamma(8) (|f|^2 + r^2)`, which reaches `sqrt(disc)` divided by
/// `2 sqrt(disc)`, `q` unamplified (no cancellation in `q`), and
/// `t0 = c / q` divided by `|q|`. Doubling for second-order terms and the
/// final division gives the `gamma(16)` terms below, plus `gamma(16) t`
/// for the relative error of `|d| = 1` and of the quotient.
fn sphere_t_tolerance(ray: &Ray, center: Vec3, radius: f32, t: f64) -> f64 {
    let f = ray.origin.as_dvec3() - center.as_dvec3();
    let d = ray.dir.as_dvec3();
    let r = f64::from(radius);
    let b = f.dot(d);
    let disc = r * r - (f - b * d).length_squared();
    let root = disc.abs().sqrt();
    let q = (-b - root.copysign(b)).abs();
    let scale = f.length_squared() + r * r;
    g(16) * (scale / q + scale / root + t.abs())
}

/// The roots of the exact quadratic for the `f32` ray, in double precision.
fn sphere_roots(ray: &Ray, center: Vec3, radius: f32) -> Option<(f64, f64)> {
    let f = ray.origin.as_dvec3() - center.as_dvec3();
    let d = ray.dir.as_dvec3();
    let r = f64::from(radius);
    let b = f.dot(d) / d.length_squared();
    let c = (f.length_squared() - r * r) / d.length_squared();
    let disc = b * b - c;
    (disc >= 0.0).then(|| (-b - disc.sqrt(), -b + disc.sqrt()))
}

/// The hit lies on the sphere within its error bound, and its normals are
/// the outward radial direction.
fn assert_on_sphere(hit: &Hit, center: Vec3, radius: f32) {
    let radial = hit.p.as_dvec3() - center.as_dvec3();
    let off = (radial.length() - f64::from(radius)).abs();
    let bound = hit.p_error.as_dvec3().length();
    assert!(off <= bound, "off the sphere by {off} > {bound}: {hit:?}");
    let outward = radial.normalize();
    assert!(hit.ng.as_dvec3().dot(outward) > 1.0 - 1e-5, "{hit:?}");
    assert_eq!(hit.n, hit.ng);
}

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

/// Strategy: a scene scale `10^x`, `x` in `[-6, 6]`.
fn scale() -> impl Strategy<Value = f32> {
    (-6.0f32..6.0).prop_map(pow10)
}

/// Strategy: how far from the origin the geometry is moved, in units of
/// the scene scale: nothing, or `10^y` with `y` in `[0, 4]`.
fn offset() -> impl Strategy<Value = Vec3> {
    prop_oneof![
        Just(Vec3::ZERO),
        (unit_vector(), 0.0f32..4.0).prop_map(|(w, y)| w * pow10(y)),
    ]
}

/// Checks a ray leaving a sphere against the exact roots of the same
/// `f32` ray. `outside`: the side the ray was spawned to, if known.
///
/// The spawned origin must lie on that side exactly. From outside, a ray
/// whose exact `f.d` is non-negative moves away from the centre and must
/// hit nothing (a hit there is the sphere hitting itself); otherwise it may
/// only hit at the near root. From inside, it must leave at the exit root.
/// Near-tangent rays (exact discriminant about zero) get the tolerance of
/// [`sphere_t_tolerance`], which grows without bound there.
fn check_left_sphere(
    prims: &Primitives,
    ray: &Ray,
    center: Vec3,
    radius: f32,
    outside: Option<bool>,
) {
    let f = ray.origin.as_dvec3() - center.as_dvec3();
    let d = ray.dir.as_dvec3();
    let r = f64::from(radius);
    let starts_outside = f.length() > r;
    if let Some(expected) = outside {
        assert_eq!(
            starts_outside, expected,
            "spawned on the wrong side: {ray:?}"
        );
    }
    let b = f.dot(d) / d.length_squared();
    let disc = b * b - (f.length_squared() - r * r) / d.length_squared();
    let root = if starts_outside {
        -b - disc.max(0.0).sqrt()
    } else {
        -b + disc.max(0.0).sqrt()
    };
    let Some(found) = linear_hit(prims, ray) else {
        // From inside the exit must be found when the interval reaches it.
        let tol = sphere_t_tolerance(ray, center, radius, root);
        assert!(
            starts_outside || root + tol >= f64::from(ray.t_max),
            "missed the exit at {root} from inside: {ray:?}"
        );
        return;
    };
    assert_no_nan(&found);
    assert!(
        !starts_outside || b < 0.0,
        "a ray leaving the sphere hit it: {found:?} along {ray:?}"
    );
    let t = f64::from(found.t);
    let tol = sphere_t_tolerance(ray, center, radius, t);
    assert!(
        (t - root).abs() <= tol,
        "hit at {t}, exact root {root} (tol {tol}): {found:?} along {ray:?}"
    );
}

proptest! {
    #![proptest_config(cases(1000))]

    /// A ray spawned from a triangle hit, in any direction or towards any
    /// point, never hits the triangle again, at any scale and offset.
    #[test]
    fn spawned_rays_leave_a_triangle(
        tri in triangle(1.0),
        (u, v) in interior_barycentrics(0.05),
        from in point(3.0),
        wi in unit_vector(),
        target in point(3.0),
        scale in scale(),
        offset in offset(),
    ) {
        let place = |p: Vec3| p * scale + offset * scale;
        let tri = tri.map(place);
        prop_assume!(well_shaped(&tri, 0.01));
        let (origin, aim) = (place(from), at_barycentric(&tri, u, v));
        let dir = (aim - origin).normalize();
        prop_assume!(dir.as_dvec3().dot(plane_normal(&tri)).abs() > 0.05);
        prop_assume!((aim - origin).length() > 0.1 * scale);
        let prims = one_triangle(tri);
        let hit = linear_hit(&prims, &Ray::new(origin, dir)).expect("aimed inside");
        assert_sane_hit(&hit, &Ray::new(origin, dir));

        let scan = LinearScan::new(&prims);
        for ray in [hit.spawn_ray(wi), hit.spawn_ray_to(place(target))] {
            prop_assert!(scan.intersect(&ray).is_none(), "re-hit from {hit:?} along {ray:?}");
            prop_assert!(!scan.occluded(&ray), "self-occluded from {hit:?} along {ray:?}");
        }
    }

    /// The same for spheres, hit from outside or from inside.
    #[test]
    fn spawned_rays_leave_a_sphere(
        center in point(1.0),
        radius in 0.1f32..1.0,
        w in unit_vector(),
        aim in unit_vector(),
        k in prop_oneof![0.0f32..0.9, 1.5f32..10.0],
        wi in unit_vector(),
        to in unit_vector(),
        to_distance in -2.0f32..1.0,
        scale in scale(),
        offset in offset(),
    ) {
        let center = (center + offset) * scale;
        let radius = radius * scale;
        let origin = center + w * (k * radius);
        // From outside, aim so that the line passes the centre at no more
        // than 0.9 r (a clear hit); from inside, any direction.
        let dir = if k > 1.0 {
            let across = aim - aim.dot(w) * w;
            (center + across * (0.9 * radius) - origin).normalize()
        } else {
            aim
        };
        prop_assume!(dir.is_finite());
        let prims = one_sphere(center, radius);
        let first = Ray::new(origin, dir);
        let hit = linear_hit(&prims, &first).expect("a clear hit");
        assert_sane_hit(&hit, &first);
        let spawned = hit.spawn_ray(wi);
        check_left_sphere(&prims, &spawned, center, radius, Some(wi.dot(hit.ng) > 0.0));

        // A shadow ray towards a point inside the sphere never hits it.
        let target = hit.p + to * (pow10(to_distance) * radius);
        let shadow = hit.spawn_ray_to(target);
        let outwards = (target - hit.p).dot(hit.ng) > 0.0;
        check_left_sphere(&prims, &shadow, center, radius, Some(outwards));
        let from_centre = (target.as_dvec3() - center.as_dvec3()).length() / f64::from(radius);
        if from_centre < 1.0 - 1e-3 {
            prop_assert!(linear_hit(&prims, &shadow).is_none(), "{hit:?} {shadow:?}");
        }
    }
}
