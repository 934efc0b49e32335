//! Every mistake of parts 1, 3, 4, 5 and 8 in the catalogue ([`pathtracer::mistakes`]) shows the
//! symptom the catalogue names: the built-in Cornell box rendered small by
//! the course's renderer with and without it, compared by the mean
//! luminance of the image or of a region, with its standard error from the
//! pixels' own variances (independent samples).
//!
//! Where the mistake changes the image by a known factor (2 pi, 1/pi,
//! 0.65, -l) the ratio must be that factor within `z` standard errors;
//! elsewhere it must move the stated way by a stated margin, far beyond
//! the noise. Every test's comparisons share [`ALPHA`] = 1e-4.

mod common;

use common::*;
use glam::Vec3;
use pathtracer::course::StarterDirect;
use pathtracer::mistakes::{Mistake, Mistakes};

use StarterDirect::{Hemisphere as H, Importance as L};

/// Part 3's mistakes that scale direct light by a known factor: at
/// `-m 1 -o 0` (direct light alone), `no-pdf` with `-H` is `1 / (2 pi)` of
/// the right image, `hemisphere-pdf-1-over-pi` half of it,
/// `brdf-is-albedo` pi times it, `light-samples-not-averaged` at `-l 4`
/// four times it.
#[test]
fn direct_light_mistakes_scale_by_their_factor() {
    let b = CourseView::new();
    let alpha = ALPHA / 4.0;
    let pi = std::f64::consts::PI;
    let cases: [(Mistake, StarterDirect, u32, f64); 4] = [
        (Mistake::NoPdf, H, 1, 1.0 / (2.0 * pi)),
        (Mistake::HemispherePdfOneOverPi, H, 1, 0.5),
        (Mistake::BrdfIsAlbedo, L, 1, pi),
        (Mistake::LightSamplesNotAveraged, L, 4, 4.0),
    ];
    for (k, (mistake, direct, l, factor)) in cases.into_iter().enumerate() {
        let spp = if direct == H { 64 } else { 16 };
        let seed = 10 * k as u64;
        let right = b.mean(
            &starter_tracer(&[], direct, l, 1, false),
            spp,
            BELOW_LAMP,
            seed,
        );
        let wrong = b.mean(
            &starter_tracer(&[mistake], direct, l, 1, false),
            spp,
            BELOW_LAMP,
            seed + 1,
        );
        assert_ratio(&mistake.to_string(), wrong, right, factor, alpha);
    }
}

/// Part 3's mistakes without a closed-form factor, at `-m 1 -o 0`:
/// `no-cosine` brightens (by 25 to 80 % below the lamp here), `no-pdf` with
/// light sampling brightens by the pdf it forgets to divide by (a lamp 1
/// to 2 units away subtends a small solid angle: its pdf is several per
/// steradian), `shadow-acne` darkens by about half (each shadow ray
/// meets its own surface at `t` within rounding of 0 half the time), and
/// `shadow-ray-reaches-light` leaves nothing (a shadow ray with no end
/// meets the lamp's mesh or the closed box beyond the light).
#[test]
fn direct_light_mistakes_move_the_image_the_stated_way() {
    let b = CourseView::new();
    let alpha = ALPHA / 4.0;
    let cases: [(Mistake, std::ops::Range<f64>); 3] = [
        (Mistake::NoCosine, 1.25..1.8),
        (Mistake::NoPdf, 2.0..12.0),
        (Mistake::ShadowAcne, 0.2..0.8),
    ];
    for (k, (mistake, range)) in cases.into_iter().enumerate() {
        let seed = 100 + 10 * k as u64;
        let right = b.mean(&starter_tracer(&[], L, 1, 1, false), 16, BELOW_LAMP, seed);
        let wrong = b.mean(
            &starter_tracer(&[mistake], L, 1, 1, false),
            16,
            BELOW_LAMP,
            seed + 1,
        );
        assert_ratio_in(&mistake.to_string(), wrong, right, range, alpha);
    }
    let right = b.mean(&starter_tracer(&[], L, 1, 1, false), 16, BELOW_LAMP, 150);
    let wrong = b.mean(
        &starter_tracer(&[Mistake::ShadowRayReachesLight], L, 1, 1, false),
        16,
        BELOW_LAMP,
        151,
    );
    eprintln!("shadow-ray-reaches-light: {wrong:?} against {right:?}");
    assert!(
        wrong.value <= 0.02 * right.value,
        "shadow-ray-reaches-light: the lamp's mesh and the box beyond the light block every sample"
    );
}

