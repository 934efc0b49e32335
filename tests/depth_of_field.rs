//! The thin lens through the drivers: a pinhole render does not change
//! when the lens code is there (`-b 0`), `--focus-at` measures the
//! distance of the surface a pixel sees, and renders through a lens stay
//! finite. Through the camera: the lens points of a render's rays are
//! uniform on the disk of radius `-b`, and a point's blur is the thin
//! lens's circle of confusion.

mod common;

use std::f64::consts::TAU;

use clap::Parser;
use common::{chi_square, ALPHA};
use glam::{DVec3, Vec2, Vec3};
use pathtracer::cli::drivers::{focus_distance, prepare};
use pathtracer::cli::{drivers, CourseArgs};
use pathtracer::depth_of_field::ThinLens;
use pathtracer::intersect::Ray;
use pathtracer::math::rng::{next_2d, sampler};
use pathtracer::raygen::Camera;
use pathtracer::render::{estimate_pixel, pixel_ray};
use pathtracer::sampling::SamplerKind;

fn render(flags: &[&str]) -> Vec<[f32; 3]> {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("render.exr");
    let mut argv = vec![
        "test",
        "-r",
        "64",
        "48",
        "-t",
        "2",
        "-f",
        out.to_str().unwrap(),
    ];
    argv.extend(flags);
    drivers::part8(&CourseArgs::parse_from(argv)).unwrap();
    let image = image::open(&out).unwrap().to_rgb32f();
    image.pixels().map(|p| p.0).collect()
}

#[test]
fn a_lens_of_radius_zero_is_the_pinhole() {
    let pinhole = render(&["-s", "4", "-m", "2"]);
    let zero = render(&["-s", "4", "-m", "2", "-b", "0", "-d", "3"]);
    assert_eq!(
        pinhole, zero,
        "-b 0 renders the pinhole image, sample for sample"
    );
    let lens = render(&["-s", "4", "-m", "2", "-b", "0.2", "-d", "3"]);
    assert_ne!(pinhole, lens, "a lens changes the image");
    assert!(lens.iter().flatten().all(|c| c.is_finite()));
}

#[test]
fn focus_at_measures_the_distance_along_the_view_axis() {
    // The built-in box: the camera looks down -Z from z = 4.8023 (the
    // course's placement), and the back wall is the plane z = -1.
    let args = CourseArgs::parse_from(["test", "-r", "160", "120"]);
    let prepared = prepare(&args).unwrap();
    let d = focus_distance(&prepared.camera, &prepared.primitives, (160, 120), (80, 40)).unwrap();
    let expected = prepared.camera.position.z + 1.0;
    assert!((d - expected).abs() < 1e-3, "{d} vs {expected}");
    // A pixel outside the image is an error, not a panic.
    assert!(focus_distance(&prepared.camera, &prepared.primitives, (160, 120), (160, 0)).is_err());
    let with_focus = CourseArgs::parse_from(["test", "-r", "160", "120", "--focus-at", "80", "40"]);
    let focused = prepare(&with_focus).unwrap();
    assert!((focused.camera.lens.focal_distance - expected).abs() < 1e-3);
}

/// A thin-lens camera looking down and sideways (so camera and world
/// axes differ), lens radius `radius`, focused at `focal_distance`.
fn lens_camera(radius: f32, focal_distance: f32) -> Camera {
    Camera::look_at(
        Vec3::new(1.0, 2.0, 3.0),
        Vec3::new(-0.5, 0.3, -1.0),
        Vec3::Y,
        50.0,
        38.0,
    )
    .with_lens(ThinLens {
        radius,
        focal_distance,
    })
}

/// The lens point of a camera ray: its origin relative to the camera, in
/// camera coordinates (`c2w` is a rotation: its transpose is its inverse).
fn lens_point(camera: &Camera, ray: &Ray) -> DVec3 {
    camera.c2w.as_dmat3().transpose() * (ray.origin - camera.position).as_dvec3()
}

