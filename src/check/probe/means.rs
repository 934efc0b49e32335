//! The z-test the estimator probes share ([`direct`](super::direct),
//! [`bounces`](super::bounces)): a function called [`CALLS`] times, the
//! driver answering the mean and the sample variance of its values per
//! channel (`MEAN(C) VAR(C)`), each mean held to its expected value within
//! `z` standard errors, `z` the normal quantile that puts all the
//! comparisons of a probe together at [`ALPHA`] (Bonferroni).

use glam::DVec3;

use super::driver::Transcript;
use super::verdict::Verdict;
use crate::check::stats::normal_upper_quantile;

/// The calls behind each mean.
pub const CALLS: usize = 20_000;
/// The level of a probe's z-tests, over all of them.
const ALPHA: f64 = 1e-6;

/// The mean and the sample variance of the calls, per place probed.
pub type Moments = Vec<(DVec3, DVec3)>;

/// The `MEAN(C) VAR(C)` answer of command `at`, or the verdict where the
/// driver stopped.
pub fn read(t: &Transcript, at: usize) -> Result<(DVec3, DVec3), Verdict> {
    let v = t
        .exactly(at, 6)
        .map_err(|stop| Verdict::stopped(&stop, t.command(at)))?;
    Ok((DVec3::new(v[0], v[1], v[2]), DVec3::new(v[3], v[4], v[5])))
}

/// Whether every call returned `value` (the starter's stubs do).
pub fn always(moments: &Moments, value: DVec3) -> bool {
    moments
        .iter()
        .all(|(m, v)| *m == value && *v == DVec3::ZERO)
}

/// The critical value of each channel's test among `places` means.
pub fn z_critical(places: usize) -> f64 {
    normal_upper_quantile(ALPHA / (2.0 * 3.0 * places as f64))
}

/// The largest `|z|` of a mean's channels against `want`.
pub fn score((mean, var): &(DVec3, DVec3), want: DVec3) -> f64 {
    (0..3)
        .map(|c| {
            let se = (var[c] / CALLS as f64).max(0.0).sqrt();
            let off = (mean[c] - want[c]).abs();
            if se > 0.0 {
                off / se
            } else if off <= 1e-9 * want[c].abs().max(1e-12) {
                0.0
            } else {
                f64::INFINITY
            }
        })
        .fold(0.0, f64::max)
}

/// Whether every mean passes its z-test against `values`.
pub fn fits(moments: &Moments, values: &[DVec3]) -> bool {
    let z = z_critical(moments.len());
    moments.iter().zip(values).all(|(m, v)| score(m, *v) <= z)
}

/// The largest `|z|` of all the means against `values`.
pub fn largest(moments: &Moments, values: &[DVec3]) -> f64 {
    moments
        .iter()
        .zip(values)
        .map(|(m, v)| score(m, *v))
        .fold(0.0, f64::max)
}

/// The place whose mean is farthest from its value, in standard errors.
pub fn worst(moments: &Moments, values: &[DVec3]) -> usize {
    (0..moments.len())
        .max_by(|a, b| score(&moments[*a], values[*a]).total_cmp(&score(&moments[*b], values[*b])))
        .unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_mean_off_by_its_noise_fits_and_one_off_by_a_factor_does_not() {
        let var = DVec3::splat(1.0);
        let right = vec![DVec3::splat(2.0); 4];
        let se = (1.0 / CALLS as f64).sqrt();
        let near: Moments = vec![(DVec3::splat(2.0 + 3.0 * se), var); 4];
        assert!(fits(&near, &right));
        let mut off: Moments = vec![(DVec3::splat(2.0 * 1.05), var); 4];
        assert!(!fits(&off, &right));
        off[2].0 = DVec3::splat(2.0 * 1.2);
        assert_eq!(worst(&off, &right), 2);
        assert!(largest(&off, &right) > 0.3 / se);
    }

    #[test]
    fn an_exact_answer_must_match_exactly() {
        let exact: Moments = vec![(DVec3::ZERO, DVec3::ZERO)];
        assert!(fits(&exact, &[DVec3::ZERO]));
        assert!(!fits(&exact, &[DVec3::splat(1e-6)]));
        assert!(always(&exact, DVec3::ZERO));
    }
}
