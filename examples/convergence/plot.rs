//! PNG line charts with plotters.
//!
//! Text is drawn by plotters' `ab_glyph` backend from DejaVu Sans, which
//! the `dejavu` crate ships as bytes: no system font and no fontconfig are
//! needed (plotters' default `ttf` feature looks fonts up through
//! font-kit and fontconfig, which a bare machine or CI may lack). The chart
//! is drawn into a buffer and saved with the `image` crate the library
//! already uses.

#[path = "../support/font.rs"]
mod font;

use std::error::Error;
use std::path::Path;

use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::prelude::*;

/// One curve: a name for the legend and its points.
pub struct Series {
    pub name: String,
    pub points: Vec<(f64, f64)>,
}

impl Series {
    pub fn new(name: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Series {
            name: name.into(),
            points,
        }
    }
}

/// A chart: title, axis labels, whether each axis is logarithmic.
pub struct Chart {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub log_x: bool,
    pub log_y: bool,
    pub series: Vec<Series>,
}

const SIZE: (u32, u32) = (800, 520);

const COLOURS: [RGBColor; 6] = [
    RGBColor(213, 94, 0),
    RGBColor(0, 114, 178),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(0, 0, 0),
    RGBColor(230, 159, 0),
];

/// Draws `chart` and writes it to `path` as PNG.
pub fn line_chart(chart: &Chart, path: &Path) -> Result<(), Box<dyn Error>> {
    font::register_font()?;
    let all = || chart.series.iter().flat_map(|s| s.points.iter());
    let span = |values: Vec<f64>, log: bool| {
        let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        if log {
            (lo / 1.3, hi * 1.3)
        } else {
            let pad = 0.05 * (hi - lo).max(1e-9);
            (lo - pad, hi + pad)
        }
    };
    let (x0, x1) = span(all().map(|p| p.0).collect(), chart.log_x);
    let (y0, y1) = span(all().map(|p| p.1).collect(), chart.log_y);
    // On log-log axes, a guide of slope -1/2 through the first point: the
    // error of an unbiased Monte Carlo estimator falls as 1 / sqrt(N), so
    // as 1 / sqrt(time) at a fixed cost per sample (x is either).
    let guide = (chart.log_x && chart.log_y)
        .then(|| chart.series.first().and_then(|s| s.points.first().copied()))
        .flatten()
        .map(|(px, py)| {
            (0..=40)
                .map(|i| x0 * (x1 / x0).powf(i as f64 / 40.0))
                .map(|x| (x, py * (px / x).sqrt()))
                .filter(|&(_, y)| y >= y0 && y <= y1)
                .collect::<Vec<_>>()
        });
    let corner = emptiest_corner(chart, (x0, x1), (y0, y1));
    let mut buffer = vec![255u8; (SIZE.0 * SIZE.1 * 3) as usize];
    let (kx, ky) = (one_two_five(x0, x1), one_two_five(y0, y1));
    let (lx, ly) = ((x0..x1).log_scale(), (y0..y1).log_scale());
    let buffer_ = &mut buffer;
    match (chart.log_x, chart.log_y) {
        (true, true) => draw(
            chart,
            buffer_,
            (lx.with_key_points(kx), ly.with_key_points(ky)),
            (&guide, corner),
        )?,
        (true, false) => draw(
            chart,
            buffer_,
            (lx.with_key_points(kx), y0..y1),
            (&guide, corner),
        )?,
        (false, true) => draw(
            chart,
            buffer_,
            (x0..x1, ly.with_key_points(ky)),
            (&guide, corner),
        )?,
        (false, false) => draw(chart, buffer_, (x0..x1, y0..y1), (&guide, corner))?,
    }
    let image = image::RgbImage::from_raw(SIZE.0, SIZE.1, buffer).ok_or("chart buffer size")?;
    image.save(path)?;
    eprintln!("wrote {}", path.display());
    Ok(())
}

/// Tick positions 1, 2, 5 times powers of ten within `[lo, hi]`.
fn one_two_five(lo: f64, hi: f64) -> Vec<f64> {
    let first = lo.log10().floor() as i32;
    let last = hi.log10().ceil() as i32;
    (first..=last)
        .flat_map(|e| [1.0, 2.0, 5.0].map(|m| m * 10f64.powi(e)))
        .filter(|&v| v >= lo && v <= hi)
        .collect()
}

