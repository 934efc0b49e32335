//! Structure-aware mutation of the course's `.dae` dialect.
//!
//! A mutation knows what it did. Those that give a field a value no
//! material or light can have, misspell a field or a profile, repeat a
//! field or split its number with a comment are *nonsense*: the renderer
//! must refuse them or warn. The others (deleted, repeated and renamed
//! elements, dropped attributes, broken references, truncation, deep
//! nesting, extreme numbers anywhere, other encodings, byte noise) may be
//! rendered in silence, but never crash, hang or write a bad pixel.
//! Values the format allows (`0.25`, `1`) must render.

use rand::seq::SliceRandom;
use rand::Rng;
use roxmltree::{Document, Node};

/// A mutated scene file.
pub struct Mutant {
    pub bytes: Vec<u8>,
    /// What the mutation did, for the failure messages.
    pub what: String,
    /// The renderer must refuse it or warn about it.
    pub nonsense: bool,
    /// The format allows it: the renderer must render it.
    pub legal: bool,
}

/// Values no field of a material or light can take.
const NONSENSE_VALUES: [&str; 12] = [
    "-1", "-0.001", "1e30", "3.4e38", "-3.4e38", "NaN", "inf", "", "abc", "1e20", "0.5 0.5",
    "1.5.2",
];
/// Values every field allows (for a colour, grey).
const LEGAL_VALUES: [&str; 2] = ["0.25", "1"];
/// Profiles that are not the course's `CGL`.
const NEAR_PROFILES: [&str; 5] = [
    r#"profile="cgl""#,
    r#"profile="CGL ""#,
    r#"profile=" CGL""#,
    r#"profile="Cgl""#,
    "",
];
/// Numbers anywhere: extreme but not all nonsense (a huge vertex).
const EXTREME_NUMBERS: [&str; 10] = [
    "1e30",
    "-1e30",
    "3.4e38",
    "1e-45",
    "0",
    "-0",
    "NaN",
    "1e39",
    "4294967296",
    "-1",
];
/// Tag names an element may be renamed to.
const TAGS: [&str; 8] = [
    "node",
    "mesh",
    "glass",
    "p",
    "color",
    "extra",
    "technique",
    "x",
];
/// Depths a scene's nodes may be nested to.
const DEPTHS: [usize; 7] = [10, 255, 300, 999, 1001, 5000, 50_000];

