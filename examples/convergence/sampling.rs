//! The `sampling` study: the sampler (independent against ZSobol) and
//! the Russian roulette rule (fixed against throughput) at equal samples
//! per pixel on `CBspheres_lambertian.dae`, `-l 1 -m 8` with MIS:
//! error, render time and efficiency `1 / (MSE x time)`.
//!
//! The four combinations render one after another in each of `ROUNDS`
//! rounds (A/B interleaved, so a busy machine slows them alike), each
//! round with its own seed; a row gives the mean time and the RMS of the
//! rounds' errors. The reference is rendered with the independent sampler
//! so that its standard errors, subtracted from the squared error
//! ([`crate::measure`]), hold.

use pathtracer::direct::DirectLights;
use pathtracer::global::{DirectStrategy, PathTracer, Roulette};
use pathtracer::sampling::SamplerKind;

use crate::measure::{Measurement, Reference};
use crate::setup::Setup;
use crate::studies::{Options, Result};

const ROUNDS: u64 = 3;
const REFERENCE_SPP: u32 = 1024;

fn tracer(roulette: Roulette) -> PathTracer {
    PathTracer {
        direct: DirectStrategy::Lights(DirectLights {
            samples_per_light: 1,
            environment_samples: None,
            mis: true,
        }),
        max_depth: 8,
        accumulate: true,
        roulette,
        glass_splits: 0,
    }
}

/// The four combinations, the course's first.
const COMBINATIONS: [(SamplerKind, Roulette, &str); 4] = [
    (
        SamplerKind::Independent,
        Roulette::Fixed,
        "independent, fixed (--course)",
    ),
    (
        SamplerKind::Independent,
        Roulette::Throughput,
        "independent, throughput",
    ),
    (SamplerKind::ZSobol, Roulette::Fixed, "zsobol, fixed"),
    (
        SamplerKind::ZSobol,
        Roulette::Throughput,
        "zsobol, throughput (default)",
    ),
];

/// Mean seconds and mean squared relative error of one combination.
#[derive(Clone, Copy, Default)]
struct Sums {
    seconds: f64,
    squared_error: f64,
}

pub fn sampling(options: &Options) -> Result<()> {
    let mut setup = options.setup("CBspheres_lambertian.dae")?;
    let reference = setup.reference(&tracer(Roulette::Fixed), REFERENCE_SPP);
    for spp in [16, 64] {
        let sums = measure(&mut setup, &reference, spp);
        print_table(spp, &sums);
    }
    Ok(())
}

fn measure(setup: &mut Setup, reference: &Reference, spp: u32) -> [Sums; 4] {
    let mut sums = [Sums::default(); 4];
    for round in 0..ROUNDS {
        for (sum, &(sampler, roulette, label)) in sums.iter_mut().zip(&COMBINATIONS) {
            setup.sampler = sampler;
            let rendered = setup.render(&tracer(roulette), spp, None, 1 + round);
            let m = Measurement::new(label, spp, &rendered, reference);
            sum.seconds += m.seconds / ROUNDS as f64;
            sum.squared_error += m.error * m.error / ROUNDS as f64;
        }
    }
    sums
}

fn print_table(spp: u32, sums: &[Sums; 4]) {
    println!(
        "\nCBspheres_lambertian, {spp} spp, -l 1 -m 8, {ROUNDS} rounds interleaved, \
         reference {REFERENCE_SPP} spp\n"
    );
    println!("| sampler, roulette | time (s) | relative RMS error | MSE / course's | time / course's | efficiency / course's |");
    println!("| --- | ---: | ---: | ---: | ---: | ---: |");
    let course = sums[0];
    for (s, (_, _, label)) in sums.iter().zip(&COMBINATIONS) {
        let mse = s.squared_error / course.squared_error;
        let time = s.seconds / course.seconds;
        println!(
            "| {label} | {:.2} | {:.3} % | {mse:.3} | {time:.3} | {:.2}x |",
            s.seconds,
            100.0 * s.squared_error.sqrt(),
            1.0 / (mse * time)
        );
    }
}
