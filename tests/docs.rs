//! The docs kept true by the tests: every relative link and anchor
//! resolves, each page stays within its words, the student chapters hold
//! no lab notes, and the numbers and flags the code can state are read
//! from the code.
//!
//! Anchors are GitHub's: a heading's text without its markup, lower case,
//! every character but letters, digits, `-`, `_` and spaces dropped, the
//! spaces turned to `-`, and `-1`, `-2`, ... after a repeated one.

use std::collections::HashMap;
use std::fs;
use std::path::{Path, PathBuf};

use clap::CommandFactory;
use pathtracer::cli::CourseArgs;
use pathtracer::mistakes::Mistake;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// The student's chapters: what a student reads while writing a part.
const STUDENT_CHAPTERS: [&str; 15] = [
    "00-conventions.md",
    "01-raygen.md",
    "02-intersect.md",
    "03-bvh.md",
    "04-direct.md",
    "05-global.md",
    "06-adaptive.md",
    "07-materials.md",
    "08-environment.md",
    "09-depth-of-field.md",
    "13-symptoms.md",
    "14-course-image.md",
    "15-check.md",
    "16-bad-input.md",
    "starter-map.md",
];

/// Words a student chapter may hold: one sitting.
const STUDENT_WORDS: usize = 3_000;

/// Pages of their own limit (issue 54): what a user decides from, not
/// the history of how it was found.
const PAGE_WORDS: [(&str, usize); 2] = [
    ("10-performance.md", 5_000),
    ("17-mutation-testing.md", 3_000),
];

/// All of docs/ and docs/maintainers/ together: half of what they had
/// grown to (issue 54).
const TOTAL_WORDS: usize = 45_000;

/// Every page the tests read: README.md and docs/ with docs/maintainers/.
fn pages() -> Vec<PathBuf> {
    let root = Path::new(ROOT);
    let mut pages = vec![root.join("README.md")];
    for dir in ["docs", "docs/maintainers"] {
        pages.extend(markdown_in(&root.join(dir)));
    }
    pages
}

fn markdown_in(dir: &Path) -> Vec<PathBuf> {
    let mut files: Vec<_> = fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|entry| entry.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    files.sort();
    files
}

fn read(path: &Path) -> String {
    fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn words(path: &Path) -> usize {
    read(path).split_whitespace().count()
}

/// The page's lines outside fenced code blocks, numbered from 1.
fn prose_lines(text: &str) -> Vec<(usize, &str)> {
    let mut fenced = false;
    let mut lines = Vec::new();
    for (i, line) in text.lines().enumerate() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
        } else if !fenced {
            lines.push((i + 1, line));
        }
    }
    lines
}

/// `line` without its inline code spans (a link inside backticks is text).
fn without_code_spans(line: &str) -> String {
    let mut out = String::new();
    for (i, part) in line.split('`').enumerate() {
        if i % 2 == 0 {
            out.push_str(part);
        }
    }
    out
}

/// The targets of the inline links and images on `line`, and of a
/// reference definition (`[name]: target`).
fn link_targets(line: &str) -> Vec<String> {
    let line = without_code_spans(line);
    let mut targets = Vec::new();
    let trimmed = line.trim_start();
    if let Some(rest) = trimmed.strip_prefix('[') {
        if let Some((_, target)) = rest.split_once("]: ") {
            targets.push(target.split_whitespace().next().unwrap_or("").to_string());
        }
    }
    let mut rest = line.as_str();
    while let Some(at) = rest.find("](") {
        let after = &rest[at + 2..];
        // A target ends at its closing parenthesis, allowing one level of
        // nesting (`foo(1).md`) and a title after a space.
        let mut depth = 0;
        let mut end = after.len();
        for (i, c) in after.char_indices() {
            match c {
                '(' => depth += 1,
                ')' if depth == 0 => {
                    end = i;
                    break;
                }
                ')' => depth -= 1,
                _ => {}
            }
        }
        let target = after[..end].split_whitespace().next().unwrap_or("");
        targets.push(target.trim_matches(['<', '>']).to_string());
        rest = &after[end..];
    }
    targets
}

/// GitHub's anchor for a heading's text.
fn slug(heading: &str) -> String {
    let text = strip_link_markup(heading);
    text.chars()
        .filter(|c| !matches!(c, '`' | '*'))
        .flat_map(char::to_lowercase)
        .filter(|c| c.is_alphanumeric() || matches!(c, '-' | '_' | ' '))
        .map(|c| if c == ' ' { '-' } else { c })
        .collect()
}

