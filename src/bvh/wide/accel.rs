//! The wide BVH as an [`Intersector`]: the binary SAH build
//! ([`crate::bvh::build`]), collapsed to eight children per node
//! ([`super::collapse`]), with its triangles in SIMD packs.
//!
//! Triangles go through the lane-wise watertight test; spheres (and every
//! triangle, if [`TriangleTest::MollerTrumbore`] is chosen) through the
//! scalar [`Shape::intersect_with`], so the hits are those of
//! [`BvhAccel`](crate::bvh::BvhAccel) and of the linear scan. The hit
//! record is finished by [`Primitives::finish_hit`], as they do.

#[cfg(target_arch = "x86_64")]
use super::avx::Avx;
use super::collapse::{collapse, MERGE};
use super::leaf::{RayShear, TrianglePack};
use super::node::{NodeTest, Sse};
use super::{WideBvh, WideLink};
use crate::bvh::build::{build_from, BuildOptions};
use crate::bvh::{Bvh, ValidationError};
use crate::intersect::{Intersector, PrimitiveHit, Primitives, Ray, Shape, ShapeHit, TriangleTest};

/// An eight-wide BVH over a scene's primitives.
pub struct WideBvhAccel {
    pub wide: WideBvh,
    pub primitives: Primitives,
}

/// The binary build's options for a wide BVH over `primitives`: the
/// defaults, except that with no spheres a node of at most
/// [`MERGE`] primitives becomes a leaf at once. The collapse would merge
/// its subtree into one leaf of the same packs, so building it would be
/// undone; skipping those levels takes the bench's build from 0.33 to
/// 0.23 s. Spheres keep the default: the collapse leaves them in their
/// own binary leaves, with tight boxes, and merges only around them.
pub fn binary_options(primitives: &Primitives) -> BuildOptions {
    if primitives.has_spheres() {
        return BuildOptions::default();
    }
    BuildOptions {
        max_leaf_size: MERGE,
        leaf_at_most: MERGE,
        ..BuildOptions::default()
    }
}

impl WideBvhAccel {
    /// Builds the binary BVH with [`binary_options`] and collapses it.
    pub fn new(primitives: Primitives) -> Self {
        let options = binary_options(&primitives);
        Self::with_options(primitives, &options)
    }

    pub fn with_options(primitives: Primitives, options: &BuildOptions) -> Self {
        let bvh = build_from(primitives.shapes.iter().map(Shape::bounds), options);
        Self::from_binary(&bvh, primitives)
    }

    /// Collapses a binary BVH built over `primitives` (by [`build_from`]).
    pub fn from_binary(bvh: &Bvh, primitives: Primitives) -> Self {
        WideBvhAccel {
            wide: collapse(bvh, &primitives.shapes),
            primitives,
        }
    }

    /// Checks the tree against the primitives.
    pub fn validate(&self) -> Result<(), ValidationError> {
        self.wide.validate(&self.primitives.shapes)
    }

    /// Lanes of `pack` that the SIMD test does not cover, by the scalar
    /// test: spheres, and triangles too when `simd` is false.
    #[inline(never)]
    fn scalar_lanes(
        &self,
        pack: &TrianglePack,
        ray: &Ray,
        mut t_max: f32,
        simd: bool,
    ) -> Option<(usize, ShapeHit)> {
        let mut best = None;
        for lane in 0..pack.ids.len() {
            let Some((id, sphere)) = pack.lane(lane) else {
                continue;
            };
            if simd && !sphere {
                continue;
            }
            let shape = &self.primitives.shapes[id as usize];
            if let Some(hit) = shape.intersect_with(ray, t_max, self.primitives.triangle_test) {
                t_max = hit.t;
                best = Some((lane, hit));
            }
        }
        best
    }

