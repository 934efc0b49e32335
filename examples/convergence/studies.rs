//! The studies: each renders a reference once, then a series of renders,
//! and writes one chart (PNG) and one Markdown table (stdout).

use std::error::Error;
use std::path::PathBuf;

use pathtracer::adaptive::Adaptive;
use pathtracer::direct::{DirectHemisphere, DirectLights};
use pathtracer::environment::{builtin_sky, EnvironmentLight, EnvironmentSampling};
use pathtracer::global::{DirectStrategy, PathTracer, Roulette};
use pathtracer::materials::{BsdfOptions, FresnelModel, MicrofacetSampling};
use pathtracer::world::WorldOptions;

use crate::course::render_direct;
use crate::measure::{mean, pixel_luminance, table, Measurement, Setup};
use crate::plot::{line_chart, Chart, Series};

pub type Result<T> = std::result::Result<T, Box<dyn Error>>;

/// What every study needs to know.
pub struct Options {
    /// `--scenes DIR`; `None`: `$CS184_SCENES` (see `course_files`).
    pub scenes: Option<PathBuf>,
    pub out: PathBuf,
    pub threads: Option<usize>,
    pub size: (u32, u32),
}

impl Options {
    pub fn setup(&self, file: &str) -> Result<Setup> {
        Setup::load(self.scenes.as_deref(), file, self.size, self.threads)
    }
}

const SPHERES: &str = "CBspheres_lambertian.dae";

fn lights(samples_per_light: u32, max_depth: u32, russian_roulette: bool) -> PathTracer {
    PathTracer {
        direct: DirectStrategy::Lights(DirectLights {
            samples_per_light,
            mis: true,
        }),
        max_depth,
        accumulate: true,
        roulette: if russian_roulette {
            Roulette::Fixed
        } else {
            Roulette::Off
        },
    }
}

fn hemisphere(directions: u32) -> PathTracer {
    PathTracer {
        direct: DirectStrategy::Hemisphere(DirectHemisphere {
            samples: directions,
        }),
        max_depth: 1,
        accumulate: true,
        roulette: Roulette::Off,
    }
}

/// Error against seconds, one series per group of measurements.
fn error_vs_time(title: &str, groups: &[(&str, &[Measurement])]) -> Chart {
    Chart {
        title: title.to_string(),
        x_label: "render time (s, wall clock, 2 cores)".into(),
        y_label: "relative RMS error (%)".into(),
        log_x: true,
        log_y: true,
        series: groups
            .iter()
            .map(|(name, ms)| {
                Series::new(
                    *name,
                    ms.iter().map(|m| (m.seconds, 100.0 * m.error)).collect(),
                )
            })
            .collect(),
    }
}

/// Hemisphere sampling (`-H`) against light sampling, direct light only.
///
/// Each estimator is measured against its own reference: in the course's
/// Cornell boxes the emissive mesh that `-H` finds and the area light that
/// light sampling samples are not the same rectangle (docs/04-direct.md),
/// so their limits differ near the ceiling; the study prints by how much.
pub fn direct(options: &Options) -> Result<()> {
    let setup = options.setup(SPHERES)?;
    let light_reference = setup.reference(&lights(4, 1, false), 1024);
    let hemi_reference = setup.reference(&hemisphere(1), 4096);
    println!(
        "\nlimits: hemisphere / light mean luminance {:.4}, RMS difference {:.2} %",
        hemi_reference.mean / light_reference.mean,
        100.0 * light_reference.relative_rms_difference(&hemi_reference)
    );
    let measure = |tracer: &PathTracer, reference, label: &str, spp: u32| {
        let rendered = setup.render(tracer, spp, None, spp as u64);
        Measurement::new(label, spp, &rendered, reference)
    };
    let light: Vec<_> = [4, 16, 64, 256]
        .into_iter()
        .map(|s| {
            measure(
                &lights(1, 1, false),
                &light_reference,
                "light sampling, -l 1",
                s,
            )
        })
        .collect();
    let hemi: Vec<_> = [4, 16, 64, 256, 1024]
        .into_iter()
        .map(|s| measure(&hemisphere(1), &hemi_reference, "hemisphere, -H -l 1", s))
        .collect();
    table(
        "direct: CBspheres_lambertian, direct light only",
        &[light.clone(), hemi.clone()].concat(),
    );
    line_chart(
        &error_vs_time(
            "Direct lighting: hemisphere vs light sampling",
            &[
                ("light sampling (-l 1)", &light),
                ("hemisphere (-H -l 1)", &hemi),
            ],
        ),
        &options.out.join("convergence-direct.png"),
    )
}

