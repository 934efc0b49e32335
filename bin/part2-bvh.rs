//! Part 2: the BVH. Renders normal shading through a BVH and reports build
//! time, render time, rays per second and the speed-up over part 1.
//! `--bench [-t N]` runs the ray-throughput benchmark instead.

use clap::Parser;
use pathtracer::cli::{drivers, exit_with, CourseArgs};

fn main() -> std::process::ExitCode {
    let mut raw: Vec<String> = std::env::args().collect();
    let bench = raw
        .iter()
        .position(|a| a == "--bench")
        .map(|i| raw.remove(i));
    let args = CourseArgs::parse_from(raw);
    if bench.is_some() {
        exit_with(drivers::bvh_benchmark(args.threads.map(usize::from)))
    } else {
        exit_with(drivers::part2(&args))
    }
}
