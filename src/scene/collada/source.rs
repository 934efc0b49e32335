//! `<source>`: a `<float_array>` read through its `<accessor>`.
//!
//! The accessor describes `count` elements of `stride` floats starting at
//! `offset` (default 0) of the array: element i is
//! `array[offset + i * stride ..][..stride]`. The checks:
//!
//! - `float_array count` equals the number of floats in its text;
//! - `offset + count * stride` fits in the array (no overflow either);
//! - every float is finite (see [`super::numbers`]).

use glam::Vec3;
use roxmltree::Node;

use super::super::SceneError;
use super::numbers::{count_attr, floats};
use super::xml::{descend, require_child, Doc};

/// The elements of one `<source>`.
#[derive(Clone, Debug, PartialEq)]
pub struct Source {
    /// Number of elements (the accessor's `count`).
    pub count: usize,
    /// Floats per element.
    pub stride: usize,
    /// The floats of the elements, `count * stride` of them.
    values: Vec<f32>,
}

impl Source {
    /// Every element's first three floats as a point (needs stride >= 3).
    pub fn points(&self) -> Vec<Vec3> {
        self.values
            .chunks_exact(self.stride.max(1))
            .filter_map(|e| match e {
                [x, y, z, ..] => Some(Vec3::new(*x, *y, *z)),
                _ => None,
            })
            .collect()
    }
}

/// Reads the `<source>` element `source`.
pub fn source(doc: &Doc, source: Node) -> Result<Source, SceneError> {
    let array = require_child(doc, source, "float_array")?;
    let values = floats(doc, array)?;
    let declared = count_attr(doc, array, "count", None)?;
    if declared != values.len() {
        return Err(doc.err(
            array,
            format!(
                "count=\"{declared}\" but the array holds {} numbers",
                values.len()
            ),
        ));
    }

    let Some(accessor) = descend(source, &["technique_common", "accessor"]) else {
        return Err(doc.err(source, "missing <technique_common><accessor>"));
    };
    let target = doc.resolve(accessor, "source", "float_array")?;
    if target != array {
        return Err(doc.err(
            accessor,
            "the accessor reads an array outside its own <source>, which is not supported",
        ));
    }
    let count = count_attr(doc, accessor, "count", None)?;
    let stride = count_attr(doc, accessor, "stride", Some(1))?;
    let offset = count_attr(doc, accessor, "offset", Some(0))?;
    if stride == 0 {
        return Err(doc.err(accessor, "stride must be at least 1"));
    }
    let end = count
        .checked_mul(stride)
        .and_then(|n| n.checked_add(offset))
        .filter(|&end| end <= values.len())
        .ok_or_else(|| {
            doc.err(
                accessor,
                format!(
                    "offset {offset} + count {count} * stride {stride} exceeds the array's {} numbers",
                    values.len()
                ),
            )
        })?;
    Ok(Source {
        count,
        stride,
        values: values.get(offset..end).unwrap_or_default().to_vec(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use roxmltree::Document;

    fn parse(
        array_count: usize,
        numbers: &str,
        acc_count: usize,
        stride: usize,
    ) -> Result<Source, SceneError> {
        let text = format!(
            r##"<source id="s"><float_array id="a" count="{array_count}">{numbers}</float_array>
            <technique_common><accessor source="#a" count="{acc_count}" stride="{stride}"/></technique_common></source>"##
        );
        let document = Document::parse(&text).unwrap();
        let doc = Doc::new(&document, "t.dae");
        source(&doc, document.root_element())
    }

    #[test]
    fn reads_points() {
        let s = parse(6, "0 1 2 3 4 5", 2, 3).unwrap();
        assert_eq!(
            s.points(),
            vec![Vec3::new(0., 1., 2.), Vec3::new(3., 4., 5.)]
        );
    }

    #[test]
    fn counts_must_agree() {
        let e = parse(7, "0 1 2 3 4 5", 2, 3).unwrap_err();
        assert!(
            e.element.ends_with("float_array[id=a]") && e.problem.contains("count"),
            "{e}"
        );
        let e = parse(6, "0 1 2 3 4 5", 3, 3).unwrap_err();
        assert!(
            e.element.ends_with("accessor") && e.problem.contains("exceeds"),
            "{e}"
        );
        let e = parse(6, "0 1 2 3 4 5", usize::MAX, 3).unwrap_err();
        assert!(e.problem.contains("exceeds"), "{e}");
    }
}
