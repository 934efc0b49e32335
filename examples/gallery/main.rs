//! The figures the course's 3-2 write-up asks for, parts 6 to 8, one
//! subcommand per chapter:
//!
//! ```text
//! export CS184_SCENES=/path/to/p3_2-pathtracer/dae
//! cargo run --release --example gallery -- part6|part7|part8 [-t N]
//! ```
//!
//! Each subcommand renders its chapter's figures and writes them to
//! `docs/images/` as labelled grids (`w32-*.png`), printing what it did:
//!
//! - `part6` (docs/07-materials.md): `CBspheres.dae` at `-m 0` to `100`;
//!   the microfacet spheres at four roughnesses, sampled three ways, and
//!   made of four metals ([`metals::METALS`]);
//! - `part7` (docs/08-environment.md): the environment map's probability
//!   picture in the course's `probability_debug.png` form and its density,
//!   and `bunny_unlit.dae`, diffuse and copper, under uniform and importance
//!   sampling of the map;
//! - `part8` (docs/09-depth-of-field.md): a focus stack and an aperture
//!   sweep of a scene made in code.
//!
//! `-t N` sets the worker threads (default 2). Scenes are framed as the
//! course frames a 480 x 360 render and rendered at 320 x 240, the same
//! view: the course's field of view follows the output size
//! (docs/01-raygen.md), so asking the binaries for 320 x 240 would crop it.
//! Everything else is what the binaries run: the same loader, BVH, plan,
//! path tracer and tone map (`setup`, shared with `examples/gallery31`).

#[path = "../support/parts.rs"]
mod parts;
#[path = "../gallery31/picture.rs"]
mod picture;
#[path = "../gallery31/setup.rs"]
mod setup;

mod maps;
mod metals;
mod part6;
mod part7;
mod part8;

use std::error::Error;

type Result<T> = std::result::Result<T, Box<dyn Error>>;

/// The size the figures are rendered at: the course's 480 x 360 framing
/// (`setup`'s `FRAME`) at two thirds of the resolution.
const SIZE: (u32, u32) = (320, 240);

fn main() -> std::process::ExitCode {
    parts::run_parts(&["part6", "part7", "part8"], |part, threads| match part {
        "part6" => part6::part6(threads),
        "part7" => part7::part7(threads),
        _ => part8::part8(threads),
    })
}
