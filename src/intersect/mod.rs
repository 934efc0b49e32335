//! Part 1: rays and their intersections with triangles and spheres.
//!
//! - [`Ray`]: `r(t) = o + t d`, `t` in `[t_min, t_max]`, `d` unit length.
//! - [`moller_trumbore`]: the course's ray-triangle test (part 1), and
//!   [`triangle`]: the watertight test of Woop et al. (part 2 onwards); both
//!   return `t` and barycentrics; [`TriangleTest`] picks one.
//! - [`sphere`]: the analytic quadratic in a cancellation-free form.
//! - [`Hit`]: the point, the interpolated shading normal, the geometric
//!   normal and a bound on the point's rounding error, so that
//!   [`Hit::spawn_ray`] can leave the surface without a magic epsilon.
//! - [`Primitives`]: every shape of a scene packed for intersection, and
//!   [`LinearScan`], part 1's "test every primitive" [`Intersector`].

pub mod aabb;
pub mod hit;
pub mod linear;
pub mod moller_trumbore;
pub mod primitives;
pub mod ray;
pub mod sphere;
pub mod triangle;

pub use aabb::Aabb;
pub use hit::Hit;
pub use linear::LinearScan;
pub use primitives::{Primitives, Shape, ShapeHit, TriangleTest};
pub use ray::Ray;

/// The closest primitive along a ray, before its hit record is made:
/// which primitive, its shape, and where on it (`t` and barycentrics).
/// This is what Embree's `rtcIntersect1` answers; the point, its error
/// bound and the normals come after, from [`Primitives::finish_hit`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PrimitiveHit {
    pub id: u32,
    pub shape: Shape,
    pub hit: ShapeHit,
}

/// Anything that can find the closest hit along a ray: a linear scan
/// (part 1) or a BVH (part 2).
pub trait Intersector: Sync {
    /// The primitives the intersector was built over.
    fn primitives(&self) -> &Primitives;

    /// The closest primitive with `t` in `[ray.t_min, ray.t_max]`, if any:
    /// the search alone, without the hit record.
    fn nearest(&self, ray: &Ray) -> Option<PrimitiveHit>;

    /// The closest hit with `t` in `[ray.t_min, ray.t_max]`, if any, with
    /// its full record.
    #[inline]
    fn intersect(&self, ray: &Ray) -> Option<Hit> {
        let PrimitiveHit { id, shape, hit } = self.nearest(ray)?;
        Some(self.primitives().finish_hit(id, &shape, ray, hit))
    }

    /// Whether anything lies on the ray within `[ray.t_min, ray.t_max]`
    /// (a shadow ray: stops at the first hit found, not the closest).
    #[doc(alias = "has_intersection")]
    fn occluded(&self, ray: &Ray) -> bool;
}

impl<T: Intersector + ?Sized> Intersector for &T {
    fn primitives(&self) -> &Primitives {
        (**self).primitives()
    }

    fn nearest(&self, ray: &Ray) -> Option<PrimitiveHit> {
        (**self).nearest(ray)
    }

    fn intersect(&self, ray: &Ray) -> Option<Hit> {
        (**self).intersect(ray)
    }

    fn occluded(&self, ray: &Ray) -> bool {
        (**self).occluded(ray)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::builtin;
    use glam::Vec3;

    /// Each method of `&T`'s impl asked through the generic code that takes
    /// `impl Intersector` (as `World::new(scene, &bvh)` does).
    fn answers(
        intersector: impl Intersector,
        ray: &Ray,
    ) -> (*const Primitives, Option<PrimitiveHit>, Option<Hit>, bool) {
        let primitives: *const Primitives = intersector.primitives();
        let nearest = intersector.nearest(ray);
        let hit = intersector.intersect(ray);
        (primitives, nearest, hit, intersector.occluded(ray))
    }

    /// A reference answers as the intersector it points to: the same
    /// primitives (not a default set) and the same hit. Each forwarding
    /// method made to return a default (a leaked empty `Primitives`, `None`,
    /// `false`) fails here; checked by hand for `primitives` and `nearest`,
    /// the two a mutation run found untested.
    #[test]
    fn a_reference_to_an_intersector_forwards_every_question() {
        let primitives = Primitives::from_scene(&builtin::cornell_box());
        let scan = LinearScan::new(&primitives);
        let ray = Ray::new(Vec3::new(0.0, 1.0, 3.0), Vec3::new(0.0, 0.0, -1.0));
        let (own_primitives, own_nearest, own_hit, own_occluded) = answers(&scan, &ray);
        assert!(own_nearest.is_some() && own_hit.is_some() && own_occluded);
        let direct = (
            scan.primitives() as *const Primitives,
            scan.nearest(&ray),
            scan.intersect(&ray),
            scan.occluded(&ray),
        );
        assert_eq!((own_primitives, own_nearest, own_hit, own_occluded), direct);
        assert!(std::ptr::eq(own_primitives, &primitives));
    }
}
