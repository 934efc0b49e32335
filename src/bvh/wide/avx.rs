//! The node's slab test in one 8-lane AVX register, where the processor
//! has AVX (detected at run time): the eight children's planes along an
//! axis are 32 contiguous bytes, one `__m256`, so a node takes half the
//! instructions of the two 4-lane groups of [`WideNode::hit`].
//!
//! The arithmetic is the same operations in the same order on the same
//! numbers (IEEE `sub`, `mul`, `min`, `max` give the same bits in any lane
//! width, and `min`/`max` take their operands in the same order, so a NaN
//! resolves alike), hence the same hits; a unit test compares the two.
//!
//! For the test to pay, the traversal around it must be compiled for AVX
//! too, so that it inlines: [`super::accel`] runs the whole closest-hit
//! and any-hit traversal inside a function with `#[target_feature(enable =
//! "avx")]`, chosen once per accelerator by `is_x86_feature_detected!`.
//! Elsewhere (no AVX, or not x86-64) the SSE/NEON path runs.

use std::arch::x86_64::*;

use super::avx_packs::intersect_pair;
use super::leaf::{RayShear, TrianglePack};
use super::node::{NodeTest, RayBoxes, WideNode};
use super::{ARITY, WIDTH};
use crate::intersect::triangle::TriangleHit;

/// The node test with AVX. Only to be used where AVX is detected.
pub struct Avx;

impl NodeTest for Avx {
    #[inline(always)]
    fn hit(node: &WideNode, ray: &RayBoxes, t_max: f32) -> (u32, [f32; ARITY]) {
        // SAFETY: `Avx` is used only inside functions that run after
        // `is_x86_feature_detected!("avx")` returned true
        // (`WideBvhAccel::avx`).
        unsafe { hit(node, ray, t_max) }
    }

    /// Two packs at a time ([`intersect_pair`]), the last one of an odd
    /// count alone.
    #[inline(always)]
    fn packs_hit(
        packs: &[TrianglePack],
        ray: &RayShear,
        mut t_max: f32,
    ) -> Option<(usize, usize, TriangleHit)> {
        let mut best = None;
        let mut pairs = packs.chunks_exact(2);
        for (i, pair) in pairs.by_ref().enumerate() {
            // SAFETY: as above.
            if let Some((lane, hit)) = unsafe { intersect_pair(&pair[0], &pair[1], ray, t_max) } {
                t_max = hit.t;
                best = Some((2 * i + lane / WIDTH, lane % WIDTH, hit));
            }
        }
        if let [last] = pairs.remainder() {
            if let Some((lane, hit)) = last.intersect(ray, t_max) {
                best = Some((packs.len() - 1, lane, hit));
            }
        }
        best
    }
}

/// [`WideNode::hit`] on all eight lanes at once.
///
/// # Safety
/// The processor must support AVX.
#[target_feature(enable = "avx")]
#[inline]
unsafe fn hit(node: &WideNode, ray: &RayBoxes, t_max: f32) -> (u32, [f32; ARITY]) {
    // A plane's two groups of four lanes: 32 contiguous bytes, aligned
    // (the node is 64-byte aligned and each plane 32 bytes long).
    let plane = |p: usize| _mm256_load_ps(node.planes[p].as_ptr() as *const f32);
    let axis = |a: usize| {
        let o = _mm256_set1_ps(ray.origin[a].x);
        let inv = _mm256_set1_ps(ray.inv_dir[a].x);
        let inv_far = _mm256_set1_ps(ray.inv_dir_far[a].x);
        let mut near = _mm256_mul_ps(_mm256_sub_ps(plane(ray.near[a]), o), inv);
        let mut far = _mm256_mul_ps(_mm256_sub_ps(plane(ray.far[a]), o), inv_far);
        if ray.has_zero_direction {
            let nan = _mm256_cmp_ps::<_CMP_UNORD_Q>(near, near);
            near = _mm256_blendv_ps(near, _mm256_set1_ps(f32::NEG_INFINITY), nan);
            let nan = _mm256_cmp_ps::<_CMP_UNORD_Q>(far, far);
            far = _mm256_blendv_ps(far, _mm256_set1_ps(f32::INFINITY), nan);
        }
        (near, far)
    };
    let (near_x, far_x) = axis(0);
    let (near_y, far_y) = axis(1);
    let (near_z, far_z) = axis(2);
    let enter = _mm256_max_ps(
        _mm256_max_ps(near_x, near_y),
        _mm256_max_ps(near_z, _mm256_set1_ps(ray.t_min)),
    );
    let exit = _mm256_min_ps(
        _mm256_min_ps(far_x, far_y),
        _mm256_min_ps(far_z, _mm256_set1_ps(t_max)),
    );
    let mask = _mm256_movemask_ps(_mm256_cmp_ps::<_CMP_LE_OQ>(enter, exit)) as u32;
    let mut entries = [0.0f32; ARITY];
    _mm256_storeu_ps(entries.as_mut_ptr(), enter);
    (mask, entries)
}

