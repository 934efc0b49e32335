//! Colour maps with their colour bars: the ratio of two renders (where a
//! figure claims a small difference), a log-scale density, and white space
//! under the pictures of a grid that have no bar, so all are one size.

use pathtracer::math::{luminance, ratio_colour, Rgb};
use pathtracer::render::Rendered;

use crate::picture::{Note, Picture};

/// Rows a colour bar adds under a picture: a gap, the strip, tick marks,
/// a gap and the ticks' text.
pub const BAR: u32 = 40;
const GAP: u32 = 4;
const STRIP: u32 = 14;
const TICK: u32 = 4;
/// Rows between a tick mark and its text (the font draws a little above
/// the point it is given).
const TEXT_GAP: u32 = 4;

/// Width of `text` in DejaVu Sans at 12 px, near enough to centre it.
fn text_width(text: &str) -> i32 {
    text.chars()
        .map(|c| if ".,:;' |".contains(c) { 4 } else { 7 })
        .sum()
}

/// `picture` with a colour bar under it: `colour(t)` for `t` from 0 (left)
/// to 1 (right), and each tick's text centred under its `t`.
pub fn with_bar(
    mut picture: Picture,
    colour: impl Fn(f32) -> Rgb,
    ticks: &[(f32, &str)],
) -> Picture {
    let (w, h) = (picture.width, picture.height);
    let x_of = |t: f32| (t * (w - 1) as f32).round() as u32;
    let mut rows = vec![Rgb::ONE; (w * BAR) as usize];
    for y in GAP..GAP + STRIP {
        for x in 0..w {
            rows[(y * w + x) as usize] = colour(x as f32 / (w - 1) as f32);
        }
    }
    for &(t, text) in ticks {
        let x = x_of(t);
        for y in GAP + STRIP..GAP + STRIP + TICK {
            rows[(y * w + x) as usize] = Rgb::ZERO;
        }
        let width = text_width(text);
        let left = (x as i32 - width / 2).clamp(0, (w as i32 - width).max(0));
        picture.notes.push(Note {
            x: left,
            y: (h + GAP + STRIP + TICK + TEXT_GAP) as i32,
            text: text.to_string(),
        });
    }
    picture.display.extend(rows);
    picture.height += BAR;
    picture
}

/// `picture` with [`BAR`] white rows under it, to stand beside pictures
/// that have a colour bar.
pub fn padded(mut picture: Picture) -> Picture {
    picture.display.extend(std::iter::repeat_n(
        Rgb::ONE,
        (picture.width * BAR) as usize,
    ));
    picture.height += BAR;
    picture
}

/// The ratio of `top`'s luminance to `bottom`'s over 4 x 4 pixel blocks
/// (less noise than pixels), as colours: blue where `top` is `max` times
/// darker, through white (equal) to red where it is `max` times brighter,
/// on a log scale; grey where both are black. With its colour bar.
pub fn ratio_map(label: &str, top: &Rendered, bottom: &Rendered, max: f32) -> Picture {
    let (w, h) = (top.film.width, top.film.height);
    let block = |r: &Rendered, x: u32, y: u32| -> f32 {
        let (x0, y0) = (x / 4 * 4, y / 4 * 4);
        (y0..(y0 + 4).min(h))
            .flat_map(|y| (x0..(x0 + 4).min(w)).map(move |x| (x, y)))
            .map(|(x, y)| luminance(r.film.get(x, y)))
            .sum()
    };
    let scale = max.log2();
    let display = (0..w * h)
        .map(|i| {
            let (a, b) = (block(top, i % w, i / w), block(bottom, i % w, i / w));
            if a <= 1e-6 && b <= 1e-6 {
                Rgb::splat(0.6)
            } else {
                ratio_colour(((a + 1e-6) / (b + 1e-6)).log2() / scale)
            }
        })
        .collect();
    let (low, high) = (format!("{:.2}", 1.0 / max), format!("{max:.2}"));
    let (mid_low, mid_high) = (
        format!("{:.2}", max.sqrt().recip()),
        format!("{:.2}", max.sqrt()),
    );
    with_bar(
        Picture::display(label, w, h, display),
        |t| ratio_colour(2.0 * t - 1.0),
        &[
            (0.0, &low),
            (0.25, &mid_low),
            (0.5, "1"),
            (0.75, &mid_high),
            (1.0, &high),
        ],
    )
}

/// Viridis (matplotlib's default colour map; its eight anchor colours,
/// linearly between them) at `t` in `[0, 1]`.
pub fn viridis(t: f32) -> Rgb {
    const ANCHORS: [[f32; 3]; 8] = [
        [68.0, 1.0, 84.0],
        [70.0, 50.0, 127.0],
        [54.0, 92.0, 141.0],
        [39.0, 127.0, 143.0],
        [31.0, 162.0, 136.0],
        [74.0, 194.0, 110.0],
        [160.0, 219.0, 57.0],
        [254.0, 232.0, 37.0],
    ];
    let x = t.clamp(0.0, 1.0) * (ANCHORS.len() - 1) as f32;
    let i = (x.floor() as usize).min(ANCHORS.len() - 2);
    let (a, b) = (Rgb::from_array(ANCHORS[i]), Rgb::from_array(ANCHORS[i + 1]));
    a.lerp(b, x - i as f32) / 255.0
}

/// The relative standard error a render printed, as a label's words.
pub fn noise(r: &Rendered) -> String {
    match r.relative_error() {
        Some(e) => format!("rel. SE {:.1} %", 100.0 * e),
        None => "rel. SE -".to_string(),
    }
}
