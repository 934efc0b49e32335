//! A fuzz test of the project's own, on the stable toolchain: seeded,
//! structure-aware mutations of the course's scenes, of environment maps
//! and of command-line values, each run through the real `pathtracer`
//! binary on a tiny render ([`run`]). No input may crash it (a panic, an
//! abort, a stack overflow), hang it, or make it write a non-finite or
//! negative pixel; nonsense (a misspelt field, an unphysical value) must
//! be refused or warned about; legal input must render.
//!
//! `cargo test --profile quick --test fuzz` runs a bounded number of inputs
//! (seconds) after the corpus of known cases. For a longer run:
//!
//! ```text
//! FUZZ_CASES=2000 FUZZ_SEED=7 cargo test --profile quick --test fuzz -- --nocapture
//! ```
//!
//! Its figures are in docs/16-bad-input.md.

/// The tests' minimal scene (`tests/common/collada.rs`).
#[path = "../common/collada.rs"]
#[allow(dead_code)]
mod common;
mod corpus;
mod flags;
mod maps;
mod run;
mod scenes;

use rand::SeedableRng;
use rand_pcg::Pcg64;

use run::{run, small_flags_except, small_render, Outcome, Workspace};

/// Inputs of each kind in a test run, unless `FUZZ_CASES` says.
const CASES: usize = 200;

