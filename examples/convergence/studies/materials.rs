//! Materials (part 6, docs/07-materials.md): MIS against light or BSDF
//! sampling alone and the microfacet samplers on glossy spheres, and
//! Schlick's Fresnel approximation against the exact equations.

use pathtracer::direct::DirectLights;
use pathtracer::global::{DirectStrategy, PathTracer, Roulette};
use pathtracer::materials::{BsdfOptions, FresnelModel, MicrofacetSampling};
use pathtracer::world::WorldOptions;

use super::{error_vs_time, lights, Options, Result};
use crate::measure::{table, Measurement};
use crate::plot::line_chart;

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
        glass_splits: 0,
    };
    let mis = with(DirectStrategy::Lights(DirectLights {
        samples_per_light: 1,
        environment_samples: None,
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
        environment_samples: None,
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
