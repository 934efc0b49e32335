//! The probe of `EnvironmentLight::init` (part 7): the tables it leaves
//! for `sample_L`, read from the light the driver built on [`envmap`]'s
//! map (`env_tables`).
//!
//! The starter already weighs each texel by its luminance times the
//! `sin theta` of its row's centre (a texel's solid angle shrinks toward
//! the poles); the student's steps are:
//!
//! 1. `pdf_envmap[w j + i] = P(i, j)`, the weights normalised to sum to 1;
//! 2. `marginal_y[j]`: the rows' distribution, `p(j) = sum_i P(i, j)`;
//! 3. `conds_y[w j + i]`: the columns' given the row, `P(i, j) / p(j)`.
//!
//! Either the distributions or their cumulative sums are right (the
//! handout leaves it to the sampler that reads them); each table is held
//! to one of the two throughout.

use super::driver::Driver;
use super::envmap::{self, probabilities, H, W};
use super::geometry::num;
use super::microfacet::near;
use super::verdict::{failure, Verdict};

/// The input every failure names.
const INPUT: &str = "init() of an EnvironmentLight on a 16 x 8 map (one bright texel)";

/// Probes `EnvironmentLight::init`.
pub fn init(driver: &Driver) -> Verdict {
    let t = match envmap::run(driver, "environment_init", vec!["env_tables".into()]) {
        Ok(t) => t,
        Err(v) => return v,
    };
    let v = match t.exactly(1, 2 * W * H + H) {
        Ok(v) => v,
        Err(stop) => return Verdict::stopped(&stop, t.command(1)),
    };
    let (pdf, rest) = v.split_at(W * H);
    let (marginal, conds) = rest.split_at(H);
    let p = probabilities();
    let sum: f64 = pdf.iter().sum();
    let scaled = |q: &[f64]| q.iter().zip(&p).all(|(a, b)| near(*a, b * sum));
    if !near(sum, 1.0) && sum > 0.0 && scaled(pdf) {
        return Verdict::NotWritten(
            "pdf_envmap holds the starter's weights (luminance times sin theta), not normalised: steps 1 to 3 are not written yet".into(),
        );
    }
    if let Some(k) = (0..W * H).find(|&k| !near(pdf[k], p[k])) {
        let (i, j) = (k % W, k / W);
        let without_sin = no_sin();
        let what = if pdf.iter().zip(&without_sin).all(|(a, b)| near(*a, *b)) {
            "pdf_envmap has no sin theta: a texel's probability is its luminance times the sin theta of its row (its solid angle), normalised"
        } else if scaled(pdf) {
            "pdf_envmap is not normalised: the texels' probabilities must sum to 1"
        } else {
            "pdf_envmap is not each texel's luminance times sin theta, normalised"
        };
        return Verdict::Fail(failure(
            INPUT,
            format!(
                "pdf_envmap[{}] (texel ({i}, {j})) = {}",
                W * j + i,
                num(p[k])
            ),
            format!("{} (the table sums to {})", num(pdf[k]), num(sum)),
            what,
            None,
        ));
    }
    let rows: Vec<f64> = (0..H).map(|j| p[j * W..(j + 1) * W].iter().sum()).collect();
    if let Err(f) = one_of("marginal_y", marginal, &rows, |j| format!("row {j}")) {
        return Verdict::Fail(f);
    }
    for (j, row) in rows.iter().enumerate() {
        let given: Vec<f64> = p[j * W..(j + 1) * W].iter().map(|q| q / row).collect();
        let at = |i: usize| format!("texel ({i}, {j}), index {}", W * j + i);
        if let Err(f) = one_of("conds_y", &conds[j * W..(j + 1) * W], &given, at) {
            return Verdict::Fail(f);
        }
    }
    Verdict::Pass {
        cases: 2 * W * H + H,
        note: Some(format!(
            "pdf_envmap sums to {}; marginal_y and conds_y as {}",
            num(sum),
            if near(marginal[H - 1], 1.0) && H > 1 && !near(marginal[0], 1.0) {
                "cumulative distributions"
            } else {
                "distributions"
            }
        )),
    }
}

/// The texels' probabilities without the `sin theta` weight.
fn no_sin() -> Vec<f64> {
    let weights: Vec<f64> = (0..H)
        .flat_map(|j| (0..W).map(move |i| envmap::luminance(envmap::texel(i, j))))
        .collect();
    let sum: f64 = weights.iter().sum();
    weights.iter().map(|w| w / sum).collect()
}

/// Whether `got` is the distribution `want` or its cumulative sum; the
/// failure at the first entry that is neither, named by `at`.
fn one_of(
    table: &str,
    got: &[f64],
    want: &[f64],
    at: impl Fn(usize) -> String,
) -> Result<(), crate::check::probe::verdict::Failure> {
    let cdf: Vec<f64> = want
        .iter()
        .scan(0.0, |s, q| {
            *s += q;
            Some(*s)
        })
        .collect();
    let matches = |form: &[f64]| got.iter().zip(form).all(|(a, b)| near(*a, *b));
    if matches(want) || matches(&cdf) {
        return Ok(());
    }
    // The first entry that fits neither form, or the first that differs
    // from the cumulative form when every entry fits one or the other.
    let k = (0..got.len())
        .find(|&k| !near(got[k], want[k]) && !near(got[k], cdf[k]))
        .unwrap_or_else(|| (0..got.len()).find(|&k| !near(got[k], cdf[k])).unwrap_or(0));
    Err(failure(
        INPUT,
        format!(
            "{table} at {}: {} (cumulative) or {} (not)",
            at(k),
            num(cdf[k]),
            num(want[k])
        ),
        num(got[k]),
        format!("{table} is neither the distribution nor its cumulative sum, whole"),
        None,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn either_form_passes_and_a_mix_does_not() {
        let want = [0.25, 0.5, 0.25];
        assert!(one_of("t", &[0.25, 0.5, 0.25], &want, |k| k.to_string()).is_ok());
        assert!(one_of("t", &[0.25, 0.75, 1.0], &want, |k| k.to_string()).is_ok());
        let mixed = one_of("t", &[0.25, 0.75, 0.25], &want, |k| k.to_string()).unwrap_err();
        assert!(mixed.expected.contains("at 2"), "{}", mixed.expected);
        let wrong = one_of("t", &[0.3, 0.5, 0.2], &want, |k| k.to_string()).unwrap_err();
        assert!(wrong.expected.contains("at 0"), "{}", wrong.expected);
    }

    #[test]
    fn the_tables_without_sin_differ_from_the_right_ones() {
        let (p, q) = (probabilities(), no_sin());
        assert!((q.iter().sum::<f64>() - 1.0).abs() < 1e-12);
        assert!(p.iter().zip(&q).any(|(a, b)| !near(*a, *b)));
    }
}
