//! Part 3 (direct lighting): hemisphere against light sampling, and soft
//! shadows.

use pathtracer::direct::DirectHemisphere;
use pathtracer::global::DirectStrategy;

use crate::picture::{grid, Picture};
use crate::setup::{direct, lights, Setup};
use crate::Result;

/// Part 3: hemisphere against light sampling at equal samples, and soft
/// shadows at one sample per pixel against samples per light.
pub fn part3(threads: usize) -> Result<()> {
    let mut pictures = Vec::new();
    for file in ["CBspheres_lambertian.dae", "CBbunny.dae"] {
        let setup = Setup::load(file, threads)?;
        let lamps = setup.scene.lights.len().max(1) as u32;
        let hemisphere = direct(DirectStrategy::Hemisphere(DirectHemisphere {
            samples: lamps * 8,
        }));
        let short = file.trim_end_matches(".dae");
        let r = setup.render(&hemisphere, 16, None, 1);
        pictures.push(Picture::of(format!("{short}, -H"), &r));
        let r = setup.render(&direct(lights(8)), 16, None, 1);
        pictures.push(Picture::of(format!("{short}, lights"), &r));
    }
    grid("w31-part3-hemisphere-lights.png", 4, &pictures)?;

    let setup = Setup::load("CBbunny.dae", threads)?;
    let mut pictures = Vec::new();
    for l in [1, 4, 16, 64] {
        let r = setup.render(&direct(lights(l)), 1, None, 2);
        pictures.push(Picture::of(format!("-s 1 -l {l}"), &r));
    }
    grid("w31-part3-soft-shadows.png", 4, &pictures)
}
