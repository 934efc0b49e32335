//! Running a student's binary through the course's command line: with a
//! time-out, in a working folder of its own (a 3-2 binary writes
//! `probability_debug.png` where it runs), its image read back and checked
//! for size. Whatever goes wrong becomes a [`RunError`] that says so in one
//! line; nothing panics.

use std::fmt;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::time::{Duration, Instant};

use crate::render::rendered::rate_image_path;

/// A student's `pathtracer` binary.
#[derive(Clone, Debug)]
pub struct Student {
    pub binary: PathBuf,
    /// Where it runs and writes its images.
    pub work: PathBuf,
    /// How long one run may take.
    pub timeout: Duration,
}

/// What the binary supports, found by trying each flag in a tiny render
/// ([`Student::capabilities`]): no starter's usage text lists `-a` or
/// `-H`, and the 2023 starters' none of `-o`, though getopt accepts what
/// its option string names and refuses the rest (it prints the usage and
/// exits with 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Capabilities {
    /// `-o 0|1` (later years only).
    pub accumulate_flag: bool,
    /// `-a BATCH TOL` (adaptive sampling).
    pub adaptive_flag: bool,
    /// `-b R` and `-d D` (the thin lens of 3-2's part 8).
    pub lens_flag: bool,
    /// `-e FILE` (the environment map of 3-2's part 7).
    pub environment_flag: bool,
}

impl Capabilities {
    /// Every flag the checks use.
    pub const ALL: Capabilities = Capabilities {
        accumulate_flag: true,
        adaptive_flag: true,
        lens_flag: true,
        environment_flag: true,
    };
}

/// Why a run gave no image to compare.
#[derive(Clone, Debug, PartialEq)]
pub enum RunError {
    Missing(PathBuf),
    NotExecutable(PathBuf, String),
    TimedOut(Duration),
    Crashed(String),
    NoImage(PathBuf),
    Unreadable(PathBuf, String),
    WrongSize {
        expected: (u32, u32),
        found: (u32, u32),
    },
}

impl fmt::Display for RunError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RunError::Missing(p) => write!(f, "{}: no such file", p.display()),
            RunError::NotExecutable(p, e) => write!(f, "{}: cannot run it: {e}", p.display()),
            RunError::TimedOut(t) => write!(
                f,
                "too slow: no image within {} s (stopped), which says nothing of right or wrong; build it Release (cmake -DCMAKE_BUILD_TYPE=Release), check that your BVH prunes (part 2), or allow more with --timeout",
                t.as_secs()
            ),
            RunError::Crashed(how) => write!(f, "it crashed: {how}"),
            RunError::NoImage(p) => write!(f, "it exited without writing {}", p.display()),
            RunError::Unreadable(p, e) => {
                write!(f, "{}: not a PNG it could read: {e}", p.display())
            }
            RunError::WrongSize { expected, found } => write!(
                f,
                "its image is {}x{}, the command asked for {}x{}",
                found.0, found.1, expected.0, expected.1
            ),
        }
    }
}

/// An 8-bit RGB image as the binary wrote it.
#[derive(Clone, Debug, PartialEq)]
pub struct StudentImage {
    pub width: u32,
    pub height: u32,
    /// Row-major, row 0 at the top, three bytes a pixel.
    pub rgb: Vec<u8>,
}

/// How long [`spawn_when_not_busy`] waits for a binary that is still open
/// for writing.
const BUSY_PATIENCE: Duration = Duration::from_secs(2);

/// Spawns `command`, trying again for up to [`BUSY_PATIENCE`] while the
/// kernel says the binary is busy (`ETXTBSY`). A binary that was just
/// written (a script, or a build that has only now finished) can be held
/// open for writing for a moment by a child that another thread forked
/// before the file was closed, until that child's own `exec` closes it
/// (see the Linux man page execve(2), ETXTBSY; Go's os/exec documents the
/// same race). It passes by itself, so it is not the student's error.
fn spawn_when_not_busy(command: &mut Command) -> std::io::Result<Child> {
    let start = Instant::now();
    loop {
        match command.spawn() {
            Err(e)
                if e.kind() == std::io::ErrorKind::ExecutableFileBusy
                    && start.elapsed() < BUSY_PATIENCE =>
            {
                std::thread::sleep(Duration::from_millis(10))
            }
            result => return result,
        }
    }
}

