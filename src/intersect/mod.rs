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
