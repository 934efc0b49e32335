//! Two triangle packs in one 8-lane AVX register: the watertight test of
//! [`TrianglePack::intersect`] on eight triangles at once, where the
//! processor has AVX. A leaf holds 2.4 packs on average, so testing them
//! two at a time takes most leaves through one or two passes instead of
//! two or three.
//!
//! Each pack's corners are loaded into one half of a 256-bit register
//! (pack `a` in lanes 0-3, pack `b` in lanes 4-7); every lane then runs
//! the same `f32` operations in the same order as the 4-lane test, so
//! each lane's result is that test's to the bit (IEEE arithmetic does not
//! depend on the lane width), and a zero edge function is recomputed in
//! `f64` by the same code.
//!
//! The nearest of the eight hits is the one the two packs tested one
//! after the other would give: there, `b` is tested with `t_max` lowered
//! to `a`'s hit and replaces it when `t_b <= t_a`, so on a tie the lane
//! in `b` wins; within a pack, the lowest lane among equal `t` wins.
//! `tests/wide_bvh.rs` compares the two on random and grazing rays and
//! on a tie across packs.

use std::arch::x86_64::*;

use glam::Vec4;

use super::leaf::{recompute_zeros, RayShear, TrianglePack};
use super::WIDTH;
use crate::intersect::triangle::TriangleHit;
use crate::math::float::gamma;

/// The nearest lane (0-3 in `a`, 4-7 in `b`) hit within `[t_min, t_max]`,
/// and its hit; `None` if no lane is hit.
///
/// # Safety
/// The processor must support AVX.
#[target_feature(enable = "avx")]
#[inline]
pub unsafe fn intersect_pair(
    a: &TrianglePack,
    b: &TrianglePack,
    ray: &RayShear,
    t_max: f32,
) -> Option<(usize, TriangleHit)> {
    let [kx, ky, kz] = ray.k;
    let splat = |v: Vec4| _mm256_set1_ps(v.x);
    let [ox, oy, oz] = ray.origin.map(splat);
    let [sx, sy, sz] = ray.shear.map(splat);
    let corner = |j: usize, axis: usize| {
        let low = _mm256_castps128_ps256(__m128::from(a.corners[j][axis]));
        _mm256_insertf128_ps::<1>(low, __m128::from(b.corners[j][axis]))
    };
    // Translate to the ray origin, permute, shear (z is scaled later).
    let sheared = |j: usize| {
        let z = _mm256_sub_ps(corner(j, kz), oz);
        let x = _mm256_add_ps(_mm256_sub_ps(corner(j, kx), ox), _mm256_mul_ps(sx, z));
        let y = _mm256_add_ps(_mm256_sub_ps(corner(j, ky), oy), _mm256_mul_ps(sy, z));
        (x, y, z)
    };
    let (x0, y0, z0) = sheared(0);
    let (x1, y1, z1) = sheared(1);
    let (x2, y2, z2) = sheared(2);
    let edge = |a, b, c, d| _mm256_sub_ps(_mm256_mul_ps(a, b), _mm256_mul_ps(c, d));
    let mut e0 = edge(x1, y2, y1, x2);
    let mut e1 = edge(x2, y0, y2, x0);
    let mut e2 = edge(x0, y1, y0, x1);
    let zero = _mm256_setzero_ps();
    let is_zero = |e| _mm256_cmp_ps::<_CMP_EQ_OQ>(e, zero);
    let zeros = _mm256_or_ps(_mm256_or_ps(is_zero(e0), is_zero(e1)), is_zero(e2));
    if _mm256_movemask_ps(zeros) != 0 {
        e0 = recompute_halves(e0, [x1, y2, y1, x2]);
        e1 = recompute_halves(e1, [x2, y0, y2, x0]);
        e2 = recompute_halves(e2, [x0, y1, y0, x1]);
    }
    let below = |e| _mm256_cmp_ps::<_CMP_LT_OQ>(e, zero);
    let above = |e| _mm256_cmp_ps::<_CMP_GT_OQ>(e, zero);
    let negative = _mm256_or_ps(_mm256_or_ps(below(e0), below(e1)), below(e2));
    let positive = _mm256_or_ps(_mm256_or_ps(above(e0), above(e1)), above(e2));
    let det = _mm256_add_ps(_mm256_add_ps(e0, e1), e2);
    let finite = _mm256_cmp_ps::<_CMP_LT_OQ>(abs(det), _mm256_set1_ps(f32::INFINITY));
    let nonzero = _mm256_cmp_ps::<_CMP_NEQ_UQ>(det, zero);
    let mut hit = _mm256_andnot_ps(
        _mm256_and_ps(negative, positive),
        _mm256_and_ps(nonzero, finite),
    );
    if _mm256_movemask_ps(hit) == 0 {
        return None;
    }
    // Scaled distance; interval test.
    let (z0, z1, z2) = (
        _mm256_mul_ps(z0, sz),
        _mm256_mul_ps(z1, sz),
        _mm256_mul_ps(z2, sz),
    );
    let t_scaled = _mm256_add_ps(
        _mm256_add_ps(_mm256_mul_ps(e0, z0), _mm256_mul_ps(e1, z1)),
        _mm256_mul_ps(e2, z2),
    );
    let inv_det = _mm256_div_ps(_mm256_set1_ps(1.0), det);
    let t = _mm256_mul_ps(t_scaled, inv_det);
    let within = _mm256_and_ps(
        _mm256_cmp_ps::<_CMP_GE_OQ>(t, _mm256_set1_ps(ray.t_min)),
        _mm256_cmp_ps::<_CMP_LE_OQ>(t, _mm256_set1_ps(t_max)),
    );
    hit = _mm256_and_ps(hit, within);
    if _mm256_movemask_ps(hit) == 0 {
        return None;
    }
    let error = distance_error(
        [x0, x1, x2],
        [y0, y1, y2],
        [z0, z1, z2],
        [e0, e1, e2],
        inv_det,
    );
    hit = _mm256_and_ps(hit, _mm256_cmp_ps::<_CMP_GT_OQ>(t, error));
    let lane = nearest_lane(hit, t)?;
    let lanes = |v: __m256| {
        let mut out = [0.0f32; 2 * WIDTH];
        _mm256_storeu_ps(out.as_mut_ptr(), v);
        out[lane]
    };
    let (t, e1, e2, inv_det) = (lanes(t), lanes(e1), lanes(e2), lanes(inv_det));
    let u = (e1 * inv_det).clamp(0.0, 1.0);
    let v = (e2 * inv_det).clamp(0.0, 1.0 - u);
    Some((lane, TriangleHit { t, u, v }))
}