/// `[text](target)` as `text`.
fn strip_link_markup(text: &str) -> String {
    let mut out = String::new();
    let mut rest = text;
    while let Some(open) = rest.find('[') {
        let Some(close) = rest[open..].find("](") else {
            break;
        };
        let Some(end) = rest[open + close..].find(')') else {
            break;
        };
        out.push_str(&rest[..open]);
        out.push_str(&rest[open + 1..open + close]);
        rest = &rest[open + close + end + 1..];
    }
    out.push_str(rest);
    out
}

/// Every anchor a page defines: its headings' slugs (numbered when
/// repeated) and explicit `id="..."` / `name="..."` attributes.
fn anchors(text: &str) -> Vec<String> {
    let mut seen: HashMap<String, usize> = HashMap::new();
    let mut anchors = Vec::new();
    for (_, line) in prose_lines(text) {
        if let Some(heading) = line.strip_prefix('#') {
            let heading = heading.trim_start_matches('#').trim();
            let base = slug(heading);
            let count = seen.entry(base.clone()).or_insert(0);
            anchors.push(if *count == 0 {
                base.clone()
            } else {
                format!("{base}-{count}")
            });
            *count += 1;
        }
        for attribute in ["id=\"", "name=\""] {
            let mut rest = line;
            while let Some(at) = rest.find(attribute) {
                let value = &rest[at + attribute.len()..];
                let end = value.find('"').unwrap_or(value.len());
                anchors.push(value[..end].to_string());
                rest = &value[end..];
            }
        }
    }
    anchors
}

/// What is wrong with the link `target` on page `page`, if anything.
fn broken(page: &Path, target: &str, cache: &mut HashMap<PathBuf, Vec<String>>) -> Option<String> {
    if target.is_empty() {
        return Some("an empty link".into());
    }
    if target.contains("://") || target.starts_with("mailto:") {
        return None;
    }
    let (path, anchor) = match target.split_once('#') {
        Some((path, anchor)) => (path, Some(anchor)),
        None => (target, None),
    };
    let file = if path.is_empty() {
        page.to_path_buf()
    } else {
        page.parent().unwrap().join(path)
    };
    if !file.exists() {
        return Some(format!("{} does not exist", file.display()));
    }
    let anchor = anchor.filter(|_| file.extension().is_some_and(|e| e == "md"))?;
    let known = cache
        .entry(file.clone())
        .or_insert_with(|| anchors(&read(&file)));
    (!known.iter().any(|a| a == anchor))
        .then(|| format!("no heading #{anchor} in {}", file.display()))
}

