//! The catalogue's mistakes of parts 1 and 2 that live in the camera and in
//! the student's intersection routines ([`pathtracer::mistakes::StudentBvh`])
//! show the symptom the catalogue names: built-in scenes rendered small by
//! the course's renderer (`-m 1`) with and without the mistake.
//!
//! Two kinds of evidence. Where a mistake cannot touch a pixel (a wall no
//! sphere hides, a camera that looks down `-z`), the pixel is the same bit
//! for bit with the same seed. Where it changes one, the change is far
//! beyond the noise: the pixels' `z = (wrong - right) / se` have a mean
//! square above [`DIFFERS`], where two renders of one image give about 0.6.

mod common;

use common::*;
use glam::Vec3;
use pathtracer::intersect::{Hit, Ray};
use pathtracer::math::luminance;
use pathtracer::mistakes::Mistake;
use pathtracer::render::Rendered;
use pathtracer::scene::builtin::{self, BALL_CENTRES, BALL_RADIUS};
use pathtracer::scene::Light;

use pathtracer::course::StarterDirect::Importance as L;

/// The mean `z^2` above which two renders are different images. Two renders
/// of one image give about 0.6 (the pixels' variances, from their own
/// samples, err on the large side; `two_renders_of_one_image_do_not_differ`
/// measures it); with 50 or more pixels a mean of 4 is out of reach of
/// chance.
const DIFFERS: f64 = 4.0;

/// The pixel's luminance and the variance of its mean.
fn pixel(image: &Rendered, i: usize) -> (f64, f64) {
    let e = &image.estimates[i];
    (luminance(e.radiance) as f64, e.variance_of_mean)
}

/// The mean of `z^2` over `pixels` between two renders.
fn mean_square_z(a: &Rendered, b: &Rendered, pixels: &[usize]) -> f64 {
    assert!(pixels.len() >= 50, "only {} pixels", pixels.len());
    let sum: f64 = pixels
        .iter()
        .map(|&i| {
            let ((x, vx), (y, vy)) = (pixel(a, i), pixel(b, i));
            let (d, v) = (x - y, vx + vy);
            if d == 0.0 {
                0.0
            } else if v == 0.0 {
                f64::INFINITY
            } else {
                d * d / v
            }
        })
        .sum();
    sum / pixels.len() as f64
}

fn assert_differs(label: &str, wrong: &Rendered, right: &Rendered, pixels: &[usize]) {
    let z2 = mean_square_z(wrong, right, pixels);
    eprintln!("{label}: mean z^2 {z2:.1} over {} pixels", pixels.len());
    assert!(z2 > DIFFERS, "{label}: mean z^2 {z2:.2} is within noise");
}

fn assert_same(label: &str, wrong: &Rendered, right: &Rendered, pixels: &[usize]) {
    assert_close(label, wrong, right, pixels, 0.0);
}

/// Asserts that `pixels` of the two renders agree within `relative`.
fn assert_close(label: &str, wrong: &Rendered, right: &Rendered, pixels: &[usize], relative: f32) {
    assert!(!pixels.is_empty());
    let changed: Vec<_> = pixels
        .iter()
        .map(|&i| (i, wrong.estimates[i].radiance, right.estimates[i].radiance))
        .filter(|(_, w, r)| (*w - *r).abs().max_element() > relative * r.max_element())
        .collect();
    let first = &changed[..changed.len().min(3)];
    assert!(
        changed.is_empty(),
        "{label}: {} pixels changed: {first:?}",
        changed.len()
    );
}

/// `view` rendered at `spp` with `mistakes`.
fn render(view: &CourseView, mistakes: &[Mistake], spp: u32, seed: u64) -> Rendered {
    view.render(&starter_tracer(mistakes, L, 1, 1, true), spp, None, seed)
}

/// `view` rendered at `spp` without and with `mistake`: the same seed
/// (`independent` false: the same samples, for pixels that must not
/// change) or two (`independent` true: independent noise, for [`DIFFERS`]).
fn both(
    view: &CourseView,
    mistake: Mistake,
    spp: u32,
    seed: u64,
    independent: bool,
) -> (Rendered, Rendered) {
    let other = seed + u64::from(independent);
    (
        render(view, &[], spp, seed),
        render(view, &[mistake], spp, other),
    )
}

/// Whether `p` lies on one of the built-in box's balls (radius 0.3).
fn on_a_ball(p: Vec3) -> bool {
    BALL_CENTRES
        .iter()
        .any(|c| (p.distance(*c) - BALL_RADIUS).abs() < 0.02)
}

/// Whether `p` lies on a wall, away from the floor, the ceiling and the balls.
fn on_a_side_wall(p: Vec3) -> bool {
    (p.x.abs() > 0.999 || p.z < -0.999) && p.y > 0.7 && p.y < 1.4
}

