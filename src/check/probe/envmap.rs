//! The environment map the part 7 probes give the student's
//! `EnvironmentLight` ([`environment`](super::environment)), and the
//! course's conventions for it, in `f64`.
//!
//! The map is [`W`] x [`H`] texels, row 0 straight up: a gradient whose
//! red grows with the column and green with the row (so every texel, and
//! every texel's mirror image in `u` or in `v`, has a radiance of its
//! own), and one bright texel, [`BRIGHT`], that holds about a third of
//! the light.
//!
//! - A direction `d` (unit) has `theta = acos(d.y)`,
//!   `phi = atan2(-d.z, d.x) + pi`, and the map position
//!   `x = phi / (2 pi) w`, `y = theta / pi h` (the starter's
//!   `dir_to_theta_phi`, `theta_phi_to_xy`); the inverse is
//!   `d = (-sin theta cos phi, cos theta, sin theta sin phi)`.
//! - Texel `(i, j)` holds the radiance at its centre `(i + 1/2, j + 1/2)`;
//!   between centres the lookup is bilinear, wrapping around in `x` and
//!   clamped in `y` (the starter's `bilerp`).
//! - The probability of texel `(i, j)` is its luminance (`illum()`,
//!   Rec. 709 weights) times `sin theta_j` at its row's centre, over the
//!   sum of them all; a direction drawn from it has the density per
//!   steradian `P w h / (2 pi^2 sin theta)`.

use std::f64::consts::PI;

use glam::DVec3;

use super::driver::{Driver, Transcript};
use super::verdict::Verdict;

pub const W: usize = 16;
pub const H: usize = 8;

/// The bright texel `(i, j)` and its radiance.
pub const BRIGHT: (usize, usize) = (11, 2);
const BRIGHT_RADIANCE: DVec3 = DVec3::new(30.0, 25.0, 20.0);

/// Texel `(i, j)`'s radiance.
pub fn texel(i: usize, j: usize) -> DVec3 {
    if (i, j) == BRIGHT {
        return BRIGHT_RADIANCE;
    }
    DVec3::new(
        0.2 + 0.05 * i as f64,
        0.1 + 0.1 * j as f64,
        0.3 + 0.02 * (i + 3 * j) as f64,
    )
}

/// The driver's `envmap` command: the texels row by row from the top.
pub fn command() -> String {
    let mut s = format!("envmap {W} {H}");
    for j in 0..H {
        for i in 0..W {
            let c = texel(i, j);
            s.push_str(&format!(" {} {} {}", c.x, c.y, c.z));
        }
    }
    s
}

/// Runs the script `name`: the `envmap` command (which constructs the
/// `EnvironmentLight`, so runs its `init`), then `commands`, numbered from
/// 1 in the transcript. The verdict instead when the driver cannot run or
/// stops at the construction.
pub fn run(driver: &Driver, name: &str, commands: Vec<String>) -> Result<Transcript, Verdict> {
    let script = std::iter::once(command()).chain(commands).collect();
    let t = driver.run(name, script).map_err(Verdict::Broken)?;
    if let Err(stop) = t.line(0) {
        return Err(Verdict::stopped(
            &stop,
            "envmap (constructing the EnvironmentLight, which runs init)",
        ));
    }
    Ok(t)
}

/// `illum()`: Rec. 709 luminance, the weights as the course's floats.
pub fn luminance(c: DVec3) -> f64 {
    f64::from(0.2126f32) * c.x + f64::from(0.7152f32) * c.y + f64::from(0.0722f32) * c.z
}

/// The polar angle of row `j`'s centre.
pub fn row_theta(j: usize) -> f64 {
    PI * (j as f64 + 0.5) / H as f64
}

/// Every texel's probability, `j * W + i`.
pub fn probabilities() -> Vec<f64> {
    let weights: Vec<f64> = (0..H)
        .flat_map(|j| (0..W).map(move |i| luminance(texel(i, j)) * row_theta(j).sin()))
        .collect();
    let sum: f64 = weights.iter().sum();
    weights.iter().map(|w| w / sum).collect()
}

/// The map position `(x, y)` of a direction.
pub fn xy(d: DVec3) -> (f64, f64) {
    let d = d.normalize();
    let theta = d.y.clamp(-1.0, 1.0).acos();
    let phi = (-d.z).atan2(d.x) + PI;
    (phi / (2.0 * PI) * W as f64, theta / PI * H as f64)
}

/// The direction of map position `(x, y)`.
pub fn direction(x: f64, y: f64) -> DVec3 {
    let (theta, phi) = (y / H as f64 * PI, x / W as f64 * 2.0 * PI);
    DVec3::new(
        -theta.sin() * phi.cos(),
        theta.cos(),
        theta.sin() * phi.sin(),
    )
}

