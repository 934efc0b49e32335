//! What differs between a student's image and the course's, in words:
//! how bright (in radiance, from the display values' ratio to the power
//! 2.2) and where the blocks that differ most lie.

use super::battery::SIZE;
use super::stats::BLOCK;

/// What differs, in words: the brightness ratio (linear, from the display
/// values' ratio to the power 2.2) and where the cells that differ most lie.
pub fn describe(x: &[f64], mean: &[f64], z: &[f64]) -> String {
    let (sx, sm): (f64, f64) = (x.iter().sum(), mean.iter().sum());
    let ratio = if sm > 0.0 {
        (sx / sm).powf(2.2)
    } else {
        f64::INFINITY
    };
    let (share, place) = differing_blocks(z, 3);
    format!(
        "{:.2} times as bright as the course's image (radiance); {:.0} % of the 16 x 16 blocks differ, {place}",
        ratio,
        100.0 * share
    )
}

/// The share of cells (`channels` a block) more than 4 standard errors
/// off, and where they lie, in words.
pub fn differing_blocks(z: &[f64], channels: usize) -> (f64, String) {
    let bw = SIZE.0.div_ceil(BLOCK) as usize;
    let bh = SIZE.1.div_ceil(BLOCK) as usize;
    let far: Vec<usize> = (0..z.len()).filter(|&i| z[i] > 4.0).collect();
    let share = far.len() as f64 / z.len().max(1) as f64;
    let (mut cx, mut cy) = (0.0, 0.0);
    for &i in &far {
        let b = i / channels;
        cx += (b % bw) as f64 / bw as f64;
        cy += (b / bw) as f64 / bh as f64;
    }
    let n = far.len().max(1) as f64;
    let (cx, cy) = (cx / n, cy / n);
    let third = |v: f64, names: [&'static str; 3]| names[((v * 3.0) as usize).min(2)];
    let place = if far.is_empty() {
        "no block alone far off: a small difference spread over the image".to_string()
    } else if share > 0.6 {
        "all over the image".to_string()
    } else {
        format!(
            "mostly {} {}",
            third(cy, ["top", "middle", "bottom"]),
            third(cx, ["left", "centre", "right"])
        )
    };
    (share, place)
}
