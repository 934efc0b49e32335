//! Adaptive sampling (part 5, docs/06-adaptive.md) against uniform
//! sampling.

use pathtracer::adaptive::Adaptive;

use super::{lights, Options, Result, SPHERES};
use crate::measure::{table, Measurement};
use crate::plot::{line_chart, Chart, Series};

/// Adaptive against uniform sampling: mean samples and time for an error.
pub fn adaptive(options: &Options) -> Result<()> {
    let setup = options.setup(SPHERES)?;
    let tracer = lights(1, 5, true);
    let reference = setup.reference(&tracer, 2048);
    let uniform: Vec<_> = [16, 32, 64, 128, 256, 512]
        .into_iter()
        .map(|s| {
            let rendered = setup.render(&tracer, s, None, s as u64);
            Measurement::new("uniform", s, &rendered, &reference)
        })
        .collect();
    let max = 2048;
    let adaptive: Vec<_> = [0.4, 0.2, 0.1, 0.05]
        .into_iter()
        .map(|tolerance| {
            let a = Adaptive {
                batch: 32,
                tolerance,
            };
            let rendered = setup.render(&tracer, max, Some(a), 7);
            Measurement::new(
                &format!("adaptive -a 32 {tolerance}"),
                max,
                &rendered,
                &reference,
            )
        })
        .collect();
    table(
        "adaptive: CBspheres_lambertian, -l 1 -m 5",
        &[uniform.clone(), adaptive.clone()].concat(),
    );
    let chart = |title: &str, y_label: &str, error: fn(&Measurement) -> f64| Chart {
        title: title.into(),
        x_label: "mean camera rays per pixel".into(),
        y_label: y_label.into(),
        log_x: true,
        log_y: true,
        series: [
            ("uniform (-s 16 ... 512)", &uniform),
            ("adaptive (-s 2048 -a 32 TOL)", &adaptive),
        ]
        .into_iter()
        .map(|(name, ms)| {
            let points = ms
                .iter()
                .map(|m| (m.mean_samples_per_pixel, 100.0 * error(m)))
                .collect();
            Series::new(name, points)
        })
        .collect(),
    };
    line_chart(
        &chart(
            "Adaptive vs uniform: error of the image",
            "relative RMS error (%)",
            |m| m.error,
        ),
        &options.out.join("convergence-adaptive.png"),
    )?;
    line_chart(
        &chart(
            "Adaptive vs uniform: error of each pixel relative to itself",
            "RMS pixel relative error (%)",
            |m| m.pixel_error,
        ),
        &options.out.join("convergence-adaptive-pixels.png"),
    )
}
