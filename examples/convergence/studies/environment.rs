//! The environment light (part 7, docs/08-environment.md): importance
//! against uniform sampling of the built-in sky, with and without MIS.

use pathtracer::direct::DirectLights;
use pathtracer::environment::{builtin_sky, EnvironmentLight, EnvironmentSampling};
use pathtracer::global::{DirectStrategy, PathTracer, Roulette};

use super::{error_vs_time, Options, Result};
use crate::measure::{table, Measurement};
use crate::plot::line_chart;

/// The environment light (part 7): `bunny_unlit.dae` lit by the built-in
/// sky, `-l 1 -m 5`; the map sampled by importance or uniformly
/// (`--env-uniform`), each with MIS and by light sampling alone
/// (`--no-mis`), and BSDF sampling alone (`--bsdf-only`).
pub fn environment(options: &Options) -> Result<()> {
    let mut setup = options.setup("bunny_unlit.dae")?;
    let importance = EnvironmentLight::new(builtin_sky()?, EnvironmentSampling::Importance);
    let uniform = importance.with_sampling(EnvironmentSampling::Uniform);
    let with = |mis| {
        DirectStrategy::Lights(DirectLights {
            samples_per_light: 1,
            environment_samples: None,
            mis,
        })
    };
    let tracer = |direct| PathTracer {
        direct,
        max_depth: 5,
        accumulate: true,
        roulette: Roulette::Fixed,
        glass_splits: 0,
    };
    setup.environment = Some(importance.clone());
    let reference = setup.reference(&tracer(with(true)), 1024);
    let spps = [4, 16, 64, 256];
    let mut series = |env: &EnvironmentLight, direct, label: &str| -> Vec<Measurement> {
        setup.environment = Some(env.clone());
        spps.iter()
            .map(|&s| {
                let rendered = setup.render(&tracer(direct), s, None, s as u64);
                Measurement::new(label, s, &rendered, &reference)
            })
            .collect()
    };
    let runs = [
        series(&importance, with(true), "importance, MIS"),
        series(
            &importance,
            with(false),
            "importance, light alone (--no-mis)",
        ),
        series(&uniform, with(true), "uniform, MIS (--env-uniform)"),
        series(
            &uniform,
            with(false),
            "uniform, light alone (--env-uniform --no-mis)",
        ),
        series(
            &importance,
            DirectStrategy::BsdfOnly,
            "BSDF alone (--bsdf-only)",
        ),
    ];
    table(
        "environment: bunny_unlit, built-in sky, -l 1 -m 5",
        &runs.concat(),
    );
    line_chart(
        &error_vs_time(
            "Environment light: importance vs uniform, MIS vs light alone",
            &[
                ("importance, MIS (default)", &runs[0]),
                ("importance, light alone", &runs[1]),
                ("uniform, MIS", &runs[2]),
                ("uniform, light alone", &runs[3]),
                ("BSDF alone", &runs[4]),
            ],
        ),
        &options.out.join("convergence-environment.png"),
    )?;
    Ok(())
}
