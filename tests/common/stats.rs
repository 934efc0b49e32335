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

/// Mean and standard error of independent samples.
#[derive(Clone, Copy, Debug)]
pub struct MeanEstimate {
    pub mean: f64,
    /// Standard error of the mean, `s / sqrt(n)` with the unbiased `s`.
    pub se: f64,
    pub n: usize,
}

impl MeanEstimate {
    pub fn of(values: impl IntoIterator<Item = f64>) -> Self {
        // Welford's running mean and variance (Knuth, TAOCP vol. 2, 4.2.2).
        let (mut n, mut mean, mut m2) = (0usize, 0.0f64, 0.0f64);
        for x in values {
            n += 1;
            let d = x - mean;
            mean += d / n as f64;
            m2 += d * (x - mean);
        }
        let var = if n > 1 { m2 / (n - 1) as f64 } else { 0.0 };
        MeanEstimate {
            mean,
            se: (var / n.max(1) as f64).sqrt(),
            n,
        }
    }
}

/// Asserts that `expected` lies in the confidence interval
/// `mean +- z se` of level `1 - alpha`, widened by `abs_floor` (for
/// estimators whose variance is zero up to rounding).
pub fn assert_mean_matches(
    label: &str,
    estimate: MeanEstimate,
    expected: f64,
    alpha: f64,
    abs_floor: f64,
) {
    let z = z_two_sided(alpha);
    let half = z * estimate.se + abs_floor;
    eprintln!(
        "{label}: {:.6} (se {:.2e}) vs {expected:.6}: {:+.2} se",
        estimate.mean,
        estimate.se,
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
/// `|a - b| <= z sqrt(se_a^2 + se_b^2)` at significance `alpha`.
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
    let se = (a.se * a.se + b.se * b.se).sqrt();
    eprintln!(
        "{label}: {:.6} vs {:.6}: {:+.2} se",
        a.mean,
        b.mean,
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
