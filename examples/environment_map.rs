//! The figures and numbers of docs/08-environment.md about environment
//! maps themselves (no scene): the built-in sky and a studio map made here,
//! their importance densities, and how much importance sampling gains.
//!
//! ```text
//! cargo run --release --example environment_map -- [--out DIR] [--hdr FILE]
//! ```
//!
//! Writes, under `--out` (default `docs/images`):
//!
//! - `env-sky.png`, `env-studio.png`: the maps, 512 x 256, tone mapped as
//!   the renders are (`render::tone_map`); row 0 is straight up (+Y),
//!   `u = 1/2` looks along +X;
//! - `env-sky-density.png`, `env-studio-density.png`: the importance
//!   density `p(u, v)` of each texel's centre, grey on a log scale from
//!   `10^-3` (black) to `10^3` (white); the uniform density is 1.
//!
//! and the studio map itself as a Radiance `.hdr` to `--hdr` (default
//! `studio.hdr`), for `-e`.
//!
//! With `--sky FILE`, it writes only an outdoor map of its own
//! (`environment::sky::Sky`) as a Radiance `.hdr`, for measuring the
//! importance sampler on maps it was not tuned on (docs/10):
//!
//! ```text
//! cargo run --release --example environment_map -- --sky FILE [--height H]
//!     [--sun-degrees R] [--black-ground]
//! ```
//!
//! `H` rows (default 1024: a 2k map), a sun of angular radius `R` degrees
//! (default the built-in sky's 2; the real sun's is 0.27) lighting a
//! surface as the built-in sun does, and black below the horizon with
//! `--black-ground`. Says how many texels hold the sun and how much of its
//! power (a texel takes the sky at its centre, so a sun smaller than a
//! texel can be lost: it warns).
//!
//! Without `--sky`, it prints per map: where its light and its sampling
//! probability sit, what sampling the cells by their texels
//! instead of the cell-averaged lookup would miss, and the standard
//! deviation of the one-sample estimators of `integral L dw` and of the
//! irradiance of an upward-facing surface, uniform against importance
//! (`10^6` samples each, fixed seeds).

use std::error::Error;
use std::f32::consts::PI;
use std::path::{Path, PathBuf};

use glam::{Vec2, Vec3};
use pathtracer::environment::sky::{sun_direction, Sky, SUN_RADIUS};
use pathtracer::environment::{
    builtin_sky, uv_to_direction, EnvironmentLight, EnvironmentMap, EnvironmentSampling,
};
use pathtracer::lights::LightPdf;
use pathtracer::math::rng::{next_2d, sampler};
use pathtracer::math::{luminance, Rgb};
use pathtracer::render::{tone_map, write_png};

type Result<T> = std::result::Result<T, Box<dyn Error>>;

/// Samples per estimator.
const N: usize = 1_000_000;

/// Elevation and azimuth (degrees) of `d`: azimuth 0 along +Z (towards
/// the course's camera), 90 along +X, as `sky::sun_direction` counts.
fn elevation_azimuth(d: Vec3) -> (f32, f32) {
    (
        d.y.clamp(-1.0, 1.0).asin().to_degrees(),
        d.x.atan2(d.z).to_degrees(),
    )
}

/// A photographer's studio: black above the horizon but for three
/// softboxes (a warm key light front right, a cool fill left, a white rim
/// light behind), a dim grey floor below.
fn studio_radiance(d: Vec3) -> Rgb {
    let (elevation, azimuth) = elevation_azimuth(d);
    let inside = |e: (f32, f32), a: (f32, f32)| {
        (e.0..=e.1).contains(&elevation) && (a.0..=a.1).contains(&azimuth)
    };
    if inside((15.0, 45.0), (20.0, 50.0)) {
        Rgb::new(24.0, 20.0, 15.0)
    } else if inside((5.0, 30.0), (-75.0, -45.0)) {
        Rgb::new(2.5, 3.0, 4.0)
    } else if inside((20.0, 35.0), (150.0, 180.0)) || inside((20.0, 35.0), (-180.0, -170.0)) {
        Rgb::splat(12.0)
    } else if elevation < 0.0 {
        Rgb::splat(0.03)
    } else {
        Rgb::ZERO
    }
}

/// The studio map, 512 x 256.
fn studio() -> Result<EnvironmentMap> {
    Ok(EnvironmentMap::from_fn(
        "studio",
        512,
        256,
        studio_radiance,
    )?)
}

fn write_hdr(map: &EnvironmentMap, path: &Path) -> Result<()> {
    let pixels: Vec<image::Rgb<f32>> = (0..map.height() as i64)
        .flat_map(|j| (0..map.width() as i64).map(move |i| (i, j)))
        .map(|(i, j)| image::Rgb(map.texel(i, j).to_array()))
        .collect();
    let file = std::io::BufWriter::new(std::fs::File::create(path)?);
    image::codecs::hdr::HdrEncoder::new(file).encode(&pixels, map.width(), map.height())?;
    Ok(())
}

