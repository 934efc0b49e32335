//! "Not written yet": the images a course binary writes where a function
//! is still the starter's, each the mark of one TODO left as handed out.
//! Read from the starters' sources (2023 and 2025 3-1, 2023 3-2) and
//! measured on binaries built from them:
//!
//! - `PathTracer::raytrace_pixel` untouched writes `(0.2, 1.0, 0.8)` to
//!   every pixel: one colour, `(143, 255, 255)` after the tone map;
//! - `Camera::generate_ray` untouched returns one ray, `(0, 0, -1)` from
//!   the camera, for every pixel (`generate_ray_for_thin_lens` does the
//!   same, called when `-b` is above 0): the whole image is one colour,
//!   up to noise;
//! - `Triangle::intersect` and `Sphere::intersect` untouched say "hit"
//!   without a `t`, and the starter then shows the ray's direction,
//!   `debug_shading(d) = normalize(|d.x|, |d.y|, 0)`;
//! - with intersections written but not part 3, the starter's
//!   `est_radiance_global_illumination` returns the normal shading,
//!   `(n + 1) / 2`;
//! - part 3's functions untouched return `Vector3D(1.0)`: every hit is
//!   white (`1.0 sqrt 2` clips), every miss black (taken as such when at
//!   least 1 % of the pixels are each);
//! - a 3-2 starter's environment light untouched returns zero for every
//!   direction: a scene lit by the map alone is black; its BSDFs
//!   untouched return zero, so their surfaces are black
//!   ([`blackened`], decided against renders, not by a rule).
//!
//! Part 5 untouched leaves the starter's sample count, every sample, in
//! each pixel (the rate image red everywhere), which is also the
//! catalogued mistake `adaptive-count-not-updated` (the starter's line
//! kept while pixels stop early): that is left to the mistakes, which
//! tell the two apart by the image's noise.
//!
//! Each rule here reads the image alone (and, for the shadings, the
//! scene's first hits); none needs a render of the course's solution, so
//! a bare starter's battery takes seconds.

use super::battery::{Check, SIZE};
use super::scenes::CheckScene;
use crate::math::Rgb;
use crate::render::{quantize_display, tone_map, Quantization};
use crate::scene::{Material, Scene};

/// A starter function left as handed out, and how its image shows it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Unwritten {
    /// The part whose task it is.
    pub part: u8,
    /// The function (or functions) to write.
    pub function: &'static str,
    /// Its file in the starter.
    pub file: &'static str,
    /// What the image shows, in words.
    pub shows: &'static str,
}

const RAYTRACE_PIXEL: Unwritten = Unwritten {
    part: 1,
    function: "PathTracer::raytrace_pixel",
    file: "src/pathtracer/pathtracer.cpp",
    shows: "every pixel is the starter's placeholder colour (0.2, 1.0, 0.8)",
};

const GENERATE_RAY: Unwritten = Unwritten {
    part: 1,
    function: "Camera::generate_ray",
    file: "src/pathtracer/camera.cpp",
    shows: "the whole image is one colour: every pixel traces the same ray",
};

const THIN_LENS: Unwritten = Unwritten {
    part: 8,
    function: "Camera::generate_ray_for_thin_lens",
    file: "src/pathtracer/camera_lens.cpp",
    shows: "with -b the whole image is one colour: every pixel traces the same ray",
};

const INTERSECT: Unwritten = Unwritten {
    part: 1,
    function: "Triangle::intersect, Sphere::intersect",
    file: "src/scene/triangle.cpp, src/scene/sphere.cpp",
    shows: "the image is the starter's debug shading of each ray's direction: nothing is hit",
};

const DIRECT_LIGHT: Unwritten = Unwritten {
    part: 3,
    function: "PathTracer::est_radiance_global_illumination (part 3)",
    file: "src/pathtracer/pathtracer.cpp",
    shows: "the image is part 1's normal shading, which the starter returns until part 3",
};

const ENVIRONMENT: Unwritten = Unwritten {
    part: 7,
    function: "EnvironmentLight::sample_dir, sample_L",
    file: "src/scene/environment_light.cpp",
    shows: "the image is black: the map gives no light",
};

/// Every starter file a "not written yet" names.
pub const FILES: [&str; 7] = [
    RAYTRACE_PIXEL.file,
    GENERATE_RAY.file,
    THIN_LENS.file,
    INTERSECT.file,
    DIRECT_LIGHT.file,
    ENVIRONMENT.file,
    "src/pathtracer/advanced_bsdf.cpp",
];

