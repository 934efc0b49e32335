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

/// Anything that can find the closest hit along a ray: a linear scan
/// (part 1) or a BVH (part 2).
pub trait Intersector: Sync {
    /// The closest hit with `t` in `[ray.t_min, ray.t_max]`, if any.
    fn intersect(&self, ray: &Ray) -> Option<Hit>;

    /// Whether anything lies on the ray within `[ray.t_min, ray.t_max]`
    /// (a shadow ray: stops at the first hit found, not the closest).
    #[doc(alias = "has_intersection")]
    fn occluded(&self, ray: &Ray) -> bool;
}

impl<T: Intersector + ?Sized> Intersector for &T {
    fn intersect(&self, ray: &Ray) -> Option<Hit> {
        (**self).intersect(ray)
    }

    fn occluded(&self, ray: &Ray) -> bool {
        (**self).occluded(ray)
    }
}
