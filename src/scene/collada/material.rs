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
//! A colour field takes one number (grey) or three. Otherwise the material
//! is diffuse with the `<diffuse><color>` of the effect's
//! phong/lambert/blinn shader (albedo 0.5, the course's default, when there
//! is none or it is a texture). An unknown CGL BSDF is an error.

use roxmltree::Node;

use super::super::{Material, SceneError};
use super::numbers::{color, single_float};
use super::xml::{child, descend, first_element, require_child, Doc};
use crate::math::Rgb;

/// The material `material` (a `<material>` element) describes.
pub fn material(doc: &Doc, material: Node) -> Result<Material, SceneError> {
    let instance = require_child(doc, material, "instance_effect")?;
    let effect = doc.resolve(instance, "url", "effect")?;
    let cgl = effect
        .descendants()
        .find(|n| n.has_tag_name("technique") && n.attribute("profile") == Some("CGL"));
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
    let rgb = |name: &str, default: f32| -> Result<Rgb, SceneError> {
        child(bsdf, name).map_or(Ok(Rgb::splat(default)), |n| color(doc, n))
    };
    let number = |name: &str, default: f32| -> Result<f32, SceneError> {
        child(bsdf, name).map_or(Ok(default), |n| single_float(doc, n))
    };
    let positive = |name: &str, default: f32| -> Result<f32, SceneError> {
        let x = number(name, default)?;
        if x > 0.0 {
            Ok(x)
        } else {
            Err(doc.err(bsdf, format!("<{name}> must be positive, found {x}")))
        }
    };
    let material = match bsdf.tag_name().name() {
        "emission" => Material::Emission {
            radiance: rgb("radiance", 1.0)?,
        },
        "mirror" => Material::Mirror {
            reflectance: rgb("reflectance", 1.0)?,
        },
        "glass" => Material::Glass {
            reflectance: rgb("reflectance", 1.0)?,
            transmittance: rgb("transmittance", 1.0)?,
            roughness: number("roughness", 0.0)?,
            ior: positive("ior", 1.5)?,
        },
        "refraction" => Material::Refraction {
            transmittance: rgb("transmittance", 1.0)?,
            roughness: number("roughness", 0.0)?,
            ior: positive("ior", 1.5)?,
        },
        "microfacet" => Material::Microfacet {
            alpha: positive("alpha", 0.5)?,
            eta: child(bsdf, "eta").map_or(Ok(COPPER_ETA), |n| color(doc, n))?,
            k: child(bsdf, "k").map_or(Ok(COPPER_K), |n| color(doc, n))?,
        },
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
    let shader = ["phong", "lambert", "blinn"]
        .iter()
        .find_map(|name| child(technique, name));
    shader
        .and_then(|s| descend(s, &["diffuse", "color"]))
        .map(|c| color(doc, c))
        .transpose()
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
