//! Test data shared by the loader tests: a small self-made COLLADA scene
//! (not course data). The course's own files are found by `course.rs`.

/// A minimal scene in the course's dialect, made for the tests. Z-up, a
/// camera, a point light, a mesh (a quad fan-triangulated into two
/// triangles and a triangle in a `<polylist>` with NORMAL at offset 1, plus a
/// `<triangles>` element) inside nested nodes, and a CGL sphere.
///
/// Hand-computed world values (G maps (x, y, z) to (-x, z, y)):
/// - tile: `2 * (p + (1, 0, 0))`, so vertex 4 (0.5, 0.5, 1) lands at (-3, 2, 1);
/// - ball: centre (0, 2, 0), radius 0.5 * 2 = 1, material `red`;
/// - lamp: point light at (0, 2, 0), intensity 2;
/// - camera: T(0,0,-1) = (0, -2, 0), so dir_to_camera = (0, 0, -1).
pub const MINIMAL: &str = r##"<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><up_axis>Z_UP</up_axis></asset>
  <library_cameras>
    <camera id="cam"><optics><technique_common><perspective>
      <xfov>40</xfov><aspect_ratio>1.5</aspect_ratio><znear>0.1</znear><zfar>50</zfar>
    </perspective></technique_common></optics></camera>
  </library_cameras>
  <library_lights>
    <light id="lamp"><technique_common><point><color>2 2 2</color></point></technique_common></light>
  </library_lights>
  <library_effects>
    <effect id="red-fx"><profile_COMMON><technique sid="common"><phong>
      <diffuse><color>0.7 0.1 0.1 1</color></diffuse></phong></technique></profile_COMMON></effect>
    <effect id="glow-fx"><extra><technique profile="CGL">
      <emission><radiance>3 3 3</radiance></emission></technique></extra></effect>
  </library_effects>
  <library_materials>
    <material id="red"><instance_effect url="#red-fx"/></material>
    <material id="glow"><instance_effect url="#glow-fx"/></material>
  </library_materials>
  <library_geometries>
    <geometry id="tile-mesh"><mesh>
      <source id="tile-pos">
        <float_array id="tile-pos-array" count="15">0 0 0 1 0 0 1 1 0 0 1 0 0.5 0.5 1</float_array>
        <technique_common><accessor source="#tile-pos-array" count="5" stride="3"/></technique_common>
      </source>
      <source id="tile-nrm">
        <float_array id="tile-nrm-array" count="3">0 0 1</float_array>
        <technique_common><accessor source="#tile-nrm-array" count="1" stride="3"/></technique_common>
      </source>
      <vertices id="tile-vtx"><input semantic="POSITION" source="#tile-pos"/></vertices>
      <polylist material="skin" count="2">
        <input semantic="VERTEX" source="#tile-vtx" offset="0"/>
        <input semantic="NORMAL" source="#tile-nrm" offset="1"/>
        <vcount>4 3</vcount>
        <p>0 0 1 0 2 0 3 0 0 0 1 0 4 0</p>
      </polylist>
      <triangles material="shine" count="1">
        <input semantic="VERTEX" source="#tile-vtx" offset="0"/>
        <p>2 3 4</p>
      </triangles>
    </mesh></geometry>
    <geometry id="ball"><extra><technique profile="CGL">
      <sphere><radius>0.5</radius></sphere></technique></extra></geometry>
  </library_geometries>
  <library_visual_scenes>
    <visual_scene id="main">
      <node id="camera-node"><matrix>1 0 0 0 0 0 -1 -3 0 1 0 0 0 0 0 1</matrix>
        <instance_camera url="#cam"/></node>
      <node id="lamp-node"><matrix>1 0 0 0 0 1 0 0 0 0 1 2 0 0 0 1</matrix>
        <instance_light url="#lamp"/></node>
      <node id="group"><matrix>2 0 0 0 0 2 0 0 0 0 2 0 0 0 0 1</matrix>
        <node id="tile"><matrix>1 0 0 1 0 1 0 0 0 0 1 0 0 0 0 1</matrix>
          <instance_geometry url="#tile-mesh"><bind_material><technique_common>
            <instance_material symbol="skin" target="#red"/>
            <instance_material symbol="shine" target="#glow"/>
          </technique_common></bind_material></instance_geometry>
        </node>
        <node id="ball-node"><matrix>1 0 0 0 0 1 0 0 0 0 1 1 0 0 0 1</matrix>
          <instance_geometry url="#ball"><bind_material><technique_common>
            <instance_material symbol="any" target="#red"/>
          </technique_common></bind_material></instance_geometry>
        </node>
      </node>
    </visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#main"/></scene>
</COLLADA>
"##;

/// [`MINIMAL`] with `from` replaced by `to` exactly once (panics, in the
/// test, if `from` is not there exactly once, so a test cannot silently
/// corrupt nothing).
pub fn corrupt(from: &str, to: &str) -> String {
    assert_eq!(
        MINIMAL.matches(from).count(),
        1,
        "pattern {from:?} must occur once"
    );
    MINIMAL.replacen(from, to, 1)
}