/// `fov-in-degrees`: `tan` of degrees read as radians is negative for the
/// course's fields of view, so the picture turns upside down: the lamp,
/// at the top of the right image, lands in its lower half.
#[test]
fn a_field_of_view_in_degrees_turns_the_picture_over() {
    let view = CourseView::new();
    let (right, wrong) = both(&view, Mistake::FovInDegrees, 4, 1100, true);
    let lamp_row = |image: &Rendered| {
        let rows: Vec<u32> = (0..image.estimates.len())
            .filter(|&i| luminance(image.estimates[i].radiance) > 5.0)
            .map(|i| i as u32 / WIDTH)
            .collect();
        assert!(!rows.is_empty(), "no lamp seen");
        rows.iter().sum::<u32>() as f64 / rows.len() as f64
    };
    let (r, w) = (lamp_row(&right), lamp_row(&wrong));
    eprintln!("lamp's mean row: right {r:.1}, wrong {w:.1} of {HEIGHT}");
    assert!(r < HEIGHT as f64 / 4.0 && w > HEIGHT as f64 / 2.0);
}

/// `ray-in-camera-space`: with the course's camera, which looks down `-z`,
/// nothing changes but rounding (its `c2w` is the identity within an ulp);
/// turned to look from the upper left, the
/// camera looks past the box at nothing.
#[test]
fn a_ray_left_in_camera_space_looks_down_minus_z() {
    let view = CourseView::new();
    let (right, wrong) = both(&view, Mistake::RayInCameraSpace, 4, 1110, false);
    let every: Vec<usize> = (0..right.estimates.len()).collect();
    assert_close(
        "ray-in-camera-space, camera down -z",
        &wrong,
        &right,
        &every,
        1e-3,
    );

    let mut scene = builtin::cornell_box();
    scene.camera.dir_to_camera = Vec3::new(-0.5, 0.4, 1.0).normalize();
    let turned = CourseView::of(scene);
    let (right, wrong) = both(&turned, Mistake::RayInCameraSpace, 4, 1111, true);
    let lit = |image: &Rendered| {
        let n = image
            .film
            .pixels
            .iter()
            .filter(|p| p.max_element() > 0.0)
            .count();
        n as f64 / image.film.pixels.len() as f64
    };
    eprintln!(
        "lit share: right {:.3}, wrong {:.3}",
        lit(&right),
        lit(&wrong)
    );
    assert!(lit(&right) > 0.5 && lit(&wrong) < 0.05);
}

/// `triangle-chained-comparison`: every shadow ray is blocked by some
/// triangle on its line, so direct light is gone: the image below the
/// lamp is black but for a few percent.
#[test]
fn a_chained_comparison_blacks_out_the_image() {
    let view = CourseView::new().on_student_bvh();
    let tracer = |m: &[Mistake]| starter_tracer(m, L, 1, 1, false);
    let right = view.mean(&tracer(&[]), 16, BELOW_LAMP, 1120);
    let wrong = view.mean(
        &tracer(&[Mistake::TriangleChainedComparison]),
        16,
        BELOW_LAMP,
        1121,
    );
    eprintln!(
        "triangle-chained-comparison: {:.4} against {:.4}",
        wrong.value, right.value
    );
    assert!(right.value > 0.0 && wrong.value < 0.05 * right.value);
}

/// `sphere-far-root`: the camera sees each ball's far side, and the
/// course shades it by its own outward normal (`make_coord_space(o2w,
/// isect.n)`, never turned to the viewer), so it is lit from behind: where
/// the far side faces up, towards the lamp, the ball is lit; where it faces
/// down it is black. The walls, whose shadow rays only ask whether a ball is
/// in the way, stay bit for bit.
#[test]
fn the_far_root_shows_the_balls_lit_from_behind() {
    let view = CourseView::new().on_student_bvh();
    let (right, wrong) = both(&view, Mistake::SphereFarRoot, 16, 1130, false);
    let Light::Area {
        center,
        dim_x,
        dim_y,
        ..
    } = builtin::cornell_box().lights[0]
    else {
        panic!("the built-in box's light is an area light");
    };
    let corners = [(-0.5, -0.5), (0.5, -0.5), (-0.5, 0.5), (0.5, 0.5)]
        .map(|(s, t)| center + s * dim_x + t * dim_y);
    // Where the camera ray leaves the ball it met, and the sign of the
    // lamp's corners seen from there against its outward normal: all of
    // the (convex) lamp above the far side's tangent plane, or all below.
    let lamp_side = |ray: &Ray, hit: &Hit| {
        let centre = *BALL_CENTRES
            .iter()
            .min_by(|a, b| a.distance(hit.p).total_cmp(&b.distance(hit.p)))
            .unwrap();
        let far = hit.p + 2.0 * (centre - hit.p).dot(ray.dir) * ray.dir;
        let n = (far - centre) / BALL_RADIUS;
        let heights = corners.map(|c| n.dot(c - far));
        if heights.iter().all(|&h| h > 0.0) {
            1
        } else if heights.iter().all(|&h| h < 0.0) {
            -1
        } else {
            0
        }
    };
    let on_ball_with_lamp =
        |side| move |ray: &Ray, hit: &Hit| on_a_ball(hit.p) && lamp_side(ray, hit) == side;
    let facing = view.pixels_where(on_ball_with_lamp(1));
    let turned_away = view.pixels_where(on_ball_with_lamp(-1));
    let sum = |image: &Rendered, pixels: &[usize]| -> f64 {
        pixels.iter().map(|&i| pixel(image, i).0).sum()
    };
    let (lit, lit_right) = (sum(&wrong, &facing), sum(&right, &facing));
    eprintln!(
        "{} pixels see a far side facing the lamp (wrong {lit:.3}, right {lit_right:.3}), {} one turned away",
        facing.len(),
        turned_away.len()
    );
    assert!(facing.len() >= 20 && turned_away.len() >= 20);
    assert_eq!(sum(&wrong, &turned_away), 0.0);
    assert!(lit > 0.25 * lit_right);
    let walls = view.pixels_seeing(on_a_side_wall);
    assert_same("sphere-far-root, walls", &wrong, &right, &walls);
}

