//! Our render of `CBbunny.dae` against the course's own 480 x 360 render
//! (`CBbunny_reference_480x360.png`): the same picture up to noise.
//! Compared by the mean display luminance (brightness) and by the
//! correlation of block means of display luminance, which is blind to
//! per-pixel noise but not to framing, shadows or colour layout.

mod common;

use pathtracer::cli::drivers::render_lighting;
use pathtracer::direct::DirectLights;
use pathtracer::global::{DirectStrategy, PathTracer, Roulette};
use pathtracer::math::{luminance, Rgb};
use pathtracer::render::{tone_map, Film, RenderSettings};
use pathtracer::world::World;

const COLS: u32 = 24;
const ROWS: u32 = 18;

fn correlation(a: &[f32], b: &[f32]) -> f32 {
    let mean = |v: &[f32]| v.iter().sum::<f32>() / v.len() as f32;
    let (ma, mb) = (mean(a), mean(b));
    let cov: f32 = a.iter().zip(b).map(|(x, y)| (x - ma) * (y - mb)).sum();
    let va: f32 = a.iter().map(|x| (x - ma) * (x - ma)).sum();
    let vb: f32 = b.iter().map(|y| (y - mb) * (y - mb)).sum();
    cov / (va * vb).sqrt()
}

fn block_luminance(film: &Film) -> Vec<f32> {
    film.block_means(COLS, ROWS)
        .into_iter()
        .map(luminance)
        .collect()
}

#[test]
fn cbbunny_looks_like_the_course_render() {
    let Some(fixture) = common::cbbunny_reference() else {
        return;
    };
    let (w, h) = (fixture.width, fixture.height);
    let reference = Film {
        width: w,
        height: h,
        pixels: fixture
            .reference
            .to_rgb32f()
            .pixels()
            .map(|p| Rgb::from_array(p.0))
            .collect(),
    };
    let (scene, camera, accel) = (&fixture.scene, &fixture.camera, &fixture.accel);
    let view = World::new(scene, accel);
    let tracer = PathTracer {
        direct: DirectStrategy::Lights(DirectLights {
            samples_per_light: 1,
            mis: true,
        }),
        max_depth: 5,
        accumulate: true,
        roulette: Roulette::Fixed,
    };
    let settings = RenderSettings {
        width: w,
        height: h,
        samples_per_pixel: 4,
        seed: 1,
        ..RenderSettings::default()
    };
    let rendered = render_lighting(&view, &tracer, camera, &settings, None);
    let ours = Film {
        pixels: rendered.film.pixels.iter().map(|&l| tone_map(l)).collect(),
        ..rendered.film
    };
    let mean = |film: &Film| {
        film.pixels.iter().map(|&p| luminance(p)).sum::<f32>() / film.pixels.len() as f32
    };
    let brightness = mean(&ours) / mean(&reference);
    eprintln!("mean display luminance, ours / course: {brightness:.4}");
    // The course's render has the physically correct brightness: 0.987 at
    // 4 spp here (tone mapping darkens noise a little; 1.002 at 64 spp),
    // while the course starter's light weighting (`--course-lights`) gives 1.15.
    assert!(
        (brightness - 1.0).abs() < 0.04,
        "brightness ratio {brightness}"
    );
    let r = correlation(&block_luminance(&ours), &block_luminance(&reference));
    eprintln!("correlation of {COLS} x {ROWS} block luminances with the course render: {r:.4}");
    // 0.98 here; a field of view 10 % too wide already gives 0.88.
    assert!(r > 0.95, "correlation {r}");
}
