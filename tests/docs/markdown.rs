//! Reading Markdown as GitHub renders it, as much as the docs' tests
//! need: the prose lines (outside fenced code), the targets of links and
//! images, the anchors a page defines, and the marks of a lab note.
//!
//! Anchors are GitHub's: a heading's text without its markup, lower case,
//! every character but letters, digits, `-`, `_` and spaces dropped, the
//! spaces turned to `-`, and `-1`, `-2`, ... after a repeated one.

use std::collections::HashMap;

/// The page's lines outside fenced code blocks, numbered from 1.
pub fn prose_lines(text: &str) -> Vec<(usize, &str)> {
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
pub fn without_code_spans(line: &str) -> String {
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
pub fn link_targets(line: &str) -> Vec<String> {
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
pub fn slug(heading: &str) -> String {
    let text = strip_link_markup(heading);
    text.chars()
        .filter(|c| !matches!(c, '`' | '*'))
        .flat_map(char::to_lowercase)
        .filter(|c| c.is_alphanumeric() || matches!(c, '-' | '_' | ' '))
        .map(|c| if c == ' ' { '-' } else { c })
        .collect()
}

/// `[text](target)` as `text`.
pub fn strip_link_markup(text: &str) -> String {
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
pub fn anchors(text: &str) -> Vec<String> {
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

/// Whether `line` carries the marks of a lab note: a date, a time of day
/// in UTC, or a commit.
pub fn lab_note_mark(line: &str) -> Option<&'static str> {
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

#[cfg(test)]
mod tests {
    use super::*;

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
}
