//! The film: one linear RGB radiance value per pixel, row 0 at the top.

use crate::math::Rgb;

/// A rendered image in linear radiance.
#[derive(Clone, Debug, PartialEq)]
pub struct Film {
    pub width: u32,
    pub height: u32,
    /// Row-major, `pixels[y * width + x]`, row 0 at the top.
    pub pixels: Vec<Rgb>,
}

impl Film {
    /// A black film.
    pub fn new(width: u32, height: u32) -> Self {
        Film {
            width,
            height,
            pixels: vec![Rgb::ZERO; width as usize * height as usize],
        }
    }

    pub fn get(&self, x: u32, y: u32) -> Rgb {
        self.pixels[y as usize * self.width as usize + x as usize]
    }

    /// Number of pixels with a NaN or infinite channel.
    pub fn non_finite_count(&self) -> usize {
        self.pixels.iter().filter(|p| !p.is_finite()).count()
    }

    /// The mean over `cols x rows` equal blocks of the image (a robust
    /// summary for snapshot tests): row-major, `rows * cols` values.
    pub fn block_means(&self, cols: u32, rows: u32) -> Vec<Rgb> {
        let mut sums = vec![(Rgb::ZERO, 0u32); (cols * rows) as usize];
        for y in 0..self.height {
            for x in 0..self.width {
                let block = (y * rows / self.height) * cols + x * cols / self.width;
                let entry = &mut sums[block as usize];
                entry.0 += self.get(x, y);
                entry.1 += 1;
            }
        }
        sums.into_iter()
            .map(|(sum, n)| if n == 0 { Rgb::ZERO } else { sum / n as f32 })
            .collect()
    }
}
