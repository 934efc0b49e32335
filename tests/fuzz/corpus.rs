//! The fuzz's corpus: every case the hostile-user trial of issue 25 found
//! (panics, aborts, infinite or negative pixels, nonsense rendered in
//! silence), run before the random inputs, each with what it must give.

use super::maps::MapMutant;
use super::run::Workspace;

/// A scene case: text and whether it is nonsense (refused or warned).
pub struct SceneCase {
    pub what: String,
    pub text: String,
    pub nonsense: bool,
}

/// `text` with the first `from` (which must be there) replaced by `to`.
fn edit(text: &str, from: &str, to: &str) -> String {
    assert!(text.contains(from), "{from:?} is in the base scene");
    text.replacen(from, to, 1)
}

/// `text` with the first element `<name>...</name>` given `value`.
fn set(text: &str, name: &str, value: &str) -> String {
    let open = format!("<{name}>");
    let start = text.find(&open).expect("the field is there") + open.len();
    let end = start + text[start..].find('<').unwrap();
    format!("{}{value}{}", &text[..start], &text[end..])
}

pub fn scene_cases() -> Vec<SceneCase> {
    // The materials box: a mirror, a glass and a copper sphere, an area light.
    let base = super::exported(&pathtracer::scene::builtin::materials_box());
    let case = |what: &str, text: String| SceneCase {
        what: what.to_string(),
        text,
        nonsense: true,
    };
    let deep = {
        let at = base.find("<visual_scene").unwrap();
        let at = at + base[at..].find('>').unwrap() + 1;
        let n = 50_000;
        format!(
            "{}{}{}{}",
            &base[..at],
            "<node>".repeat(n),
            "</node>".repeat(n),
            &base[at..]
        )
    };
    let mut cases = vec![
        case("nodes nested 50000 deep", deep),
        case(
            "<iorr>",
            edit(&edit(&base, "<ior>", "<iorr>"), "</ior>", "</iorr>"),
        ),
        case(
            "<alfa>",
            edit(&edit(&base, "<alpha>", "<alfa>"), "</alpha>", "</alfa>"),
        ),
        case(
            "<reflectence>",
            edit(
                &edit(&base, "<reflectance>", "<reflectence>"),
                "</reflectance>",
                "</reflectence>",
            ),
        ),
        case(
            "<ior> twice, NaN second",
            edit(&base, "</ior>", "</ior><ior>NaN</ior>"),
        ),
        case("<ior>1.<!-- -->45</ior>", set(&base, "ior", "1.<!-- -->45")),
    ];
    for profile in [r#"profile="cgl""#, r#"profile="CGL ""#, ""] {
        let text = edit(
            &base,
            r#"<technique profile="CGL"><glass>"#,
            &format!("<technique {profile}><glass>"),
        );
        cases.push(case(&format!("glass under [{profile}]"), text));
    }
    for (field, value) in [
        ("reflectance", "-0.5"),
        ("transmittance", "-1"),
        ("eta", "-1 1 1"),
        ("k", "-2"),
        ("roughness", "-0.1"),
        ("alpha", "1e30"),
        ("eta", "1e30"),
        ("k", "1e30"),
        ("ior", "-1.5"),
    ] {
        cases.push(case(&format!("<{field}>{value}"), set(&base, field, value)));
    }
    let minimal = super::common::MINIMAL;
    cases.push(case(
        "<radience>",
        edit(
            minimal,
            "<radiance>3 3 3</radiance>",
            "<radience>3 3 3</radience>",
        ),
    ));
    cases.push(case(
        "emission -3",
        edit(
            minimal,
            "<radiance>3 3 3</radiance>",
            "<radiance>-3</radiance>",
        ),
    ));
    cases.push(case(
        "emission 3.4e38",
        edit(
            minimal,
            "<radiance>3 3 3</radiance>",
            "<radiance>3.4e38</radiance>",
        ),
    ));
    cases.push(case("area light 3.4e38", {
        let at = base.find("<area><color>").unwrap() + "<area><color>".len();
        let end = at + base[at..].find('<').unwrap();
        format!("{}3.4e38 3.4e38 3.4e38{}", &base[..at], &base[end..])
    }));
    cases
}

pub fn map_cases() -> Vec<MapMutant> {
    let hdr = |what: &str, bytes: Vec<u8>, nonsense: bool, legal: bool| MapMutant {
        bytes,
        extension: "hdr",
        what: what.to_string(),
        nonsense,
        legal,
    };
    let flat = |first_line: &str| {
        let mut bytes = format!("{first_line}\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n").into_bytes();
        bytes.extend([128u8, 128, 128, 129].repeat(8));
        bytes
    };
    let brightest = {
        // RGBE's largest exponent byte: texels of about 2^127.
        let mut bytes = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n".to_vec();
        bytes.extend([255u8, 255, 255, 255].repeat(8));
        bytes
    };
    let full = flat("#?RADIANCE");
    vec![
        hdr("an empty map", Vec::new(), true, false),
        hdr(
            "a truncated map",
            full[..full.len() - 5].to_vec(),
            true,
            false,
        ),
        hdr(
            "a PNG called .hdr",
            b"\x89PNG\r\n\x1a\n0000".to_vec(),
            true,
            false,
        ),
        hdr("texels of 2^127", brightest, true, false),
        hdr("#?RGBE", flat("#?RGBE"), false, true),
        hdr("#?RADIANCE", full, false, true),
    ]
}

/// Flags the trial found panicking, aborting or misread.
pub fn flag_cases(space: &Workspace) -> Vec<Vec<String>> {
    let map = space.path("corpus.hdr");
    std::fs::write(&map, &map_cases()[5].bytes).unwrap();
    let map = map.display().to_string();
    let cases: [&[&str]; 12] = [
        &["-b", "1e20"],
        &["-b", "0.05", "-d", "1e20"],
        &["-b", "1e20", "-e", &map],
        &["-b", "0.05", "-d", "1e20", "-e", &map],
        &["-b", "-1"],
        &["-d", "-1"],
        &["-s", "-1"],
        &["-m", "-1"],
        &["-t", "-1"],
        &["-a", "-1", "0.05"],
        &["--seed", "-1"],
        &["-a", "4294967296", "0.05"],
    ];
    cases
        .iter()
        .map(|c| c.iter().map(|s| s.to_string()).collect())
        .collect()
}
