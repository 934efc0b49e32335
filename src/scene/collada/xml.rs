//! Navigation helpers over the parsed COLLADA tree: child lookup, attributes,
//! `#id` references and the element paths that errors print.
//!
//! Every lookup that can fail returns a [`SceneError`] naming the element
//! where the problem is, as a path from below `<COLLADA>`, for example
//! `library_geometries/geometry[id=floor-mesh]/mesh/polylist/p`. An element
//! with an `id` shows it; an element without one that has same-named
//! siblings shows its 1-based position (`polylist[2]`), as in XPath.

use std::cell::RefCell;
use std::collections::HashMap;

use roxmltree::{Document, Node};

use super::super::SceneError;

/// A parsed document with its `id` index, the file name for errors and
/// the warnings gathered while reading it.
pub struct Doc<'a, 'input> {
    /// The file (or name) that errors report.
    pub file: &'a str,
    ids: HashMap<&'a str, Node<'a, 'input>>,
    warnings: RefCell<Vec<String>>,
}

impl<'a, 'input> Doc<'a, 'input> {
    /// Indexes every element with an `id` attribute; the first of duplicate
    /// ids wins, as a lookup by `#id` in the course's reader would find it.
    pub fn new(document: &'a Document<'input>, file: &'a str) -> Self {
        let mut ids = HashMap::new();
        for node in document.descendants().filter(Node::is_element) {
            if let Some(id) = node.attribute("id") {
                ids.entry(id).or_insert(node);
            }
        }
        Doc {
            file,
            ids,
            warnings: RefCell::default(),
        }
    }

    /// Records a warning located at `node` ([`Doc::take_warnings`]); the
    /// same warning twice (an element read once per instance) is kept once.
    pub fn warn(&self, node: Node, problem: impl Into<String>) {
        let note = self.note(node, problem);
        let mut warnings = self.warnings.borrow_mut();
        if !warnings.contains(&note) {
            warnings.push(note);
        }
    }

    /// The warnings recorded so far, in order; the list is emptied.
    pub fn take_warnings(&self) -> Vec<String> {
        self.warnings.take()
    }

    /// An error located at `node`.
    pub fn err(&self, node: Node, problem: impl Into<String>) -> SceneError {
        SceneError::new(self.file, element_path(node), problem)
    }

    /// A warning located at `node`, formatted like an error.
    pub fn note(&self, node: Node, problem: impl Into<String>) -> String {
        self.err(node, problem).to_string()
    }

    /// The element `node` refers to through its URL attribute `attr`
    /// (`url`, `source`, `target`), which must be a local `#id` reference to
    /// an element named `expected`.
    pub fn resolve(
        &self,
        node: Node<'a, 'input>,
        attr: &str,
        expected: &str,
    ) -> Result<Node<'a, 'input>, SceneError> {
        let url = require_attr(self, node, attr)?;
        let Some(id) = url.strip_prefix('#') else {
            return Err(self.err(
                node,
                format!("{attr}=\"{url}\" is not a local reference of the form #id"),
            ));
        };
        let Some(&target) = self.ids.get(id) else {
            return Err(self.err(
                node,
                format!("{attr}=\"{url}\" refers to no element (dangling reference)"),
            ));
        };
        if target.tag_name().name() != expected {
            return Err(self.err(
                node,
                format!(
                    "{attr}=\"{url}\" refers to element <{}>, expected element <{expected}>",
                    target.tag_name().name()
                ),
            ));
        }
        Ok(target)
    }
}

/// The first child element of `node` named `name`.
pub fn child<'a, 'input>(node: Node<'a, 'input>, name: &str) -> Option<Node<'a, 'input>> {
    node.children()
        .find(|c| c.is_element() && c.tag_name().name() == name)
}

/// Every child element of `node` named `name`, in document order.
pub fn children<'a, 'input: 'a>(
    node: Node<'a, 'input>,
    name: &'a str,
) -> impl Iterator<Item = Node<'a, 'input>> + 'a {
    node.children()
        .filter(move |c| c.is_element() && c.tag_name().name() == name)
}

/// The first child element of `node` named `name`, or an error saying it is missing.
pub fn require_child<'a, 'input>(
    doc: &Doc,
    node: Node<'a, 'input>,
    name: &str,
) -> Result<Node<'a, 'input>, SceneError> {
    child(node, name).ok_or_else(|| doc.err(node, format!("missing child element <{name}>")))
}

/// Follows a chain of child names, `None` as soon as one is missing.
pub fn descend<'a, 'input>(node: Node<'a, 'input>, path: &[&str]) -> Option<Node<'a, 'input>> {
    path.iter().try_fold(node, |n, name| child(n, name))
}