/// `light-from-behind`: with the lamp hung 0.3 below the ceiling, the
/// ceiling behind the one-sided lamp (facing down) gets no direct light
/// from it in the right image (but at pixels that straddle a wall) and
/// plenty in the wrong one.
#[test]
fn light_from_behind_lights_the_ceiling() {
    let b = CourseView::with_lamp_lowered(0.3);
    let ceiling = b.pixels_seeing(|p| p.y > 1.495);
    assert!(ceiling.len() > 50, "{} ceiling pixels", ceiling.len());
    let right = b.mean_over(&starter_tracer(&[], L, 1, 1, false), 16, &ceiling, 1);
    let wrong = b.mean_over(
        &starter_tracer(&[Mistake::LightFromBehind], L, 1, 1, false),
        16,
        &ceiling,
        2,
    );
    eprintln!("ceiling: right {right:?}, wrong {wrong:?}");
    let z = z_two_sided(ALPHA);
    assert!(
        wrong.value - right.value > z * (wrong.se + right.se) && wrong.value > 20.0 * right.value,
        "the ceiling is not lit from behind: {wrong:?} against {right:?}"
    );
}

/// Part 4's mistakes with a known factor: at `-m 3 -o 0` the light of the
/// third bounce has passed one roulette (at the second vertex), so
/// `roulette-not-divided` keeps 0.65 of it; at `-m 2 -o 0` the second
/// bounce's light is carried by one diffuse bounce, whose weight
/// `f cos / pdf = albedo` becomes `f = albedo / pi`
/// (`throughput-without-cos-pdf`).
#[test]
fn path_mistakes_scale_by_their_factor() {
    let b = CourseView::new();
    let alpha = ALPHA / 2.0;
    let cases: [(Mistake, u32, f64); 2] = [
        (Mistake::RouletteNotDivided, 3, 0.65),
        (
            Mistake::ThroughputWithoutCosPdf,
            2,
            1.0 / std::f64::consts::PI,
        ),
    ];
    for (k, (mistake, depth, factor)) in cases.into_iter().enumerate() {
        let seed = 200 + 10 * k as u64;
        let right = b.mean(&starter_tracer(&[], L, 1, depth, false), 32, ALL_ROWS, seed);
        let wrong = b.mean(
            &starter_tracer(&[mistake], L, 1, depth, false),
            32,
            ALL_ROWS,
            seed + 1,
        );
        assert_ratio(&mistake.to_string(), wrong, right, factor, alpha);
    }
}

/// Part 4's mistakes that render another setting: `depth-off-by-one` at
/// `-m 1` is the right image at `-m 2`, `o0-accumulates` at `-m 3 -o 0` is
/// the right one at `-o 1`, the lamp itself (the camera's zero bounce)
/// included, as a C++ solution that ignores `-o` renders it; and
/// `emission-every-bounce` brightens the
/// second bounce (`-m 2 -o 0`) by the direct light it counts again.
#[test]
fn path_mistakes_render_another_setting() {
    let b = CourseView::new();
    let alpha = ALPHA / 3.0;
    let as_m2 = b.mean(&starter_tracer(&[], L, 1, 2, true), 32, ALL_ROWS, 300);
    let off_by_one = b.mean(
        &starter_tracer(&[Mistake::DepthOffByOne], L, 1, 1, true),
        32,
        ALL_ROWS,
        301,
    );
    assert_ratio(
        "depth-off-by-one at -m 1 against -m 2",
        off_by_one,
        as_m2,
        1.0,
        alpha,
    );

    let accumulated = b.mean(&starter_tracer(&[], L, 1, 3, true), 32, ALL_ROWS, 310);
    let sums_all = b.mean(
        &starter_tracer(&[Mistake::NoAccumulationSumsAll], L, 1, 3, false),
        32,
        ALL_ROWS,
        311,
    );
    assert_ratio(
        "o0-accumulates against -o 1",
        sums_all,
        accumulated,
        1.0,
        alpha,
    );

    let right = b.mean(&starter_tracer(&[], L, 1, 2, false), 32, ALL_ROWS, 320);
    let twice = b.mean(
        &starter_tracer(&[Mistake::EmissionEveryBounce], L, 1, 2, false),
        32,
        ALL_ROWS,
        321,
    );
    assert_ratio_in("emission-every-bounce", twice, right, 1.3..10.0, alpha);
}

