//! `<camera>` with its `<instance_camera>` node: the course's [`CameraInfo`].
//!
//! The course keeps only a viewing direction from the file and re-places the
//! camera itself (the starter's `Application::init_camera`):
//!
//! ```text
//! dir_to_camera = normalize( G * (T * (0, 0, -1, 1)).xyz )
//! ```
//!
//! translation included, a quirk of the course: for the Cornell boxes it is
//! the direction from the origin to a point one unit in front of the camera.
//! If that point is the origin the direction is undefined: the loader keeps
//! the default (+Z) and warns.
//!
//! Fields of view, in degrees, from `optics/technique_common/perspective`:
//! `hfov = xfov`; `vfov = yfov` when present, else
//! `2 atan(tan(hfov / 2) / aspect_ratio)`. With only `yfov` and an aspect
//! ratio, `hfov = 2 atan(tan(vfov / 2) * aspect_ratio)`. Anything missing
//! takes [`CameraInfo::default`]: hfov 50, vfov 35, znear 0.001, zfar 1000.
//! A field of view under 0.01 or over 179 degrees either way is warned about.

use glam::Vec3;
use roxmltree::Node;

use super::super::{CameraInfo, SceneError};
use super::numbers::single_float;
use super::transform::Placement;
use super::xml::{child, descend, Doc};
use crate::math::float::readable;

/// The camera `camera` placed by `place`.
pub fn camera_info(
    doc: &Doc,
    camera: Node,
    place: &Placement,
    warnings: &mut Vec<String>,
) -> Result<CameraInfo, SceneError> {
    let mut info = CameraInfo::default();
    let dir = place.point(Vec3::NEG_Z).normalize_or_zero();
    if dir == Vec3::ZERO {
        warnings.push(doc.note(camera, "the camera's course viewing direction is undefined (T * (0,0,-1,1) is the origin); using +Z"));
    } else {
        info.dir_to_camera = dir;
    }

    let Some(perspective) = descend(camera, &["optics", "technique_common", "perspective"]) else {
        return Ok(info);
    };
    let field = |name: &str| -> Result<Option<f32>, SceneError> {
        child(perspective, name)
            .map(|n| single_float(doc, n))
            .transpose()
    };
    let xfov = field("xfov")?;
    let yfov = field("yfov")?;
    let aspect = field("aspect_ratio")?;
    for (name, value) in [("xfov", xfov), ("yfov", yfov)] {
        if value.is_some_and(|v| !(v > 0.0 && v < 180.0)) {
            return Err(doc.err(perspective, format!("<{name}> must be in (0, 180) degrees")));
        }
    }
    if aspect.is_some_and(|a| a <= 0.0) {
        return Err(doc.err(perspective, "<aspect_ratio> must be positive"));
    }

    let half_tan = |deg: f32| (deg.to_radians() / 2.0).tan();
    let full_deg = |t: f32| 2.0 * t.atan().to_degrees();
    match (xfov, yfov, aspect) {
        (Some(x), Some(y), _) => (info.hfov_deg, info.vfov_deg) = (x, y),
        (Some(x), None, Some(a)) => (info.hfov_deg, info.vfov_deg) = (x, full_deg(half_tan(x) / a)),
        (Some(x), None, None) => info.hfov_deg = x,
        (None, Some(y), Some(a)) => (info.hfov_deg, info.vfov_deg) = (full_deg(half_tan(y) * a), y),
        (None, Some(y), None) => info.vfov_deg = y,
        (None, None, _) => {}
    }

    if let Some(z) = field("znear")? {
        info.znear = z;
    }
    if let Some(z) = field("zfar")? {
        info.zfar = z;
    }
    if !(info.znear >= 0.0 && info.znear < info.zfar) {
        return Err(doc.err(perspective, "expected 0 <= znear < zfar"));
    }
    let (narrowest, widest) = (
        info.hfov_deg.min(info.vfov_deg),
        info.hfov_deg.max(info.vfov_deg),
    );
    if !(FOV_WARNING_DEG.0..=FOV_WARNING_DEG.1).contains(&narrowest)
        || !(FOV_WARNING_DEG.0..=FOV_WARNING_DEG.1).contains(&widest)
    {
        warnings.push(doc.note(
            perspective,
            format!(
                "the field of view is {} x {} degrees (from <xfov>, <yfov> and <aspect_ratio>): \
                 outside {} to {} degrees, the picture shows a speck of the scene or a smear of it",
                readable(info.hfov_deg),
                readable(info.vfov_deg),
                FOV_WARNING_DEG.0,
                FOV_WARNING_DEG.1
            ),
        ));
    }
    Ok(info)
}