/// A tick label with at most three significant digits, no trailing zeros.
fn tick(v: &f64) -> String {
    let decimals = (2 - v.abs().log10().floor() as i32).clamp(0, 6) as usize;
    let s = format!("{v:.decimals$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// The place (a corner or a side's middle) with the fewest points near it (in axis
/// fractions, logarithmic where the axis is), where the legend hides none.
fn emptiest_corner(chart: &Chart, xs: (f64, f64), ys: (f64, f64)) -> SeriesLabelPosition {
    let fraction = |v: f64, (lo, hi): (f64, f64), log: bool| {
        if log {
            (v / lo).ln() / (hi / lo).ln()
        } else {
            (v - lo) / (hi - lo)
        }
    };
    // Each place with the box of axis fractions a legend there covers.
    let places = [
        (SeriesLabelPosition::UpperRight, (0.55, 1.0), (0.65, 1.0)),
        (SeriesLabelPosition::UpperLeft, (0.0, 0.45), (0.65, 1.0)),
        (SeriesLabelPosition::LowerLeft, (0.0, 0.45), (0.0, 0.35)),
        (SeriesLabelPosition::LowerRight, (0.55, 1.0), (0.0, 0.35)),
        (SeriesLabelPosition::MiddleRight, (0.55, 1.0), (0.3, 0.7)),
        (SeriesLabelPosition::MiddleLeft, (0.0, 0.45), (0.3, 0.7)),
    ];
    let crowding = |(x0, x1): (f64, f64), (y0, y1): (f64, f64)| {
        chart
            .series
            .iter()
            .flat_map(|s| s.points.iter())
            .filter(|&&(x, y)| {
                let fx = fraction(x, xs, chart.log_x);
                let fy = fraction(y, ys, chart.log_y);
                (x0..=x1).contains(&fx) && (y0..=y1).contains(&fy)
            })
            .count()
    };
    places
        .into_iter()
        .min_by_key(|&(_, x, y)| crowding(x, y))
        .map_or(SeriesLabelPosition::UpperRight, |p| p.0)
}

type Guide = Option<Vec<(f64, f64)>>;

fn draw<X, Y>(
    chart: &Chart,
    buffer: &mut [u8],
    (x, y): (X, Y),
    (guide, corner): (&Guide, SeriesLabelPosition),
) -> Result<(), Box<dyn Error>>
where
    X: AsRangedCoord<Value = f64>,
    Y: AsRangedCoord<Value = f64>,
    X::CoordDescType: ValueFormatter<f64>,
    Y::CoordDescType: ValueFormatter<f64>,
{
    let root = BitMapBackend::with_buffer(buffer, SIZE).into_drawing_area();
    root.fill(&WHITE)?;
    let mut plot = ChartBuilder::on(&root)
        .caption(&chart.title, ("sans-serif", 22))
        .margin(14)
        .x_label_area_size(44)
        .y_label_area_size(64)
        .build_cartesian_2d(x, y)?;
    plot.configure_mesh()
        .x_desc(&chart.x_label)
        .y_desc(&chart.y_label)
        .x_label_formatter(&tick)
        .y_label_formatter(&tick)
        .x_labels(12)
        .y_labels(12)
        .label_style(("sans-serif", 15))
        .axis_desc_style(("sans-serif", 17))
        .light_line_style(RGBColor(235, 235, 235))
        .draw()?;
    for (i, series) in chart.series.iter().enumerate() {
        let colour = COLOURS[i % COLOURS.len()];
        plot.draw_series(LineSeries::new(
            series.points.iter().copied(),
            colour.stroke_width(2),
        ))?
        .label(&series.name)
        .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], colour.stroke_width(2)));
        plot.draw_series(
            series
                .points
                .iter()
                .map(|&p| Circle::new(p, 4, colour.filled())),
        )?;
    }
    if let Some(points) = guide {
        let grey = RGBColor(150, 150, 150);
        plot.draw_series(DashedLineSeries::new(
            points.iter().copied(),
            6,
            5,
            grey.stroke_width(1),
        ))?
        .label("slope -1/2 guide (error ~ 1 / sqrt(x))")
        .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], grey.stroke_width(1)));
    }
    plot.configure_series_labels()
        .position(corner)
        .label_font(("sans-serif", 15))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()?;
    root.present()?;
    Ok(())
}
