//! Numbers in element text and attributes: whitespace-separated lists of
//! floats or indices, counts, colours.
//!
//! Every float must be finite: `NaN`, `inf` and values that overflow `f32`
//! (for example `1e60`) are rejected with the offending token, so nothing
//! non-finite reaches the renderer. Errors name the element and the 0-based
//! position of the bad token.

use roxmltree::Node;

use super::super::SceneError;
use super::xml::{require_attr, Doc};
use crate::math::Rgb;

/// The text of `node` as a list of finite floats.
pub fn floats(doc: &Doc, node: Node) -> Result<Vec<f32>, SceneError> {
    let text = &element_text(doc, node);
    let mut out = Vec::new();
    for (i, token) in text.split_ascii_whitespace().enumerate() {
        let value: f32 = token
            .parse()
            .map_err(|_| doc.err(node, format!("number {i} is \"{token}\", not a number")))?;
        if !value.is_finite() {
            return Err(doc.err(
                node,
                format!("number {i} is \"{token}\", not a finite number"),
            ));
        }
        out.push(value);
    }
    Ok(out)
}

/// The text of `node`: all its text, also where a comment or an element
/// splits it (`<ior>1.<!-- -->45</ior>` is `1.45`, as XML reads it), with
/// a warning when text follows the split: the course's reader takes only
/// the text before the first comment or element (`1.`).
fn element_text<'a>(doc: &Doc, node: Node<'a, '_>) -> std::borrow::Cow<'a, str> {
    let mut children = node.children();
    let before: String = children
        .by_ref()
        .take_while(Node::is_text)
        .filter_map(|c| c.text())
        .collect();
    let after: String = children
        .filter_map(|c| c.text().filter(|_| c.is_text()))
        .collect();
    if after.trim().is_empty() {
        return before.into();
    }
    let whole = format!("{before}{after}");
    let course = match before.trim() {
        "" => "nothing".to_string(),
        text => format!("\"{text}\""),
    };
    doc.warn(
        node,
        format!(
            "a comment or an element splits the text; read as \"{}\" (the course's reader takes {course}, the text before it)",
            whole.trim()
        ),
    );
    whole.into()
}

/// The text of `node` as a list of non-negative integers (indices, counts).
pub fn indices(doc: &Doc, node: Node) -> Result<Vec<u32>, SceneError> {
    let text = &element_text(doc, node);
    text.split_ascii_whitespace()
        .enumerate()
        .map(|(i, token)| {
            token.parse::<u32>().map_err(|_| {
                doc.err(
                    node,
                    format!("value {i} is \"{token}\", not a non-negative integer"),
                )
            })
        })
        .collect()
}

/// The text of `node` as exactly one finite float.
pub fn single_float(doc: &Doc, node: Node) -> Result<f32, SceneError> {
    match floats(doc, node)?.as_slice() {
        [x] => Ok(*x),
        other => Err(doc.err(node, format!("expected one number, found {}", other.len()))),
    }
}

/// The text of `node` as a colour: one number (grey) or at least three (the
/// first three are red, green and blue; a fourth, alpha, is ignored).
pub fn color(doc: &Doc, node: Node) -> Result<Rgb, SceneError> {
    match floats(doc, node)?.as_slice() {
        [g] => Ok(Rgb::splat(*g)),
        [r, g, b, ..] => Ok(Rgb::new(*r, *g, *b)),
        other => Err(doc.err(
            node,
            format!("expected a colour of 1 or 3 numbers, found {}", other.len()),
        )),
    }
}

/// The attribute `name` of `node` as a non-negative integer; `default` when
/// it is absent and `default` is given.
pub fn count_attr(
    doc: &Doc,
    node: Node,
    name: &str,
    default: Option<usize>,
) -> Result<usize, SceneError> {
    let text = match (node.attribute(name), default) {
        (None, Some(d)) => return Ok(d),
        (None, None) => require_attr(doc, node, name)?,
        (Some(t), _) => t,
    };
    text.trim().parse().map_err(|_| {
        doc.err(
            node,
            format!("attribute {name}=\"{text}\" is not a non-negative integer"),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use roxmltree::Document;

    fn with_node<T>(text: &str, f: impl FnOnce(&Doc, Node) -> T) -> T {
        let document = Document::parse(text).unwrap();
        let doc = Doc::new(&document, "t.dae");
        f(&doc, document.root_element())
    }

    #[test]
    fn floats_parse_course_spellings() {
        let v = with_node("<a> .3 1e-7\n-2 </a>", |d, n| floats(d, n).unwrap());
        assert_eq!(v, vec![0.3, 1e-7, -2.0]);
    }

    #[test]
    fn bad_and_non_finite_tokens_are_named() {
        for (text, token) in [
            ("<a>1 x2</a>", "x2"),
            ("<a>NaN</a>", "NaN"),
            ("<a>1e60</a>", "1e60"),
        ] {
            let e = with_node(text, |d, n| floats(d, n).unwrap_err());
            assert!(e.problem.contains(token), "{e}");
        }
        let e = with_node("<a>1 -2</a>", |d, n| indices(d, n).unwrap_err());
        assert!(e.problem.contains("\"-2\""), "{e}");
    }

    #[test]
    fn colours_take_grey_or_rgb() {
        let grey = with_node("<c>0.5</c>", |d, n| color(d, n).unwrap());
        assert_eq!(grey, Rgb::splat(0.5));
        let rgb = with_node("<c>0.6 0.2 0.2 1</c>", |d, n| color(d, n).unwrap());
        assert_eq!(rgb, Rgb::new(0.6, 0.2, 0.2));
        assert!(with_node("<c>1 2</c>", color).is_err());
    }

    #[test]
    fn count_attributes() {
        let n = with_node(r#"<a count="12"/>"#, |d, n| count_attr(d, n, "count", None));
        assert_eq!(n.unwrap(), 12);
        let s = with_node("<a/>", |d, n| count_attr(d, n, "stride", Some(1)));
        assert_eq!(s.unwrap(), 1);
        assert!(with_node(r#"<a count="-1"/>"#, |d, n| count_attr(d, n, "count", None)).is_err());
    }
}