/// Centre of texel `(i, j)` in `(u, v)`.
fn centre(map: &EnvironmentMap, i: usize, j: usize) -> Vec2 {
    Vec2::new(
        (i as f32 + 0.5) / map.width() as f32,
        (j as f32 + 0.5) / map.height() as f32,
    )
}

/// The map tone mapped, and its importance density on a log scale.
fn pictures(light: &EnvironmentLight, name: &str, out: &Path) -> Result<()> {
    let map = light.map();
    let (w, h) = (map.width(), map.height());
    let mut shown = Vec::with_capacity(w * h);
    let mut density = Vec::with_capacity(w * h);
    for j in 0..h {
        for i in 0..w {
            let uv = centre(map, i, j);
            shown.push(tone_map(map.texel(i as i64, j as i64)));
            let sin_theta = (PI * uv.y).sin();
            let p = light.pdf_li(uv_to_direction(uv)) * 2.0 * PI * PI * sin_theta;
            let grey = if p > 0.0 {
                ((p.log10() + 3.0) / 6.0).clamp(0.0, 1.0)
            } else {
                0.0
            };
            density.push(Rgb::splat(grey));
        }
    }
    for (file, pixels) in [
        (format!("env-{name}.png"), &shown),
        (format!("env-{name}-density.png"), &density),
    ] {
        let path = out.join(file);
        write_png(w as u32, h as u32, pixels, &path)?;
        eprintln!("wrote {}", path.display());
    }
    Ok(())
}

/// Where the light and the probability of the importance sampler sit:
/// the share of `integral L dw` (luminance) and of the probability in the
/// texels with `selected(direction)`.
fn shares(light: &EnvironmentLight, selected: impl Fn(Vec3) -> bool) -> (usize, f64, f64) {
    let map = light.map();
    let (w, h) = (map.width(), map.height());
    let (mut count, mut light_in, mut light_all, mut probability) = (0, 0.0, 0.0, 0.0);
    for j in 0..h {
        for i in 0..w {
            let uv = centre(map, i, j);
            let d = uv_to_direction(uv);
            let sin_theta = f64::from((PI * uv.y).sin());
            let l = f64::from(luminance(map.texel(i as i64, j as i64))) * sin_theta;
            light_all += l;
            if selected(d) {
                count += 1;
                light_in += l;
                probability +=
                    f64::from(light.pdf_li(d)) * 2.0 * std::f64::consts::PI.powi(2) * sin_theta
                        / (w * h) as f64;
            }
        }
    }
    (count, light_in / light_all, probability)
}

/// Cells whose texel is black but whose bilinear lookup is not, and the
/// share of `integral L dw` (of the lookup, 8 x 8 points a cell) they hold:
/// what a sampler weighting cells by their texels would never sample.
fn missed_by_texel_weights(map: &EnvironmentMap) -> (usize, f64) {
    let (w, h) = (map.width(), map.height());
    let (mut cells, mut missed, mut all) = (0, 0.0, 0.0);
    for j in 0..h {
        for i in 0..w {
            let mut integral = 0.0;
            for k in 0..64 {
                let uv = Vec2::new(
                    (i as f32 + ((k % 8) as f32 + 0.5) / 8.0) / w as f32,
                    (j as f32 + ((k / 8) as f32 + 0.5) / 8.0) / h as f32,
                );
                integral += f64::from(luminance(map.lookup(uv)) * (PI * uv.y).sin());
            }
            all += integral;
            if luminance(map.texel(i as i64, j as i64)) == 0.0 && integral > 0.0 {
                cells += 1;
                missed += integral;
            }
        }
    }
    (cells, missed / all)
}

/// Mean and standard deviation of the one-sample estimator
/// `luminance(L(wi)) g(wi) / p(wi)` under `sampling`.
fn moments(light: &EnvironmentLight, g: impl Fn(Vec3) -> f32, seed: u64) -> (f64, f64) {
    let mut rng = sampler(seed, 0);
    let (mut s1, mut s2) = (0.0f64, 0.0f64);
    for _ in 0..N {
        let x = light
            .sample_li(next_2d(&mut rng))
            .map_or(0.0, |s| match s.pdf {
                LightPdf::SolidAngle(p) => f64::from(luminance(s.radiance) * g(s.wi) / p),
                LightPdf::Delta => unreachable!("an environment sample is not a delta"),
            });
        s1 += x;
        s2 += x * x;
    }
    let mean = s1 / N as f64;
    let variance = (s2 / N as f64 - mean * mean).max(0.0) * N as f64 / (N - 1) as f64;
    (mean, variance.sqrt())
}