/// Camera rays per pixel (`-s`) against samples per light (`-l`).
pub fn samples(options: &Options) -> Result<()> {
    let setup = options.setup(SPHERES)?;
    let reference = setup.reference(&lights(4, 1, false), 1024);
    let mut groups = Vec::new();
    for l in [1, 4, 16] {
        let runs: Vec<_> = [2, 8, 32, 128]
            .into_iter()
            .map(|s| s * 4 / l)
            .filter(|&s| s >= 2)
            .map(|s| {
                let rendered = setup.render(&lights(l, 1, false), s, None, s as u64);
                Measurement::new(&format!("-s {s} -l {l}"), s, &rendered, &reference)
            })
            .collect();
        groups.push((
            if l == 1 {
                "1 sample per light (-l 1)".to_string()
            } else {
                format!("{l} samples per light (-l {l})")
            },
            runs,
        ));
    }
    let all: Vec<_> = groups.iter().flat_map(|g| g.1.clone()).collect();
    table("samples: CBspheres_lambertian, direct light only", &all);
    let named: Vec<(&str, &[Measurement])> = groups
        .iter()
        .map(|(n, r)| (n.as_str(), r.as_slice()))
        .collect();
    line_chart(
        &error_vs_time(
            "Direct lighting: camera rays (-s) vs light samples (-l)",
            &named,
        ),
        &options.out.join("convergence-samples.png"),
    )
}

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

/// How much brighter the course's direct lighting is (area light pdf from
/// an unnormalised direction; point lights without 1/r^2).
pub fn course(options: &Options) -> Result<()> {
    println!("\n| scene | light | mean luminance, course / here | pixel ratio, 5th and 95th percentile |");
    println!("| --- | --- | ---: | ---: |");
    for (file, light) in [(SPHERES, "area"), ("CBempty.dae", "point")] {
        let setup = options.setup(file)?;
        let spp = 256;
        // Light sampling only: the emission of surfaces that stand in for
        // no light (CBempty's ceiling quad) is left out of both.
        let ours = render_direct(&setup, spp, 1, false);
        let theirs = render_direct(&setup, spp, 1, true);
        let (a, b) = (pixel_luminance(&ours), pixel_luminance(&theirs));
        let mut ratios: Vec<f64> = a
            .iter()
            .zip(&b)
            .filter(|(x, _)| **x > 1e-3)
            .map(|(x, y)| y / x)
            .collect();
        ratios.sort_by(f64::total_cmp);
        let pick = |q: f64| ratios[((ratios.len() - 1) as f64 * q) as usize];
        println!(
            "| {file} | {light} | {:.3} | {:.2} – {:.2} |",
            mean(&b) / mean(&a),
            pick(0.05),
            pick(0.95)
        );
        let stem = file.trim_end_matches(".dae");
        for (who, rendered) in [("here", &ours), ("course", &theirs)] {
            let path = options.out.join(format!("direct-only-{stem}-{who}.png"));
            pathtracer::render::write_image(&rendered.film, &path)?;
            eprintln!("wrote {}", path.display());
        }
    }
    Ok(())
}

/// The glossy scene of the materials study: an aluminium sphere of
/// roughness 0.025 and a silver one of 0.25 (the course's file).
const GLOSSY: &str = "CBspheres_microfacet_al_ag.dae";

