//! Direct lighting (part 3, docs/04-direct.md): hemisphere against light
//! sampling, camera rays against light samples, and how much brighter the
//! course's direct lighting is.

use pathtracer::global::PathTracer;

use super::{error_vs_time, hemisphere, lights, Options, Result, SPHERES};
use crate::course::render_direct;
use crate::measure::{mean, pixel_luminance, table, Measurement};
use crate::plot::line_chart;

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