fn report(name: &str, map: EnvironmentMap, out: &Path) -> Result<()> {
    let light = EnvironmentLight::new(map, EnvironmentSampling::Importance);
    let uniform = light.with_sampling(EnvironmentSampling::Uniform);
    pictures(&light, name, out)?;
    let map = light.map();
    let total = f64::from(luminance(light.power(1.0))) / std::f64::consts::PI;
    println!(
        "\n{name}: {} x {}, integral of L dw (luminance) {total:.4}",
        map.width(),
        map.height()
    );
    let (cells, missed) = missed_by_texel_weights(map);
    println!(
        "{name}: {cells} cells with a black texel and a positive lookup hold {:.3} % of integral L dw (missed by texel weights)",
        100.0 * missed
    );
    if name == "sky" {
        for (label, radius) in [
            ("the sun's disk", SUN_RADIUS),
            ("twice its radius", 2.0 * SUN_RADIUS),
        ] {
            let (count, light_share, probability) = shares(&light, |d| {
                d.dot(sun_direction()).clamp(-1.0, 1.0).acos() <= radius
            });
            println!(
                "{name}: {count} texels within {label} ({:.3} % of {}): {:.1} % of integral L dw, sampling probability {:.1} %",
                100.0 * count as f64 / (map.width() * map.height()) as f64,
                map.width() * map.height(),
                100.0 * light_share,
                100.0 * probability
            );
        }
    }
    println!("\n| {name} | estimator | mean ± SE, uniform | mean ± SE, importance | std dev, uniform | std dev, importance | variance ratio |");
    println!("| --- | --- | ---: | ---: | ---: | ---: | ---: |");
    let one = |_: Vec3| 1.0;
    let cos_up = |w: Vec3| w.y.max(0.0);
    let estimators: [(&str, &dyn Fn(Vec3) -> f32); 2] =
        [("integral L dw", &one), ("irradiance, facing up", &cos_up)];
    for (k, (label, g)) in estimators.into_iter().enumerate() {
        let (m_u, s_u) = moments(&uniform, g, 2 * k as u64);
        let (m_i, s_i) = moments(&light, g, 2 * k as u64 + 1);
        let se = |s: f64| s / (N as f64).sqrt();
        println!(
            "| {name} | {label} | {m_u:.3} ± {:.3} | {m_i:.4} ± {:.4} | {s_u:.3} | {s_i:.3} | {:.0} |",
            se(s_u),
            se(s_i),
            (s_u * s_u) / (s_i * s_i)
        );
    }
    Ok(())
}

const USAGE: &str = "usage: environment_map [--out DIR] [--hdr FILE]\n       \
     environment_map --sky FILE [--height H] [--sun-degrees R] [--black-ground]";

fn main() -> Result<()> {
    let mut out = PathBuf::from("docs/images");
    let mut hdr = PathBuf::from("studio.hdr");
    let (mut sky_file, mut sky, mut height) = (None::<PathBuf>, Sky::default(), 1024);
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        let mut value = |what: &str| args.next().ok_or(format!("{arg} needs {what}\n{USAGE}"));
        match arg.as_str() {
            "--out" => out = value("a directory")?.into(),
            "--hdr" => hdr = value("a file")?.into(),
            "--sky" => sky_file = Some(value("a file")?.into()),
            "--height" => height = value("a number of rows")?.parse()?,
            "--sun-degrees" => {
                let degrees: f32 = value("an angle in degrees")?.parse()?;
                if !(degrees > 0.0 && degrees < 90.0) {
                    return Err(format!("--sun-degrees {degrees}: not in (0, 90)").into());
                }
                sky = sky.with_sun_radius(degrees.to_radians());
            }
            "--black-ground" => sky.ground = Rgb::ZERO,
            other => return Err(format!("unexpected argument {other}\n{USAGE}").into()),
        }
    }
    if let Some(file) = sky_file {
        let map = sky.map(&file.display().to_string(), height)?;
        write_hdr(&map, &file)?;
        eprintln!("wrote {} ({} x {height})", file.display(), 2 * height);
        let sun = sky.sun_in_map(height);
        eprintln!(
            "the sun: {} texels, holding {:.1} % of its power (each texel takes the sky at its centre)",
            sun.texels,
            100.0 * sun.power_in_map / sun.power
        );
        if sun.texels == 0 {
            eprintln!("warning: no texel's centre lies in the sun: this map has no sun (more rows, or a larger --sun-degrees, give it one)");
        }
        return Ok(());
    }
    std::fs::create_dir_all(&out)?;
    report("sky", builtin_sky()?, &out)?;
    let studio = studio()?;
    write_hdr(&studio, &hdr)?;
    eprintln!("wrote {}", hdr.display());
    report("studio", studio, &out)
}