/// Part 3's functions as handed out (`Vector3D(1.0)` each), named for
/// `check`: the estimator it exercises, else the two that call them.
fn placeholder_one(check: &Check) -> Unwritten {
    Unwritten {
        part: 3,
        function: if check.part == 3 {
            check.function
        } else {
            "PathTracer::zero_bounce_radiance, one_bounce_radiance"
        },
        file: "src/pathtracer/pathtracer.cpp",
        shows: "every surface is white and every miss black: the starter's placeholder 1",
    }
}

/// The starter's first-hit shadings of a stage, rendered at the pixels'
/// centres through the course's tone map (8-bit, three a pixel).
pub struct Shadings {
    /// `debug_shading` of each camera ray's direction.
    pub debug: Vec<u8>,
    /// `(n + 1) / 2` at each camera ray's first hit, black for a miss.
    pub normal: Vec<u8>,
}

impl Shadings {
    /// From the centre rays' directions and first-hit normals, row 0 at
    /// the top.
    pub fn new(rays: impl Iterator<Item = (glam::Vec3, Option<glam::Vec3>)>) -> Self {
        let (mut debug, mut normal) = (Vec::new(), Vec::new());
        for (d, n) in rays {
            let shown = glam::Vec3::new(d.x.abs(), d.y.abs(), 0.0).normalize_or_zero();
            debug.push(Rgb::new(shown.x, shown.y, shown.z));
            normal.push(n.map_or(Rgb::ZERO, |n| 0.5 * (Rgb::new(n.x, n.y, n.z) + Rgb::ONE)));
        }
        let display = |v: &[Rgb]| {
            let mapped: Vec<Rgb> = v.iter().map(|&c| tone_map(c)).collect();
            quantize_display(&mapped, Quantization::Truncate)
        };
        Shadings {
            debug: display(&debug),
            normal: display(&normal),
        }
    }
}

/// The largest mean difference, in display levels of 255, at which an
/// image is taken to be a placeholder shading (a correct render differs
/// from the normal shading by tens of levels; the placeholder from its
/// centre-ray image by a fraction of one, from jitter at edges).
const SHADING_TOLERANCE: f64 = 6.0;

/// The largest distance, in display levels, of any 16 x 16 block's mean
/// from the image's mean for it to count as one colour.
const FLAT_TOLERANCE: f64 = 12.0;

/// The staff library's stamp, "CS184 SU2020", in every image of a 3-2
/// binary at 480 x 360: the pixels left of `x = 64` from row 352 down
/// (measured: columns 0 to 47, rows 355 to 359).
pub const STAMP: (usize, usize) = (64, 352);

/// `image` (8-bit, three a pixel, [`SIZE`]) with the stamp's pixels
/// ([`STAMP`]) replaced by `fill`'s at the same place.
pub fn stamp_from(image: &[u8], fill: &[u8]) -> Vec<u8> {
    let width = SIZE.0 as usize;
    let mut out = image.to_vec();
    for (k, pixel) in out.chunks_mut(3).enumerate() {
        if k % width < STAMP.0 && k / width >= STAMP.1 {
            pixel.copy_from_slice(&fill[3 * k..3 * k + 3]);
        }
    }
    out
}

/// `image` with the stamp's pixels replaced by the row above it, for the
/// placeholders' rules.
pub fn stamp_from_row_above(image: &[u8]) -> Vec<u8> {
    let row = 3 * SIZE.0 as usize;
    let above = &image[(STAMP.1 - 1) * row..STAMP.1 * row];
    let fill: Vec<u8> = above.iter().copied().cycle().take(image.len()).collect();
    stamp_from(image, &fill)
}

/// The starter function whose placeholder `image` (8-bit, three a pixel,
/// [`SIZE`]) is for `check`, if it is one.
pub fn placeholder(check: &Check, image: &[u8], shadings: &Shadings) -> Option<Unwritten> {
    let pixels: Vec<&[u8]> = image.chunks(3).collect();
    if pixels.iter().all(|p| *p == [143, 255, 255]) {
        return Some(RAYTRACE_PIXEL);
    }
    if pixels.iter().all(|p| *p == [0, 0, 0]) {
        return (check.environment && check.scene == CheckScene::Sky).then_some(ENVIRONMENT);
    }
    let (white, black) = (
        pixels.iter().filter(|p| **p == [255, 255, 255]).count(),
        pixels.iter().filter(|p| **p == [0, 0, 0]).count(),
    );
    if white + black == pixels.len() && white.min(black) * 100 >= pixels.len() {
        return Some(placeholder_one(check));
    }
    // A wrong renderer can be black but for a few pixels (a shadow ray
    // that every wall blocks, at -o 0): flat, but no placeholder's.
    if is_flat(image) && !is_dark(image) {
        return Some(if check.lens.is_some() {
            THIN_LENS
        } else {
            GENERATE_RAY
        });
    }
    if mean_difference(image, &shadings.debug) <= SHADING_TOLERANCE {
        return Some(INTERSECT);
    }
    if mean_difference(image, &shadings.normal) <= SHADING_TOLERANCE {
        return Some(DIRECT_LIGHT);
    }
    None
}

