//! Where the course's own scene files are found.
//!
//! The course's `.dae` scenes (`CBbunny.dae`, `CBspheres_lambertian.dae`,
//! ...) come with the CS184 PathTracer starter repository, in its `dae/`
//! folder and the subfolders `dae/sky`, `dae/simple`, `dae/meshedit`. This
//! project does not ship them. The tests, the examples and the commands in
//! the docs find them through the environment variable
//! [`CS184_SCENES`](ENV_VAR):
//!
//! ```text
//! export CS184_SCENES=/path/to/p3_1-pathtracer/dae
//! cargo run --release --bin pathtracer -- $CS184_SCENES/sky/CBbunny.dae
//! ```
//!
//! Lookup is by file name: every folder under `$CS184_SCENES` is searched
//! (so `CBbunny.dae` is found in `dae/sky/`), then, only when it exists,
//! the fallback folder `../shared/scenes/cs184` beside the crate.

use std::path::{Path, PathBuf};

/// The environment variable naming the folder of course scenes.
pub const ENV_VAR: &str = "CS184_SCENES";

/// What a user does to make the course's scenes available.
pub const HOW_TO_ENABLE: &str =
    "set CS184_SCENES to the course starter repository's dae/ folder (or any folder of .dae files)";

/// The fallback folder, used only when it exists.
pub const FALLBACK: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../shared/scenes/cs184");

/// Folders deeper than this below a root are not searched (the starter
/// keeps its scenes one level down).
const MAX_DEPTH: usize = 4;

/// `$CS184_SCENES` when it is set and not empty (a folder or not).
pub fn env_root() -> Option<PathBuf> {
    std::env::var_os(ENV_VAR)
        .filter(|v| !v.is_empty())
        .map(PathBuf::from)
}

/// The folders searched, in order: `$CS184_SCENES` when it is set and names
/// a folder, then [`FALLBACK`] when it exists.
pub fn roots() -> Vec<PathBuf> {
    env_root()
        .into_iter()
        .chain([PathBuf::from(FALLBACK)])
        .filter(|dir| dir.is_dir())
        .collect()
}

/// One line saying where course scenes were looked for, for messages.
pub fn searched() -> String {
    let env = match std::env::var_os(ENV_VAR) {
        Some(v) if !v.is_empty() => {
            let dir = PathBuf::from(v);
            if dir.is_dir() {
                format!("{ENV_VAR}={}", dir.display())
            } else {
                format!("{ENV_VAR}={} (not a folder)", dir.display())
            }
        }
        _ => format!("{ENV_VAR} not set"),
    };
    let fallback = if Path::new(FALLBACK).is_dir() {
        "fallback ../shared/scenes/cs184"
    } else {
        "no ../shared/scenes/cs184"
    };
    format!("{env}, {fallback}")
}

/// The file called `name` under the first root that has one; within a
/// root, the least deep match, then the first in path order.
pub fn find(name: &str) -> Option<PathBuf> {
    find_in(&roots(), name)
}

/// Every `.dae` file under the roots, one per file name (the first root,
/// then the least deep, wins), sorted by file name.
pub fn all_scenes() -> Vec<PathBuf> {
    all_scenes_in(&roots())
}

/// [`find`] over the given roots.
pub fn find_in(roots: &[PathBuf], name: &str) -> Option<PathBuf> {
    roots.iter().find_map(|root| {
        files_under(root)
            .into_iter()
            .find(|p| p.file_name().is_some_and(|n| n == name))
    })
}

/// [`all_scenes`] over the given roots.
pub fn all_scenes_in(roots: &[PathBuf]) -> Vec<PathBuf> {
    let mut scenes: Vec<PathBuf> = Vec::new();
    for root in roots {
        for path in files_under(root) {
            let is_dae = path
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("dae"));
            if is_dae && !scenes.iter().any(|s| s.file_name() == path.file_name()) {
                scenes.push(path);
            }
        }
    }
    scenes.sort_by(|a, b| a.file_name().cmp(&b.file_name()));
    scenes
}

/// Files under `root`, shallowest first, each depth in path order; hidden
/// entries and anything deeper than [`MAX_DEPTH`] are skipped. Unreadable
/// folders are skipped too: this is a search, not a load.
fn files_under(root: &Path) -> Vec<PathBuf> {
    let mut files = Vec::new();
    let mut level = vec![root.to_path_buf()];
    for _ in 0..=MAX_DEPTH {
        let mut next = Vec::new();
        for dir in &level {
            let Ok(entries) = std::fs::read_dir(dir) else {
                continue;
            };
            let mut entries: Vec<PathBuf> = entries
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| {
                    p.file_name()
                        .is_some_and(|n| !n.to_string_lossy().starts_with('.'))
                })
                .collect();
            entries.sort();
            for path in entries {
                if path.is_dir() {
                    next.push(path);
                } else {
                    files.push(path);
                }
            }
        }
        if next.is_empty() {
            break;
        }
        level = next;
    }
    files
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn files_are_found_in_subfolders_shallowest_first() {
        let dir = tempfile::tempdir().unwrap();
        let sky = dir.path().join("sky");
        let deep = dir.path().join("a").join("b");
        std::fs::create_dir_all(&sky).unwrap();
        std::fs::create_dir_all(&deep).unwrap();
        std::fs::create_dir_all(dir.path().join(".git")).unwrap();
        std::fs::write(sky.join("CBbunny.dae"), "").unwrap();
        std::fs::write(deep.join("CBbunny.dae"), "").unwrap();
        std::fs::write(dir.path().join(".git").join("x.dae"), "").unwrap();
        std::fs::write(dir.path().join("notes.txt"), "").unwrap();
        let files = files_under(dir.path());
        assert_eq!(
            files,
            vec![
                dir.path().join("notes.txt"),
                sky.join("CBbunny.dae"),
                deep.join("CBbunny.dae"),
            ]
        );
        let roots = [dir.path().to_path_buf()];
        assert_eq!(
            find_in(&roots, "CBbunny.dae"),
            Some(sky.join("CBbunny.dae"))
        );
        assert_eq!(find_in(&roots, "teapot.dae"), None);
        assert_eq!(all_scenes_in(&roots), vec![sky.join("CBbunny.dae")]);
    }

    #[test]
    fn the_first_root_wins_and_scenes_sort_by_name() {
        let (a, b) = (tempfile::tempdir().unwrap(), tempfile::tempdir().unwrap());
        for (dir, name) in [(&a, "b.dae"), (&b, "b.dae"), (&b, "a.DAE"), (&b, "c.dae")] {
            std::fs::write(dir.path().join(name), "").unwrap();
        }
        let roots = [a.path().to_path_buf(), b.path().to_path_buf()];
        assert_eq!(find_in(&roots, "b.dae"), Some(a.path().join("b.dae")));
        assert_eq!(
            all_scenes_in(&roots),
            vec![
                b.path().join("a.DAE"),
                a.path().join("b.dae"),
                b.path().join("c.dae")
            ]
        );
    }
}
