//! One fuzz input run through the real `pathtracer` binary, and what came
//! of it: refused with an error, rendered (with or without a warning about
//! the scene), or one of the failures the fuzz exists to find: a panic or
//! an abort, a hang, an image with a non-finite or negative value, an
//! error that is not a clear `error:` line.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use pathtracer::cli::drivers::OUT_OF_RANGE_PIXELS;

const PATHTRACER: &str = env!("CARGO_BIN_EXE_pathtracer");

/// The longest a tiny render may take before it counts as a hang.
const TIME_LIMIT: Duration = Duration::from_secs(60);

/// The flags of every fuzz render, with their values: tiny, one thread,
/// few samples, with light sampling and bounces so every material is
/// evaluated.
const SMALL: [(&str, &[&str]); 5] = [
    ("-r", &["8", "6"]),
    ("-s", &["4"]),
    ("-m", &["3"]),
    ("-l", &["1"]),
    ("-t", &["1"]),
];

/// The small render's flags, minus those `fuzzed` sets.
pub fn small_flags_except(fuzzed: &[String]) -> Vec<String> {
    SMALL
        .iter()
        .filter(|(flag, _)| !fuzzed.iter().any(|f| f == flag))
        .flat_map(|(flag, values)| std::iter::once(*flag).chain(values.iter().copied()))
        .map(str::to_string)
        .collect()
}

/// What one input did.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// Exit code 1 (or 2, clap's for a command line) with an `error:`
    /// message.
    Refused(String),
    /// An image was written, all of it finite and non-negative; `warned`:
    /// the input itself was warned about.
    Rendered { warned: bool },
    /// A panic, an abort or death by a signal.
    Crashed(String),
    /// Still running after [`TIME_LIMIT`].
    Hung,
    /// An image holding a NaN, an infinity or a negative value.
    BadPixels(String),
    /// A failure without a clear message, or success without an image.
    Unclear(String),
}

/// A place for one run's files.
pub struct Workspace {
    pub dir: tempfile::TempDir,
}

impl Workspace {
    pub fn new() -> Self {
        Workspace {
            dir: tempfile::tempdir().unwrap(),
        }
    }

    /// `name` inside the workspace.
    pub fn path(&self, name: &str) -> PathBuf {
        self.dir.path().join(name)
    }
}

/// Runs `pathtracer` with `args`, writing `image` (an `.exr`), and sorts
/// the result; `warning_about` is the text a warning about the input names
/// (the scene file's element paths, `FILE: <`, or the map's name).
pub fn run(args: &[String], image: &Path, warning_about: &str) -> Outcome {
    let _ = std::fs::remove_file(image);
    let mut child = Command::new(PATHTRACER)
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("pathtracer starts");
    let stderr_pipe = child.stderr.take().unwrap();
    let reader =
        std::thread::spawn(move || std::io::read_to_string(stderr_pipe).unwrap_or_default());
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break Some(status);
        }
        if start.elapsed() > TIME_LIMIT {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(2));
    };
    let stderr = reader.join().unwrap();
    let Some(status) = status else {
        return Outcome::Hung;
    };
    if stderr.contains("panicked") || stderr.contains("fatal runtime error") {
        return Outcome::Crashed(stderr);
    }
    match status.code() {
        None => Outcome::Crashed(format!("killed by a signal ({status}): {stderr}")),
        // 1: the renderer's errors; 2: clap's, for the command line.
        Some(1 | 2) if stderr.starts_with("error: ") || stderr.contains("\nerror: ") => {
            Outcome::Refused(stderr)
        }
        Some(0) if stderr.contains(OUT_OF_RANGE_PIXELS) => Outcome::BadPixels(stderr),
        Some(0) => match check_image(image) {
            Ok(()) => Outcome::Rendered {
                warned: stderr
                    .lines()
                    .any(|l| l.starts_with("warning: ") && l.contains(warning_about)),
            },
            Err(problem) => Outcome::BadPixels(problem),
        },
        Some(code) => Outcome::Unclear(format!("exit code {code}: {stderr}")),
    }
}

/// Every value of the EXR at `path` is finite and non-negative.
fn check_image(path: &Path) -> Result<(), String> {
    let image = image::open(path)
        .map_err(|e| format!("{}: no readable image: {e}", path.display()))?
        .into_rgb32f();
    match image
        .as_raw()
        .iter()
        .position(|v| !v.is_finite() || *v < 0.0)
    {
        None => Ok(()),
        Some(i) => Err(format!("value {i} of the image is {}", image.as_raw()[i])),
    }
}

/// The arguments of a small render of `scene` (or the built-in scene) to
/// `image`, with `extra` flags after the small ones.
pub fn small_render(scene: Option<&Path>, image: &Path, extra: &[String]) -> Vec<String> {
    let mut args = small_flags_except(&[]);
    args.extend(extra.iter().cloned());
    args.push("-f".into());
    args.push(image.display().to_string());
    if let Some(scene) = scene {
        args.push(scene.display().to_string());
    }
    args
}
