//! Renders an image in square tiles on a pool of threads, with a progress
//! bar on a terminal.

use std::time::Instant;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;

use crate::sampling::{PixelSampler, SamplerKind};

/// Side of a square tile, pixels.
pub const TILE_SIZE: u32 = 32;

/// What to render and how.
#[derive(Clone, Copy, Debug)]
pub struct RenderSettings {
    pub width: u32,
    pub height: u32,
    /// Camera rays per pixel (`-s`).
    pub samples_per_pixel: u32,
    /// Worker threads (`-t`); `None` for every core.
    pub threads: Option<usize>,
    /// Seed of every random number of the render.
    pub seed: u64,
    /// Where the random numbers come from (`--sampler`).
    pub sampler: SamplerKind,
    /// Show a progress bar (only ever drawn on a terminal).
    pub progress: bool,
}

impl Default for RenderSettings {
    fn default() -> Self {
        RenderSettings {
            width: 800,
            height: 600,
            samples_per_pixel: 1,
            threads: None,
            seed: 0,
            sampler: SamplerKind::default(),
            progress: false,
        }
    }
}

/// How long a render took.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderStats {
    /// Wall-clock seconds of the render (not counting set-up).
    pub seconds: f64,
    /// Threads used.
    pub threads: usize,
}

/// Renders every pixel with `shade(x, y, sampler)`, where `sampler` is a
/// copy of the render's sampler ([`SamplerKind::for_render`]) that
/// `shade` starts at each of the pixel's samples. Tiles run in parallel
/// on `settings.threads`.
/// Returns the pixels' results row by row, row 0 at the top.
pub fn render_tiles<T: Copy + Default + Send>(
    settings: &RenderSettings,
    shade: impl Fn(u32, u32, &mut PixelSampler) -> T + Sync,
) -> (Vec<T>, RenderStats) {
    let (width, height) = (settings.width, settings.height);
    let tiles: Vec<(u32, u32)> = (0..height.div_ceil(TILE_SIZE))
        .flat_map(|ty| {
            (0..width.div_ceil(TILE_SIZE)).map(move |tx| (tx * TILE_SIZE, ty * TILE_SIZE))
        })
        .collect();
    let bar = progress_bar(settings.progress, tiles.len() as u64);
    let pool = thread_pool(settings);
    let sampler =
        settings
            .sampler
            .for_render(settings.seed, (width, height), settings.samples_per_pixel);
    let start = Instant::now();
    let rendered: Vec<Vec<T>> = pool.install(|| {
        tiles
            .par_iter()
            .map(|&(x0, y0)| {
                let mut pixels = Vec::with_capacity((TILE_SIZE * TILE_SIZE) as usize);
                let mut sampler = sampler.clone();
                for y in y0..(y0 + TILE_SIZE).min(height) {
                    for x in x0..(x0 + TILE_SIZE).min(width) {
                        pixels.push(shade(x, y, &mut sampler));
                    }
                }
                bar.inc(1);
                pixels
            })
            .collect()
    });
    let seconds = start.elapsed().as_secs_f64();
    bar.finish_and_clear();
    let mut image = vec![T::default(); width as usize * height as usize];
    for (&(x0, y0), pixels) in tiles.iter().zip(rendered) {
        let tile_width = (x0 + TILE_SIZE).min(width) - x0;
        for (i, value) in pixels.into_iter().enumerate() {
            let (x, y) = (x0 + i as u32 % tile_width, y0 + i as u32 / tile_width);
            image[(y * width + x) as usize] = value;
        }
    }
    let stats = RenderStats {
        seconds,
        threads: pool.current_num_threads(),
    };
    (image, stats)
}

/// A pool of `settings.threads` threads (every core for `None`).
pub fn thread_pool(settings: &RenderSettings) -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(settings.threads.unwrap_or(0))
        .build()
        .expect("a thread pool")
}

fn progress_bar(enabled: bool, tiles: u64) -> ProgressBar {
    if !enabled {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::with_draw_target(Some(tiles), ProgressDrawTarget::stderr());
    if let Ok(style) =
        ProgressStyle::with_template("{elapsed_precise} [{bar:40}] {percent}% tiles, eta {eta}")
    {
        bar.set_style(style.progress_chars("=> "));
    }
    bar
}