#[test]
fn every_relative_link_and_anchor_resolves() {
    let mut cache = HashMap::new();
    let mut problems = Vec::new();
    let mut links = 0;
    for page in pages() {
        let text = read(&page);
        for (number, line) in prose_lines(&text) {
            for target in link_targets(line) {
                links += 1;
                if let Some(problem) = broken(&page, &target, &mut cache) {
                    problems.push(format!("{}:{number}: ({target}) {problem}", page.display()));
                }
            }
        }
    }
    assert!(links > 300, "only {links} links found: the scan is broken");
    assert!(
        problems.is_empty(),
        "{} broken links:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

#[test]
fn pages_stay_within_their_words() {
    let docs = Path::new(ROOT).join("docs");
    let mut over = Vec::new();
    let limits = STUDENT_CHAPTERS
        .iter()
        .map(|&name| (name, STUDENT_WORDS))
        .chain(PAGE_WORDS);
    for (name, limit) in limits {
        let count = words(&docs.join(name));
        if count > limit {
            over.push(format!("docs/{name}: {count} words, at most {limit}"));
        }
    }
    let total: usize = pages().iter().skip(1).map(|p| words(p)).sum();
    if total > TOTAL_WORDS {
        over.push(format!(
            "docs/ and docs/maintainers/: {total} words, at most {TOTAL_WORDS}"
        ));
    }
    assert!(over.is_empty(), "{}", over.join("\n"));
}

/// Whether `line` carries the marks of a lab note: a date, a time of day
/// in UTC, or a commit.
fn lab_note_mark(line: &str) -> Option<&'static str> {
    let bytes = line.as_bytes();
    let digits = |from: usize, n: usize| {
        bytes.len() >= from + n && bytes[from..from + n].iter().all(u8::is_ascii_digit)
    };
    let dated = (0..bytes.len()).any(|i| {
        digits(i, 4)
            && bytes.get(i + 4) == Some(&b'-')
            && digits(i + 5, 2)
            && bytes.get(i + 7) == Some(&b'-')
            && digits(i + 8, 2)
    });
    if dated {
        Some("a date")
    } else if line.contains(" UTC") {
        Some("a time in UTC")
    } else if line
        .split("commit ")
        .skip(1)
        .any(|after| after.len() >= 7 && after[..7].bytes().all(|b| b.is_ascii_hexdigit()))
    {
        Some("a commit")
    } else {
        None
    }
}

#[test]
fn student_chapters_hold_no_lab_notes() {
    let docs = Path::new(ROOT).join("docs");
    let mut notes = Vec::new();
    for name in STUDENT_CHAPTERS {
        let text = read(&docs.join(name));
        for (number, line) in prose_lines(&text) {
            if let Some(mark) = lab_note_mark(line) {
                notes.push(format!("docs/{name}:{number}: {mark}: {line}"));
            }
        }
    }
    assert!(
        notes.is_empty(),
        "lab notes in student chapters (they belong in docs/maintainers/):\n{}",
        notes.join("\n")
    );
}

#[test]
fn the_lab_note_marks_are_seen() {
    assert_eq!(
        lab_note_mark("measured 2026-11-28 on two cores"),
        Some("a date")
    );
    assert_eq!(lab_note_mark("(18:10-19:15 UTC)"), Some("a time in UTC"));
    assert_eq!(lab_note_mark("at commit 9266146, before"), Some("a commit"));
    assert_eq!(lab_note_mark("the commit message says so"), None);
    assert_eq!(lab_note_mark("a 480 x 360 image, 2-4 bounces"), None);
}

#[test]
fn slugs_are_github_s() {
    assert_eq!(slug("`sphere-far-root`"), "sphere-far-root");
    assert_eq!(
        slug("1. Traversal and build against Embree, one core"),
        "1-traversal-and-build-against-embree-one-core"
    );
    assert_eq!(slug("10 · Performance"), "10--performance");
    assert_eq!(
        slug("Eight seeds (2026-11-28, 20:40–21:20 UTC)"),
        "eight-seeds-2026-11-28-20402120-utc"
    );
    assert_eq!(slug("The [BSDF](x.md) contract"), "the-bsdf-contract");
    let text = "# A\n## Tests\n```\n# not a heading\n```\n### Tests\n";
    assert_eq!(anchors(text), ["a", "tests", "tests-1"]);
}

#[test]
fn links_are_found_where_markdown_has_them() {
    let line =
        "See [05](05-global.md#russian-roulette) and ![x](images/a.png), not `[c](code.md)`.";
    assert_eq!(
        link_targets(line),
        ["05-global.md#russian-roulette", "images/a.png"]
    );
    assert_eq!(link_targets("[ref]: ../src/lib.rs"), ["../src/lib.rs"]);
    assert_eq!(link_targets("[f](a(1).md \"title\")"), ["a(1).md"]);
}

/// Every "N mistakes" and "N catalogued mistakes" in the docs is the
/// catalogue's length.
#[test]
fn the_mistake_count_is_the_catalogue_s() {
    let count = Mistake::ALL.len();
    let mut wrong = Vec::new();
    for page in pages() {
        let text = read(&page);
        for (number, line) in prose_lines(&text) {
            let words: Vec<&str> = line.split_whitespace().collect();
            for (i, word) in words.iter().enumerate() {
                let Ok(n) = word.trim_start_matches('(').parse::<usize>() else {
                    continue;
                };
                let next = words.get(i + 1).copied().unwrap_or("");
                let after = if next == "catalogued" {
                    words.get(i + 2).copied().unwrap_or("")
                } else {
                    next
                };
                // "the 25 mistakes of parts 1 to 5" counts a part of them.
                let part = words.get(i + if next == "catalogued" { 3 } else { 2 }) == Some(&"of");
                if after.trim_end_matches([',', '.', ';', ':', ')']) == "mistakes"
                    && !part
                    && n != count
                {
                    wrong.push(format!(
                        "{}:{number}: {n} mistakes, the catalogue has {count}",
                        page.display()
                    ));
                }
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// Every flag in README's table of `pathtracer`'s flags is one of its flags.
#[test]
fn readme_s_flags_are_the_renderer_s() {
    let command = CourseArgs::command();
    let known = |flag: &str| {
        command.get_arguments().any(|arg| {
            flag.strip_prefix("--")
                .map(|long| arg.get_long() == Some(long))
                .unwrap_or_else(|| {
                    let short = flag.trim_start_matches('-');
                    short.chars().count() == 1 && arg.get_short() == short.chars().next()
                })
        })
    };
    let readme = read(&Path::new(ROOT).join("README.md"));
    let mut flags = 0;
    let mut unknown = Vec::new();
    for line in readme.lines() {
        let Some(cell) = line.strip_prefix("| `-") else {
            continue;
        };
        let flag = format!("-{}", cell.split(['`', ' ', '[', '=']).next().unwrap());
        flags += 1;
        if !known(&flag) {
            unknown.push(flag);
        }
    }
    assert!(flags >= 20, "only {flags} flags found in README's table");
    assert!(
        unknown.is_empty(),
        "README lists flags pathtracer does not have: {unknown:?}"
    );
}
