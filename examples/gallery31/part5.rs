//! Part 5 (adaptive sampling): renders and their sample-rate images.

use pathtracer::adaptive::Adaptive;

use crate::picture::{grid, Picture};
use crate::setup::{paths, Setup};
use crate::Result;

/// Part 5: two scenes at 2048 samples per pixel with adaptive sampling
/// (the course's default `-a 32 0.05`), with their rate images.
pub fn part5(threads: usize) -> Result<()> {
    let spp = 2048;
    let mut pictures = Vec::new();
    for file in ["CBbunny.dae", "CBspheres_lambertian.dae"] {
        let setup = Setup::load(file, threads)?;
        let r = setup.render(&paths(4, 5, true), spp, Some(Adaptive::default()), 60);
        let short = file.trim_end_matches(".dae");
        pictures.push(Picture::of(short, &r));
        let mean = r.mean_samples_per_pixel();
        pictures.push(Picture::rate(format!("rate: mean {mean:.0} spp"), &r, spp));
    }
    grid("w31-part5-adaptive.png", 4, &pictures)
}