fn cases() -> usize {
    std::env::var("FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(CASES)
}

fn rng(stream: u64) -> Pcg64 {
    let seed: u64 = std::env::var("FUZZ_SEED")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(25);
    Pcg64::seed_from_u64(seed * 1000 + stream)
}

/// What a batch of inputs did.
#[derive(Default)]
struct Tally {
    inputs: usize,
    refused: usize,
    rendered: usize,
    nonsense: usize,
    silent_nonsense: Vec<String>,
    legal_refused: Vec<String>,
    failures: Vec<String>,
}

impl Tally {
    fn add(&mut self, what: &str, outcome: Outcome, nonsense: bool, legal: bool) {
        self.inputs += 1;
        self.nonsense += usize::from(nonsense);
        match &outcome {
            Outcome::Refused(message) => {
                self.refused += 1;
                if legal {
                    self.legal_refused.push(format!("{what}: {message}"));
                }
            }
            Outcome::Rendered { warned } => {
                self.rendered += 1;
                if nonsense && !warned {
                    self.silent_nonsense.push(what.to_string());
                }
            }
            failure => self.failures.push(format!("{what}: {failure:?}")),
        }
    }

    /// Prints the figures and fails on any failure, silent nonsense or
    /// legal input refused.
    fn check(&self, kind: &str) {
        println!(
            "{kind}: {} inputs, {} refused, {} rendered; {} nonsense, {} of it silent; \
             {} legal refused; {} crashes, hangs, bad pixels or unclear errors",
            self.inputs,
            self.refused,
            self.rendered,
            self.nonsense,
            self.silent_nonsense.len(),
            self.legal_refused.len(),
            self.failures.len()
        );
        assert!(self.failures.is_empty(), "{kind}: {:#?}", self.failures);
        assert!(
            self.silent_nonsense.is_empty(),
            "{kind} rendered in silence: {:#?}",
            self.silent_nonsense
        );
        assert!(
            self.legal_refused.is_empty(),
            "{kind} refused: {:#?}",
            self.legal_refused
        );
    }
}

/// `scene` in the course's dialect.
fn exported(scene: &pathtracer::scene::Scene) -> String {
    let mut out = Vec::new();
    pathtracer::scene::export_scene::write_scene_dae(scene, &mut out).unwrap();
    String::from_utf8(out).unwrap()
}

/// The scenes mutations start from: the tests' minimal scene, the
/// materials box and the Cornell box exported to the course's dialect,
/// and the course's `CBspheres.dae` where it is found.
fn base_scenes() -> Vec<String> {
    let mut bases = vec![
        common::MINIMAL.to_string(),
        exported(&pathtracer::scene::builtin::materials_box()),
        exported(&pathtracer::scene::builtin::cornell_box()),
    ];
    if let Some(path) = pathtracer::scene::course_files::find("CBspheres.dae") {
        bases.push(std::fs::read_to_string(path).unwrap());
    }
    bases
}

/// Runs a scene file's bytes; the outcome and the file name.
fn run_scene(space: &Workspace, bytes: &[u8], extra: &[String]) -> Outcome {
    let scene = space.path("scene.dae");
    std::fs::write(&scene, bytes).unwrap();
    let image = space.path("out.exr");
    let about = format!("{}: <", scene.display());
    run(&small_render(Some(&scene), &image, extra), &image, &about)
}

/// Runs a map's bytes lighting the built-in scene.
fn run_map(space: &Workspace, bytes: &[u8], extension: &str) -> Outcome {
    let map = space.path(&format!("map.{extension}"));
    std::fs::write(&map, bytes).unwrap();
    let image = space.path("out.exr");
    let extra = ["-e".to_string(), map.display().to_string()];
    run(
        &small_render(None, &image, &extra),
        &image,
        &map.display().to_string(),
    )
}

/// Runs the built-in scene with the fuzzed `flags` and the small render's
/// other flags; no warning is about the input.
fn run_flags(space: &Workspace, flags: &[String]) -> Outcome {
    let image = space.path("out.exr");
    let mut args = small_flags_except(flags);
    args.extend(flags.iter().cloned());
    args.extend(["-f".to_string(), image.display().to_string()]);
    run(&args, &image, "<none>")
}

#[test]
fn the_corpus_of_known_cases() {
    let space = Workspace::new();
    let mut tally = Tally::default();
    for case in corpus::scene_cases() {
        let outcome = run_scene(&space, case.text.as_bytes(), &[]);
        tally.add(&case.what, outcome, case.nonsense, false);
    }
    for case in corpus::map_cases() {
        let outcome = run_map(&space, &case.bytes, case.extension);
        tally.add(&case.what, outcome, case.nonsense, case.legal);
    }
    for flags in corpus::flag_cases(&space) {
        let outcome = run_flags(&space, &flags);
        tally.add(&flags.join(" "), outcome, true, false);
    }
    tally.check("corpus");
}

#[test]
fn mutated_scenes() {
    let space = Workspace::new();
    let mut rng = rng(1);
    let mut tally = Tally::default();
    let bases = base_scenes();
    for i in 0..cases() {
        let base = &bases[i % bases.len()];
        let mutant = scenes::mutate(base, &mut rng);
        let outcome = run_scene(&space, &mutant.bytes, &[]);
        let what = format!("scene {} (base {}): {}", i, i % bases.len(), mutant.what);
        if let Ok(dir) = std::env::var("FUZZ_KEEP") {
            std::fs::write(format!("{dir}/scene{i}.dae"), &mutant.bytes).unwrap();
        }
        tally.add(&what, outcome, mutant.nonsense, mutant.legal);
    }
    tally.check("scenes");
}

#[test]
fn mutated_maps() {
    let space = Workspace::new();
    let mut rng = rng(2);
    let mut tally = Tally::default();
    for _ in 0..cases() {
        let mutant = maps::mutate(&mut rng);
        let outcome = run_map(&space, &mutant.bytes, mutant.extension);
        tally.add(&mutant.what, outcome, mutant.nonsense, mutant.legal);
    }
    tally.check("maps");
}

#[test]
fn mutated_flags() {
    let space = Workspace::new();
    let mut rng = rng(3);
    let mut tally = Tally::default();
    for _ in 0..cases() {
        let mutant = flags::mutate(&mut rng);
        let outcome = run_flags(&space, &mutant.flags);
        if let Outcome::Refused(message) = &outcome {
            assert!(
                flags::quotes_as_typed(message, &mutant.flags),
                "{}: not quoted as typed: {message}",
                mutant.what
            );
        }
        tally.add(&mutant.what, outcome, false, false);
    }
    tally.check("flags");
}
