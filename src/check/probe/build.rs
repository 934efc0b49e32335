//! Building the probe driver against a student's tree, through their own
//! CMake: `probe.cmake`, handed to CMake as `CMAKE_PROJECT_INCLUDE`, adds
//! a target `cs184_probe` at the end of their top-level `CMakeLists.txt`:
//! `driver.cpp` plus the sources of their `pathtracer` target but its
//! `main`, with that target's libraries, folders and flags. Their tree is
//! only read; everything is written under `OUT/probe/`.
//!
//! The flags are those the shared README names for the course's trees on
//! a current compiler: `-fcommon` (the bundled GLFW and GLEW predate
//! GCC 10's default), `-w`, and CMake's policy minimum 3.5.

use std::path::{Path, PathBuf};
use std::process::Command;

/// The driver's source, written into the output folder to be built.
const DRIVER_CPP: &str = include_str!("driver.cpp");
/// The CMake hook that adds the driver's target.
const PROBE_CMAKE: &str = include_str!("probe.cmake");

/// Builds `cs184_probe` for the tree at `source` in `out/probe/build`
/// (again only what changed, when run a second time) and returns it. An
/// error names the step, the first compiler error and its file, and the
/// log that has the rest.
pub fn build_driver(source: &Path, out: &Path, jobs: u16) -> Result<PathBuf, String> {
    if !source.join("CMakeLists.txt").is_file() {
        return Err(format!(
            "{}: no CMakeLists.txt; --source is the folder of your starter that holds it (and src/)",
            source.display()
        ));
    }
    let source = std::path::absolute(source).map_err(|e| e.to_string())?;
    let dir = std::path::absolute(out.join("probe")).map_err(|e| e.to_string())?;
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let driver = dir.join("driver.cpp");
    let hook = dir.join("probe.cmake");
    write_if_changed(&driver, DRIVER_CPP)?;
    write_if_changed(&hook, PROBE_CMAKE)?;
    let build = dir.join("build");
    forget_another_tree(&build, &source)?;
    let configure = [
        "-S".into(),
        source.display().to_string(),
        "-B".into(),
        build.display().to_string(),
        "-DCMAKE_BUILD_TYPE=Release".into(),
        "-DCMAKE_C_FLAGS=-fcommon -w".into(),
        "-DCMAKE_CXX_FLAGS=-w".into(),
        "-DCMAKE_BUILD_RPATH=$ORIGIN".into(),
        "-DCMAKE_POLICY_VERSION_MINIMUM=3.5".into(),
        format!("-DCMAKE_PROJECT_INCLUDE={}", hook.display()),
        format!("-DCS184_PROBE_DRIVER={}", driver.display()),
    ];
    cmake(&configure, &dir.join("configure.log"), "configuring")?;
    let compile = [
        "--build".into(),
        build.display().to_string(),
        "--target".into(),
        "cs184_probe".into(),
        "-j".into(),
        jobs.to_string(),
    ];
    cmake(&compile, &dir.join("build.log"), "compiling")?;
    let binary = build.join("cs184_probe");
    if binary.is_file() {
        Ok(binary)
    } else {
        Err(format!(
            "compiling the probe: CMake succeeded but {} is missing",
            binary.display()
        ))
    }
}

/// Writes `text` to `path` unless it already holds it (so a second build
/// does not recompile an unchanged driver).
fn write_if_changed(path: &Path, text: &str) -> Result<(), String> {
    if std::fs::read_to_string(path).ok().as_deref() == Some(text) {
        return Ok(());
    }
    std::fs::write(path, text).map_err(|e| format!("{}: {e}", path.display()))
}

/// Removes the build folder when CMake configured it for another tree
/// (an `--out` used before with another `--source`), which CMake would
/// refuse to configure again.
fn forget_another_tree(build: &Path, source: &Path) -> Result<(), String> {
    let Ok(cache) = std::fs::read_to_string(build.join("CMakeCache.txt")) else {
        return Ok(());
    };
    let home = cache
        .lines()
        .find_map(|l| l.strip_prefix("CMAKE_HOME_DIRECTORY:INTERNAL="));
    if home.is_some_and(|h| Path::new(h) == source) {
        return Ok(());
    }
    std::fs::remove_dir_all(build).map_err(|e| format!("{}: {e}", build.display()))
}

/// Runs `cmake args`, its output kept in `log`; on failure the step, the
/// first error line and the log's name.
fn cmake(args: &[String], log: &Path, step: &str) -> Result<(), String> {
    let out = Command::new("cmake").args(args).output().map_err(|e| {
        format!("{step} the probe: cannot run cmake ({e}); install CMake and a C++ compiler")
    })?;
    let mut text = String::from_utf8_lossy(&out.stdout).into_owned();
    text.push_str(&String::from_utf8_lossy(&out.stderr));
    let _ = std::fs::write(log, &text);
    if out.status.success() {
        return Ok(());
    }
    Err(format!(
        "{step} the probe against your tree failed: {}\n(the whole output: {})",
        first_error(&text),
        log.display()
    ))
}

/// The first line that reports an error (GCC's and Clang's
/// `file:line:col: error: ...`, the linker's `undefined reference`,
/// CMake's `CMake Error`), else the output's last line.
pub fn first_error(output: &str) -> String {
    let error = output.lines().find(|l| {
        l.contains(": error:")
            || l.contains("fatal error")
            || l.contains("undefined reference")
            || l.starts_with("CMake Error")
    });
    let line = error.or_else(|| output.lines().rev().find(|l| !l.trim().is_empty()));
    line.unwrap_or("no output").trim().to_owned()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_first_compiler_error_is_named_with_its_file() {
        let log = "[ 10%] Building CXX object\n\
                   /s/src/scene/triangle.cpp: In member function\n\
                   /s/src/scene/triangle.cpp:42:10: error: 'foo' was not declared in this scope\n\
                   /s/src/scene/sphere.cpp:7:1: error: expected ';'\n";
        assert_eq!(
            first_error(log),
            "/s/src/scene/triangle.cpp:42:10: error: 'foo' was not declared in this scope"
        );
        assert_eq!(
            first_error("a\nCMake Error at CMakeLists.txt:3 (project):\n"),
            "CMake Error at CMakeLists.txt:3 (project):"
        );
        assert_eq!(
            first_error("make: *** [all] Error 2\n\n"),
            "make: *** [all] Error 2"
        );
    }

    /// A build folder of another tree goes; one of this tree stays.
    #[test]
    fn a_build_of_another_tree_is_forgotten() {
        let build = std::env::temp_dir().join("cs184-probe-other-tree");
        std::fs::create_dir_all(&build).unwrap();
        let cache = |home: &str| {
            let text = format!("# cache\nCMAKE_HOME_DIRECTORY:INTERNAL={home}\n");
            std::fs::write(build.join("CMakeCache.txt"), text).unwrap();
        };
        cache("/students/mine");
        forget_another_tree(&build, Path::new("/students/mine")).unwrap();
        assert!(build.join("CMakeCache.txt").is_file());
        forget_another_tree(&build, Path::new("/students/theirs")).unwrap();
        assert!(!build.exists());
    }

    #[test]
    fn a_folder_without_cmake_lists_is_named() {
        let dir = std::env::temp_dir().join("cs184-probe-no-cmake");
        std::fs::create_dir_all(&dir).unwrap();
        let e = build_driver(&dir, &dir, 1).unwrap_err();
        assert!(
            e.contains("no CMakeLists.txt") && e.contains("cs184-probe-no-cmake"),
            "{e}"
        );
    }
}
