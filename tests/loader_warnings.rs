//! What the course's format would let default in silence: a misspelt
//! field, a misspelt profile, a field given twice, a number split by a
//! comment, and values no material or light can have. Each is a warning
//! naming the file, the element and the value, or an error where nothing
//! sensible can be rendered. Every case here loaded without a word before
//! these checks existed.

mod common;

use pathtracer::math::Rgb;
use pathtracer::scene::{collada, Material, Scene};

use common::corrupt;

const FILE: &str = "minimal.dae";
/// The self-made scene's emissive material, which each case rewrites.
const GLOW: &str = "<emission><radiance>3 3 3</radiance></emission>";

fn with_bsdf(bsdf: &str) -> String {
    corrupt(GLOW, bsdf)
}

fn load(text: &str) -> Scene {
    collada::load_str(text, FILE).unwrap_or_else(|e| panic!("{e}"))
}

/// The warnings of `text`, each checked to name the file.
fn warnings(text: &str) -> Vec<String> {
    let scene = load(text);
    for w in &scene.warnings {
        assert!(w.starts_with(FILE), "{w}");
    }
    scene.warnings
}

/// The one warning of `text`, checked to mention every one of `words`.
fn one_warning(text: &str, words: &[&str]) {
    let w = warnings(text);
    assert_eq!(w.len(), 1, "{w:?}");
    for word in words {
        assert!(w[0].contains(word), "{word:?} not in {}", w[0]);
    }
}

#[test]
fn the_scene_itself_loads_without_a_warning() {
    assert!(warnings(common::MINIMAL).is_empty());
}

#[test]
fn misspelt_fields_are_named_with_the_field_meant() {
    for (bsdf, typo, meant) in [
        ("<glass><iorr>1.2</iorr></glass>", "iorr", "ior"),
        ("<microfacet><alfa>0.1</alfa></microfacet>", "alfa", "alpha"),
        (
            "<mirror><reflectence>0.5</reflectence></mirror>",
            "reflectence",
            "reflectance",
        ),
        (
            "<emission><radience>5</radience></emission>",
            "radience",
            "radiance",
        ),
    ] {
        one_warning(
            &with_bsdf(bsdf),
            &[&format!("<{typo}>"), &format!("did you mean <{meant}>?")],
        );
    }
    // A required field misspelt is an error that names it.
    let text = corrupt(
        "<point><color>2 2 2</color>",
        "<point><colour>2 2 2</colour>",
    );
    let e = collada::load_str(&text, FILE).unwrap_err();
    assert!(
        e.problem
            .contains("missing child element <color> (<colour> is given"),
        "{e}"
    );
    let text = corrupt("<radius>0.5</radius>", "<raduis>0.5</raduis>");
    let e = collada::load_str(&text, FILE).unwrap_err();
    assert!(e.problem.contains("<raduis> is given"), "{e}");
    // The light's fields too.
    let text = corrupt(
        "<point><color>2 2 2</color>",
        "<point><color>2 2 2</color><colour>1</colour>",
    );
    one_warning(&text, &["point/colour", "did you mean <color>?"]);
}