    /// The nearest hit in a leaf within `[ray.t_min, t_max]`: its pack,
    /// lane and hit.
    #[inline(always)]
    fn leaf_hit<T: NodeTest>(
        &self,
        link: WideLink,
        ray: &Ray,
        shear: &RayShear,
        mut t_max: f32,
    ) -> Option<LaneHit> {
        let simd = self.primitives.triangle_test == TriangleTest::Watertight;
        if simd && !link.has_spheres() {
            let packs = link.packs();
            let first = packs.start;
            let (offset, lane, hit) = T::packs_hit(&self.wide.packs[packs], shear, t_max)?;
            return Some(LaneHit {
                index: first + offset,
                lane,
                hit: hit.into(),
            });
        }
        let mut best = None;
        for index in link.packs() {
            let pack = &self.wide.packs[index];
            if simd {
                if let Some((lane, hit)) = pack.intersect(shear, t_max) {
                    t_max = hit.t;
                    let hit = hit.into();
                    best = Some(LaneHit { index, lane, hit });
                }
            }
            if !simd || link.has_spheres() {
                if let Some((lane, hit)) = self.scalar_lanes(pack, ray, t_max, simd) {
                    t_max = hit.t;
                    best = Some(LaneHit { index, lane, hit });
                }
            }
        }
        best
    }
}

/// A hit in lane `lane` of pack `index`.
#[derive(Clone, Copy)]
struct LaneHit {
    index: usize,
    lane: usize,
    hit: ShapeHit,
}

impl WideBvhAccel {
    /// Whether this processor has AVX (the eight lanes of a node in one
    /// register, [`super::avx`]); asked once, the answer is cached by std.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    fn avx() -> bool {
        std::arch::is_x86_feature_detected!("avx")
    }

    /// The closest primitive, the nodes tested by `T`.
    #[inline(always)]
    fn closest<T: NodeTest>(&self, ray: &Ray) -> Option<PrimitiveHit> {
        let shear = RayShear::new(ray);
        let mut best = None;
        self.wide.closest_hit::<T>(ray, |link, t_max| {
            let found = self.leaf_hit::<T>(link, ray, &shear, t_max)?;
            if let Some((id, _)) = self.wide.packs[found.index].lane(found.lane) {
                self.primitives.prefetch_shading(id);
            }
            best = Some(found);
            Some(found.hit.t)
        });
        let LaneHit { index, lane, hit } = best?;
        // The triangle from the pack, just read, rather than from
        // `primitives.shapes`, which would be one more cache miss.
        let pack = &self.wide.packs[index];
        let (id, sphere) = pack.lane(lane)?;
        let shape = if sphere {
            self.primitives.shapes[id as usize]
        } else {
            Shape::Triangle(pack.triangle(lane))
        };
        Some(PrimitiveHit { id, shape, hit })
    }

    /// Whether anything blocks the ray, the nodes tested by `T`.
    #[inline(always)]
    fn any<T: NodeTest>(&self, ray: &Ray) -> bool {
        let shear = RayShear::new(ray);
        self.wide.any_hit::<T>(ray, |link| {
            self.leaf_hit::<T>(link, ray, &shear, ray.t_max).is_some()
        })
    }

    /// [`WideBvhAccel::closest`] compiled for AVX, so that the whole
    /// traversal, the node test included, inlines into one function.
    ///
    /// # Safety
    /// The processor must support AVX.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    unsafe fn closest_avx(&self, ray: &Ray) -> Option<PrimitiveHit> {
        self.closest::<Avx>(ray)
    }

    /// [`WideBvhAccel::any`] compiled for AVX.
    ///
    /// # Safety
    /// The processor must support AVX.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    unsafe fn any_avx(&self, ray: &Ray) -> bool {
        self.any::<Avx>(ray)
    }
}

impl Intersector for WideBvhAccel {
    fn primitives(&self) -> &Primitives {
        &self.primitives
    }

    fn nearest(&self, ray: &Ray) -> Option<PrimitiveHit> {
        #[cfg(target_arch = "x86_64")]
        if Self::avx() {
            // SAFETY: AVX was detected.
            return unsafe { self.closest_avx(ray) };
        }
        self.closest::<Sse>(ray)
    }

    fn occluded(&self, ray: &Ray) -> bool {
        #[cfg(target_arch = "x86_64")]
        if Self::avx() {
            // SAFETY: AVX was detected.
            return unsafe { self.any_avx(ray) };
        }
        self.any::<Sse>(ray)
    }
}
