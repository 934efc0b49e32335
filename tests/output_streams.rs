//! What the renderer does when its output cannot go where it is sent: a
//! closed pipe ends it quietly, a full device gets a clear error, an image
//! too big for memory is refused with the figures before the render, and
//! in no case is a partial image left behind.

use std::io::Read;
use std::process::{Command, Stdio};

const PATHTRACER: &str = env!("CARGO_BIN_EXE_pathtracer");

/// A small render of the built-in scene at `spp` samples a pixel into
/// `image` (at 64, a tenth of a second or more).
fn small_render(image: &std::path::Path, spp: u32) -> Command {
    let mut command = Command::new(PATHTRACER);
    command.args(["-r", "64", "48", "-t", "1", "-s", &spp.to_string(), "-f"]);
    command.arg(image);
    command
}

#[test]
fn a_closed_pipe_ends_the_run_quietly_without_an_image() {
    let dir = tempfile::tempdir().unwrap();
    let image = dir.path().join("piped.png");
    // A render of a second or more, so that the test's thread, however
    // late a loaded machine schedules it, closes the pipe before it ends.
    let mut child = small_render(&image, 512)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Read one byte (`| head -c 1`), then close the pipe.
    let mut stdout = child.stdout.take().unwrap();
    let mut byte = [0u8; 1];
    stdout.read_exact(&mut byte).unwrap();
    drop(stdout);
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    // Without the quiet exit, println! panics: "failed printing to stdout".
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(!stderr.contains("error"), "not quiet: {stderr}");
    // The first line comes before the render, which takes far longer than
    // closing the pipe: the next line meets the closed pipe.
    assert_eq!(out.status.code(), Some(141), "{stderr}");
    assert!(!image.exists());
    let leftovers: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .filter(|n| n.to_string_lossy() != "piped.png")
        .filter(|n| n.to_string_lossy() != "piped_rate.png")
        .collect();
    assert!(leftovers.is_empty(), "temporary files left: {leftovers:?}");
}

#[test]
fn a_full_device_on_stdout_is_a_clear_error() {
    let Ok(full) = std::fs::OpenOptions::new().write(true).open("/dev/full") else {
        eprintln!("skipped: no /dev/full on this system");
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let out = small_render(&dir.path().join("full.png"), 64)
        .stdout(full)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.starts_with("error: cannot write to standard output"),
        "{stderr}"
    );
    assert!(!stderr.contains("panicked"), "{stderr}");
}

#[test]
fn an_image_too_big_for_memory_is_refused_before_the_render() {
    let available = pathtracer::render::memory::available_bytes();
    let biggest = pathtracer::render::memory::image_bytes(16384, 16384);
    if available.is_none_or(|a| a >= biggest) {
        eprintln!("skipped: this machine has room for a 16384 x 16384 render");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let image = dir.path().join("huge.png");
    let out = Command::new(PATHTRACER)
        .args(["-r", "16384", "16384", "-f"])
        .arg(&image)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("16384 x 16384 image needs about"),
        "{stderr}"
    );
    assert!(stderr.contains("GB is available"), "{stderr}");
    assert!(!image.exists());
}
