//! Unit tests of the interface's own code: how a file's area light
//! becomes a rectangle.

use super::*;

/// The rectangle [`Light::from_scene`] makes of an area light with these
/// edges and emitting direction.
fn rectangle(dim_x: Vec3, dim_y: Vec3, direction: Vec3) -> RectLight {
    let area = SceneLight::Area {
        radiance: Rgb::splat(1.0),
        center: Vec3::ZERO,
        direction,
        dim_x,
        dim_y,
    };
    match Light::from_scene(&area, LightConvention::Physical) {
        Light::Rect(rect) => rect,
        other => panic!("an area light became a {} light", other.kind()),
    }
}

// Each of these fails with a mutant of `plane_normal`'s guards: `d > 0`
// made `false` or `d < 0` made `true` or `false` returns the file's
// direction or the wrong side; `>` made `>=` or `<` made `<=` returns the
// plane's normal for a direction in the plane.

#[test]
fn an_area_light_faces_the_side_its_file_names_with_the_planes_unit_normal() {
    // X x Z = -Y. The file's direction is tilted and not of unit length:
    // the normal is the plane's, on the direction's side.
    let (x, z) = (Vec3::X * 2.0, Vec3::Z * 0.5);
    let down = rectangle(x, z, Vec3::new(0.3, -2.0, 0.1));
    assert_eq!(down.normal, Vec3::NEG_Y);
    let up = rectangle(x, z, Vec3::new(-0.3, 2.0, 0.1));
    assert_eq!(up.normal, Vec3::Y);
    // The edges in the other order span the same plane.
    assert_eq!(
        rectangle(z, x, Vec3::new(0.3, -2.0, 0.1)).normal,
        Vec3::NEG_Y
    );
}

#[test]
fn a_file_that_contradicts_itself_keeps_its_stated_direction() {
    let stated = Vec3::new(1.0, 0.0, 0.5);
    // The direction lies in the plane of the edges.
    assert_eq!(rectangle(Vec3::X, Vec3::Z, stated).normal, stated);
    // The edges are parallel and span no plane.
    assert_eq!(rectangle(Vec3::X, Vec3::X * 3.0, stated).normal, stated);
}