/// Waits for `child` to exit, at most `timeout`: its status, or `None`
/// when it took longer (it is then killed and reaped) or could not be
/// waited for.
pub fn wait_at_most(child: &mut Child, timeout: Duration) -> Option<ExitStatus> {
    let start = Instant::now();
    loop {
        match child.try_wait() {
            Ok(Some(status)) => return Some(status),
            Ok(None) if start.elapsed() < timeout => std::thread::sleep(Duration::from_millis(20)),
            _ => {
                let _ = child.kill();
                let _ = child.wait();
                return None;
            }
        }
    }
}

impl Student {
    /// Runs the binary with `args` and waits at most [`Student::timeout`];
    /// its output is captured (kept for a crash's message).
    fn run(&self, args: &[String]) -> Result<std::process::Output, RunError> {
        if !self.binary.exists() {
            return Err(RunError::Missing(self.binary.clone()));
        }
        let mut command = Command::new(&self.binary);
        command
            .args(args)
            .current_dir(&self.work)
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped());
        let mut child = spawn_when_not_busy(&mut command)
            .map_err(|e| RunError::NotExecutable(self.binary.clone(), e.to_string()))?;
        // Drain the pipes on threads, so a chatty binary cannot block.
        let drain = |pipe: Option<Box<dyn std::io::Read + Send>>| {
            std::thread::spawn(move || {
                let mut bytes = Vec::new();
                if let Some(mut pipe) = pipe {
                    let _ = pipe.read_to_end(&mut bytes);
                }
                bytes
            })
        };
        let out = drain(child.stdout.take().map(|p| Box::new(p) as _));
        let err = drain(child.stderr.take().map(|p| Box::new(p) as _));
        let status =
            wait_at_most(&mut child, self.timeout).ok_or(RunError::TimedOut(self.timeout))?;
        Ok(std::process::Output {
            status,
            stdout: out.join().unwrap_or_default(),
            stderr: err.join().unwrap_or_default(),
        })
    }

    /// Whether the binary renders the lamps the 3-2 way: at `-m 0` its
    /// render of `glowing_box` ([`super::scenes::glowing_box`], every
    /// surface emitting, no light) is black, as only a 3-2 starter's
    /// loader makes it (but for the staff library's stamp in the bottom
    /// left corner: nine in ten pixels black is enough), while its render
    /// of the lit box `lit_box` at `-m 1` is not (a 3-1 binary whose
    /// camera rays miss everything renders both black). `None` when the
    /// binary gave no image.
    pub fn renders_lamps_as_quads(&self, glowing_box: &Path, lit_box: &Path) -> Option<bool> {
        let black_at = |depth: &str, scene: &Path| -> Option<bool> {
            let args: Vec<String> = [
                "-t", "1", "-s", "1", "-l", "1", "-m", depth, "-r", "48", "36",
            ]
            .iter()
            .map(|w| w.to_string())
            .chain([scene.to_string_lossy().into_owned()])
            .collect();
            let image = self.render(&args, "lamps.png", (48, 36)).ok()?;
            let black = image.rgb.chunks(3).filter(|p| *p == [0, 0, 0]).count();
            Some(black * 10 >= 9 * image.rgb.len() / 3)
        };
        Some(black_at("0", glowing_box)? && !black_at("1", lit_box)?)
    }

    /// What the binary supports: a tiny render of `scene_file` (8 x 6
    /// pixels, one sample, `-m 0`) with each flag. A flag is missing when
    /// the render without it writes its image and the one with it exits
    /// with 1, writes none and prints the usage, as the course's getopt
    /// does for a flag it does not know. A binary whose tiny render fails
    /// anyway is taken to have every flag: the checks then say how it
    /// fails. `map` is an environment map to try `-e` with (without one,
    /// `-e` is taken as there). An error only when the binary cannot be
    /// run at all.
    pub fn capabilities(
        &self,
        scene_file: &str,
        map: Option<&Path>,
    ) -> Result<Capabilities, RunError> {
        let probe = |flags: &[&str]| -> Result<Option<bool>, RunError> {
            let image = "probe.png";
            let path = self.work.join(image);
            let _ = std::fs::remove_file(&path);
            let mut args: Vec<String> = ["-f", image, "-t", "1", "-s", "1", "-l", "1", "-m", "0"]
                .iter()
                .chain(&["-r", "8", "6"])
                .chain(flags)
                .map(|w| w.to_string())
                .collect();
            args.push(scene_file.to_string());
            let output = self.run(&args)?;
            let wrote = path.exists();
            let _ = std::fs::remove_file(&path);
            let _ = std::fs::remove_file(rate_image_path(&path));
            let text = String::from_utf8_lossy(&output.stdout).to_lowercase()
                + &String::from_utf8_lossy(&output.stderr).to_lowercase();
            let refused = output.status.code() == Some(1) && !wrote && text.contains("usage");
            Ok(if wrote {
                Some(true)
            } else if refused {
                Some(false)
            } else {
                None
            })
        };
        if probe(&[])? != Some(true) {
            return Ok(Capabilities::ALL);
        }
        let has = |flags: &[&str]| probe(flags).map(|found| found != Some(false));
        let map = map.map(|m| m.to_string_lossy().into_owned());
        Ok(Capabilities {
            accumulate_flag: has(&["-o", "1"])?,
            adaptive_flag: has(&["-a", "2", "0.2"])?,
            lens_flag: has(&["-b", "0.1", "-d", "3"])?,
            environment_flag: match &map {
                Some(m) => has(&["-e", m])?,
                None => true,
            },
        })
    }

    /// Renders with `args` (the course's flags, the scene last) into
    /// `image` (a name inside the working folder) of size `size`.
    /// The command [`Student::render`] runs, the binary first: to
    /// reproduce it by hand in [`Student::work`].
    pub fn command_line(&self, args: &[String], image: &str) -> Vec<String> {
        let mut all = vec![
            self.binary.to_string_lossy().into_owned(),
            "-f".to_string(),
            image.to_string(),
        ];
        all.extend_from_slice(args);
        all
    }

    pub fn render(
        &self,
        args: &[String],
        image: &str,
        size: (u32, u32),
    ) -> Result<StudentImage, RunError> {
        let path = self.work.join(image);
        let _ = std::fs::remove_file(&path);
        let _ = std::fs::remove_file(rate_image_path(&path));
        let output = self.run(&self.command_line(args, image)[1..])?;
        if !output.status.success() {
            let last = String::from_utf8_lossy(&output.stderr);
            let line = last
                .lines()
                .rev()
                .find(|l| !l.trim().is_empty())
                .unwrap_or("");
            return Err(RunError::Crashed(format!(
                "{} ({})",
                output.status,
                line.trim()
            )));
        }
        read_png(&path, size)
    }

    /// The rate image the last [`Student::render`] into `image` wrote
    /// beside it (`NAME_rate.png`), which must be `size`; `None` when it
    /// wrote none.
    pub fn rate_image(
        &self,
        image: &str,
        size: (u32, u32),
    ) -> Option<Result<StudentImage, RunError>> {
        let path = rate_image_path(&self.work.join(image));
        path.exists().then(|| read_png(&path, size))
    }
}

