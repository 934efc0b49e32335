//! Dielectric Fresnel (`materials::fresnel::dielectric` and `schlick`)
//! against [`reference`](crate::reference) at every tenth of a degree,
//! entering and leaving, and against published values.
//!
//! Tolerance: the library works in `f32`; its reflectance differs from the
//! `f64` answer by rounding only, at most 1.2e-6 observed over the sweeps
//! (angles within 0.2 degrees of the critical one left out, where
//! `cos_t = sqrt(1 - sin_t^2)` amplifies the rounding of `eta` and
//! `cos_i`). [`TOL`] = 1e-5 is 8 times that, and far smaller than what
//! the wrong formulas below change (0.06 and more at some angle).

use pathtracer::materials::fresnel;

use crate::reference::{schlick, snell_fresnel};

pub const TOL: f64 = 1e-5;

/// `(n1, n2)`: light arriving from `n1`: entering glass (1.5) and
/// diamond-like 2.4, and leaving each.
pub const SIDES: [(f64, f64); 4] = [(1.0, 1.5), (1.5, 1.0), (1.0, 2.4), (2.4, 1.0)];

/// The incident cosines of a sweep from 0 to 89.9 degrees by tenths, and
/// whether each is past the critical angle (`None` within 0.2 degrees of it).
fn sweep(n1: f64, n2: f64) -> impl Iterator<Item = (f32, Option<bool>)> {
    let critical = (n1 > n2).then(|| (n2 / n1).asin().to_degrees());
    (0..900).map(move |tenth| {
        let degrees = f64::from(tenth) / 10.0;
        let past = match critical {
            Some(c) if (degrees - c).abs() < 0.2 => None,
            Some(c) => Some(degrees > c),
            None => Some(false),
        };
        (degrees.to_radians().cos() as f32, past)
    })
}

/// Checked against: `r_par` with `cos_i` and `cos_t` exchanged,
/// `(eta cos_t - cos_i) / (eta cos_t + cos_i)` (equal at normal incidence
/// only; 0.177 for 0.089 at 60 degrees entering glass), and Snell's law
/// with `eta` the wrong way up (`sin_t = eta sin_i`: total internal
/// reflection entering glass, none leaving it).
#[test]
fn exact_dielectric_follows_snells_law_entering_and_leaving() {
    for (n1, n2) in SIDES {
        let eta = (n2 / n1) as f32;
        let (mut worst, mut beyond) = (0.0f64, 0);
        for (cos_i, past) in sweep(n1, n2) {
            let Some(past) = past else { continue };
            let got = f64::from(fresnel::dielectric(cos_i, eta));
            let expected = snell_fresnel(n1, n2, f64::from(cos_i));
            if past {
                assert_eq!(got, 1.0, "n {n1} -> {n2}, cos {cos_i}: total reflection");
                beyond += 1;
            }
            worst = worst.max((got - expected).abs());
            assert!(
                (got - expected).abs() <= TOL,
                "n {n1} -> {n2}, cos_i {cos_i}: {got} vs Snell {expected}"
            );
        }
        eprintln!("exact, n {n1} -> {n2}: worst {worst:.1e}, {beyond} angles past critical");
        assert_eq!(beyond > 0, n1 > n2);
    }
}

/// Published values: at normal incidence `((n - 1) / (n + 1))^2` (0.04 for
/// glass); at Brewster's angle `tan(theta_B) = n2 / n1` the p amplitude
/// vanishes and `R_s = ((n^2 - 1) / (n^2 + 1))^2` (0.148 for n = 1.5, the
/// textbook figure for glass, e.g. Hecht's *Optics*), so `R = R_s / 2`,
/// the same entering and leaving. Checked against the exchanged `r_par`
/// above (0.148 at Brewster's angle, not 0.074: `r_p` is no longer 0).
#[test]
fn published_values_at_normal_incidence_and_brewsters_angle() {
    for (n, r0, brewster) in [(1.5f64, 0.04, 0.073_964_5), (2.4, 0.169_550_2, 0.247_908)] {
        for (n1, n2) in [(1.0, n), (n, 1.0)] {
            let eta = (n2 / n1) as f32;
            let normal = f64::from(fresnel::dielectric(1.0, eta));
            assert!(
                (normal - r0).abs() < TOL,
                "n {n1} -> {n2}: {normal} vs {r0}"
            );
            let cos_b = (n2 / n1).atan().cos();
            let at_b = f64::from(fresnel::dielectric(cos_b as f32, eta));
            assert!(
                (at_b - brewster).abs() < TOL,
                "n {n1} -> {n2}, Brewster: {at_b} vs {brewster}"
            );
            // The reference agrees with the published numbers too.
            assert!((snell_fresnel(n1, n2, cos_b) - brewster).abs() < 1e-6);
        }
    }
}

/// The course's glass uses Schlick's approximation (`--schlick` here; exact
/// Fresnel by default). Checked against `R0 = |1 - eta| / (1 + eta)`
/// unsquared (0.2 for 0.04 at normal incidence) and the power 4 for 5
/// (0.220 for 0.158 at 70 degrees).
#[test]
fn schlick_is_the_courses_formula() {
    for (n1, n2) in SIDES {
        let eta = (n2 / n1) as f32;
        let mut apart = 0.0f64;
        for (cos_i, past) in sweep(n1, n2) {
            if past.is_none() {
                continue;
            }
            let got = f64::from(fresnel::schlick(cos_i, eta));
            let expected = schlick(n1, n2, f64::from(cos_i));
            assert!(
                (got - expected).abs() <= TOL,
                "n {n1} -> {n2}, cos_i {cos_i}: {got} vs Schlick {expected}"
            );
            apart = apart.max((expected - snell_fresnel(n1, n2, f64::from(cos_i))).abs());
        }
        // Large enough that a glass using the other formula fails below.
        assert!(apart > 0.02, "n {n1} -> {n2}: Schlick within {apart}");
    }
}
