//! Bad input to the COLLADA loader: every kind of problem gives a
//! `SceneError` naming the file, the element and what was wrong. Each case
//! corrupts the self-made minimal scene (`tests/loader_fuzz.rs` checks that
//! no input panics).

mod common;

use pathtracer::scene::{collada, load, SceneError};

use common::{corrupt, MINIMAL};

const FILE: &str = "minimal.dae";

fn error_of(text: &str) -> SceneError {
    match collada::load_str(text, FILE) {
        Ok(_) => panic!("expected an error"),
        Err(e) => e,
    }
}

/// Asserts the error's file, that its element path ends with `element`, and
/// that its problem mentions every one of `words`.
fn expect(text: &str, element: &str, words: &[&str]) {
    let e = error_of(text);
    assert_eq!(e.file, FILE);
    assert!(
        e.element.ends_with(element),
        "element {:?} in {e}",
        e.element
    );
    for w in words {
        assert!(e.problem.contains(w), "{w:?} not in {e}");
    }
}

const P: &str = "library_geometries/geometry[id=tile-mesh]/mesh/polylist/p";

#[test]
fn malformed_xml_reports_line_and_column() {
    let e = error_of(&corrupt("</mesh>", ""));
    eprintln!("{e}");
    assert!(
        e.problem.contains("malformed XML") && e.problem.contains(':'),
        "{e}"
    );
    assert_eq!(e.element, "");
}

#[test]
fn truncated_file() {
    let e = error_of(&MINIMAL[..MINIMAL.len() / 2]);
    assert!(e.problem.contains("malformed XML"), "{e}");
}

#[test]
fn empty_file() {
    for text in ["", "  \n\t"] {
        let e = error_of(text);
        assert!(e.problem.contains("empty"), "{e}");
    }
}

#[test]
fn missing_and_unreadable_files() {
    let e = load(std::path::Path::new("/no/such/dir/scene.dae")).unwrap_err();
    assert!(
        e.file.contains("scene.dae") && e.problem.contains("cannot read"),
        "{e}"
    );
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("binary.dae");
    std::fs::write(&path, [0x3c, 0xff, 0xfe, 0x00]).unwrap();
    let e = load(&path).unwrap_err();
    assert!(e.problem.contains("cannot read"), "{e}");
}

#[test]
fn root_must_be_collada() {
    let e = error_of("<scene><node/></scene>");
    assert!(
        e.problem.contains("not <COLLADA>") && e.element == "scene",
        "{e}"
    );
}

