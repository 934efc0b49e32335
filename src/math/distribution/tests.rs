//! Tests of `math::distribution`: 1D tables, the guide, the ends of the
//! range, the hint and the 2D distribution.

use super::*;

#[test]
fn one_dimension_samples_invert_and_skip_empty_cells() {
    let d = Distribution1D::new(&[1.0, 0.0, 3.0, 0.0]);
    assert_eq!(d.integral(), 1.0);
    assert_eq!(d.cdf(), &[0.0, 0.25, 0.25, 1.0, 1.0]);
    for k in 0..1000 {
        let u = k as f32 / 1000.0;
        let s = d.sample(u);
        assert!(s.cell == 0 || s.cell == 2, "u {u}: cell {}", s.cell);
        assert_eq!(s.pdf, d.pdf(s.x));
        assert!((d.invert(s.x) - u).abs() < 1e-5, "u {u}");
    }
    assert_eq!(d.sample(0.25).cell, 2);
    assert_eq!(d.pdf(0.3), 0.0);
    assert_eq!(d.pdf(0.6), 3.0);
}

/// The guide table finds the same cell as a binary search over the
/// cdf, for skewed functions with runs of empty cells and for `u` at
/// and next to every cell boundary.
#[test]
fn the_guide_table_finds_the_binary_search_cell() {
    let mut rng = crate::math::rng::sampler(7, 0);
    for n in [1usize, 2, 3, 17, 256, 1000] {
        use rand::Rng;
        let f: Vec<f32> = (0..n)
            .map(|_| match rng.gen_range(0..4) {
                0 => 0.0,
                1 => rng.gen::<f32>() * 1e4,
                _ => rng.gen::<f32>(),
            })
            .collect();
        let d = Distribution1D::new(&f);
        let mut us: Vec<f32> = (0..4 * n).map(|_| rng.gen()).collect();
        for &c in d.cdf() {
            us.extend([c, next_down(c), crate::math::float::next_float_up(c)]);
        }
        for u in us.into_iter().filter(|u| (0.0..1.0).contains(u)) {
            let search = (d.cdf.partition_point(|&c| c <= u).saturating_sub(1)).min(n - 1);
            let expected = (0..=search)
                .rev()
                .find(|&k| d.cell_probability(k) > 0.0)
                .unwrap_or(search);
            assert_eq!(d.sample(u).cell, expected, "n {n}, u {u}");
        }
    }
}

/// Each guide entry is the cell of `u = k / n`: the last cell whose
/// cdf is at most `k / n`. A wrong guide still finds the right cell,
/// since the search walks from it, only more slowly, so no test of
/// the samples can see it; this one reads the table.
#[test]
fn the_guide_holds_the_cell_of_each_k_over_n() {
    let functions: [Vec<f32>; 4] = [
        vec![1.0],
        vec![0.0, 0.0, 5.0, 1.0],
        vec![1e4, 1.0, 1.0, 1.0, 0.0, 2.0],
        (0..100).map(|i| (i % 7) as f32).collect(),
    ];
    for f in functions {
        let d = Distribution1D::new(&f);
        let n = f.len();
        assert_eq!(d.guide.len(), n);
        for (k, &guide) in d.guide.iter().enumerate() {
            let u = k as f32 / n as f32;
            let cell = (0..n).rev().find(|&i| d.cdf[i] <= u).unwrap();
            assert_eq!(guide as usize, cell, "n {n}, k {k}");
        }
    }
}

fn next_down(c: f32) -> f32 {
    crate::math::float::next_float_down(c).max(0.0)
}

/// Negative and non-finite values count as 0 beside positive ones;
/// the integral is the function's mean (here not 1); `u = 1` and
/// `x = 1` belong to the last cell (with mass, for `u`).
#[test]
fn empty_values_and_the_ends_of_the_range() {
    let d = Distribution1D::new(&[-1.0, 3.0, f32::NAN, 7.0, f32::INFINITY, 0.0]);
    assert!(!d.is_empty());
    assert_eq!(d.len(), 6);
    assert!((d.integral() - 10.0 / 6.0).abs() < 1e-6);
    assert_eq!(d.cdf(), &[0.0, 0.0, 0.3, 0.3, 1.0, 1.0, 1.0]);
    let end = d.sample(1.0);
    assert_eq!(end.cell, 3);
    assert!(end.x < 1.0 && (end.x - 4.0 / 6.0).abs() < 1e-6);
    assert!((end.pdf - 4.2).abs() < 1e-5);
    assert_eq!(d.pdf(1.0), 0.0);
    assert_eq!(d.invert(1.0), 1.0);
}