/// Part 6 on a glossy scene: multiple importance sampling against light
/// sampling alone (`--no-mis`) and BSDF sampling alone (`--bsdf-only`);
/// then the three samplers of the microfacet BSDF
/// (`--microfacet-sampling`), each with MIS. `-l 1 -m 5`, roulette on.
/// One reference for all: the estimators share their expectation
/// (tests/light_transport.rs).
pub fn materials(options: &Options) -> Result<()> {
    let setup = options.setup(GLOSSY)?;
    let with = |direct| PathTracer {
        direct,
        max_depth: 5,
        accumulate: true,
        roulette: Roulette::Fixed,
    };
    let mis = with(DirectStrategy::Lights(DirectLights {
        samples_per_light: 1,
        mis: true,
    }));
    let reference = setup.reference(&mis, 2048);
    let spps = [4, 16, 64, 256];
    let series = |tracer: &PathTracer, sampling, label: &str| -> Vec<Measurement> {
        let world = WorldOptions {
            bsdf: BsdfOptions {
                microfacet: sampling,
                ..BsdfOptions::default()
            },
            ..WorldOptions::default()
        };
        spps.iter()
            .map(|&s| {
                let rendered = setup.render_with(tracer, world, s, s as u64);
                Measurement::new(label, s, &rendered, &reference)
            })
            .collect()
    };
    let visible = MicrofacetSampling::VisibleNormals;
    let light_only = with(DirectStrategy::Lights(DirectLights {
        samples_per_light: 1,
        mis: false,
    }));
    let strategies = [
        series(&mis, visible, "MIS"),
        series(&light_only, visible, "light sampling alone (--no-mis)"),
        series(
            &with(DirectStrategy::BsdfOnly),
            visible,
            "BSDF sampling alone (--bsdf-only)",
        ),
    ];
    table(
        "materials: CBspheres_microfacet_al_ag, -l 1 -m 5, light strategies",
        &strategies.concat(),
    );
    line_chart(
        &error_vs_time(
            "Glossy spheres: MIS vs light sampling vs BSDF sampling",
            &[
                ("MIS (default)", &strategies[0]),
                ("light sampling alone (--no-mis)", &strategies[1]),
                ("BSDF sampling alone (--bsdf-only)", &strategies[2]),
            ],
        ),
        &options.out.join("convergence-mis.png"),
    )?;
    let samplers = [
        series(&mis, MicrofacetSampling::CosineHemisphere, "cosine"),
        series(&mis, MicrofacetSampling::HalfVector, "half vector"),
        series(&mis, visible, "visible normals"),
    ];
    table(
        "materials: CBspheres_microfacet_al_ag, -l 1 -m 5, MIS, microfacet sampling",
        &samplers.concat(),
    );
    line_chart(
        &error_vs_time(
            "Glossy spheres: sampling the microfacet BSDF (with MIS)",
            &[
                ("cosine hemisphere", &samplers[0]),
                ("half vector (course)", &samplers[1]),
                ("visible normals (default)", &samplers[2]),
            ],
        ),
        &options.out.join("convergence-microfacet.png"),
    )?;
    schlick(options)
}

/// `--schlick` against the exact Fresnel equations on the course's glass
/// sphere (`CBspheres.dae`, `-m 5`): mean luminance, RMS difference less
/// the noise, and the pixels that differ by more than 4 standard errors
/// (chart `schlick-difference.png`: red where Schlick is brighter, blue
/// where darker, grey elsewhere).
fn schlick(options: &Options) -> Result<()> {
    let setup = options.setup("CBspheres.dae")?;
    let tracer = lights(1, 5, true);
    let fresnel = |model| WorldOptions {
        bsdf: BsdfOptions {
            fresnel: model,
            ..BsdfOptions::default()
        },
        ..WorldOptions::default()
    };
    let exact = setup.reference_with(&tracer, fresnel(FresnelModel::Exact), 2048);
    let schlick = setup.reference_with(&tracer, fresnel(FresnelModel::Schlick), 2048);
    let mut colours = Vec::with_capacity(exact.luminance.len());
    let (mut brighter, mut darker, mut shift) = (0usize, 0usize, Vec::new());
    for i in 0..exact.luminance.len() {
        let d = schlick.luminance[i] - exact.luminance[i];
        let se = (exact.variance_of_mean[i] + schlick.variance_of_mean[i]).sqrt();
        let grey = (exact.luminance[i] / (4.0 * exact.mean)).min(1.0) as f32;
        colours.push(if exact.mask[i] && d.abs() > 4.0 * se {
            shift.push(d / exact.luminance[i].max(1e-9));
            if d > 0.0 {
                brighter += 1;
                pathtracer::math::Rgb::new(1.0, 0.0, 0.0)
            } else {
                darker += 1;
                pathtracer::math::Rgb::new(0.0, 0.3, 1.0)
            }
        } else {
            pathtracer::math::Rgb::splat(grey)
        });
    }
    shift.sort_by(f64::total_cmp);
    let pick = |q: f64| shift.get(((shift.len().max(1) - 1) as f64 * q) as usize);
    println!(
        "\nschlick: CBspheres, -l 1 -m 5, 2048 spp each: mean luminance Schlick / exact {:.4}, RMS difference less noise {:.2} %, pixels beyond 4 SE: {} brighter, {} darker of {}, relative change there: median {:+.1} %, 5th {:+.1} %, 95th {:+.1} %",
        schlick.mean / exact.mean,
        100.0 * exact.relative_rms_difference(&schlick),
        brighter,
        darker,
        exact.mask.iter().filter(|&&m| m).count(),
        100.0 * pick(0.5).copied().unwrap_or(0.0),
        100.0 * pick(0.05).copied().unwrap_or(0.0),
        100.0 * pick(0.95).copied().unwrap_or(0.0),
    );
    let path = options.out.join("schlick-difference.png");
    pathtracer::render::write_png(setup.width, setup.height, &colours, &path)?;
    eprintln!("wrote {}", path.display());
    Ok(())
}

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
            mis,
        })
    };
    let tracer = |direct| PathTracer {
        direct,
        max_depth: 5,
        accumulate: true,
        roulette: Roulette::Fixed,
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
