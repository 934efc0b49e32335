use super::*;
use crate::math::rng;
use rand::Rng;
use statrs::distribution::{ChiSquared, ContinuousCDF};

fn pairs(count: usize, seed: u64) -> Vec<Vec2> {
    let mut r = rng::sampler(seed, 0);
    (0..count)
        .map(|_| Vec2::new(r.gen::<f32>(), r.gen::<f32>()))
        .collect()
}

// Every point lies in `[0, 1)^2`, keeps its `x`, and point `k` lies in the
// `k`-th stratum of rows (to rounding on its edges), for any pair, the
// largest below 1 included. So for any height `a` the points below it
// number `floor(a n)` or `ceil(a n)`: of an interval's count, only the
// strata its two ends cut vary. Fails with the stratum made `(k + y) n`, `k` dropped,
// or the clamp below 1 removed.
#[test]
fn each_point_lies_in_its_own_stratum() {
    let mut all = pairs(2000, 1);
    all.extend([Vec2::ZERO, Vec2::splat(ONE_BELOW_ONE)]);
    for n in 1..=16 {
        for &u in &all {
            for k in 0..n {
                let p = stratum_point(u, k, n);
                assert!((0.0..1.0).contains(&p.y), "{p}");
                assert_eq!(p.x, u.x);
                // To rounding on the edges: `(1 + 0.99999994) / 3` is 2/3 in `f32`.
                let row = f64::from(p.y) * n as f64;
                assert!(
                    k as f64 - 1e-6 <= row && row <= (k + 1) as f64 + 1e-6,
                    "n {n}, k {k}, pair {u}: {p}"
                );
            }
            for a in [0.0917f32, 0.3141, 0.5563, 0.8629] {
                let below = (0..n).filter(|&k| stratum_point(u, k, n).y < a).count();
                let share = a * n as f32;
                assert!(
                    below == share.floor() as usize || below == share.ceil() as usize,
                    "n {n}, a {a}: {below}"
                );
            }
        }
    }
}

// The last stratum's top: `(3 + 0.99999994) / 4` rounds to 1, and the
// point is the largest `f32` below 1, not 1 nor a few units lower (fails
// with the clamp's `EPSILON / 2` made `EPSILON * 2` or `EPSILON % 2`).
#[test]
fn the_last_stratum_ends_just_below_one() {
    let top = 0.999_999_94f32;
    assert_eq!(stratum_point(Vec2::new(0.5, top), 3, 4).y, top);
}

// Each point is uniform in its stratum for a uniform pair (what keeps the
// average unbiased): point `k` of `n` over 64,000 pairs, in 64 equal
// slices of its stratum, by a chi-square test at the 1e-6 level (63
// degrees of freedom). Fails with `y` not scaled by `1 / n`, or squared.
#[test]
fn each_point_is_uniform_in_its_stratum() {
    let all = pairs(64_000, 2);
    let critical = ChiSquared::new(63.0).unwrap().inverse_cdf(1.0 - 1e-6);
    for (n, k) in [(4, 0), (4, 3), (5, 2), (11, 7)] {
        let mut cells = [0u32; 64];
        for &u in &all {
            let slice = ((stratum_point(u, k, n).y * n as f32 - k as f32) * 64.0) as usize;
            cells[slice.min(63)] += 1;
        }
        let expected = all.len() as f64 / 64.0;
        let chi2: f64 = cells
            .iter()
            .map(|&c| (f64::from(c) - expected).powi(2) / expected)
            .sum();
        assert!(chi2 < critical, "n {n}, k {k}: chi-square {chi2}");
    }
}
