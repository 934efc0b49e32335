//! Part 1 (ray generation and intersection): normal shading of small
//! scenes.

use pathtracer::cli::drivers::render_normals;
use pathtracer::intersect::{LinearScan, TriangleTest};

use crate::picture::{grid, Picture};
use crate::setup::Setup;
use crate::Result;

/// Part 1: normal shading of small scenes by linear scan and
/// Möller-Trumbore, as `part1-raygen` renders it.
pub fn part1(threads: usize) -> Result<()> {
    let mut pictures = Vec::new();
    for file in [
        "CBempty.dae",
        "CBspheres_lambertian.dae",
        "cube.dae",
        "plane.dae",
    ] {
        let setup = Setup::load(file, threads)?;
        let mut primitives = setup.accel.primitives.clone();
        primitives.triangle_test = TriangleTest::MollerTrumbore;
        let rendered = render_normals(
            LinearScan::new(&primitives),
            &setup.camera,
            &setup.settings(1, 0),
        );
        println!(
            "  {file}: {} primitives, {:.2} s",
            primitives.len(),
            rendered.stats.seconds
        );
        pictures.push(Picture::of(file, &rendered));
    }
    grid("w31-part1-normals.png", 4, &pictures)
}