/// `fov-full-angle`: the view about twice as wide, so the box fills much
/// less of the frame and the dark outside much more (`-m 1`).
#[test]
fn a_full_angle_fov_shrinks_the_scene() {
    let b = CourseView::new();
    let dark = |mistakes: &[Mistake], seed| {
        let image = b.render(&starter_tracer(mistakes, L, 1, 1, true), 4, None, seed);
        let black = image
            .film
            .pixels
            .iter()
            .filter(|p| p.max_element() == 0.0)
            .count();
        black as f64 / image.film.pixels.len() as f64
    };
    let (right, wrong) = (dark(&[], 700), dark(&[Mistake::FovFullAngle], 701));
    eprintln!("black pixels: right {right:.3}, wrong {wrong:.3}");
    assert!(
        wrong > right + 0.25,
        "fov-full-angle: black {wrong} against {right}"
    );
}

/// Part 5 at `-s 128 -a 32 0.05`, `-m 1`: `adaptive-n-not-square-rooted`
/// stops pixels at the first check (a half-width too small by sqrt(n)),
/// so the mean sample count drops; `adaptive-count-not-updated` reports
/// every pixel at 128 samples and darkens those that stopped early by the
/// share they took; `adaptive-population-variance` stops some pixels a
/// batch early and none later.
#[test]
fn adaptive_mistakes_show_in_the_sample_counts() {
    let b = CourseView::new();
    let adaptive = Some(pathtracer::adaptive::Adaptive::default());
    let tracer = |mistakes: &[Mistake]| starter_tracer(mistakes, L, 1, 1, true);
    let right = b.render(&tracer(&[]), 128, adaptive, 710);
    let early = b.render(
        &tracer(&[Mistake::AdaptiveNotSquareRooted]),
        128,
        adaptive,
        711,
    );
    let (n_right, n_early) = (
        right.mean_samples_per_pixel(),
        early.mean_samples_per_pixel(),
    );
    eprintln!("mean samples per pixel: right {n_right:.1}, n not square-rooted {n_early:.1}");
    assert!(n_early < 0.6 * n_right, "{n_early} against {n_right}");

    let stuck = b.render(
        &tracer(&[Mistake::AdaptiveCountNotUpdated]),
        128,
        adaptive,
        710,
    );
    assert!(stuck.estimates.iter().all(|e| e.samples == 128));
    // Same seed as `right`: the same samples, each pixel scaled by n / 128.
    for (w, r) in stuck.estimates.iter().zip(&right.estimates) {
        let expected = r.radiance * (r.samples as f32 / 128.0);
        assert!(
            (w.radiance - expected).abs().max_element() <= 1e-5 * expected.max_element().max(1.0)
        );
    }
    assert!(
        right.estimates.iter().any(|e| e.samples < 128),
        "no pixel stopped early"
    );

    // Same seed again: the population variance is the sample variance
    // times (n - 1) / n, so no pixel stops later, and some stop a batch
    // earlier.
    let population = b.render(
        &tracer(&[Mistake::AdaptivePopulationVariance]),
        128,
        adaptive,
        710,
    );
    let pairs = population.estimates.iter().zip(&right.estimates);
    assert!(pairs.clone().all(|(p, r)| p.samples <= r.samples));
    let earlier = pairs.filter(|(p, r)| p.samples < r.samples).count();
    eprintln!("population variance: {earlier} pixels stop earlier");
    assert!(earlier > 0);
}

/// A cheap measure of how sharp an image is, blind to most of its noise:
/// the mean absolute difference of the display luminance (tone mapped, so
/// that the lamp does not outweigh every other edge) of neighbouring 4 x 4
/// pixel blocks.
fn sharpness(image: &pathtracer::render::Rendered) -> f64 {
    let (cols, rows) = (image.film.width / 4, image.film.height / 4);
    let display = pathtracer::render::Film {
        pixels: image
            .film
            .pixels
            .iter()
            .map(|&p| p.min(glam::Vec3::ONE))
            .collect(),
        ..image.film.clone()
    };
    let blocks: Vec<f64> = display
        .block_means(cols, rows)
        .into_iter()
        .map(|b| pathtracer::math::luminance(pathtracer::render::tone_map(b)) as f64)
        .collect();
    let mut sum = 0.0;
    for y in 0..rows {
        for x in 1..cols {
            let i = (y * cols + x) as usize;
            sum += (blocks[i] - blocks[i - 1]).abs();
        }
    }
    sum / (rows * (cols - 1)) as f64
}

