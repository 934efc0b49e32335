//! `<light>` with its `<instance_light>` node: the course's [`Light`]s
//! (the starter's `ColladaParser::parse_light`, `src/scene/collada/collada.cpp`).
//!
//! The light's kind is the first element of `<extra><technique
//! profile="CGL">` when there is one (it wins), else of `<technique_common>`.
//! Every kind has a `<color>`. With T the node matrix and G the up-axis map,
//! every point below is `G * (T * (p, 1)).xyz`:
//!
//! - `area`: centre `c = T(0,0,0)`, emitting direction
//!   `normalize(T(0,0,-1) - c)`, edges `dim_x = T(-1,0,0) - c` and
//!   `dim_y = T(0,1,0) - c`; radiance = colour. In the Cornell boxes this
//!   gives centre (0, 1.49, 0), facing -Y, 0.6 (along X) x 0.8 (along Z).
//!   Note that the boxes' emissive mesh `light` at the same place is
//!   0.8 (X) x 0.6 (Z): the two rectangles are turned 90 degrees apart.
//! - `point`: position `T(0,0,0)`, intensity = colour (the course ignores
//!   the attenuation fields).
//! - `directional`: direction towards the light `normalize(T(0,0,-1))`,
//!   translation included (a course quirk); radiance = colour.
//! - `ambient`: a uniform sky, radiance = colour.
//! - `spot`: position and direction as above; it contributes nothing.
//!
//! The colour is radiance or intensity: negative values and values above
//! `MAX_RADIANCE` are errors; unknown fields are warnings
//! (`super::fields`). Unknown kinds, and directions that come out undefined (zero length), are
//! skipped with a warning rather than failing the whole scene.

use glam::Vec3;
use roxmltree::Node;

use super::super::{Light, SceneError};
use super::fields::{Fields, RADIANCE};
use super::transform::Placement;
use super::xml::{cgl_technique, child, first_element, Doc};

/// The light `light` placed by `place`; `None` (with a warning) for a kind
/// the course does not know.
pub fn light(
    doc: &Doc,
    light: Node,
    place: &Placement,
    warnings: &mut Vec<String>,
) -> Result<Option<Light>, SceneError> {
    let technique = child(light, "extra")
        .and_then(|e| cgl_technique(doc, e))
        .or_else(|| child(light, "technique_common"));
    let Some(kind) = technique.and_then(first_element) else {
        warnings.push(doc.note(light, "no light description; the light is skipped"));
        return Ok(None);
    };
    let name = kind.tag_name().name();
    if !matches!(name, "area" | "point" | "directional" | "ambient" | "spot") {
        warnings.push(doc.note(kind, "unknown light kind; the light is skipped"));
        return Ok(None);
    }
    let fields = Fields::new(doc, kind, light_fields(name));
    fields.required("color")?;
    let rgb = fields.colour("color", Vec3::ZERO, RADIANCE)?;
    let center = place.point(Vec3::ZERO);
    let front = place.point(Vec3::NEG_Z);
    // The course's direction for directional and spot lights keeps the
    // translation; the area light's is relative to its centre.
    let towards = if name == "area" {
        front - center
    } else {
        front
    };
    let Some(direction) = towards.try_normalize() else {
        warnings.push(doc.note(
            kind,
            "the light's direction is undefined (zero length); the light is skipped",
        ));
        return Ok(None);
    };
    Ok(Some(match name {
        "area" => Light::Area {
            radiance: rgb,
            center,
            direction,
            dim_x: place.point(Vec3::NEG_X) - center,
            dim_y: place.point(Vec3::Y) - center,
        },
        "point" => Light::Point {
            intensity: rgb,
            position: center,
        },
        "directional" => Light::Directional {
            radiance: rgb,
            direction,
        },
        "ambient" => Light::Ambient { radiance: rgb },
        _ => Light::Spot {
            intensity: rgb,
            position: center,
            direction,
        },
    }))
}

/// The fields a light of kind `name` has (COLLADA 1.4.1, section 5): the
/// colour, and the attenuation and falloff the course reads and ignores.
fn light_fields(name: &str) -> &'static [&'static str] {
    const SPOT: [&str; 6] = [
        "color",
        "constant_attenuation",
        "linear_attenuation",
        "quadratic_attenuation",
        "falloff_angle",
        "falloff_exponent",
    ];
    match name {
        "point" => &SPOT[..4],
        "spot" => &SPOT,
        _ => &SPOT[..1],
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{Mat3, Mat4};
    use roxmltree::Document;

    fn load(text: &str, rows: [f32; 16]) -> (Option<Light>, Vec<String>) {
        let document = Document::parse(text).unwrap();
        let doc = Doc::new(&document, "t.dae");
        let place = Placement {
            t: Mat4::from_cols_array(&rows).transpose(),
            g: Mat3::from_cols(-Vec3::X, Vec3::Z, Vec3::Y),
        };
        let mut w = Vec::new();
        let l = light(&doc, document.root_element(), &place, &mut w).unwrap();
        (l, w)
    }

    const AREA_T: [f32; 16] = [
        0.6, 0., 0., 0., 0., 0.8, 0., 0., 0., 0., 1., 1.49, 0., 0., 0., 1.,
    ];

    #[test]
    fn cgl_area_wins_over_point() {
        let (l, w) = load(
            r#"<light><technique_common><point><color>1 1 1</color></point></technique_common>
               <extra><technique profile="CGL"><area><color>10 10 10</color></area></technique></extra></light>"#,
            AREA_T,
        );
        assert!(w.is_empty());
        let Some(Light::Area {
            radiance,
            center,
            direction,
            dim_x,
            dim_y,
        }) = l
        else {
            panic!("{l:?}")
        };
        assert_eq!(radiance, Vec3::splat(10.0));
        assert!((center - Vec3::new(0.0, 1.49, 0.0)).length() < 1e-6);
        assert!((direction - Vec3::NEG_Y).length() < 1e-6);
        assert!((dim_x.length() - 0.6).abs() < 1e-6 && (dim_y.length() - 0.8).abs() < 1e-6);
    }

    #[test]
    fn directional_keeps_translation() {
        let (l, _) = load(
            "<light><technique_common><directional><color>1 1 1</color></directional></technique_common></light>",
            [1., 0., 0., 0., 0., 1., 0., 0., 0., 0., 1., 2., 0., 0., 0., 1.],
        );
        // T(0,0,-1) = (0,0,1), G maps it to (0,1,0).
        assert_eq!(
            l,
            Some(Light::Directional {
                radiance: Vec3::ONE,
                direction: Vec3::Y
            })
        );
    }

    #[test]
    fn unknown_kind_is_skipped_with_a_warning() {
        let (l, w) = load(
            "<light><technique_common><laser><color>1</color></laser></technique_common></light>",
            AREA_T,
        );
        assert_eq!((l, w.len()), (None, 1));
    }
}