/// Fields of view (degrees) outside which a camera is warned about: a
/// hundredth of a degree is a 1000 mm lens's view of a few millimetres,
/// 179 degrees nearly a half-space.
const FOV_WARNING_DEG: (f32, f32) = (0.01, 179.0);

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{Mat3, Mat4};
    use roxmltree::Document;

    const CAMERA: &str = r#"<camera id="c"><optics><technique_common><perspective>
        <xfov>49.13434</xfov><aspect_ratio>1.333333</aspect_ratio>
        <znear>0.1</znear><zfar>100</zfar></perspective></technique_common></optics></camera>"#;

    fn z_up(rows: [f32; 16]) -> Placement {
        Placement {
            t: Mat4::from_cols_array(&rows).transpose(),
            g: Mat3::from_cols(-Vec3::X, Vec3::Z, Vec3::Y),
        }
    }

    #[test]
    fn cbbunny_camera_looks_from_minus_z() {
        let document = Document::parse(CAMERA).unwrap();
        let doc = Doc::new(&document, "t.dae");
        let place = z_up([
            1., 0., 0., 0., 0., 0., -1., -3., 0., 1., 0., 0., 0., 0., 0., 1.,
        ]);
        let mut w = Vec::new();
        let info = camera_info(&doc, document.root_element(), &place, &mut w).unwrap();
        assert!((info.dir_to_camera - Vec3::NEG_Z).length() < 1e-6);
        assert_eq!(info.hfov_deg, 49.13434);
        // 2 atan(tan(24.57 deg) / 1.3333) = 37.85 degrees.
        assert!((info.vfov_deg - 37.849).abs() < 0.01, "{}", info.vfov_deg);
        assert_eq!((info.znear, info.zfar), (0.1, 100.0));
        assert!(w.is_empty());
    }

    #[test]
    fn a_field_of_view_of_a_speck_or_a_half_space_is_warned_about() {
        let place = z_up([
            1., 0., 0., 0., 0., 0., -1., -3., 0., 1., 0., 0., 0., 0., 0., 1.,
        ]);
        for (aspect, warned) in [("1.333333", false), ("1e30", true), ("1e-30", true)] {
            let text = CAMERA.replace("1.333333", aspect);
            let document = Document::parse(&text).unwrap();
            let doc = Doc::new(&document, "t.dae");
            let mut w = Vec::new();
            camera_info(&doc, document.root_element(), &place, &mut w).unwrap();
            assert_eq!(w.len(), usize::from(warned), "aspect {aspect}: {w:?}");
        }
    }

    #[test]
    fn undefined_direction_warns_and_keeps_default() {
        let document = Document::parse("<camera/>").unwrap();
        let doc = Doc::new(&document, "t.dae");
        let place = z_up([
            1., 0., 0., 0., 0., 1., 0., 0., 0., 0., 1., 1., 0., 0., 0., 1.,
        ]);
        let mut w = Vec::new();
        let info = camera_info(&doc, document.root_element(), &place, &mut w).unwrap();
        assert_eq!(info, CameraInfo::default());
        assert_eq!(w.len(), 1);
    }
}
