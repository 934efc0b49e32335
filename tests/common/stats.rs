//! Statistics for the statistical tests: Pearson's chi-square goodness of
//! fit with pooled cells, normal quantiles, means with standard errors and
//! z-tests, all in `f64`.
//!
//! Every test fixes its seeds, so it is deterministic; the significance
//! levels say how often a *correct* implementation would fail for a random
//! seed. The suite's rule: less than once in 10^4 runs per test, so
//! [`ALPHA`] per test, divided among a test's comparisons (Bonferroni).

use statrs::distribution::{ChiSquared, ContinuousCDF, Normal};

/// Significance level of one test (all its comparisons together).
pub const ALPHA: f64 = 1e-4;

/// The two-sided standard normal quantile for significance `alpha`:
/// `z` with `P(|Z| > z) = alpha` (3.89 for 1e-4).
pub fn z_two_sided(alpha: f64) -> f64 {
    Normal::standard().inverse_cdf(1.0 - alpha / 2.0)
}

/// Mean and standard error of independent samples, with how well the
/// sample knows its own variance.
#[derive(Clone, Copy, Debug)]
pub struct MeanEstimate {
    pub mean: f64,
    /// Standard error of the mean, `s / sqrt(n)` with the unbiased `s`.
    pub se: f64,
    pub n: usize,
    /// The relative standard error of the sample variance `s^2`:
    /// `Var(s^2) = (mu_4 - sigma^4 (n - 3) / (n - 1)) / n` (Cramér,
    /// *Mathematical Methods of Statistics*, 1946, 27.4), estimated with
    /// the sample's fourth central moment. Small for light tails (about
    /// `sqrt(2 / n)` for normal samples); large when a few rare, large
    /// samples (a caustic path, a small light's `1 / pdf`, roulette's
    /// survivors) carry the variance, and then `se` is uncertain too.
    pub variance_error: f64,
}

/// The largest [`MeanEstimate::variance_error`] a z-test accepts: past
/// it the sample's variance is uncertain by more than a quarter, and the
/// false-failure rate the test states would hold only roughly even with
/// the held `se`. Such a test must take more samples (finite variance) or
/// bound its estimator (infinite variance); docs/17-mutation-testing.md
/// tells the cases found and how each was fixed.
pub const HEAVY_TAIL: f64 = 0.25;

impl MeanEstimate {
    pub fn of(values: impl IntoIterator<Item = f64>) -> Self {
        let values: Vec<f64> = values.into_iter().collect();
        let n = values.len();
        // Two passes in f64: the mean, then the central moments.
        let mean = values.iter().sum::<f64>() / n.max(1) as f64;
        let (mut m2, mut m4) = (0.0f64, 0.0f64);
        for x in &values {
            let d2 = (x - mean) * (x - mean);
            m2 += d2;
            m4 += d2 * d2;
        }
        let var = if n > 1 { m2 / (n - 1) as f64 } else { 0.0 };
        let nf = n.max(4) as f64;
        let variance_error = if var > 0.0 {
            let kurtosis = (m4 / nf) / (var * var);
            ((kurtosis - (nf - 3.0) / (nf - 1.0)).max(0.0) / nf).sqrt()
        } else {
            0.0
        };
        MeanEstimate {
            mean,
            se: (var / n.max(1) as f64).sqrt(),
            n,
            variance_error,
        }
    }

    /// The standard error used by the z-tests: `se` at the upper end of
    /// its own uncertainty (`s^2` three of its standard errors high), so
    /// that a sample whose variance came out low by chance, as a
    /// heavy-tailed one's often does, does not narrow the interval.
    ///
    /// Panics, naming `label`, where the tail is too heavy for the sample
    /// to know its variance ([`HEAVY_TAIL`]): no interval built on `se`
    /// would then keep its stated rate.
    pub fn held_se(&self, label: &str) -> f64 {
        assert!(
            self.variance_error <= HEAVY_TAIL,
            "{label}: heavy tail: the sample's variance is uncertain by {:.0} % (n {}), \
             more than {:.0} %: take more samples, or bound the estimator if its variance \
             is infinite",
            100.0 * self.variance_error,
            self.n,
            100.0 * HEAVY_TAIL
        );
        self.se * (1.0 + 3.0 * self.variance_error).sqrt()
    }
}

/// [`MeanEstimate::held_se`], except where the interval is the floor's
/// (`z se <= abs_floor`: an estimator exact up to rounding, whose
/// rounding noise has any tail).
pub fn held_above_floor(label: &str, estimate: MeanEstimate, z: f64, abs_floor: f64) -> f64 {
    if z * estimate.se <= abs_floor {
        estimate.se
    } else {
        estimate.held_se(label)
    }
}

