//! The BVH as an [`Intersector`]: the tree plus the shapes stored in leaf
//! order, so a leaf's shapes are contiguous in memory.

use super::build::{build_from, BuildOptions};
use super::Bvh;
use crate::intersect::{Aabb, Hit, Intersector, Primitives, Ray, Shape};

/// A BVH over a scene's primitives.
pub struct BvhAccel {
    pub bvh: Bvh,
    /// `shapes[slot]` is primitive `bvh.order[slot]`.
    shapes: Vec<Shape>,
    pub primitives: Primitives,
}

impl BvhAccel {
    /// Builds the BVH with the default SAH options.
    pub fn new(primitives: Primitives) -> Self {
        Self::with_options(primitives, &BuildOptions::default())
    }

    pub fn with_options(primitives: Primitives, options: &BuildOptions) -> Self {
        let bvh = build_from(primitives.shapes.iter().map(Shape::bounds), options);
        let shapes = bvh
            .order
            .iter()
            .map(|&id| primitives.shapes[id as usize])
            .collect();
        BvhAccel {
            bvh,
            shapes,
            primitives,
        }
    }

    /// Capacity of the leaf-ordered shapes, for [`BvhAccel::heap_bytes`].
    pub(crate) fn shapes_capacity(&self) -> usize {
        self.shapes.capacity()
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
    fn intersect(&self, ray: &Ray) -> Option<Hit> {
        let mut best = None;
        let test = self.primitives.triangle_test;
        self.bvh.closest_hit(ray, |slot, t_max| {
            let hit = self.shapes[slot as usize].intersect_with(ray, t_max, test)?;
            best = Some((slot, hit));
            Some(hit.t)
        });
        best.map(|(slot, hit)| {
            let shape = &self.shapes[slot as usize];
            self.primitives
                .finish_hit(self.bvh.order[slot as usize], shape, ray, hit)
        })
    }

    fn occluded(&self, ray: &Ray) -> bool {
        let test = self.primitives.triangle_test;
        self.bvh.any_hit(ray, |slot| {
            self.shapes[slot as usize]
                .intersect_with(ray, ray.t_max, test)
                .is_some()
        })
    }
}
