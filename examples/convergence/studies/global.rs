//! Global illumination (part 4, docs/05-global.md): path depth, and
//! Russian roulette on and off.

use pathtracer::global::PathTracer;

use super::{error_vs_time, lights, Options, Result, SPHERES};
use crate::measure::{table, Measurement};
use crate::plot::{line_chart, Chart, Series};

/// Max depth 1..8 against the converged image, and Russian roulette on
/// and off at depth 8.
pub fn global(options: &Options) -> Result<()> {
    let setup = options.setup(SPHERES)?;
    // Depth: the converged image (RR makes 64 bounces affordable).
    let converged = setup.reference(&lights(1, 64, true), 1024);
    let mut accumulated = Vec::new();
    let mut only = Vec::new();
    for m in 1..=8 {
        let tracer = lights(1, m, true);
        let rendered = setup.render(&tracer, 64, None, m as u64);
        accumulated.push(Measurement::new(
            &format!("-m {m}"),
            64,
            &rendered,
            &converged,
        ));
        let tracer = PathTracer {
            accumulate: false,
            ..tracer
        };
        let rendered = setup.render(&tracer, 64, None, 100 + m as u64);
        only.push(Measurement::new(
            &format!("-m {m} -o 0"),
            64,
            &rendered,
            &converged,
        ));
    }
    table(
        "global: CBspheres_lambertian, depth against the converged image (-m 64)",
        &[accumulated.clone(), only.clone()].concat(),
    );
    let by_depth = |ms: &[Measurement], f: fn(&Measurement) -> f64| {
        ms.iter()
            .enumerate()
            .map(|(i, m)| ((i + 1) as f64, f(m)))
            .collect()
    };
    line_chart(
        &Chart {
            title: "Path depth: brightness and error against the converged image".into(),
            x_label: "max depth m".into(),
            y_label: "fraction of the converged mean luminance / error".into(),
            log_x: false,
            log_y: false,
            series: vec![
                Series::new(
                    "-o 1: mean luminance",
                    by_depth(&accumulated, |m| m.brightness),
                ),
                Series::new("-o 0: m-th bounce only", by_depth(&only, |m| m.brightness)),
                Series::new(
                    "-o 1: relative RMS error",
                    by_depth(&accumulated, |m| m.error),
                ),
            ],
        },
        &options.out.join("convergence-depth.png"),
    )?;

    // Russian roulette on and off at the same depth.
    let depth = 8;
    let reference = setup.reference(&lights(1, depth, true), 1024);
    let run = |rr: bool| -> Vec<Measurement> {
        [4, 16, 64, 256]
            .into_iter()
            .map(|s| {
                let rendered = setup.render(&lights(1, depth, rr), s, None, s as u64);
                let label = format!("-m {depth}, RR {}", if rr { "on" } else { "off" });
                Measurement::new(&label, s, &rendered, &reference)
            })
            .collect()
    };
    let (on, off) = (run(true), run(false));
    table(
        "global: CBspheres_lambertian, Russian roulette at -m 8",
        &[on.clone(), off.clone()].concat(),
    );
    line_chart(
        &error_vs_time(
            "Russian roulette on and off, max depth 8",
            &[("RR on (q = 0.65)", &on), ("RR off", &off)],
        ),
        &options.out.join("convergence-roulette.png"),
    )
}
