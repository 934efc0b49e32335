//! The pictures of a figure and the labelled grid (PNG) they are written
//! as. Shared (`#[path]`) by `examples/gallery31`, `examples/gallery` and
//! `examples/symptoms`.

#[path = "../support/font.rs"]
mod font;

use std::path::{Path, PathBuf};

use pathtracer::adaptive::rate_colour;
use pathtracer::math::Rgb;
use pathtracer::render::{tone_map, write_png, Rendered};
use plotters::prelude::*;

use crate::Result;

/// Height of the label band above each picture of a grid, pixels.
const LABEL: u32 = 20;

/// Display values (tone mapped, in `[0, 1]`) of one picture of a grid.
pub struct Picture {
    label: String,
    pub width: u32,
    pub height: u32,
    pub display: Vec<Rgb>,
    /// Text drawn over the picture (a colour bar's ticks).
    pub notes: Vec<Note>,
}

/// A line of text drawn over a picture, its top left corner at `(x, y)`
/// pixels from the picture's own top left corner.
#[allow(dead_code)] // Made by examples/gallery, not by gallery31 or symptoms.
pub struct Note {
    pub x: i32,
    pub y: i32,
    pub text: String,
}

impl Picture {
    pub fn radiance(label: impl Into<String>, width: u32, height: u32, radiance: &[Rgb]) -> Self {
        Picture {
            label: label.into(),
            width,
            height,
            display: radiance.iter().map(|&l| tone_map(l)).collect(),
            notes: Vec::new(),
        }
    }

    /// Display values as they are, in `[0, 1]` (a colour map).
    #[allow(dead_code)] // Used by examples/symptoms and gallery, not by gallery31.
    pub fn display(label: impl Into<String>, width: u32, height: u32, display: Vec<Rgb>) -> Self {
        Picture {
            label: label.into(),
            width,
            height,
            display,
            notes: Vec::new(),
        }
    }

    pub fn of(label: impl Into<String>, rendered: &Rendered) -> Self {
        let film = &rendered.film;
        Picture::radiance(label, film.width, film.height, &film.pixels)
    }

    /// The course's sample-rate image of an adaptive render.
    #[allow(dead_code)] // Used by examples/gallery31 and symptoms, not by gallery.
    pub fn rate(label: impl Into<String>, rendered: &Rendered, max_samples: u32) -> Self {
        Picture {
            label: label.into(),
            width: rendered.film.width,
            height: rendered.film.height,
            display: rendered
                .estimates
                .iter()
                .map(|e| rate_colour(e.samples, max_samples))
                .collect(),
            notes: Vec::new(),
        }
    }
}

/// Writes `pictures` (all one size) as a grid of `columns`, each with its
/// label above it, to `docs/images/NAME`.
pub fn grid(name: &str, columns: usize, pictures: &[Picture]) -> Result<()> {
    font::register_font()?;
    let (w, h) = (pictures[0].width, pictures[0].height);
    let gap = 4;
    let cols = columns.min(pictures.len()) as u32;
    let rows = pictures.len().div_ceil(columns) as u32;
    let (cell_w, cell_h) = (w + gap, h + LABEL + gap);
    let (width, height) = (cols * cell_w - gap, rows * cell_h - gap);
    let mut buffer = vec![255u8; (width * height * 3) as usize];
    for (i, picture) in pictures.iter().enumerate() {
        let (x0, y0) = (
            (i as u32 % cols) * cell_w,
            (i as u32 / cols) * cell_h + LABEL,
        );
        for y in 0..h {
            for x in 0..w {
                let v = picture.display[(y * w + x) as usize].clamp(Rgb::ZERO, Rgb::ONE) * 255.0;
                let at = (((y0 + y) * width + x0 + x) * 3) as usize;
                buffer[at..at + 3].copy_from_slice(&v.round().to_array().map(|c| c as u8));
            }
        }
    }
    {
        let root = BitMapBackend::with_buffer(&mut buffer, (width, height)).into_drawing_area();
        let style = TextStyle::from(("sans-serif", 15).into_font()).color(&BLACK);
        let small = TextStyle::from(("sans-serif", 12).into_font()).color(&BLACK);
        for (i, picture) in pictures.iter().enumerate() {
            let (x0, y0) = ((i as u32 % cols) * cell_w, (i as u32 / cols) * cell_h);
            root.draw_text(&picture.label, &style, (x0 as i32 + 2, y0 as i32 + 2))?;
            for note in &picture.notes {
                let at = (x0 as i32 + note.x, (y0 + LABEL) as i32 + note.y);
                root.draw_text(&note.text, &small, at)?;
            }
        }
        root.present()?;
    }
    let display: Vec<Rgb> = buffer
        .chunks(3)
        .map(|c| Rgb::new(c[0] as f32, c[1] as f32, c[2] as f32) / 255.0)
        .collect();
    let path = images().join(name);
    write_png(width, height, &display, &path)?;
    println!("wrote {}", path.display());
    Ok(())
}

fn images() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/images")
}