/// Asserts that `expected` lies in the confidence interval
/// `mean +- z se` of level `1 - alpha` (`se` held against the sample's
/// tail: [`MeanEstimate::held_se`]), widened by `abs_floor` (for
/// estimators whose variance is zero up to rounding).
pub fn assert_mean_matches(
    label: &str,
    estimate: MeanEstimate,
    expected: f64,
    alpha: f64,
    abs_floor: f64,
) {
    let z = z_two_sided(alpha);
    let half = z * held_above_floor(label, estimate, z, abs_floor) + abs_floor;
    eprintln!(
        "{label}: {:.6} (se {:.2e}, variance known to {:.0} %) vs {expected:.6}: {:+.2} se",
        estimate.mean,
        estimate.se,
        100.0 * estimate.variance_error,
        (estimate.mean - expected) / estimate.se
    );
    assert!(
        (estimate.mean - expected).abs() <= half,
        "{label}: estimate {:.6} +- {:.6} (z {z:.2}, se {:.3e}, n {}) misses the closed form {expected:.6} \
         (off by {:.2} standard errors)",
        estimate.mean,
        half,
        estimate.se,
        estimate.n,
        (estimate.mean - expected) / estimate.se
    );
}

/// Two-sample z-test of equal means for independent estimates: asserts
/// `|a - b| <= z sqrt(se_a^2 + se_b^2)` at significance `alpha` (each
/// `se` held: [`MeanEstimate::held_se`]).
pub fn assert_means_agree(label: &str, a: MeanEstimate, b: MeanEstimate, alpha: f64) {
    assert_means_agree_within(label, a, b, alpha, 0.0);
}

/// [`assert_means_agree`] with the limit widened by `abs_floor` (for
/// estimators whose variance is zero up to rounding).
pub fn assert_means_agree_within(
    label: &str,
    a: MeanEstimate,
    b: MeanEstimate,
    alpha: f64,
    abs_floor: f64,
) {
    let z = z_two_sided(alpha);
    let (held_a, held_b) = (
        held_above_floor(label, a, z, abs_floor),
        held_above_floor(label, b, z, abs_floor),
    );
    let se = (held_a * held_a + held_b * held_b).sqrt();
    eprintln!(
        "{label}: {:.6} vs {:.6} (variances known to {:.0} % and {:.0} %): {:+.2} se",
        a.mean,
        b.mean,
        100.0 * a.variance_error,
        100.0 * b.variance_error,
        (a.mean - b.mean) / se
    );
    assert!(
        (a.mean - b.mean).abs() <= z * se + abs_floor,
        "{label}: {:.6} (se {:.2e}) and {:.6} (se {:.2e}) differ by {:.2} standard errors (limit {z:.2} and {abs_floor:.1e})",
        a.mean,
        a.se,
        b.mean,
        b.se,
        (a.mean - b.mean) / se
    );
}

/// Result of [`chi_square`].
#[derive(Clone, Copy, Debug)]
pub struct ChiSquare {
    pub statistic: f64,
    pub degrees_of_freedom: usize,
    pub p_value: f64,
}

/// Pearson's chi-square goodness of fit of `observed` counts against
/// `expected` counts (same total up to the sampler's correctness).
///
/// Cells are visited in order and pooled until their expected count
/// reaches 5 (the usual validity rule, Cochran 1954), and the last pool
/// is merged into the one before if it stays under 5. Degrees of freedom:
/// pooled cells - 1 (no parameter is fitted). Cells of zero expected
/// count join the current pool like any other (a sample there then shows
/// as an excess of its pool); callers check separately that no sample
/// falls where the density is known to vanish.
pub fn chi_square(observed: &[u64], expected: &[f64]) -> ChiSquare {
    assert_eq!(observed.len(), expected.len());
    let mut pools: Vec<(u64, f64)> = Vec::new();
    let mut current = (0u64, 0.0f64);
    for (&o, &e) in observed.iter().zip(expected) {
        current.0 += o;
        current.1 += e;
        if current.1 >= 5.0 {
            pools.push(current);
            current = (0, 0.0);
        }
    }
    if current.0 > 0 || current.1 > 0.0 {
        match pools.last_mut() {
            Some(last) => {
                last.0 += current.0;
                last.1 += current.1;
            }
            None => pools.push(current),
        }
    }
    let statistic: f64 = pools
        .iter()
        .map(|&(o, e)| {
            let d = o as f64 - e;
            d * d / e
        })
        .sum();
    let degrees_of_freedom = pools.len().saturating_sub(1).max(1);
    let p_value = ChiSquared::new(degrees_of_freedom as f64)
        .expect("positive degrees of freedom")
        .sf(statistic);
    ChiSquare {
        statistic,
        degrees_of_freedom,
        p_value,
    }
}
