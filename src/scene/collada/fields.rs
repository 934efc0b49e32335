//! The fields of a CGL element (a material's BSDF, a light's kind, a
//! sphere), read so that a typo is never taken for a default in silence.
//!
//! The course's reader looks each field up by name and takes a default
//! when it finds none, so `<iorr>1.2</iorr>` gives glass of index 1.5
//! without a word. Here:
//!
//! - a child element that is not one of the element's fields is a warning
//!   naming it, the fields the element has, and the nearest one (at most
//!   two letters off: `<iorr>` -> `<ior>`, `<alfa>` -> `<alpha>`);
//! - a field given twice is a warning naming both values (the first is
//!   used, as the course's reader would);
//! - a value outside its [`Rule`]'s range is an error (a negative
//!   reflectance, an `alpha` of `1e30`), and a value above its plausible
//!   bound a warning (a reflectance above 1 reflects more light than
//!   arrives).

use roxmltree::Node;

use super::super::SceneError;
use super::numbers::{color, single_float};
use super::xml::{children, Doc};
use crate::math::float::readable;
use crate::math::{Rgb, MAX_RADIANCE};

/// The range a field's values must lie in.
#[derive(Clone, Copy, Debug)]
pub struct Rule {
    /// The smallest value allowed (itself excluded when `exclusive`).
    pub min: f32,
    /// Whether `min` itself is refused (an index of refraction of 0).
    pub exclusive: bool,
    /// The largest value allowed.
    pub max: f32,
    /// Above this a value is allowed but warned about, with the reason.
    pub plausible: Option<(f32, &'static str)>,
}

/// Reflectance, transmittance and albedo: at least 0; above 1 the
/// surface gives back more light than it receives.
pub const REFLECTANCE: Rule = Rule {
    min: 0.0,
    exclusive: false,
    max: MAX_RADIANCE,
    plausible: Some((1.0, "the surface gives back more light than it receives")),
};

/// Radiance and intensity: at least 0, at most [`MAX_RADIANCE`].
pub const RADIANCE: Rule = Rule {
    min: 0.0,
    exclusive: false,
    max: MAX_RADIANCE,
    plausible: None,
};

/// An index of refraction: above 0 (below 1 is a medium thinner than its
/// outside), at most 100 (real dielectrics stay below about 4).
pub const IOR: Rule = Rule {
    min: 0.0,
    exclusive: true,
    max: 100.0,
    plausible: Some((5.0, "real dielectrics stay below about 4")),
};

/// A conductor's `eta` or `k` per channel: at least 0, at most 100 (metals
/// stay below about 10 in the visible range).
pub const CONDUCTOR: Rule = Rule {
    min: 0.0,
    exclusive: false,
    max: 100.0,
    plausible: None,
};

/// Beckmann roughness `alpha`: above 0, at most 100 (beyond about 1 the
/// surface is as rough as the model goes).
pub const ALPHA: Rule = Rule {
    min: 0.0,
    exclusive: true,
    max: 100.0,
    plausible: None,
};

/// Glass's `roughness` (the course keeps it and does not use it): at
/// least 0, at most 100.
pub const ROUGHNESS: Rule = Rule {
    min: 0.0,
    exclusive: false,
    max: 100.0,
    plausible: None,
};

/// The fields of one CGL element.
pub struct Fields<'d, 'a, 'input> {
    doc: &'d Doc<'a, 'input>,
    element: Node<'a, 'input>,
}

impl<'d, 'a, 'input> Fields<'d, 'a, 'input> {
    /// The fields of `element`, whose known names are `known`; warns about
    /// the children that are not among them and the ones given twice.
    pub fn new(doc: &'d Doc<'a, 'input>, element: Node<'a, 'input>, known: &[&str]) -> Self {
        let name = element.tag_name().name();
        for field in element.children().filter(Node::is_element) {
            let field_name = field.tag_name().name();
            if !known.contains(&field_name) {
                let hint = nearest(field_name, known)
                    .map_or(String::new(), |k| format!(" (did you mean <{k}>?)"));
                let list = known.iter().map(|k| format!("<{k}>")).collect::<Vec<_>>();
                doc.warn(
                    field,
                    format!(
                        "<{name}> has no field <{field_name}>{hint}; it is ignored. Its fields are {}",
                        list.join(", ")
                    ),
                );
            }
        }
        for &field_name in known {
            let given: Vec<Node> = children(element, field_name).collect();
            if given.len() > 1 {
                let values: Vec<String> = given.iter().map(|n| text_of(*n)).collect();
                doc.warn(
                    given[1],
                    format!(
                        "<{field_name}> is given {} times ({}); the first is used",
                        given.len(),
                        values.join(", ")
                    ),
                );
            }
        }
        Fields { doc, element }
    }

    /// The colour field `name` (one number or three), `default` when it is
    /// missing, each channel checked against `rule`.
    pub fn colour(&self, name: &str, default: Rgb, rule: Rule) -> Result<Rgb, SceneError> {
        let Some(node) = self.node(name) else {
            return Ok(default);
        };
        let value = color(self.doc, node)?;
        let lowest = Rule {
            plausible: None,
            ..rule
        };
        self.check(node, name, value.min_element(), lowest)?;
        self.check(node, name, value.max_element(), rule)?;
        Ok(value)
    }

    /// The number field `name`, `default` when it is missing, checked
    /// against `rule`.
    pub fn number(&self, name: &str, default: f32, rule: Rule) -> Result<f32, SceneError> {
        let Some(node) = self.node(name) else {
            return Ok(default);
        };
        let value = single_float(self.doc, node)?;
        self.check(node, name, value, rule)?;
        Ok(value)
    }