/// `|v|` lane-wise: the sign bit cleared.
#[target_feature(enable = "avx")]
#[inline]
unsafe fn abs(v: __m256) -> __m256 {
    _mm256_andnot_ps(_mm256_set1_ps(-0.0), v)
}

/// [`super::leaf`]'s bound on the rounding error of `t`, on eight lanes,
/// in the same order of operations.
#[target_feature(enable = "avx")]
#[inline]
unsafe fn distance_error(
    x: [__m256; 3],
    y: [__m256; 3],
    z: [__m256; 3],
    e: [__m256; 3],
    inv_det: __m256,
) -> __m256 {
    let max_abs = |v: [__m256; 3]| _mm256_max_ps(_mm256_max_ps(abs(v[0]), abs(v[1])), abs(v[2]));
    let (max_x, max_y, max_z, max_e) = (max_abs(x), max_abs(y), max_abs(z), max_abs(e));
    let times = |c: f32, v| _mm256_mul_ps(_mm256_set1_ps(c), v);
    let mul = |a, b| _mm256_mul_ps(a, b);
    let add = |a, b| _mm256_add_ps(a, b);
    let delta_z = times(gamma(3), max_z);
    let delta_x = times(gamma(5), add(max_x, max_z));
    let delta_y = times(gamma(5), add(max_y, max_z));
    let delta_e = times(
        2.0,
        add(
            add(mul(times(gamma(2), max_x), max_y), mul(delta_y, max_x)),
            mul(delta_x, max_y),
        ),
    );
    let sum = add(
        add(mul(times(gamma(3), max_e), max_z), mul(delta_e, max_z)),
        mul(delta_z, max_e),
    );
    mul(times(3.0, sum), abs(inv_det))
}

/// The lane of smallest `t` among those set in `hit`; on a tie, the
/// lowest such lane of pack `b` if it has one, else of pack `a`.
#[target_feature(enable = "avx")]
#[inline]
unsafe fn nearest_lane(hit: __m256, t: __m256) -> Option<usize> {
    let mask = _mm256_movemask_ps(hit) as u32;
    if mask == 0 {
        return None;
    }
    if mask.is_power_of_two() {
        return Some(mask.trailing_zeros() as usize);
    }
    let mut t_lanes = [0.0f32; 2 * WIDTH];
    _mm256_storeu_ps(t_lanes.as_mut_ptr(), t);
    let nearest = (0..2 * WIDTH)
        .filter(|&i| mask >> i & 1 != 0)
        .map(|i| t_lanes[i])
        .fold(f32::INFINITY, f32::min);
    let at_nearest = (0..2 * WIDTH)
        .filter(|&i| mask >> i & 1 != 0 && t_lanes[i] == nearest)
        .fold(0u32, |bits, i| bits | 1 << i);
    let in_b = at_nearest >> WIDTH;
    Some(if in_b != 0 {
        WIDTH + in_b.trailing_zeros() as usize
    } else {
        at_nearest.trailing_zeros() as usize
    })
}

/// [`recompute_zeros`] on each half.
#[cold]
#[target_feature(enable = "avx")]
unsafe fn recompute_halves(e: __m256, operands: [__m256; 4]) -> __m256 {
    let half = |v: __m256, h: usize| -> Vec4 {
        let mut out = [0.0f32; 2 * WIDTH];
        _mm256_storeu_ps(out.as_mut_ptr(), v);
        Vec4::from_slice(&out[h * WIDTH..])
    };
    let [low, high] =
        [0, 1].map(|h| __m128::from(recompute_zeros(half(e, h), operands.map(|v| half(v, h)))));
    _mm256_insertf128_ps::<1>(_mm256_castps128_ps256(low), high)
}
