//! Light samples at a vertex in strata: sample `k` of the `n` an
//! environment map takes at a vertex ([`crate::direct::DirectLights`])
//! keeps its pair `u` from the sampler but moves its second coordinate
//! (the one the map's importance sampling draws its row from; the azimuth
//! under uniform sampling) into the `k`-th of `n` equal strata:
//!
//! ```text
//! u_k = ( u.x,  (k + u.y) / n )
//! ```
//!
//! This is stratified sampling with one sample a stratum (Cochran,
//! *Sampling Techniques*, 1977, chapter 5): the average over the `n`
//! samples is unbiased (each stratum has probability `1 / n` and `u_k` is
//! uniform in it), and its variance, `(1 / n)` times the strata's mean
//! variance within, is never more than that of `n` independent samples
//! (proportional allocation, Cochran's theorem 5.8; for independent
//! numbers: under ZSobol that is measured, not proved). The numbers drawn
//! are the same, so the sampler's own stratification across a pixel's
//! samples is kept.
//!
//! Why it pays on an environment map: its importance sampling draws the
//! row from `u.y` (the marginal). A sun of a few texels holds half of an
//! outdoor map's light or more, so its rows hold an interval of that
//! length of the marginal: `n` independent samples find it a binomial
//! number of times (at four samples and a half share, 0 to 4 times, a
//! variance of 1); in strata only the two strata that the interval's ends
//! cut can find it or not, so the count varies by a variance of at most
//! 1/2 (1/4 for an interval from 0). Measured in docs/11-render-plan.md.

use glam::Vec2;

use crate::math::float::ONE_BELOW_ONE;

/// Sample `k`'s pair (the module doc's `u_k`) of `n`, for `k < n` and
/// `u` in `[0, 1)^2`.
pub fn stratum_point(u: Vec2, k: usize, n: usize) -> Vec2 {
    // `(k + y) / n` rounds to 1 for `y` just below 1 in the last stratum
    // (`3 + 0.99999997` is 4 in `f32`); a sample's numbers stay below 1.
    Vec2::new(u.x, ((k as f32 + u.y) / n as f32).min(ONE_BELOW_ONE))
}

#[cfg(test)]
mod tests;