/// The mean absolute difference of two 8-bit images, in levels.
fn mean_difference(a: &[u8], b: &[u8]) -> f64 {
    if a.len() != b.len() || a.is_empty() {
        return f64::INFINITY;
    }
    let sum: u64 = a.iter().zip(b).map(|(x, y)| x.abs_diff(*y) as u64).sum();
    sum as f64 / a.len() as f64
}

/// The mean, in display levels, below which an image is dark: black but
/// for noise.
const DARK_LEVEL: f64 = 2.0;

/// Whether `image`'s mean value lies below [`DARK_LEVEL`].
fn is_dark(image: &[u8]) -> bool {
    let sum: u64 = image.iter().map(|&v| v as u64).sum();
    (sum as f64) < DARK_LEVEL * image.len().max(1) as f64
}

/// Whether every 16 x 16 block's mean, per channel, lies within
/// [`FLAT_TOLERANCE`] of the image's mean: one colour up to noise.
fn is_flat(image: &[u8]) -> bool {
    let cells = super::stats::cells(SIZE.0, SIZE.1, image);
    let blocks = cells.len() / 3;
    if blocks == 0 {
        return false;
    }
    (0..3).all(|c| {
        let mean = (0..blocks).map(|b| cells[3 * b + c]).sum::<f64>() / blocks as f64;
        (0..blocks).all(|b| 255.0 * (cells[3 * b + c] - mean).abs() <= FLAT_TOLERANCE)
    })
}

/// The BSDFs of part 6 as the 3-2 starter hands them out: each returns
/// zero, so its surfaces are black. A check of part 6 whose image fails
/// is held against renders of this scene before the mistakes.
pub fn blackened(scene: &Scene) -> Scene {
    let mut scene = scene.clone();
    for m in &mut scene.materials {
        if matches!(
            m,
            Material::Mirror { .. }
                | Material::Glass { .. }
                | Material::Refraction { .. }
                | Material::Microfacet { .. }
        ) {
            *m = Material::Diffuse { albedo: Rgb::ZERO };
        }
    }
    scene
}

/// The part 6 functions [`blackened`] stands for, by the check's scene.
pub fn part_6(check: &Check) -> Unwritten {
    let (function, file) = match check.scene {
        CheckScene::Microfacet => (
            "MicrofacetBSDF::f, sample_f (and D, F, G)",
            "src/pathtracer/advanced_bsdf.cpp",
        ),
        _ => (
            "MirrorBSDF::sample_f, GlassBSDF::sample_f, BSDF::reflect, BSDF::refract",
            "src/pathtracer/advanced_bsdf.cpp",
        ),
    };
    Unwritten {
        part: 6,
        function,
        file,
        shows: "its surfaces are black: the BSDF returns zero, as the starter does",
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::battery::battery_of;
    use crate::course::Assignment;

    fn image(value: impl Fn(usize) -> u8) -> Vec<u8> {
        (0..3 * (SIZE.0 * SIZE.1) as usize).map(value).collect()
    }

    /// One flat colour is `generate_ray`'s placeholder (every pixel the
    /// same ray); an image black but for a few lit pixels is flat too, but
    /// a wrong renderer's, not a placeholder.
    #[test]
    fn a_flat_colour_is_generate_rays_and_a_dark_image_no_ones() {
        let check = battery_of(Assignment::PathTracer1)[1];
        let shadings = Shadings {
            debug: image(|_| 7),
            normal: image(|_| 9),
        };
        let grey = image(|_| 80);
        assert_eq!(placeholder(&check, &grey, &shadings), Some(GENERATE_RAY));
        let nearly_black = image(|k| if k % 997 == 0 { 200 } else { 0 });
        assert!(is_flat(&nearly_black));
        assert_eq!(placeholder(&check, &nearly_black, &shadings), None);
    }
}
