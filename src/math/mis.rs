//! Multiple importance sampling (Veach and Guibas 1995; Veach 1997,
//! chapter 9): several strategies sample the same integral, and each
//! sample is weighted so that the weights of all strategies sum to 1 at
//! every point, which keeps the combined estimator unbiased.
//!
//! The power heuristic with exponent 2, for strategy `f` taking `n_f`
//! samples with density `p_f` against strategy `g` with `n_g`, `p_g`:
//!
//! ```text
//! w_f = (n_f p_f)^2 / ((n_f p_f)^2 + (n_g p_g)^2)
//! ```
//!
//! Each sample then contributes `w_f f(x) / (n_f p_f(x))`.

/// The power heuristic weight of strategy `f` against `g` (exponent 2).
/// 1 when `g` cannot sample the point, 0 when `f` cannot.
pub fn power_heuristic(n_f: f32, p_f: f32, n_g: f32, p_g: f32) -> f32 {
    let f = n_f * p_f;
    let g = n_g * p_g;
    if f.is_nan() || f <= 0.0 {
        return 0.0;
    }
    if g.is_nan() || g <= 0.0 {
        return 1.0;
    }
    if f.is_infinite() {
        return if g.is_infinite() { 0.5 } else { 1.0 };
    }
    // Divide through by the larger term so the squares cannot overflow.
    let (f, g) = (f / f.max(g), g / f.max(g));
    f * f / (f * f + g * g)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weights_of_two_strategies_sum_to_one() {
        for (pf, pg) in [(0.3f32, 2.0f32), (1e-30, 1e30), (1e30, 1e30), (5.0, 5.0)] {
            for (nf, ng) in [(1.0, 1.0), (4.0, 1.0)] {
                let sum = power_heuristic(nf, pf, ng, pg) + power_heuristic(ng, pg, nf, pf);
                assert!((sum - 1.0).abs() < 1e-6, "{pf} {pg} {nf} {ng}: {sum}");
            }
        }
        assert_eq!(power_heuristic(1.0, 2.0, 1.0, 0.0), 1.0);
        assert_eq!(power_heuristic(1.0, 0.0, 1.0, 2.0), 0.0);
        assert_eq!(power_heuristic(1.0, 1.0, 1.0, 1.0), 0.5);
    }
}