#[test]
fn dangling_references() {
    expect(
        &corrupt(r##"url="#tile-mesh""##, r##"url="#tile-mush""##),
        "node[id=tile]/instance_geometry",
        &["#tile-mush", "dangling"],
    );
    expect(
        &corrupt(r##"target="#glow""##, r##"target="#gone""##),
        "instance_material[2]",
        &["#gone"],
    );
    expect(
        &corrupt(r##"url="#glow-fx""##, r##"url="#red""##),
        "material[id=glow]/instance_effect",
        &["expected element <effect>"],
    );
    expect(
        &corrupt(r##"source="#tile-pos-array""##, r##"source="#nowhere""##),
        "source[id=tile-pos]/technique_common/accessor",
        &["#nowhere"],
    );
}

#[test]
fn missing_elements_and_attributes() {
    expect(
        &corrupt(r##"<instance_effect url="#red-fx"/>"##, ""),
        "material[id=red]",
        &["<instance_effect>"],
    );
    expect(
        &corrupt(r##"<input semantic="POSITION" source="#tile-pos"/>"##, ""),
        "vertices[id=tile-vtx]",
        &["POSITION"],
    );
    expect(
        &corrupt(
            r##"<input semantic="VERTEX" source="#tile-vtx" offset="0"/>
        <p>2 3 4</p>"##,
            "<p>2 3 4</p>",
        ),
        "mesh/triangles",
        &["VERTEX"],
    );
    expect(
        &corrupt(
            r##"source="#tile-nrm" offset="1""##,
            r##"source="#tile-nrm""##,
        ),
        "polylist/input[2]",
        &["offset"],
    );
}

#[test]
fn float_array_count_must_match() {
    expect(
        &corrupt(r#"count="15""#, r#"count="16""#),
        "source[id=tile-pos]/float_array[id=tile-pos-array]",
        &["16", "15 numbers"],
    );
}

#[test]
fn accessor_must_fit_its_array() {
    expect(
        &corrupt(r#"count="5" stride="3""#, r#"count="6" stride="3""#),
        "source[id=tile-pos]/technique_common/accessor",
        &["exceeds"],
    );
}

#[test]
fn polylist_count_must_match_vcount() {
    expect(
        &corrupt(
            r#"<polylist material="skin" count="2">"#,
            r#"<polylist material="skin" count="3">"#,
        ),
        "polylist/vcount",
        &["3", "2 entries"],
    );
}

#[test]
fn p_length_must_match_vcount_and_stride_and_indices_their_sources() {
    // (replace, with, element, words in the problem)
    let cases: [(&str, &str, &str, &[&str]); 4] = [
        ("3 0 0 0 1 0 4 0</p>", "3 0 0 0 1 0 4</p>", P, &["14", "13"]),
        (
            "<p>2 3 4</p>",
            "<p>2 3 4 0</p>",
            "triangles/p",
            &["found 4"],
        ),
        ("1 0 4 0</p>", "1 0 5 0</p>", P, &["index 5", "VERTEX"]),
        ("1 0 4 0</p>", "1 0 4 1</p>", P, &["index 1", "NORMAL"]),
    ];
    for (from, to, element, words) in cases {
        expect(&corrupt(from, to), element, words);
    }
}

#[test]
fn non_numeric_values_are_named() {
    expect(
        &corrupt("0.5 0.5 1</float_array>", "0.5 abc 1</float_array>"),
        "float_array[id=tile-pos-array]",
        &["\"abc\""],
    );
    expect(&corrupt("1 0 4 0</p>", "1 0 four 0</p>"), P, &["\"four\""]);
    expect(
        &corrupt("<vcount>4 3</vcount>", "<vcount>4 3.0</vcount>"),
        "vcount",
        &["\"3.0\""],
    );
    expect(
        &corrupt(r#"<xfov>40</xfov>"#, r#"<xfov>wide</xfov>"#),
        "camera[id=cam]/optics/technique_common/perspective/xfov",
        &["\"wide\""],
    );
}

#[test]
fn non_finite_numbers_are_rejected() {
    for bad in ["NaN", "inf", "-infinity", "1e39"] {
        let text = corrupt(
            "0.5 0.5 1</float_array>",
            &format!("0.5 {bad} 1</float_array>"),
        );
        expect(&text, "float_array[id=tile-pos-array]", &[bad, "finite"]);
    }
    let matrix = "2 0 0 0 0 2 0 0 0 0 2 0 0 0 0 1";
    expect(
        &corrupt(matrix, "2 0 0 0 0 2 0 0 0 0 2 nan 0 0 0 1"),
        "node[id=group]/matrix",
        &["nan"],
    );
}

#[test]
fn polygons_need_three_vertices() {
    expect(
        &corrupt("<vcount>4 3</vcount>", "<vcount>4 2</vcount>"),
        "polylist/vcount",
        &["2 vertices"],
    );
}

#[test]
fn negative_radius() {
    expect(
        &corrupt("<radius>0.5</radius>", "<radius>-0.5</radius>"),
        "sphere/radius",
        &["negative"],
    );
}

#[test]
fn bad_matrices_and_materials() {
    let matrix = "2 0 0 0 0 2 0 0 0 0 2 0 0 0 0 1";
    expect(
        &corrupt(matrix, "2 0 0 0 0 2 0 0 0 0 2 0"),
        "node[id=group]/matrix",
        &["16", "found 12"],
    );
    expect(
        &corrupt(
            "<emission><radiance>3 3 3</radiance></emission>",
            "<velvet/>",
        ),
        "effect[id=glow-fx]/extra/technique/velvet",
        &["unknown CGL material"],
    );
}

#[test]
fn a_fifteen_number_matrix_is_a_warning_not_an_error() {
    let matrix = "2 0 0 0 0 2 0 0 0 0 2 0 0 0 0 1";
    let scene = collada::load_str(&corrupt(matrix, "2 0 0 0 0 2 0 0 0 0 2 0 0 0 0"), FILE).unwrap();
    assert_eq!(scene.warnings.len(), 1);
    assert!(
        scene.warnings[0].contains("node[id=group]/matrix") && scene.warnings[0].contains("15")
    );
}

#[test]
fn hostile_sizes_do_not_allocate_or_overflow() {
    let huge = "18446744073709551615";
    expect(
        &corrupt(
            r#"count="5" stride="3""#,
            &format!(r#"count="{huge}" stride="3""#),
        ),
        "accessor",
        &["exceeds"],
    );
    expect(
        &corrupt(
            r#"<triangles material="shine" count="1">"#,
            &format!(r#"<triangles material="shine" count="{huge}">"#),
        ),
        "triangles",
        &["count"],
    );
    let deep = format!(
        "<COLLADA><library_visual_scenes><visual_scene id=\"s\">{}{}</visual_scene></library_visual_scenes></COLLADA>",
        "<node>".repeat(300),
        "</node>".repeat(300)
    );
    expect(&deep, "node", &["nested deeper"]);
    assert!(error_of(&deep).element.len() < 200, "the path is elided");
}
