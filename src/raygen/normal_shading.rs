//! Normal shading: the colour of a camera ray is `(n + 1) / 2` for the
//! shading normal `n` at its first hit, black for a miss. No light
//! transport: this checks ray generation and intersection by eye.

use crate::intersect::{Intersector, Ray};
use crate::math::Rgb;

/// Part 1's "integrator": shading normals as colours.
pub struct NormalShading<I> {
    pub intersector: I,
}

impl<I: Intersector> NormalShading<I> {
    /// `(n + 1) / 2` at the first hit, black for a miss.
    #[doc(alias = "debug_shading")]
    pub fn radiance(&self, ray: &Ray) -> Rgb {
        match self.intersector.intersect(ray) {
            Some(hit) => 0.5 * (hit.n + Rgb::ONE),
            None => Rgb::ZERO,
        }
    }
}