/// `barycentric-normals-permuted`: on balls made of triangles with smooth
/// normals the shading changes beyond the noise; on the walls, whose
/// vertex normals are all equal, not a bit.
#[test]
fn permuted_barycentrics_reshade_smooth_meshes_only() {
    let view = CourseView::of(builtin::mesh_balls_box()).on_student_bvh();
    let (right, wrong) = both(&view, Mistake::BarycentricsPermuted, 256, 1140, true);
    let balls = view.pixels_seeing(on_a_ball);
    assert_differs(
        "barycentric-normals-permuted, balls",
        &wrong,
        &right,
        &balls,
    );
    let (right, wrong) = both(&view, Mistake::BarycentricsPermuted, 4, 1141, false);
    let walls = view.pixels_seeing(on_a_side_wall);
    assert_same(
        "barycentric-normals-permuted, walls",
        &wrong,
        &right,
        &walls,
    );
}

/// `bbox-misses-rays-from-inside`: shadow rays start inside the boxes
/// around them and miss them, so the balls cast no shadow: the floor
/// around them brightens.
#[test]
fn a_box_test_that_misses_from_inside_casts_no_shadows() {
    let view = CourseView::new().on_student_bvh();
    let tracer = |m: &[Mistake]| starter_tracer(m, L, 1, 1, false);
    let near_balls = |p: Vec3| {
        let on_floor = |c: &Vec3| Vec3::new(c.x, 0.0, c.z);
        p.y < 1e-3 && BALL_CENTRES.iter().any(|c| p.distance(on_floor(c)) < 0.5)
    };
    let floor = view.pixels_seeing(near_balls);
    let right = view.mean_over(&tracer(&[]), 16, &floor, 1150);
    let wrong = view.mean_over(
        &tracer(&[Mistake::BoxMissesRaysFromInside]),
        16,
        &floor,
        1151,
    );
    assert_ratio_in(
        "bbox-misses-rays-from-inside",
        wrong,
        right,
        1.15..10.0,
        ALPHA,
    );
}

/// `bvh-first-hit` and `max-t-not-shrunk`: farther surfaces show through
/// nearer ones, so the balls' pixels change beyond the noise; with
/// `max-t-not-shrunk` the ceiling also shows through the lamp.
#[test]
fn traversal_mistakes_show_farther_surfaces() {
    let view = CourseView::of(builtin::mesh_balls_box()).on_student_bvh();
    let balls = view.pixels_seeing(on_a_ball);
    for (k, mistake) in [Mistake::TraversalReturnsFirstHit, Mistake::MaxTNotShrunk]
        .into_iter()
        .enumerate()
    {
        let (right, wrong) = both(&view, mistake, 16, 1160 + 2 * k as u64, true);
        assert_differs(&mistake.to_string(), &wrong, &right, &balls);
    }
    let view = CourseView::new().on_student_bvh();
    let (right, wrong) = both(&view, Mistake::MaxTNotShrunk, 4, 1170, true);
    let lamp = view.pixels_seeing(|p| p.y > 1.485 && p.y < 1.495);
    let total = |image: &Rendered| lamp.iter().map(|&i| pixel(image, i).0).sum::<f64>();
    eprintln!(
        "lamp: right {:.1}, wrong {:.1}",
        total(&right),
        total(&wrong)
    );
    assert!(!lamp.is_empty() && total(&wrong) < 0.1 * total(&right));
}

/// The measure of [`assert_differs`] on two renders of one image (two
/// seeds, no mistake) at the settings above: about 0.6, far below
/// [`DIFFERS`].
#[test]
fn two_renders_of_one_image_do_not_differ() {
    let view = CourseView::of(builtin::mesh_balls_box()).on_student_bvh();
    let balls = view.pixels_seeing(on_a_ball);
    for spp in [16, 256] {
        let (a, b) = (render(&view, &[], spp, 1180), render(&view, &[], spp, 1181));
        let z2 = mean_square_z(&a, &b, &balls);
        eprintln!("one image at {spp} spp: mean z^2 {z2:.2}");
        assert!(z2 < 0.5 * DIFFERS, "{z2}");
    }
}