/// The attribute `name` of `node`, or an error saying it is missing.
pub fn require_attr<'a>(doc: &Doc, node: Node<'a, '_>, name: &str) -> Result<&'a str, SceneError> {
    node.attribute(name)
        .ok_or_else(|| doc.err(node, format!("missing attribute {name}")))
}

/// The `<technique profile="CGL">` directly under `node`, if any
/// ([`is_cgl`]).
pub fn cgl_technique<'a, 'input>(doc: &Doc, node: Node<'a, 'input>) -> Option<Node<'a, 'input>> {
    children(node, "technique").find(|t| is_cgl(doc, *t))
}

/// Whether `technique` is the course's `profile="CGL"`, matched exactly
/// as the course's reader matches it. A profile that is CGL in another
/// case or with spaces is not, and gets a warning; so does a technique
/// under `<extra>` without a profile (COLLADA requires one there).
pub fn is_cgl(doc: &Doc, technique: Node) -> bool {
    let said = match technique.attribute("profile") {
        Some("CGL") => return true,
        Some(p) if p.trim().eq_ignore_ascii_case("CGL") => format!("profile=\"{p}\""),
        None if technique.parent().is_some_and(|p| p.has_tag_name("extra")) => {
            "no profile".to_string()
        }
        _ => return false,
    };
    doc.warn(
        technique,
        format!(
            "a technique with {said} is not the course's profile=\"CGL\" (matched exactly); \
             it is ignored, as the course ignores it"
        ),
    );
    false
}

/// The first child element of `node`, whatever its name.
pub fn first_element<'a, 'input>(node: Node<'a, 'input>) -> Option<Node<'a, 'input>> {
    node.children().find(Node::is_element)
}

/// Longest element path printed in full; deeper paths elide their middle.
const MAX_PATH_STEPS: usize = 12;

/// The path of `node` below the `<COLLADA>` root, for error messages.
pub fn element_path(node: Node) -> String {
    let mut parts: Vec<String> = node
        .ancestors()
        .filter(|n| n.is_element() && n.parent().is_some_and(|p| p.is_element()))
        .map(step)
        .collect();
    parts.reverse();
    // Keep messages readable for absurdly deep nesting.
    if parts.len() > MAX_PATH_STEPS {
        let hidden = parts.len() - MAX_PATH_STEPS;
        parts.splice(4..4 + hidden, [format!("...({hidden} more)...")]);
    }
    if parts.is_empty() && node.is_element() {
        // The root element itself.
        return node.tag_name().name().to_string();
    }
    parts.join("/")
}

/// One step of an element path: `name`, `name[id=X]` or `name[k]`.
fn step(node: Node) -> String {
    let name = node.tag_name().name();
    if let Some(id) = node.attribute("id") {
        return format!("{name}[id={id}]");
    }
    let same = |n: &Node| n.is_element() && n.tag_name().name() == name;
    let before = node.prev_siblings().skip(1).filter(same).count();
    let after = node.next_siblings().skip(1).filter(same).count();
    if before + after == 0 {
        name.to_string()
    } else {
        format!("{name}[{}]", before + 1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const TEXT: &str = r##"<COLLADA><library_geometries><geometry id="g"><mesh>
        <polylist/><polylist><p/></polylist></mesh></geometry></library_geometries>
        <a url="#g"/><b url="g"/><c url="#nope"/><d url="#g"/></COLLADA>"##;

    #[test]
    fn paths_name_ids_and_positions() {
        let document = Document::parse(TEXT).unwrap();
        let p = document
            .descendants()
            .find(|n| n.has_tag_name("p"))
            .unwrap();
        assert_eq!(
            element_path(p),
            "library_geometries/geometry[id=g]/mesh/polylist[2]/p"
        );
        assert_eq!(element_path(document.root_element()), "COLLADA");
    }

    #[test]
    fn references_resolve_or_explain() {
        let document = Document::parse(TEXT).unwrap();
        let doc = Doc::new(&document, "t.dae");
        let get = |name: &str| {
            document
                .descendants()
                .find(|n| n.has_tag_name(name))
                .unwrap()
        };
        assert!(doc.resolve(get("a"), "url", "geometry").is_ok());
        let e = doc.resolve(get("b"), "url", "geometry").unwrap_err();
        assert!(e.problem.contains("local reference"), "{e}");
        let e = doc.resolve(get("c"), "url", "geometry").unwrap_err();
        assert!(e.problem.contains("dangling"), "{e}");
        let e = doc.resolve(get("d"), "url", "material").unwrap_err();
        assert!(e.problem.contains("expected element <material>"), "{e}");
        assert_eq!(e.element, "d");
    }
}
