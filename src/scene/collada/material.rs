//! `<material>` -> `<instance_effect>` -> `<effect>`: the course's
//! [`Material`]s (the starter's `ColladaParser::parse_material`,
//! `src/scene/collada/collada.cpp`).
//!
//! If the effect contains a `<technique profile="CGL">` anywhere (under
//! `effect/extra`, or under `profile_COMMON/extra`), its first element names
//! the BSDF, with these fields and defaults when a field is missing:
//!
//! | CGL element | fields (default) |
//! | --- | --- |
//! | `emission` | `radiance` (1 1 1) |
//! | `mirror` | `reflectance` (1 1 1) |
//! | `glass` | `reflectance` (1 1 1), `transmittance` (1 1 1), `roughness` (0), `ior` (1.5) |
//! | `refraction` | `transmittance` (1 1 1), `roughness` (0), `ior` (1.5) |
//! | `microfacet` | `alpha` (0.5), `eta` and `k` (copper: 0.33228 1.0162 1.2474 and 3.1646 2.5785 2.4603, the format doc's example) |
//!
//! A colour field takes one number (grey) or three. Unknown or repeated
//! fields are warnings and values out of range errors (`super::fields`);
//! a technique that was meant as CGL but is not spelled `profile="CGL"`
//! exactly is ignored with a warning, as the course's reader ignores it. Otherwise the material
//! is diffuse with the `<diffuse><color>` of the effect's `<phong>`
//! shader (albedo 0.5, the course's default, when there is none or it is a
//! texture); the course reads no other shader, so a `<lambert>` or
//! `<blinn>` colour is ignored with a warning. An unknown CGL BSDF is an error.

use roxmltree::Node;

use super::super::{Material, SceneError};
use super::fields::{Fields, ALPHA, CONDUCTOR, IOR, RADIANCE, REFLECTANCE, ROUGHNESS};
use super::xml::{child, descend, first_element, is_cgl, require_child, Doc};
use crate::math::Rgb;

/// The material `material` (a `<material>` element) describes.
pub fn material(doc: &Doc, material: Node) -> Result<Material, SceneError> {
    let instance = require_child(doc, material, "instance_effect")?;
    let effect = doc.resolve(instance, "url", "effect")?;
    let mut cgl = None;
    for technique in effect.descendants().filter(|n| n.has_tag_name("technique")) {
        if is_cgl(doc, technique) {
            cgl = cgl.or(Some(technique));
        }
    }
    match cgl {
        Some(technique) => cgl_bsdf(doc, technique),
        None => Ok(Material::Diffuse {
            albedo: diffuse_color(doc, effect)?.unwrap_or(Rgb::splat(0.5)),
        }),
    }
}

/// The BSDF a CGL technique names.
fn cgl_bsdf(doc: &Doc, technique: Node) -> Result<Material, SceneError> {
    let Some(bsdf) = first_element(technique) else {
        return Err(doc.err(technique, "the CGL technique names no material"));
    };
    if let Some(extra) = bsdf.next_siblings().skip(1).find(Node::is_element) {
        doc.warn(
            extra,
            "the CGL technique names more than one material; the first is used",
        );
    }
    let name = bsdf.tag_name().name();
    let material = match name {
        "emission" => {
            let f = Fields::new(doc, bsdf, &["radiance"]);
            Material::Emission {
                radiance: f.colour("radiance", Rgb::ONE, RADIANCE)?,
            }
        }
        "mirror" => {
            let f = Fields::new(doc, bsdf, &["reflectance"]);
            Material::Mirror {
                reflectance: f.colour("reflectance", Rgb::ONE, REFLECTANCE)?,
            }
        }
        "glass" => {
            let f = Fields::new(doc, bsdf, &["reflectance", "transmittance", "roughness", "ior"]);
            Material::Glass {
                reflectance: f.colour("reflectance", Rgb::ONE, REFLECTANCE)?,
                transmittance: f.colour("transmittance", Rgb::ONE, REFLECTANCE)?,
                roughness: f.number("roughness", 0.0, ROUGHNESS)?,
                ior: f.number("ior", 1.5, IOR)?,
            }
        }
        "refraction" => {
            let f = Fields::new(doc, bsdf, &["transmittance", "roughness", "ior"]);
            Material::Refraction {
                transmittance: f.colour("transmittance", Rgb::ONE, REFLECTANCE)?,
                roughness: f.number("roughness", 0.0, ROUGHNESS)?,
                ior: f.number("ior", 1.5, IOR)?,
            }
        }
        "microfacet" => {
            let f = Fields::new(doc, bsdf, &["alpha", "eta", "k"]);
            Material::Microfacet {
                alpha: f.number("alpha", 0.5, ALPHA)?,
                eta: f.colour("eta", COPPER_ETA, CONDUCTOR)?,
                k: f.colour("k", COPPER_K, CONDUCTOR)?,
            }
        }
        other => {
            return Err(doc.err(
                bsdf,
                format!(
                    "unknown CGL material \"{other}\", expected emission, mirror, glass, refraction or microfacet"
                ),
            ))
        }
    };
    Ok(material)
}