/// The bilinear lookup at `(x, y)`, wrapping in `x`, clamped in `y`.
pub fn lookup(x: f64, y: f64) -> DVec3 {
    let (fx, fy) = (x - 0.5, y - 0.5);
    let (i0, j0) = (fx.floor(), fy.floor());
    let (s, t) = (fx - i0, fy - j0);
    let col = |i: f64| (i as i64).rem_euclid(W as i64) as usize;
    let row = |j: f64| (j as i64).clamp(0, H as i64 - 1) as usize;
    let at = |i: f64, j: f64| texel(col(i), row(j));
    (1.0 - t) * ((1.0 - s) * at(i0, j0) + s * at(i0 + 1.0, j0))
        + t * ((1.0 - s) * at(i0, j0 + 1.0) + s * at(i0 + 1.0, j0 + 1.0))
}

/// `d` read with `u` flipped (`phi -> 2 pi - phi`): `env-map-u-flipped`.
pub fn flip_u(d: DVec3) -> DVec3 {
    DVec3::new(d.x, d.y, -d.z)
}

/// `d` read with `v` flipped (`theta -> pi - theta`): `env-map-v-flipped`.
pub fn flip_v(d: DVec3) -> DVec3 {
    DVec3::new(d.x, -d.y, d.z)
}

/// How near a texel's edge (in texels) a position may be read as either
/// side's.
const EDGE: f64 = 1e-6;

/// The texels `d` may be said to lie in: its own, and a neighbour's when
/// it lies on their common edge (a sampler may return a texel's corner,
/// `xy_to_theta_phi` of its integer position); at a pole, where the
/// column is lost, any texel of the pole's row.
pub fn candidates(d: DVec3) -> Vec<(usize, usize)> {
    let (x, y) = xy(d);
    let near = |v: f64| [v.floor(), (v + EDGE).floor(), (v - EDGE).floor()];
    let mut cols: Vec<usize> = near(x)
        .iter()
        .map(|i| (*i as i64).rem_euclid(W as i64) as usize)
        .collect();
    if d.normalize().y.abs() >= 1.0 - 1e-12 {
        cols = (0..W).collect();
    }
    let mut out = Vec::new();
    for j in near(y).map(|j| (j as i64).clamp(0, H as i64 - 1) as usize) {
        for &i in &cols {
            if !out.contains(&(i, j)) {
                out.push((i, j));
            }
        }
    }
    out
}

/// Whether `d` is at a pole.
pub fn at_pole(d: DVec3) -> bool {
    d.normalize().y.abs() >= 1.0 - 1e-12
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn texel_centres_map_to_themselves_and_flips_to_their_mirrors() {
        for j in 0..H {
            for i in 0..W {
                let (x, y) = (i as f64 + 0.5, j as f64 + 0.5);
                let d = direction(x, y);
                let (x2, y2) = xy(d);
                assert!((x2 - x).abs() < 1e-12 && (y2 - y).abs() < 1e-12, "{i} {j}");
                assert!((lookup(x2, y2) - texel(i, j)).length() < 1e-12);
                let (xu, _) = xy(flip_u(d));
                assert!((xu - (W - 1 - i) as f64 - 0.5).abs() < 1e-12);
                let (_, yv) = xy(flip_v(d));
                assert!((yv - (H - 1 - j) as f64 - 0.5).abs() < 1e-12);
                assert!(texel(W - 1 - i, j) != texel(i, j) && texel(i, H - 1 - j) != texel(i, j));
                assert_eq!(candidates(d), vec![(i, j)]);
            }
        }
        // Across the seam, half of column W - 1 and half of column 0.
        let seam = lookup(0.0, 3.5);
        assert!((seam - 0.5 * (texel(W - 1, 3) + texel(0, 3))).length() < 1e-12);
        assert_eq!(lookup(4.5, 0.1), texel(4, 0));
    }

    #[test]
    fn the_bright_texel_holds_about_a_third_and_none_is_rare() {
        let p = probabilities();
        assert!((p.iter().sum::<f64>() - 1.0).abs() < 1e-12);
        let bright = p[BRIGHT.1 * W + BRIGHT.0];
        assert!(bright > 0.25 && bright < 0.45, "{bright}");
        let least = p.iter().cloned().fold(1.0, f64::min);
        assert!(least * 20_000.0 > 5.0, "{least}");
    }

    #[test]
    fn a_corner_is_in_its_texel_and_the_pole_in_its_row() {
        // Texel (3, 2)'s top-left corner, (3, 2) in map units.
        assert!(candidates(direction(3.0, 2.0)).contains(&(3, 2)));
        assert!(candidates(direction(0.0, 5.0)).contains(&(0, 5)));
        let pole = candidates(direction(7.0, 0.0));
        assert!(pole.len() == W && pole.iter().all(|&(_, j)| j == 0));
    }
}