#[test]
fn a_function_without_mass_is_uniform() {
    // The last: a positive mean that underflows f32 (1e-45 / 2 rounds to
    // 0) has no mass either; its tables would divide by 0.
    for f in [
        [0.0, 0.0],
        [-1.0, f32::NAN],
        [f32::INFINITY, 0.0],
        [1e-45, 0.0],
    ] {
        let d = Distribution1D::new(&f);
        assert_eq!(d.integral(), 0.0);
        assert_eq!(d.pdf(0.2), 1.0);
        assert_eq!(d.sample(0.7).x, 0.7);
    }
}

/// Just below a guide boundary, rounding can start the search past the
/// sample's cell: with 20 equal cells, `u` = 0.84999996 (the float below
/// 0.85) gives `fl(20 u) = 17`, and the guide's cell 17 begins at `cdf =
/// 0.85 > u`. The search must step back to cell 16 (found by a search
/// over every n below 40 and every boundary; a back walk that never runs,
/// or runs the wrong way, fails here).
#[test]
fn a_sample_just_below_a_guide_boundary_steps_back() {
    let d = Distribution1D::new(&[1.0; 20]);
    let u = f32::from_bits(0.85f32.to_bits() - 1);
    assert_eq!((u * 20.0) as usize, 17, "the guide starts at cell 17");
    let s = d.sample(u);
    assert_eq!(s.cell, 16);
    assert!(s.x < 0.85 && s.x > 0.8499, "{}", s.x);
    assert!((s.pdf - 1.0).abs() < 1e-5, "{}", s.pdf);
}

/// The hint sees the sample's `v` and the column its search starts
/// from, at or before the sampled one, and changes nothing.
#[test]
fn the_hint_names_the_samples_v_and_where_the_search_starts() {
    let f: Vec<f32> = (0..64 * 8).map(|k| ((k * 37) % 11) as f32).collect();
    let d = Distribution2D::new(&f, 64, 8);
    for k in 0..1000 {
        let u = Vec2::new((k as f32 * 0.618_034).fract(), k as f32 / 1000.0);
        let mut seen = None;
        let s = d.sample_hinted(u, |v, column| seen = Some((v, column)));
        let (v, column) = seen.expect("the hint is called");
        assert_eq!(v, s.x.y, "u {u}");
        assert!(column <= s.cell, "u {u}: hint {column}, cell {}", s.cell);
        assert_eq!(s, d.sample(u));
    }
}

#[test]
fn two_dimensions_sample_rows_then_columns() {
    let d = Distribution2D::new(&[0.0, 1.0, 2.0, 1.0, 0.0, 0.0], 3, 2);
    assert_eq!((d.width(), d.height()), (3, 2));
    // Row 0 has 3/4 of the mass, row 1 a quarter; p = f / c with c = 4/6.
    assert!((d.pdf(Vec2::new(0.5, 0.2)) - 1.5).abs() < 1e-6);
    assert!((d.pdf(Vec2::new(0.9, 0.2)) - 3.0).abs() < 1e-6);
    assert_eq!(d.pdf(Vec2::new(0.1, 0.2)), 0.0);
    assert!((d.pdf(Vec2::new(0.2, 0.7)) - 1.5).abs() < 1e-6);
    for k in 0..400 {
        let u = Vec2::new((k % 20) as f32 / 20.0 + 0.01, (k / 20) as f32 / 20.0 + 0.01);
        let s = d.sample(u);
        assert!(s.pdf > 0.0);
        assert!((s.pdf - d.pdf(s.x)).abs() < 1e-5 * s.pdf);
        assert!((d.invert(s.x) - u).length() < 1e-4, "{u} -> {:?}", s.x);
    }
}
