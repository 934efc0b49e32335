//! The command line the galleries share (`examples/gallery31`,
//! `examples/gallery`): the parts to render, in order, and `-t N`, the
//! worker threads (default 2).

use std::error::Error;
use std::process::ExitCode;
use std::time::Instant;

type Result<T> = std::result::Result<T, Box<dyn Error>>;

/// The parts named on the command line (each of `names`) and the threads.
fn parse(names: &[&str], args: &[String]) -> Result<(Vec<String>, usize)> {
    let usage = format!("{} [-t N]", names.join(" | "));
    let mut threads = 2;
    let mut parts = Vec::new();
    let mut it = args.iter();
    while let Some(arg) = it.next() {
        if arg == "-t" {
            threads = it.next().ok_or("-t needs a value")?.parse()?;
        } else if names.contains(&arg.as_str()) {
            parts.push(arg.clone());
        } else {
            return Err(format!("unexpected argument {arg}; expected {usage}").into());
        }
    }
    if parts.is_empty() {
        return Err(format!("which part? {usage}").into());
    }
    Ok((parts, threads))
}

/// Runs `part(name, threads)` for each part the command line names,
/// printing its name and how long it took; an error ends the run.
pub fn run_parts(names: &[&str], part: impl Fn(&str, usize) -> Result<()>) -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let run = || -> Result<()> {
        let (parts, threads) = parse(names, &args)?;
        for name in parts {
            println!("{name}:");
            let start = Instant::now();
            part(&name, threads)?;
            println!("{name}: {:.0} s", start.elapsed().as_secs_f64());
        }
        Ok(())
    };
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
