//! `check --source` on real C++ of assignment 3-2 that is wrong in one
//! catalogued way: a copy of the course's 3-2 starter
//! (`CS184_STARTER_DIR/p3_2-sp23`, its parts 1 to 5 the staff's library,
//! copied under the test's temporary folder) whose functions of parts 6
//! to 8 are replaced by short, correct stand-ins
//! (`check_source_standins_32/functions.cpp`), each catalogued mistake one
//! macro of the header `src/standin_mistake.h` that the test writes before
//! each build (the same build folder each time, so a build recompiles only
//! the changed files). It proves that
//!
//! - with no mistake, every probe of parts 6 to 8 passes and `check`
//!   exits with 0;
//! - with each mistake, the function it is in fails, the table's "likely
//!   mistake" column names it, every function it does not touch (and that
//!   does not call a function it is in) still passes, and `check` exits
//!   with 1;
//! - a slip the catalogue does not hold, `init`'s tables without the
//!   `sin theta` weight, fails `init` and names no mistake.
//!
//! Without the variable the tests skip with a line, except under
//! `CI=true`, where they fail.

#![cfg(unix)]

mod common;

use common::Standins;

/// The stand-ins of `check_source_standins_32/functions.cpp` in the `p3_2-sp23` starter.
const STANDINS: Standins = Standins {
    starter: "p3_2-sp23",
    functions: include_str!("check_source_standins_32/functions.cpp"),
    parts: &[6, 7, 8],
    prelude: "#include <algorithm>\n",
    samplers: &["MicrofacetBSDF::sample_f", "EnvironmentLight::sample_L"],
};

#[test]
fn the_correct_stand_ins_pass_every_probe() {
    STANDINS.all_pass();
}

standin_mistakes! {
    STANDINS;
    reflect_wrong_axis: "reflect-wrong-axis" in "BSDF::reflect";
    refraction_ratio_inverted: "refraction-ratio-inverted" in "BSDF::refract";
    no_eta_squared: "no-eta-squared" in "RefractionBSDF::sample_f";
    no_total_internal_reflection: "no-total-internal-reflection" in "GlassBSDF::sample_f";
    schlick_r0_not_squared: "schlick-r0-not-squared" in "GlassBSDF::sample_f";
    microfacet_no_4: "microfacet-no-4" in "MicrofacetBSDF::f";
    microfacet_d_no_cos4: "microfacet-d-no-cos4" in "MicrofacetBSDF::D";
    microfacet_pdf_no_jacobian: "microfacet-pdf-no-jacobian" in "MicrofacetBSDF::sample_f";
    env_pdf_no_sin: "env-pdf-no-sin" in "EnvironmentLight::sample_L";
    env_pdf_no_jacobian: "env-pdf-no-jacobian" in "EnvironmentLight::sample_L";
    env_map_u_flipped: "env-map-u-flipped"
        in "EnvironmentLight::sample_dir", "EnvironmentLight::sample_L";
    env_map_v_flipped: "env-map-v-flipped"
        in "EnvironmentLight::sample_dir", "EnvironmentLight::sample_L";
    lens_radius_unscaled: "lens-radius-unscaled" in "Camera::generate_ray_for_thin_lens";
    focus_on_a_sphere: "focus-on-a-sphere" in "Camera::generate_ray_for_thin_lens";
}

#[test]
fn tables_without_sin_theta_fail_init() {
    STANDINS.a_slip_fails(
        "env-init-no-sin",
        &["EnvironmentLight::init"],
        "pdf_envmap has no sin theta",
    );
}
