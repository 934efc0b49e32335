//! The BVH as an [`Intersector`]: the tree over the scene's primitives.
//!
//! A leaf's slot `s` holds primitive `bvh.order[s]`, whose shape is read
//! from [`Primitives::shapes`] through that id. (Until the scale work the
//! shapes were also copied into leaf order, so a leaf's shapes were
//! contiguous; the copy cost 40 bytes per triangle, a third of the
//! accelerator's memory, and a few percent of the primary-ray rate; see
//! `docs/03-bvh.md`, "Scale".)

use super::build::{build_from, BuildOptions};
use super::Bvh;
use crate::intersect::{Aabb, Intersector, PrimitiveHit, Primitives, Ray, Shape};

/// A BVH over a scene's primitives.
pub struct BvhAccel {
    pub bvh: Bvh,
    pub primitives: Primitives,
}

impl BvhAccel {
    /// Builds the BVH with the default SAH options.
    pub fn new(primitives: Primitives) -> Self {
        Self::with_options(primitives, &BuildOptions::default())
    }

    pub fn with_options(primitives: Primitives, options: &BuildOptions) -> Self {
        let bvh = build_from(primitives.shapes.iter().map(Shape::bounds), options);
        BvhAccel { bvh, primitives }
    }

    /// The primitive id and shape at leaf slot `slot`.
    #[inline(always)]
    fn slot(&self, slot: u32) -> (u32, &Shape) {
        let id = self.bvh.order[slot as usize];
        (id, &self.primitives.shapes[id as usize])
    }

    /// Checks the tree against the primitives' boxes.
    pub fn validate(&self) -> Result<(), super::ValidationError> {
        self.bvh.validate(&primitive_bounds(&self.primitives))
    }
}

/// The box of every primitive, by id.
pub fn primitive_bounds(primitives: &Primitives) -> Vec<Aabb> {
    primitives.shapes.iter().map(Shape::bounds).collect()
}

impl Intersector for BvhAccel {
    fn primitives(&self) -> &Primitives {
        &self.primitives
    }

    fn nearest(&self, ray: &Ray) -> Option<PrimitiveHit> {
        let mut best = None;
        let test = self.primitives.triangle_test;
        self.bvh.closest_hit(ray, |slot, t_max| {
            let (id, shape) = self.slot(slot);
            let hit = shape.intersect_with(ray, t_max, test)?;
            best = Some((id, shape, hit));
            Some(hit.t)
        });
        best.map(|(id, &shape, hit)| PrimitiveHit { id, shape, hit })
    }

    fn occluded(&self, ray: &Ray) -> bool {
        let test = self.primitives.triangle_test;
        self.bvh.any_hit(ray, |slot| {
            let (_, shape) = self.slot(slot);
            shape.intersect_with(ray, ray.t_max, test).is_some()
        })
    }
}