    /// The field `name`, which must be given; when it is missing, the error
    /// names a field given that is at most two letters off (`<colour>`).
    pub fn required(&self, name: &str) -> Result<Node<'a, 'input>, SceneError> {
        self.node(name).ok_or_else(|| {
            let near = self
                .element
                .children()
                .filter(Node::is_element)
                .map(|c| c.tag_name().name())
                .find(|given| edit_distance(given, name) <= 2);
            let hint = near.map_or(String::new(), |g| format!(" (<{g}> is given: misspelt?)"));
            self.doc.err(
                self.element,
                format!("missing child element <{name}>{hint}"),
            )
        })
    }

    /// The first child element named `name`.
    fn node(&self, name: &str) -> Option<Node<'a, 'input>> {
        self.element
            .children()
            .find(|c| c.is_element() && c.tag_name().name() == name)
    }

    /// Refuses `value` outside `rule`'s range; warns above its plausible bound.
    fn check(&self, node: Node, name: &str, value: f32, rule: Rule) -> Result<(), SceneError> {
        let too_small = if rule.exclusive {
            value <= rule.min
        } else {
            value < rule.min
        };
        if too_small || value > rule.max {
            let low = if rule.exclusive {
                format!("above {}", rule.min)
            } else {
                format!("at least {}", rule.min)
            };
            return Err(self.doc.err(
                node,
                format!(
                    "<{name}> must be {low} and at most {}; found {}",
                    readable(rule.max),
                    readable(value)
                ),
            ));
        }
        if let Some((bound, why)) = rule.plausible {
            if value > bound {
                self.doc
                    .warn(node, format!("<{name}> is {value}, above {bound}: {why}"));
            }
        }
        Ok(())
    }
}

/// The text of `node`, trimmed, for messages.
fn text_of(node: Node) -> String {
    let text: String = node.children().filter_map(|c| c.text()).collect();
    format!("\"{}\"", text.trim())
}

/// The name among `known` at most two edits from `name` (the nearest).
fn nearest<'k>(name: &str, known: &[&'k str]) -> Option<&'k str> {
    known
        .iter()
        .map(|k| (edit_distance(name, k), *k))
        .filter(|&(d, _)| d <= 2)
        .min_by_key(|&(d, _)| d)
        .map(|(_, k)| k)
}

/// The Levenshtein distance: the fewest insertions, deletions and
/// substitutions of one character that turn `a` into `b`.
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let substitution = diagonal + usize::from(ca != cb);
            diagonal = row[j + 1];
            row[j + 1] = substitution.min(row[j] + 1).min(row[j + 1] + 1);
        }
    }
    row[b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;
    use roxmltree::Document;

    #[test]
    fn edit_distances() {
        assert_eq!(edit_distance("iorr", "ior"), 1);
        assert_eq!(edit_distance("alfa", "alpha"), 2);
        assert_eq!(edit_distance("reflectence", "reflectance"), 1);
        assert_eq!(edit_distance("radience", "radiance"), 1);
        assert_eq!(edit_distance("", "abc"), 3);
        assert_eq!(nearest("colour", &["color"]), Some("color"));
        assert_eq!(nearest("velvet", &["ior", "alpha"]), None);
    }

    fn read<T>(text: &str, f: impl FnOnce(&Fields) -> T) -> (T, Vec<String>) {
        let document = Document::parse(text).unwrap();
        let doc = Doc::new(&document, "t.dae");
        let fields = Fields::new(&doc, document.root_element(), &["ior", "reflectance"]);
        let value = f(&fields);
        (value, doc.take_warnings())
    }

    #[test]
    fn typos_and_repeats_are_warned_about() {
        let (ior, w) = read("<glass><iorr>1.2</iorr></glass>", |f| {
            f.number("ior", 1.5, IOR).unwrap()
        });
        assert_eq!(ior, 1.5);
        assert!(
            w.len() == 1 && w[0].contains("did you mean <ior>?"),
            "{w:?}"
        );
        let (ior, w) = read("<glass><ior>2.4</ior><ior>NaN</ior></glass>", |f| {
            f.number("ior", 1.5, IOR).unwrap()
        });
        assert_eq!(ior, 2.4);
        assert!(w.len() == 1 && w[0].contains("\"2.4\", \"NaN\""), "{w:?}");
    }

    #[test]
    fn values_out_of_range_are_errors_and_implausible_ones_warnings() {
        let (e, _) = read("<glass><reflectance>1 -0.5 1</reflectance></glass>", |f| {
            f.colour("reflectance", Rgb::ONE, REFLECTANCE).unwrap_err()
        });
        assert!(e.problem.contains("-0.5"), "{e}");
        let (e, _) = read("<glass><ior>1e30</ior></glass>", |f| {
            f.number("ior", 1.5, IOR).unwrap_err()
        });
        assert!(e.problem.contains("at most 100;"), "{e}");
        let (e, _) = read("<glass><ior>0</ior></glass>", |f| {
            f.number("ior", 1.5, IOR).unwrap_err()
        });
        assert!(e.problem.contains("above 0"), "{e}");
        let (r, w) = read("<glass><reflectance>1.5</reflectance></glass>", |f| {
            f.colour("reflectance", Rgb::ONE, REFLECTANCE).unwrap()
        });
        assert_eq!(r, Rgb::splat(1.5));
        assert!(w.len() == 1 && w[0].contains("more light"), "{w:?}");
    }
}
