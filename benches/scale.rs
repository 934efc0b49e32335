//! The scale benchmark: build time, bytes per triangle, peak memory and
//! ray rates of the BVH from about 10k to 10M triangles
//! ([`pathtracer::bvh::scale`], results in `docs/03-bvh.md`, "Scale").
//!
//! ```text
//! cargo bench --bench scale                  # the table, 10k to 10M triangles
//! cargo bench --bench scale -- --max 1000000 # stop after 1M
//! cargo bench --bench scale -- --build 1024 512 5 [-t N]
//!                                            # build times only, 5 runs
//! cargo bench --bench scale -- --write-dae 1024 512 bumpy-1m.dae
//!                                            # the sphere as a scene file
//! ```
//!
//! `-t N` sets the thread pool the build runs on (default: one thread,
//! the comparison with Embree's build on one core); the ray rates are
//! always traced on one thread and timed in CPU time
//! ([`pathtracer::bvh::scale::closest_hit_rate`]).

use pathtracer::bvh::scale::{build_times, scale_row, write_bumpy_sphere, ScaleRow, SIZES};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let value = |flag: &str, i: usize| -> Option<u64> {
        let at = args.iter().position(|a| a == flag)?;
        args.get(at + 1 + i)?.parse().ok()
    };
    let threads = value("-t", 0).unwrap_or(1) as usize;
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build_global()
        .expect("the global thread pool");
    if let Some(at) = args.iter().position(|a| a == "--write-dae") {
        let phi = value("--write-dae", 0).unwrap_or(1024) as u32;
        let theta = value("--write-dae", 1).unwrap_or(512) as u32;
        let path = args.get(at + 3).expect("--write-dae PHI THETA FILE");
        write_bumpy_sphere(phi, theta, path.as_ref()).expect("writing the scene file");
        println!("wrote {path}: {} triangles", 2 * phi * (theta - 1));
        return;
    }
    if args.iter().any(|a| a == "--build") {
        let phi = value("--build", 0).unwrap_or(1024) as u32;
        let theta = value("--build", 1).unwrap_or(512) as u32;
        let runs = value("--build", 2).unwrap_or(5) as usize;
        let (times, cost) = build_times(phi, theta, runs);
        let list: Vec<String> = times.iter().map(|t| format!("{:.3}", t.wall)).collect();
        let best = times.iter().map(|t| t.wall).fold(f64::INFINITY, f64::min);
        let cpu = match times.iter().filter_map(|t| t.cpu).reduce(f64::min) {
            Some(c) => format!("{c:.3} s"),
            None => "n/a".into(),
        };
        println!(
            "build {phi}x{theta} {threads}T: best {best:.3} s of [{}] (main thread CPU: best {cpu}) SAH cost {cost:.3}",
            list.join(", ")
        );
        return;
    }
    let max = value("--max", 0).unwrap_or(u64::MAX);
    println!("{}", ScaleRow::HEADER);
    for (phi, theta) in SIZES {
        if 2 * u64::from(phi) * u64::from(theta - 1) > max {
            break;
        }
        println!("{}", scale_row(phi, theta));
    }
}