#[cfg(test)]
mod tests {
    use glam::Vec3;
    use rand::Rng;

    use super::*;
    use crate::bvh::wide::node::Sse;
    use crate::bvh::wide::WideLink;
    use crate::intersect::Aabb;
    use crate::math::rng::sampler;

    /// Random boxes and rays, some with zero (±0) or tiny direction
    /// components, origins on planes, `t_min` above 0: both tests give the
    /// same mask and distances.
    #[test]
    fn avx_and_sse_agree_bit_for_bit() {
        if !is_x86_feature_detected!("avx") {
            return;
        }
        let mut rng = sampler(7, 1);
        let coord = |rng: &mut crate::math::rng::Sampler| (rng.gen::<f32>() * 8.0).floor() - 4.0;
        for _ in 0..2000 {
            let children: Vec<(Aabb, WideLink)> = (0..1 + rng.gen::<u32>() as usize % 8)
                .map(|_| {
                    let a = Vec3::new(coord(&mut rng), coord(&mut rng), coord(&mut rng));
                    let b = Vec3::new(coord(&mut rng), coord(&mut rng), coord(&mut rng));
                    (Aabb::from_points([a, b]), WideLink::default())
                })
                .collect();
            let node = WideNode::new(&children);
            let origin = Vec3::new(coord(&mut rng), coord(&mut rng), coord(&mut rng));
            let mut dir = Vec3::new(
                rng.gen::<f32>() - 0.5,
                rng.gen::<f32>() - 0.5,
                rng.gen::<f32>() - 0.5,
            );
            // Zero components of either sign, and ones so small that the
            // reciprocal is finite but the far factor makes it infinite.
            let axis = rng.gen::<u32>() as usize % 3;
            match rng.gen::<u32>() % 6 {
                0 => dir[axis] = 0.0,
                1 => dir[axis] = -0.0,
                2 => dir[axis] = 2.938_737e-39 * dir[axis].signum(),
                _ => {}
            }
            let t_min = if rng.gen::<bool>() {
                0.0
            } else {
                rng.gen::<f32>() * 2.0
            };
            let ray = RayBoxes::new(origin, dir, t_min);
            let t_max = if rng.gen::<u32>() % 2 == 0 {
                f32::INFINITY
            } else {
                3.0
            };
            let (m_sse, e_sse) = Sse::hit(&node, &ray, t_max);
            let (m_avx, e_avx) = Avx::hit(&node, &ray, t_max);
            assert_eq!(m_sse, m_avx, "{origin} {dir}");
            for i in 0..ARITY {
                if m_sse >> i & 1 != 0 {
                    assert_eq!(e_sse[i].to_bits(), e_avx[i].to_bits(), "{origin} {dir} {i}");
                }
            }
        }
    }
}
