//! Part 2: the BVH. Renders normal shading through a BVH and reports build
//! time, render time, rays per second and the speed-up over part 1.
//! `--bench [-t N] [--accel wide|binary]` runs the ray-throughput
//! benchmark instead (on the wide BVH unless told), `--scaling`
//! the table of build time and ray rates against triangle count.

use clap::Parser;
use pathtracer::cli::args::BvhArgs;
use pathtracer::cli::{drivers, exit_with};

fn main() -> std::process::ExitCode {
    let args = BvhArgs::parse();
    exit_with(if args.bench {
        drivers::bvh_benchmark(args.course.threads.map(usize::from), args.accel)
    } else if args.scaling {
        drivers::bvh_scaling()
    } else {
        drivers::part2(&args.course)
    })
}
