//! Conductors from their complex index `eta + i k` ([`METALS`]), and a
//! scene's microfacet materials given another roughness or metal in code
//! ([`set_microfacets`]): what part 6's roughness and metal figures and
//! part 7's copper bunny change.

use pathtracer::math::Rgb;
use pathtracer::scene::{Material, Scene};

/// Complex indices of refraction `(eta, k)` as RGB triples: Mitsuba's
/// conductor presets `Au`, `Ag`, `Al`, `Cu` (measured spectra from Palik,
/// *Handbook of Optical Constants of Solids*, 1985, reduced to RGB), the
/// same numbers as Yocto/GL's `conductor_eta` table.
pub const METALS: [(&str, [f32; 3], [f32; 3]); 4] = [
    (
        "gold",
        [0.143119, 0.374957, 1.442479],
        [3.98316, 2.385721, 1.603215],
    ),
    (
        "silver",
        [0.155265, 0.116723, 0.138381],
        [4.828343, 3.122246, 2.14695],
    ),
    (
        "aluminium",
        [1.65746, 0.880369, 0.521229],
        [9.223869, 6.269523, 4.837001],
    ),
    (
        "copper",
        [0.200438, 0.924033, 1.102212],
        [3.912949, 2.452848, 2.142188],
    ),
];

/// The conductor `name` of [`METALS`] with roughness `alpha`.
pub fn metal(name: &str, alpha: f32) -> Material {
    let (_, eta, k) = METALS
        .iter()
        .find(|m| m.0 == name)
        .unwrap_or_else(|| panic!("{name} is not in METALS"));
    Material::Microfacet {
        alpha,
        eta: Rgb::from_array(*eta),
        k: Rgb::from_array(*k),
    }
}

/// Gives every microfacet material of `scene` the roughness `alpha` and
/// the index of the metal `name`, where given; returns how many changed.
pub fn set_microfacets(scene: &mut Scene, new_alpha: Option<f32>, name: Option<&str>) -> usize {
    let mut changed = 0;
    for m in &mut scene.materials {
        if let Material::Microfacet { alpha, eta, k } = m {
            if let Some(a) = new_alpha {
                *alpha = a;
            }
            if let Some(Material::Microfacet { eta: e, k: kk, .. }) = name.map(|n| metal(n, 0.0)) {
                (*eta, *k) = (e, kk);
            }
            changed += 1;
        }
    }
    changed
}
