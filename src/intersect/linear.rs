//! Part 1's intersector: test the ray against every primitive, keep the closest.
//! Cost O(N) per ray; the reference every acceleration structure is checked against.

use super::{Intersector, PrimitiveHit, Primitives, Ray};

/// Closest hit by testing every primitive.
pub struct LinearScan<'a> {
    pub primitives: &'a Primitives,
}

impl<'a> LinearScan<'a> {
    pub fn new(primitives: &'a Primitives) -> Self {
        LinearScan { primitives }
    }
}

impl Intersector for LinearScan<'_> {
    fn primitives(&self) -> &Primitives {
        self.primitives
    }

    fn nearest(&self, ray: &Ray) -> Option<PrimitiveHit> {
        let mut t_max = ray.t_max;
        let mut best = None;
        for (id, shape) in self.primitives.shapes.iter().enumerate() {
            if let Some(hit) = shape.intersect_with(ray, t_max, self.primitives.triangle_test) {
                t_max = hit.t;
                best = Some((id as u32, hit));
            }
        }
        best.map(|(id, hit)| PrimitiveHit {
            id,
            shape: self.primitives.shapes[id as usize],
            hit,
        })
    }

    fn occluded(&self, ray: &Ray) -> bool {
        self.primitives.shapes.iter().any(|s| {
            s.intersect_with(ray, ray.t_max, self.primitives.triangle_test)
                .is_some()
        })
    }
}
