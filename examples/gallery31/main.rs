//! The figures the course's 3-1 write-up asks for, parts 1 to 5, one
//! subcommand per chapter:
//!
//! ```text
//! export CS184_SCENES=/path/to/p3_1-pathtracer/dae
//! cargo run --release --example gallery31 -- part1|part2|part3|part4|part5 [-t N]
//! ```
//!
//! Each subcommand renders its chapter's figures and writes them to
//! `docs/images/` as labelled grids (`w31-*.png`), printing what it did.
//! `-t N` sets the worker threads (default 2).
//!
//! Scenes are framed as the course frames a 480 x 360 render (the whole
//! Cornell box) and rendered at 240 x 180: the course's field of view
//! follows the output size (docs/01-raygen.md), so asking the binaries for
//! 240 x 180 would crop the view instead. Everything else is what the
//! binaries run: the same loader, BVH, plan
//! ([`Plan::specialise`](pathtracer::plan::Plan::specialise)), path tracer
//! and tone map.

mod part1;
mod part2;
mod part3;
mod part4;
mod part5;
#[path = "../support/parts.rs"]
mod parts;
mod picture;
mod setup;

use std::error::Error;

use part1::part1;
use part2::part2;
use part3::part3;
use part4::part4;
use part5::part5;

type Result<T> = std::result::Result<T, Box<dyn Error>>;

/// The size the figures are rendered at (the course's 480 x 360 framing,
/// `setup`'s `FRAME`, at half the resolution).
const SIZE: (u32, u32) = (240, 180);

fn main() -> std::process::ExitCode {
    let names = ["part1", "part2", "part3", "part4", "part5"];
    parts::run_parts(&names, |part, threads| match part {
        "part1" => part1(threads),
        "part2" => part2(threads),
        "part3" => part3(threads),
        "part4" => part4(threads),
        _ => part5(threads),
    })
}