/// The lens points of the rays a render draws are uniform on the disk of
/// radius `-b` in the lens plane: the camera rays of one pixel, made by
/// `render::estimate_pixel` with the independent sampler, through a camera
/// turned away from the axes, their origins taken back to camera space.
/// Pearson's chi-square over 8 equal-area annuli times 8 sectors, and over
/// 20 annuli and 20 sectors alone (expected counts `N / cells`: `r^2` and
/// the angle are uniform), at [`ALPHA`] over the six tests of two radii;
/// every point in the plane `z = 0` and within `b`, the farthest within
/// `1e-3 b` of the rim (missing it by more has probability `e^-120`).
///
/// Checked by hand to fail when `ThinLens::ray` takes the course's polar
/// map without the square root (`r = b u1`: the inner annuli overfull),
/// with the angle `pi u2` (half the sectors empty), with the radius `2 b`
/// (points beyond `b`), and when it leaves the lens point in camera
/// coordinates (`origin = position + p_lens` in `Camera::generate_ray`:
/// points off the lens plane).
#[test]
fn lens_points_are_uniform_on_the_disk_of_radius_b() {
    const N: u32 = 60_000;
    let tests = 6;
    for (k, radius) in [0.3f32, 0.05].into_iter().enumerate() {
        let camera = lens_camera(radius, 4.0);
        let size = (8, 6);
        let mut sampler = SamplerKind::Independent.for_render(40 + k as u64, size, N);
        let mut points = Vec::with_capacity(N as usize);
        estimate_pixel(&camera, size, (3, 2), N, None, &mut sampler, |ray, _| {
            points.push(lens_point(&camera, ray));
            Vec3::ZERO
        });
        assert_eq!(points.len(), N as usize);
        let b = radius as f64;
        let label = format!("lens radius {radius}");
        let (mut joint, mut annuli, mut sectors) = ([0u64; 64], [0u64; 20], [0u64; 20]);
        let mut farthest = 0.0f64;
        for p in &points {
            assert!(
                p.z.abs() <= 1e-5,
                "{label}: lens point {p} off the lens plane"
            );
            let r2 = (p.x * p.x + p.y * p.y) / (b * b);
            assert!(r2 <= 1.0 + 1e-4, "{label}: lens point {p} beyond the rim");
            farthest = farthest.max(r2.sqrt());
            let r2 = r2.min(1.0 - 1e-12);
            let turn = (p.y.atan2(p.x) / TAU).rem_euclid(1.0).min(1.0 - 1e-12);
            let (a8, s8) = ((r2 * 8.0) as usize, (turn * 8.0) as usize);
            joint[8 * a8 + s8] += 1;
            annuli[(r2 * 20.0) as usize] += 1;
            sectors[(turn * 20.0) as usize] += 1;
        }
        assert!(
            farthest >= 1.0 - 1e-3,
            "{label}: the farthest lens point is at {farthest} b"
        );
        for (name, counts) in [
            ("annuli x sectors", &joint[..]),
            ("annuli", &annuli[..]),
            ("sectors", &sectors[..]),
        ] {
            let expected = vec![N as f64 / counts.len() as f64; counts.len()];
            let test = chi_square(counts, &expected);
            eprintln!(
                "{label}, {name}: chi2 {:.1}, p {:.3}",
                test.statistic, test.p_value
            );
            assert!(
                test.p_value >= ALPHA / tests as f64,
                "{label}: lens points not uniform over the {name}: {test:?}, counts {counts:?}"
            );
        }
    }
}

/// The blur of a point against the thin lens's circle of confusion: the
/// rays of one film point (a pixel's centre) through every part of the
/// lens meet the plane at distance `z` along the view axis in a disk
/// around the pinhole ray's point there, of radius
///
/// ```text
/// c(z) = b |z - d| / d
/// ```
///
/// The ray from lens point `p` towards `d w` (`w` the pinhole direction,
/// `z = -1` in camera space) reaches `z w + (1 - z / d) p` at depth `z`:
/// each ray's point is the pinhole point plus `(1 - z / d)` times its
/// lens point, which holds for any map of the lens square to the disk.
/// For three pixels and five depths, 4000 random lens samples each, to
/// `2e-5 z` for `f32` rays: every ray's point where the relation puts it;
/// the farthest within `c(z)` and beyond `(1 - 3e-3) c(z)` (the lens
/// points fill the disk: missing its outer `3e-3` has probability
/// `e^-24`); and at `z = d` every point on the pinhole point (the plane of
/// focus is sharp).
///
/// Checked by hand to fail when `ThinLens::ray` aims at
/// `d * normalize(d_cam)` (focus on a sphere: off-centre pixels blur at
/// `z = d`), when it aims from the lens point the wrong way
/// (`p_focus + p_lens`), with the radius `2 b`, and when the lens point
/// stays in camera coordinates (`Camera::generate_ray`); and to pass with
/// the course's polar map `r = b sqrt(u1)`, `theta = 2 pi u2`.
#[test]
fn a_point_s_blur_is_the_thin_lens_circle_of_confusion() {
    let (b, d) = (0.25f32, 4.0f32);
    let camera = lens_camera(b, d);
    let view = camera.view_direction().as_dvec3();
    let eye = camera.position.as_dvec3();
    let size = (64, 48);
    let mut rng = sampler(7, 0);
    let lens: Vec<Vec2> = (0..4000).map(|_| next_2d(&mut rng)).collect();
    for pixel in [(32, 24), (3, 5), (60, 41)] {
        // The pixel's centre, y from the bottom (render::film_point).
        let film = Vec2::new(
            (pixel.0 as f32 + 0.5) / size.0 as f32,
            (size.1 - 1 - pixel.1) as f32 / size.1 as f32 + 0.5 / size.1 as f32,
        );
        let pinhole = camera.ray(film.x, film.y);
        for z in [0.5 * d, 0.8 * d, d, 1.5 * d, 3.0 * d].map(|z| z as f64) {
            let label = format!("pixel {pixel:?}, depth {z} (focus {d}, lens {b})");
            // Where a ray reaches the plane at distance z along the view axis.
            let at_depth = |ray: &Ray| {
                let (o, dir) = (ray.origin.as_dvec3(), ray.dir.as_dvec3());
                o + (z - (o - eye).dot(view)) / dir.dot(view) * dir
            };
            let centre = at_depth(&pinhole);
            let coc = b as f64 * (z - d as f64).abs() / d as f64;
            let slack = 2e-5 * z;
            let mut farthest = 0.0f64;
            for &u in &lens {
                let ray = pixel_ray(&camera, size, pixel, Vec2::splat(0.5), u);
                let offset = at_depth(&ray) - centre;
                let lens_offset = (ray.origin - camera.position).as_dvec3();
                let predicted = (1.0 - z / d as f64) * lens_offset;
                assert!(
                    offset.distance(predicted) <= slack,
                    "{label}: the ray through lens point {lens_offset} arrives at {offset} \
                     from the pinhole point, not {predicted}"
                );
                farthest = farthest.max(offset.length());
            }
            assert!(
                farthest <= coc + slack && farthest >= (1.0 - 3e-3) * coc - slack,
                "{label}: the blur's radius is {farthest}, not the circle of confusion {coc}"
            );
        }
    }
}
