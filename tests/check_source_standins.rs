//! `check --source` on real C++ that is wrong in one catalogued way: a
//! copy of the course's 2025 3-1 starter (`CS184_STARTER_DIR`, copied
//! under the test's temporary folder) whose functions of parts 1 to 5 are
//! replaced by short, correct stand-ins (`check_source_standins/
//! functions.cpp`), each catalogued mistake one macro of the header
//! `src/standin_mistake.h` that the test writes before each build (the
//! same build folder each time, so a build recompiles only the changed
//! files). It proves that
//!
//! - with no mistake, every probe of parts 1 to 5 passes and `check`
//!   exits with 0;
//! - with each mistake, the function it is in fails, the table's "likely
//!   mistake" column names it, every function it does not touch (and that
//!   does not call a function it is in) still passes, and `check` exits
//!   with 1;
//! - slips the catalogue does not hold fail their function, name no
//!   mistake and say what is wrong: a traversal that tests no node's box
//!   (its answers right, its work a scan's, on the course's bunny), a
//!   triangle test that ignores `max_t` (not a chained comparison, which
//!   ignores `min_t` too), slabs not swapped where the direction is
//!   negative, a leaf's loop that stops at its first hit;
//! - `roulette-not-divided` fails its function unnamed: what it makes
//!   depends on the roulette's schedule, which the probe does not model.
//!
//! Without the variable the tests skip with a line, except under
//! `CI=true`, where they fail.

#![cfg(unix)]

mod common;

use common::Standins;

/// The stand-ins of `check_source_standins/functions.cpp` in the `p3_1-2025` starter.
const STANDINS: Standins = Standins {
    starter: "p3_1-2025",
    functions: include_str!("check_source_standins/functions.cpp"),
    parts: &[1, 2, 3, 4, 5],
    prelude: "",
    samplers: &["DiffuseBSDF::sample_f"],
};

#[test]
fn the_correct_stand_ins_pass_every_probe() {
    STANDINS.all_pass();
}

standin_mistakes! {
    STANDINS;
    fov_in_degrees: "fov-in-degrees" in "Camera::generate_ray";
    ray_in_camera_space: "ray-in-camera-space" in "Camera::generate_ray";
    fov_full_angle: "fov-full-angle" in "Camera::generate_ray";
    triangle_chained_comparison: "triangle-chained-comparison"
        in "Triangle::has_intersection", "Triangle::intersect";
    barycentric_normals_permuted: "barycentric-normals-permuted" in "Triangle::intersect";
    max_t_not_shrunk: "max-t-not-shrunk" in "Triangle::intersect";
    sphere_far_root: "sphere-far-root" in "Sphere::intersect";
    bbox_misses_rays_from_inside: "bbox-misses-rays-from-inside" in "BBox::intersect";
    bvh_first_hit: "bvh-first-hit" in "BVHAccel::intersect";
    brdf_is_albedo: "brdf-is-albedo" in "DiffuseBSDF::f";
    no_cosine: "no-cosine" in "PathTracer::estimate_direct_lighting_hemisphere",
        "PathTracer::estimate_direct_lighting_importance";
    no_pdf: "no-pdf" in "PathTracer::estimate_direct_lighting_hemisphere",
        "PathTracer::estimate_direct_lighting_importance";
    hemisphere_pdf_1_over_pi: "hemisphere-pdf-1-over-pi"
        in "PathTracer::estimate_direct_lighting_hemisphere";
    shadow_acne: "shadow-acne" in "PathTracer::estimate_direct_lighting_importance";
    shadow_ray_reaches_light: "shadow-ray-reaches-light"
        in "PathTracer::estimate_direct_lighting_importance";
    light_from_behind: "light-from-behind" in "PathTracer::estimate_direct_lighting_importance";
    light_samples_not_averaged: "light-samples-not-averaged"
        in "PathTracer::estimate_direct_lighting_importance";
    depth_off_by_one: "depth-off-by-one" in "PathTracer::at_least_one_bounce_radiance";
    emission_every_bounce: "emission-every-bounce"
        in "PathTracer::at_least_one_bounce_radiance";
    throughput_without_cos_pdf: "throughput-without-cos-pdf"
        in "PathTracer::at_least_one_bounce_radiance";
    o0_accumulates: "o0-accumulates" in "PathTracer::at_least_one_bounce_radiance";
    adaptive_count_not_updated: "adaptive-count-not-updated" in "PathTracer::raytrace_pixel";
    adaptive_n_not_square_rooted: "adaptive-n-not-square-rooted" in "PathTracer::raytrace_pixel";
}

#[test]
fn roulette_not_divided_fails_its_function() {
    STANDINS.a_slip_fails(
        "roulette-not-divided",
        &["PathTracer::at_least_one_bounce_radiance"],
        "the bounces do not add up",
    );
}

#[test]
fn a_traversal_that_tests_no_box_fails_the_race() {
    STANDINS.a_slip_fails(
        "bvh-no-box-test",
        &["BVHAccel::intersect"],
        "every ray tests every triangle",
    );
}

#[test]
fn a_triangle_test_that_ignores_max_t_is_not_a_chained_comparison() {
    STANDINS.a_slip_fails(
        "triangle-ignores-max-t",
        &["Triangle::has_intersection", "Triangle::intersect"],
        "the test ignores max_t",
    );
}

#[test]
fn slabs_not_swapped_are_told_from_rays_inside() {
    STANDINS.a_slip_fails(
        "bbox-slabs-not-swapped",
        &["BBox::intersect"],
        "must be swapped",
    );
}

#[test]
fn a_leaf_that_stops_at_its_first_hit_is_not_bvh_first_hit() {
    STANDINS.a_slip_fails(
        "bvh-leaf-stops-at-first-hit",
        &["BVHAccel::intersect"],
        "a farther triangle of the same leaf",
    );
}