#[test]
fn a_misspelt_profile_is_warned_about_and_ignored_as_the_course_does() {
    let cgl = r#"<effect id="glow-fx"><extra><technique profile="CGL">"#;
    for profile in [r#"profile="cgl""#, r#"profile="CGL ""#, r#"profile="Cgl""#] {
        let text = corrupt(
            cgl,
            &format!(r#"<effect id="glow-fx"><extra><technique {profile}>"#),
        );
        let scene = load(&text);
        assert!(
            scene
                .warnings
                .iter()
                .any(|w| w.contains(profile) && w.contains("glow-fx") && w.contains("ignored")),
            "{profile}: {:?}",
            scene.warnings
        );
        // The course reads the material as diffuse; so does the loader.
        assert!(scene
            .materials
            .iter()
            .all(|m| !matches!(m, Material::Emission { .. })));
    }
    let text = corrupt(cgl, r#"<effect id="glow-fx"><extra><technique>"#);
    one_warning(&text, &["with no profile", "glow-fx"]);
    // The sphere's technique.
    let text = corrupt(
        r#"<technique profile="CGL">
      <sphere>"#,
        r#"<technique profile="cgl">
      <sphere>"#,
    );
    let w = warnings(&text);
    assert!(!w.is_empty(), "no warning");
    assert!(
        w[0].contains("geometry[id=ball]") && w[0].contains("profile=\"cgl\""),
        "{w:?}"
    );
}

#[test]
fn a_field_given_twice_names_both_values() {
    let text = with_bsdf("<glass><ior>2.4</ior><ior>NaN</ior></glass>");
    one_warning(
        &text,
        &[
            "<ior> is given 2 times",
            "\"2.4\", \"NaN\"",
            "first is used",
        ],
    );
    let scene = load(&text);
    assert!(scene
        .materials
        .iter()
        .any(|m| matches!(m, Material::Glass { ior, .. } if *ior == 2.4)));
}

#[test]
fn a_number_split_by_a_comment_is_read_whole_with_a_warning() {
    let text = with_bsdf("<glass><ior>1.<!-- -->45</ior></glass>");
    one_warning(&text, &["glass/ior", "\"1.45\"", "takes \"1.\""]);
    let text = with_bsdf("<glass><ior><!-- before -->1.45</ior></glass>");
    one_warning(&text, &["glass/ior", "\"1.45\"", "takes nothing"]);
    // A comment after the number changes nothing the course reads.
    let text = with_bsdf("<glass><ior>1.45<!-- after -->\n</ior></glass>");
    assert!(warnings(&text).is_empty());
    let scene = load(&text);
    assert!(scene
        .materials
        .iter()
        .any(|m| matches!(m, Material::Glass { ior, .. } if *ior == 1.45)));
}

#[test]
fn unphysical_values_are_errors_naming_the_field_and_value() {
    for (bsdf, field, value) in [
        (
            "<mirror><reflectance>1 -0.2 1</reflectance></mirror>",
            "reflectance",
            "-0.2",
        ),
        (
            "<glass><transmittance>-1</transmittance></glass>",
            "transmittance",
            "-1",
        ),
        (
            "<emission><radiance>-3</radiance></emission>",
            "radiance",
            "-3",
        ),
        (
            "<emission><radiance>3.4e38</radiance></emission>",
            "radiance",
            "3.4e38",
        ),
        ("<microfacet><eta>-1 1 1</eta></microfacet>", "eta", "-1"),
        ("<microfacet><k>1e30</k></microfacet>", "k", "1e30"),
        (
            "<microfacet><alpha>1e30</alpha></microfacet>",
            "alpha",
            "1e30",
        ),
        (
            "<microfacet><alpha>-0.1</alpha></microfacet>",
            "alpha",
            "-0.1",
        ),
        (
            "<glass><roughness>-1</roughness></glass>",
            "roughness",
            "-1",
        ),
        ("<glass><ior>1e30</ior></glass>", "ior", "1e30"),
        ("<refraction><ior>-1.5</ior></refraction>", "ior", "-1.5"),
    ] {
        let e = collada::load_str(&with_bsdf(bsdf), FILE).unwrap_err();
        assert_eq!(e.file, FILE);
        assert!(e.element.ends_with(field), "{bsdf}: {e}");
        assert!(e.problem.contains(&format!("found {value}")), "{bsdf}: {e}");
    }
    for colour in ["-2 2 2", "3.4e38"] {
        let text = corrupt(
            "<point><color>2 2 2</color>",
            &format!("<point><color>{colour}</color>"),
        );
        let e = collada::load_str(&text, FILE).unwrap_err();
        assert!(e.element.ends_with("point/color"), "{e}");
    }
}

#[test]
fn implausible_but_possible_values_are_warnings() {
    one_warning(
        &with_bsdf("<mirror><reflectance>1.5</reflectance></mirror>"),
        &["reflectance", "more light than it receives"],
    );
    let text = corrupt("0.7 0.1 0.1 1", "1.7 0.1 0.1 1");
    one_warning(&text, &["diffuse/color", "1.7"]);
    let scene = load(&text);
    assert!(scene.materials.contains(&Material::Diffuse {
        albedo: Rgb::new(1.7, 0.1, 0.1)
    }));
}

#[test]
fn geometry_placed_out_of_reach_is_an_error_and_collapsed_geometry_a_warning() {
    let tile = "<matrix>1 0 0 1 0 1 0 0 0 0 1 0 0 0 0 1</matrix>";
    let text = corrupt(tile, "<matrix>1e30 0 0 1 0 1 0 0 0 0 1 0 0 0 0 1</matrix>");
    let e = collada::load_str(&text, FILE).unwrap_err();
    assert!(
        e.element.ends_with("node[id=tile]/instance_geometry"),
        "{e}"
    );
    assert!(e.problem.contains("coordinates beyond 1e15"), "{e}");
    let text = corrupt(tile, "<matrix>0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 1</matrix>");
    one_warning(&text, &["node[id=tile]/instance_geometry", "singular"]);
}