/// The PNG at `path`, which must be `size`.
pub fn read_png(path: &Path, size: (u32, u32)) -> Result<StudentImage, RunError> {
    if !path.exists() {
        return Err(RunError::NoImage(path.to_path_buf()));
    }
    let decoded = image::open(path)
        .map_err(|e| RunError::Unreadable(path.to_path_buf(), e.to_string()))?
        .to_rgb8();
    let found = decoded.dimensions();
    if found != size {
        return Err(RunError::WrongSize {
            expected: size,
            found,
        });
    }
    Ok(StudentImage {
        width: found.0,
        height: found.1,
        rgb: decoded.into_raw(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Write;
    use std::os::unix::fs::PermissionsExt;

    /// A script held open for writing cannot be run (ETXTBSY); the spawn
    /// waits until the writer lets go, rather than calling it unrunnable.
    #[test]
    fn a_binary_still_open_for_writing_is_run_once_it_is_closed() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("busy.sh");
        let mut writer = std::fs::File::create(&path).unwrap();
        writer.write_all(b"#!/bin/sh\nexit 7\n").unwrap();
        std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o755)).unwrap();
        match Command::new(&path).spawn() {
            Err(busy) => assert_eq!(busy.kind(), std::io::ErrorKind::ExecutableFileBusy),
            Ok(mut child) => {
                child.wait().unwrap();
                eprintln!("skipped: this kernel runs a file open for writing (no ETXTBSY)");
                return;
            }
        }
        let release = std::thread::spawn(move || {
            std::thread::sleep(Duration::from_millis(100));
            drop(writer);
        });
        let mut child = spawn_when_not_busy(&mut Command::new(&path)).unwrap();
        assert_eq!(child.wait().unwrap().code(), Some(7));
        release.join().unwrap();
    }
}