/// `lens-radius-unscaled`: at `-b 0.02 -d 2` (focused in front of the
/// box, 3 to 4 units from everything in it) the right image is nearly
/// sharp (a circle of confusion of 0.01 units at the back wall, a fifth of
/// a pixel); the mistaken lens, of radius 1, blurs it by 0.6 units, a
/// dozen pixels, and its edges lose most of their contrast.
#[test]
fn an_unscaled_lens_blurs_everything() {
    let lens = pathtracer::depth_of_field::ThinLens {
        radius: 0.02,
        focal_distance: 2.0,
    };
    let b = CourseView::new().with_lens(lens);
    let tracer = |mistakes: &[Mistake]| starter_tracer(mistakes, L, 1, 1, true);
    let right = sharpness(&b.render(&tracer(&[]), 256, None, 720));
    let wrong = sharpness(&b.render(&tracer(&[Mistake::LensRadiusUnscaled]), 256, None, 721));
    eprintln!("sharpness: right {right:.4}, lens of radius 1 {wrong:.4}");
    assert!(wrong < 0.6 * right, "{wrong} against {right}");
}

/// `focus-on-a-sphere`: the rays of one film point meet at distance `d`
/// along the pinhole ray instead of on the plane `z = -d`. At the image's
/// centre the two agree; at a corner the wrong focus is nearer by the
/// factor `cos` of the ray's angle to the axis (6 % at the course boxes'
/// corners, under a pixel of blur at 480 x 360: an image cannot show it
/// there, so this checks the rays).
#[test]
fn focus_on_a_sphere_focuses_the_corners_nearer() {
    use pathtracer::course::pixel::generate_ray;
    use pathtracer::raygen::CameraSample;
    let lens = pathtracer::depth_of_field::ThinLens {
        radius: 0.3,
        focal_distance: 5.0,
    };
    let camera = pathtracer::raygen::Camera::look_at(Vec3::ZERO, -Vec3::Z, Vec3::Y, 60.0, 45.0)
        .with_lens(lens);
    let wrong = Mistakes::of(&[Mistake::FocusOnASphere]);
    let meeting_depth = |film: glam::Vec2, mistakes| {
        // Two lens points' rays, left and right: where they cross, in z.
        let a = generate_ray(
            &camera,
            &CameraSample {
                film,
                lens: glam::Vec2::new(0.0, 0.5),
            },
            mistakes,
        );
        let b = generate_ray(
            &camera,
            &CameraSample {
                film,
                lens: glam::Vec2::new(1.0, 0.5),
            },
            mistakes,
        );
        // Solve a.o + s a.d = b.o + t b.d in x and z.
        let det = a.dir.x * -b.dir.z + b.dir.x * a.dir.z;
        let (dx, dz) = (b.origin.x - a.origin.x, b.origin.z - a.origin.z);
        let s = (dx * -b.dir.z + b.dir.x * dz) / det;
        -(a.origin.z + s * a.dir.z)
    };
    let centre = glam::Vec2::splat(0.5);
    let corner = glam::Vec2::new(0.98, 0.5);
    let right_corner = meeting_depth(corner, Mistakes::NONE);
    let wrong_corner = meeting_depth(corner, wrong);
    assert!((meeting_depth(centre, Mistakes::NONE) - 5.0).abs() < 1e-3);
    assert!((meeting_depth(centre, wrong) - 5.0).abs() < 1e-3);
    assert!((right_corner - 5.0).abs() < 1e-3, "{right_corner}");
    // The corner ray's angle to the axis: tan = 0.96 tan(30 degrees).
    let cos = (0.96 * 30f32.to_radians().tan()).atan().cos();
    assert!(
        (wrong_corner - 5.0 * cos).abs() < 1e-3,
        "{wrong_corner} against {}",
        5.0 * cos
    );
}