/// One mutation of `base`, chosen by `rng`.
pub fn mutate(base: &str, rng: &mut impl Rng) -> Mutant {
    let document = Document::parse(base).expect("the base scene parses");
    let elements: Vec<Node> = document.descendants().filter(Node::is_element).collect();
    let fields: Vec<Node> = elements
        .iter()
        .copied()
        .filter(|n| is_read_field(n) && is_used(&document, *n))
        .collect();
    let text = |what: String, text: String, nonsense: bool| Mutant {
        bytes: text.into_bytes(),
        what,
        nonsense,
        legal: false,
    };
    let field = *fields.choose(rng).expect("the base scene has fields");
    let element = *elements[1..].choose(rng).unwrap();
    match rng.gen_range(0..14) {
        0 => {
            let name = field.tag_name().name();
            let typo = misspell(name, rng);
            let what = format!("field <{name}> misspelt <{typo}>");
            text(what, rename(base, field, &typo), true)
        }
        1 | 2 => {
            let value = *NONSENSE_VALUES.choose(rng).unwrap();
            let what = format!("<{}> given \"{value}\"", path(field));
            text(what, set_text(base, field, value), true)
        }
        3 => {
            let value = *LEGAL_VALUES.choose(rng).unwrap();
            let what = format!("<{}> given \"{value}\"", path(field));
            Mutant {
                legal: true,
                ..text(what, set_text(base, field, value), false)
            }
        }
        4 => {
            let techniques: Vec<&Node> = elements
                .iter()
                .filter(|n| n.attribute("profile") == Some("CGL") && is_used(&document, **n))
                .collect();
            let technique = techniques.choose(rng).unwrap();
            let profile = *NEAR_PROFILES.choose(rng).unwrap();
            let start = &base[technique.range()];
            let changed = start.replacen(r#"profile="CGL""#, profile, 1);
            let mutated = splice(base, technique.range(), &changed);
            text(
                format!("{} with [{profile}]", path(**technique)),
                mutated,
                true,
            )
        }
        5 => {
            let copy = format!("<{0}>0.3</{0}>", field.tag_name().name());
            let end = field.range().end;
            let mutated = splice(base, end..end, &copy);
            text(format!("<{}> given twice", path(field)), mutated, true)
        }
        6 => {
            let inner = inner_range(base, field);
            let number = &base[inner.clone()];
            let Some(at) = number.trim_start().char_indices().nth(1).map(|(i, _)| i) else {
                return mutate(base, rng);
            };
            let at = inner.start + (number.len() - number.trim_start().len()) + at;
            let mutated = splice(base, at..at, "<!-- split -->");
            text(
                format!("<{}> split by a comment", path(field)),
                mutated,
                true,
            )
        }
        7 => text(
            format!("{} deleted", path(element)),
            splice(base, element.range(), ""),
            false,
        ),
        8 => {
            let copy = base[element.range()].to_string();
            let end = element.range().end;
            text(
                format!("{} repeated", path(element)),
                splice(base, end..end, &copy),
                false,
            )
        }
        9 => {
            let tag = *TAGS.choose(rng).unwrap();
            let what = format!("{} renamed <{tag}>", path(element));
            text(what, rename(base, element, tag), false)
        }
        10 => {
            let mutated = match element.attributes().collect::<Vec<_>>().choose(rng) {
                Some(a) => {
                    let value = ["", "#nope", "#", "-1", "99999999999"].choose(rng).unwrap();
                    splice(base, a.range_value(), value)
                }
                None => base.to_string(),
            };
            text(
                format!("an attribute of {} changed", path(element)),
                mutated,
                false,
            )
        }
        11 => {
            let depth = *DEPTHS.choose(rng).unwrap();
            let at = elements
                .iter()
                .find(|n| n.has_tag_name("visual_scene"))
                .map_or(0, |v| {
                    v.range().start + base[v.range()].find('>').unwrap() + 1
                });
            let nest = format!("{}{}", "<node>".repeat(depth), "</node>".repeat(depth));
            text(
                format!("nodes nested {depth} deep"),
                splice(base, at..at, &nest),
                false,
            )
        }
        12 => {
            let inner = inner_range(base, element);
            let tokens: Vec<(usize, &str)> = base[inner.clone()]
                .split_ascii_whitespace()
                .map(|t| (t.as_ptr() as usize - base.as_ptr() as usize, t))
                .filter(|(_, t)| t.parse::<f64>().is_ok())
                .collect();
            let Some(&(at, token)) = tokens.choose(rng) else {
                return mutate(base, rng);
            };
            let value = *EXTREME_NUMBERS.choose(rng).unwrap();
            let what = format!("a number of {} set to {value}", path(element));
            text(what, splice(base, at..at + token.len(), value), false)
        }
        _ => raw_mutation(base, rng),
    }
}

/// Byte-level mutations: truncation, encodings, noise.
fn raw_mutation(base: &str, rng: &mut impl Rng) -> Mutant {
    let bytes = base.as_bytes();
    let (what, bytes) = match rng.gen_range(0..4) {
        0 => {
            let cut = rng.gen_range(0..bytes.len());
            (format!("truncated at byte {cut}"), bytes[..cut].to_vec())
        }
        1 => (
            "with a UTF-8 byte order mark".into(),
            [b"\xef\xbb\xbf", bytes].concat(),
        ),
        2 => {
            let utf16: Vec<u8> = std::iter::once(0xfeff)
                .chain(base.encode_utf16())
                .flat_map(u16::to_le_bytes)
                .collect();
            ("in UTF-16".into(), utf16)
        }
        _ => {
            let mut noisy = bytes.to_vec();
            for _ in 0..rng.gen_range(1..8) {
                let at = rng.gen_range(0..noisy.len());
                noisy[at] = *b"<>/\"=&;#x09 \0\xff".choose(rng).unwrap();
            }
            ("with noise bytes".into(), noisy)
        }
    };
    Mutant {
        bytes,
        what,
        nonsense: false,
        legal: false,
    }
}

/// Whether `node` is a field the course's reader reads: a child of a CGL
/// BSDF, light or sphere, of the light kind that is used, or the colour of
/// a common-profile diffuse when the effect has no CGL technique.
fn is_read_field(node: &Node) -> bool {
    let Some(parent) = node.parent_element() else {
        return false;
    };
    let under_cgl = parent
        .ancestors()
        .any(|a| a.has_tag_name("technique") && a.attribute("profile") == Some("CGL"));
    let light = parent.ancestors().find(|a| a.has_tag_name("light"));
    let light_has_cgl = light.is_some_and(|l| {
        l.descendants()
            .any(|d| d.attribute("profile") == Some("CGL"))
    });
    let effect = parent.ancestors().find(|a| a.has_tag_name("effect"));
    let effect_has_cgl = effect.is_some_and(|e| {
        e.descendants()
            .any(|d| d.attribute("profile") == Some("CGL"))
    });
    let common_diffuse = parent.has_tag_name("diffuse") && node.has_tag_name("color");
    let radius = node.has_tag_name("radius");
    if radius {
        return false; // geometry: not a material or light field
    }
    let light_colour = light.is_none() || node.has_tag_name("color");
    (under_cgl && parent.tag_name().name() != "technique" && light_colour)
        || (light.is_some()
            && !light_has_cgl
            && node.has_tag_name("color")
            && parent
                .parent_element()
                .is_some_and(|t| t.has_tag_name("technique_common")))
        || (common_diffuse && effect.is_some() && !effect_has_cgl)
}

/// Whether the geometry, light or effect holding `node` is used by the
/// scene: a library element nothing refers to is not read, by the course's
/// reader or this one, and what is in it cannot matter.
fn is_used(document: &Document, node: Node) -> bool {
    let referred = |attribute: &str, id: &str| {
        let reference = format!("#{id}");
        document
            .descendants()
            .any(|n| n.attribute(attribute) == Some(reference.as_str()))
    };
    let Some(owner) = node
        .ancestors()
        .find(|a| ["geometry", "light", "effect"].contains(&a.tag_name().name()))
    else {
        return true;
    };
    let Some(id) = owner.attribute("id") else {
        return false;
    };
    if !owner.has_tag_name("effect") {
        return referred("url", id);
    }
    let effect_url = format!("#{id}");
    document
        .descendants()
        .filter(|n| n.has_tag_name("material"))
        .filter(|m| {
            m.descendants()
                .any(|i| i.attribute("url") == Some(effect_url.as_str()))
        })
        .any(|m| m.attribute("id").is_some_and(|mid| referred("target", mid)))
}

/// `name` one or two letters off.
fn misspell(name: &str, rng: &mut impl Rng) -> String {
    let mut chars: Vec<char> = name.chars().collect();
    match rng.gen_range(0..3) {
        0 => {
            let at = rng.gen_range(0..=chars.len());
            chars.insert(at, *['r', 'e', 'a', 'x'].choose(rng).unwrap());
        }
        1 if chars.len() > 1 => {
            chars.remove(rng.gen_range(0..chars.len()));
        }
        _ => {
            let at = rng.gen_range(0..chars.len());
            chars[at] = if chars[at] == 'e' { 'a' } else { 'e' };
        }
    }
    let typo: String = chars.into_iter().collect();
    if typo == name {
        format!("{name}s")
    } else {
        typo
    }
}

/// `base` with `range` replaced by `with`.
fn splice(base: &str, range: std::ops::Range<usize>, with: &str) -> String {
    format!("{}{with}{}", &base[..range.start], &base[range.end..])
}

/// The byte range of `node`'s content, between its start and end tags
/// (empty, at the end, for a self-closing element).
fn inner_range(base: &str, node: Node) -> std::ops::Range<usize> {
    let whole = &base[node.range()];
    let open_end = node.range().start + whole.find('>').unwrap() + 1;
    if whole.ends_with("/>") {
        return node.range().end..node.range().end;
    }
    let close_start = node.range().start + whole.rfind("</").unwrap();
    open_end..close_start
}

/// `base` with `node`'s text set to `value`.
fn set_text(base: &str, node: Node, value: &str) -> String {
    let inner = inner_range(base, node);
    if inner.is_empty() && base[node.range()].ends_with("/>") {
        let name = node.tag_name().name();
        return splice(base, node.range(), &format!("<{name}>{value}</{name}>"));
    }
    splice(base, inner, value)
}

/// `base` with `node`'s start and end tags renamed `to`.
fn rename(base: &str, node: Node, to: &str) -> String {
    let name = node.tag_name().name();
    let range = node.range();
    let whole = &base[range.clone()];
    let renamed = if whole.ends_with("/>") {
        whole.replacen(&format!("<{name}"), &format!("<{to}"), 1)
    } else {
        let close = format!("</{name}>");
        let body = &whole[..whole.len() - close.len()];
        format!(
            "{}</{to}>",
            body.replacen(&format!("<{name}"), &format!("<{to}"), 1)
        )
    };
    splice(base, range, &renamed)
}

/// `node`'s tag and its parent's, for messages.
fn path(node: Node) -> String {
    match node.parent_element() {
        Some(p) => format!("{}/{}", p.tag_name().name(), node.tag_name().name()),
        None => node.tag_name().name().to_string(),
    }
}
