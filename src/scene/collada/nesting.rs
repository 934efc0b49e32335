//! How deeply a document's elements nest, found before the XML parser
//! sees it.
//!
//! The XML parser (`roxmltree`) descends one function call per element
//! level, so a file with tens of thousands of nested elements would
//! overflow the stack. [`check_nesting`] scans the text once, without
//! recursion, and refuses a document deeper than [`MAX_XML_DEPTH`] with
//! the line where the limit is passed. The course's scenes nest about ten
//! levels deep.
//!
//! The scan only counts: `<name ...>` opens a level, `</name>` closes one,
//! `<name .../>`, comments `<!-- -->`, `<![CDATA[ ]]>`, processing
//! instructions `<? ?>` and declarations `<! >` do neither; quoted
//! attribute values may hold `>`. Whether the document is well formed is
//! the parser's business afterwards.

use super::super::SceneError;

/// The deepest element nesting a scene file may have. A test parses a
/// document this deep on a 2 MiB thread stack (a test thread's).
pub const MAX_XML_DEPTH: usize = 1000;

/// Refuses `text` if its elements nest deeper than [`MAX_XML_DEPTH`].
pub fn check_nesting(text: &str, file: &str) -> Result<(), SceneError> {
    let bytes = text.as_bytes();
    let mut depth = 0usize;
    let mut i = 0;
    while let Some(offset) = find(bytes, i, b"<") {
        let start = offset;
        let rest = &bytes[start..];
        i = if rest.starts_with(b"<!--") {
            after(bytes, start + 4, b"-->")
        } else if rest.starts_with(b"<![CDATA[") {
            after(bytes, start + 9, b"]]>")
        } else if rest.starts_with(b"<?") {
            after(bytes, start + 2, b"?>")
        } else if rest.starts_with(b"</") {
            depth = depth.saturating_sub(1);
            after(bytes, start + 2, b">")
        } else {
            let (end, self_closing) = tag_end(bytes, start + 1);
            if !rest.starts_with(b"<!") && !self_closing {
                depth += 1;
                if depth > MAX_XML_DEPTH {
                    let line = 1 + bytes[..start].iter().filter(|&&b| b == b'\n').count();
                    return Err(SceneError::new(
                        file,
                        "",
                        format!(
                            "elements nest more than {MAX_XML_DEPTH} levels deep (line {line}); \
                             a scene needs a few dozen at most"
                        ),
                    ));
                }
            }
            end
        };
    }
    Ok(())
}

/// The position of the first `pattern` at or after `from`.
fn find(bytes: &[u8], from: usize, pattern: &[u8]) -> Option<usize> {
    bytes
        .get(from..)?
        .windows(pattern.len())
        .position(|w| w == pattern)
        .map(|p| from + p)
}

/// The position just after the first `pattern` at or after `from`, or the
/// end of the text.
fn after(bytes: &[u8], from: usize, pattern: &[u8]) -> usize {
    find(bytes, from, pattern).map_or(bytes.len(), |p| p + pattern.len())
}

/// The position after the `>` ending the tag that starts before `from`,
/// skipping quoted attribute values, and whether the tag ends in `/>`.
fn tag_end(bytes: &[u8], from: usize) -> (usize, bool) {
    let mut quote = None;
    for (k, &b) in bytes.iter().enumerate().skip(from) {
        match (quote, b) {
            (Some(q), _) if b == q => quote = None,
            (Some(_), _) => {}
            (None, b'"' | b'\'') => quote = Some(b),
            (None, b'>') => return (k + 1, bytes[k - 1] == b'/'),
            _ => {}
        }
    }
    (bytes.len(), false)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn nested(levels: usize) -> String {
        format!(
            "<COLLADA>\n{}{}</COLLADA>",
            "<node a='>'>".repeat(levels - 1),
            "</node>".repeat(levels - 1)
        )
    }

    #[test]
    fn counts_levels_not_tags() {
        assert!(check_nesting(&nested(MAX_XML_DEPTH), "t.dae").is_ok());
        let e = check_nesting(&nested(MAX_XML_DEPTH + 1), "t.dae").unwrap_err();
        assert!(e.problem.contains("line 2"), "{e}");
        // Siblings, self-closing tags, comments and CDATA add no level.
        let flat = format!(
            "<a>{}</a>",
            "<b/><c x=\"/>\"></c><!-- <d> --><![CDATA[<e>]]><?pi <f>?>".repeat(5000)
        );
        assert!(check_nesting(&flat, "t.dae").is_ok());
    }

    #[test]
    fn the_deepest_accepted_document_parses_on_a_test_threads_stack() {
        // Test threads have 2 MiB stacks; the main thread has 8 MiB.
        let text = nested(MAX_XML_DEPTH);
        let parsed = std::thread::Builder::new()
            .stack_size(2 << 20)
            .spawn(move || roxmltree::Document::parse(&text).is_ok())
            .unwrap()
            .join()
            .unwrap();
        assert!(parsed);
    }
}