/// Copper's index of refraction at about 614, 549 and 466 nm.
const COPPER_ETA: Rgb = Rgb::new(0.33228, 1.0162, 1.2474);
/// Copper's extinction coefficient at about 614, 549 and 466 nm.
const COPPER_K: Rgb = Rgb::new(3.1646, 2.5785, 2.4603);

/// The `<diffuse><color>` of the effect's common-profile shader, if any.
fn diffuse_color(doc: &Doc, effect: Node) -> Result<Option<Rgb>, SceneError> {
    let Some(technique) = descend(effect, &["profile_COMMON", "technique"]) else {
        return Ok(None);
    };
    // The course reads `phong/diffuse/color` alone: another shader's
    // colour is lost in a course binary, so it is here too, said.
    for other in ["lambert", "blinn"] {
        if let Some(shader) = child(technique, other) {
            doc.warn(
                shader,
                format!("the course reads only <phong>'s colour: this <{other}> is diffuse 0.5, as in a course binary"),
            );
        }
    }
    let Some(diffuse) = child(technique, "phong").and_then(|s| child(s, "diffuse")) else {
        return Ok(None);
    };
    let fields = Fields::new(doc, diffuse, &["color", "texture"]);
    if child(diffuse, "color").is_none() {
        return Ok(None);
    }
    fields
        .colour("color", Rgb::splat(0.5), REFLECTANCE)
        .map(Some)
}

#[cfg(test)]
mod tests {
    use super::*;
    use roxmltree::Document;

    fn parse(effect_body: &str) -> Result<Material, SceneError> {
        let text = format!(
            r##"<COLLADA><effect id="e">{effect_body}</effect>
                <material id="m"><instance_effect url="#e"/></material></COLLADA>"##
        );
        let document = Document::parse(&text).unwrap();
        let doc = Doc::new(&document, "t.dae");
        let m = document
            .descendants()
            .find(|n| n.has_tag_name("material"))
            .unwrap();
        material(&doc, m)
    }

    #[test]
    fn phong_diffuse_and_default() {
        let m = parse(
            "<profile_COMMON><technique><phong><diffuse><color>0.6 0.2 0.2 1</color></diffuse></phong></technique></profile_COMMON>",
        );
        assert_eq!(
            m.unwrap(),
            Material::Diffuse {
                albedo: Rgb::new(0.6, 0.2, 0.2)
            }
        );
        assert_eq!(parse("").unwrap(), Material::DEFAULT);
        // The course reads no <lambert> colour (a course binary renders it
        // grey), nor does this loader.
        let lambert = parse(
            "<profile_COMMON><technique><lambert><diffuse><color>0.6 0.2 0.2 1</color></diffuse></lambert></technique></profile_COMMON>",
        );
        assert_eq!(lambert.unwrap(), Material::DEFAULT);
    }

    #[test]
    fn cgl_under_profile_common_extra_is_found() {
        let m = parse(
            r#"<profile_COMMON><extra><technique profile="CGL"><microfacet><alpha>0.05</alpha>
               <eta>1 2 3</eta></microfacet></technique></extra></profile_COMMON>"#,
        );
        assert_eq!(
            m.unwrap(),
            Material::Microfacet {
                alpha: 0.05,
                eta: Rgb::new(1.0, 2.0, 3.0),
                k: COPPER_K
            }
        );
    }

    #[test]
    fn defaults_and_errors() {
        let m = parse(r#"<extra><technique profile="CGL"><refraction/></technique></extra>"#);
        assert_eq!(
            m.unwrap(),
            Material::Refraction {
                transmittance: Rgb::ONE,
                roughness: 0.0,
                ior: 1.5
            }
        );
        let e =
            parse(r#"<extra><technique profile="CGL"><velvet/></technique></extra>"#).unwrap_err();
        assert!(
            e.problem.contains("velvet") && e.element.ends_with("velvet"),
            "{e}"
        );
        let e = parse(
            r#"<extra><technique profile="CGL"><glass><ior>0</ior></glass></technique></extra>"#,
        )
        .unwrap_err();
        assert!(e.problem.contains("ior"), "{e}");
    }
}
