//! Renders of small scenes by the course's renderer, with and without a
//! mistake of the catalogue, and the statistics that compare them
//! (`tests/mistakes.rs`, `tests/mistakes_3_2.rs`).

use pathtracer::adaptive::Adaptive;
use pathtracer::bvh::BvhAccel;
use pathtracer::course::{
    self, Assignment, Choices, CourseExact, Lamps, StarterDirect, StarterTracer,
};
use pathtracer::depth_of_field::ThinLens;
use pathtracer::environment::EnvironmentLight;
use pathtracer::intersect::{Intersector, Primitives};
use pathtracer::math::luminance;
use pathtracer::mistakes::{Mistake, Mistakes, StudentBvh};
use pathtracer::raygen::Camera;
use pathtracer::render::{pixel_ray, RenderSettings, Rendered};
use pathtracer::sampling::SamplerKind;
use pathtracer::scene::{builtin, Scene};

use super::stats::z_two_sided;

pub const WIDTH: u32 = 64;
pub const HEIGHT: u32 = 48;

/// Mean luminance over rows `rows` of a render and its standard error.
#[derive(Clone, Copy, Debug)]
pub struct Mean {
    pub value: f64,
    pub se: f64,
}

/// A scene as the course's renderer sees it (the built-in Cornell box by
/// default), framed as the course frames 480 x 360 and rendered at
/// [`WIDTH`] x [`HEIGHT`].
pub struct CourseView {
    pub environment: Option<EnvironmentLight>,
    scene: Scene,
    camera: Camera,
    accel: BvhAccel,
    student_bvh: bool,
}

impl CourseView {
    pub fn new() -> Self {
        Self::of(builtin::cornell_box())
    }

    /// The box with its lamp (the area light and its emissive quad) hung
    /// `drop` lower, so that the ceiling lies behind it at a slant.
    pub fn with_lamp_lowered(drop: f32) -> Self {
        let mut scene = builtin::cornell_box();
        for light in &mut scene.lights {
            if let pathtracer::scene::Light::Area { center, .. } = light {
                center.y -= drop;
            }
        }
        let lamp: Vec<u32> = scene
            .mesh
            .triangles
            .iter()
            .zip(&scene.mesh.materials)
            .filter(|(_, &m)| {
                matches!(
                    scene.materials[m as usize],
                    pathtracer::scene::Material::Emission { .. }
                )
            })
            .flat_map(|(t, _)| *t)
            .collect();
        let mut moved = vec![false; scene.mesh.positions.len()];
        for v in lamp {
            if !std::mem::replace(&mut moved[v as usize], true) {
                scene.mesh.positions[v as usize].y -= drop;
            }
        }
        Self::of(scene)
    }

    pub fn of(scene: Scene) -> Self {
        let primitives = Primitives::from_scene(&scene);
        // Framed as the course frames 480 x 360 (smaller sizes zoom in),
        // rendered at 64 x 48.
        let camera = Camera::course_placement(&scene.camera, &primitives.bounds(), 480, 360);
        CourseView {
            environment: None,
            accel: BvhAccel::new(primitives),
            scene,
            camera,
            student_bvh: false,
        }
    }

    /// The pixels whose centre and four corners all see a point for which
    /// `keep` holds (so that no sample of the pixel sees anything else).
    pub fn pixels_seeing(&self, keep: impl Fn(glam::Vec3) -> bool) -> Vec<usize> {
        self.pixels_where(|_, hit| keep(hit.p))
    }

    /// The pixels whose centre and four corners all send a camera ray that
    /// meets the scene at a hit for which `keep(ray, hit)` holds.
    pub fn pixels_where(
        &self,
        keep: impl Fn(&pathtracer::intersect::Ray, &pathtracer::intersect::Hit) -> bool,
    ) -> Vec<usize> {
        let primitives = Primitives::from_scene(&self.scene);
        let linear = pathtracer::intersect::LinearScan::new(&primitives);
        let points = [(0.5, 0.5), (0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)];
        (0..WIDTH * HEIGHT)
            .filter(|&i| {
                points.iter().all(|&(u, v)| {
                    let at = glam::Vec2::new(u, v);
                    let ray = pixel_ray(
                        &self.camera,
                        (WIDTH, HEIGHT),
                        (i % WIDTH, i / WIDTH),
                        at,
                        at,
                    );
                    linear.intersect(&ray).is_some_and(|hit| keep(&ray, &hit))
                })
            })
            .map(|i| i as usize)
            .collect()
    }

    /// The mean luminance of rows `rows` rendered by `tracer` at `spp`.
    pub fn mean(
        &self,
        tracer: &StarterTracer,
        spp: u32,
        rows: std::ops::Range<u32>,
        seed: u64,
    ) -> Mean {
        let pixels: Vec<usize> = rows
            .flat_map(|y| (0..WIDTH).map(move |x| (y * WIDTH + x) as usize))
            .collect();
        self.mean_over(tracer, spp, &pixels, seed)
    }

    /// The same view through `lens`.
    pub fn with_lens(mut self, lens: ThinLens) -> Self {
        self.camera = self.camera.with_lens(lens);
        self
    }

    /// The image `tracer` renders (its mistakes made) at up to `spp`
    /// samples per pixel, stopping where `adaptive` says.
    pub fn render(
        &self,
        tracer: &StarterTracer,
        spp: u32,
        adaptive: Option<Adaptive>,
        seed: u64,
    ) -> Rendered {
        let exact = CourseExact {
            assignment: Assignment::PathTracer1,
        };
        let view = course::CourseView {
            scene: &self.scene,
            camera: &self.camera,
            environment: self.environment.as_ref(),
        };
        let settings = RenderSettings {
            width: WIDTH,
            height: HEIGHT,
            samples_per_pixel: spp,
            threads: None,
            seed,
            sampler: SamplerKind::Independent,
            progress: false,
        };
        let sampling = course::CourseSampling { settings, adaptive };
        if self.student_bvh {
            let student = StudentBvh::new(&self.accel.primitives, Mistakes::NONE);
            return exact.render(view, &student, tracer, &sampling);
        }
        exact.render(view, &self.accel, tracer, &sampling)
    }

    /// The same view traced by a student's BVH whatever the mistakes
    /// ([`StudentBvh`], Möller and Trumbore's test), so that a mistake of
    /// parts 1 and 2 is compared with the same intersector without it.
    pub fn on_student_bvh(mut self) -> Self {
        self.student_bvh = true;
        self
    }

    /// The ratio of `wrong`'s mean over `pixels` to `right`'s, each pair
    /// rendered at `spp` with one seed (`seed`, then `seed + 1`): the same
    /// samples, where a mistake only scales their weights, so that the
    /// noise they share cancels. Its standard error: with `d = w - R r` a
    /// pixel's residual in one pair, the two pairs' `d` differ by noise
    /// alone, and `sum (d1 - d2)^2` estimates the variance of
    /// `sum (d1 + d2)` (pixel by pixel, each pixel's samples its own);
    /// `se = sqrt(that) / sum (r1 + r2)`, the delta method.
    pub fn paired_ratio(
        &self,
        right: &StarterTracer,
        wrong: &StarterTracer,
        spp: u32,
        pixels: &[usize],
        seed: u64,
    ) -> Mean {
        let values = |tracer, seed| {
            let rendered = self.render(tracer, spp, None, seed);
            assert_eq!(rendered.rejected(), 0);
            pixels
                .iter()
                .map(|&i| luminance(rendered.estimates[i].radiance) as f64)
                .collect::<Vec<f64>>()
        };
        let pairs = [seed, seed + 1].map(|s| (values(right, s), values(wrong, s)));
        let sum = |v: &Vec<f64>| v.iter().sum::<f64>();
        let total_right: f64 = pairs.iter().map(|(r, _)| sum(r)).sum();
        let value = pairs.iter().map(|(_, w)| sum(w)).sum::<f64>() / total_right;
        let residuals = pairs.map(|(r, w)| {
            r.iter()
                .zip(&w)
                .map(|(r, w)| w - value * r)
                .collect::<Vec<_>>()
        });
        let variance: f64 = residuals[0]
            .iter()
            .zip(&residuals[1])
            .map(|(a, b)| (a - b).powi(2))
            .sum();
        Mean {
            value,
            se: variance.sqrt() / total_right,
        }
    }

    /// The mean luminance of `pixels` rendered by `tracer` at `spp`.
    pub fn mean_over(&self, tracer: &StarterTracer, spp: u32, pixels: &[usize], seed: u64) -> Mean {
        let rendered = self.render(tracer, spp, None, seed);
        assert_eq!(rendered.rejected(), 0);
        let n = pixels.len() as f64;
        let value = pixels
            .iter()
            .map(|&i| luminance(rendered.estimates[i].radiance) as f64)
            .sum::<f64>()
            / n;
        let variance: f64 = pixels
            .iter()
            .map(|&i| rendered.estimates[i].variance_of_mean)
            .sum();
        Mean {
            value,
            se: variance.sqrt() / n,
        }
    }
}

pub fn starter_tracer(
    mistakes: &[Mistake],
    direct: StarterDirect,
    light_samples: u32,
    max_depth: u32,
    accumulate: bool,
) -> StarterTracer {
    StarterTracer {
        direct,
        light_samples,
        max_depth,
        accumulate,
        lamps: Lamps::MeshFaces,
        choices: Choices::of(Assignment::PathTracer1),
        mistakes: Mistakes::of(mistakes),
    }
}

pub const ALL_ROWS: std::ops::Range<u32> = 0..HEIGHT;
/// Below the lamp's rows, so that its emission does not dilute ratios.
pub const BELOW_LAMP: std::ops::Range<u32> = 8..HEIGHT;

/// The ratio `a / b` and its standard error (independent estimates).
pub fn ratio(a: Mean, b: Mean) -> (f64, f64) {
    let r = a.value / b.value;
    // The delta method's standard error, written so that a = 0 is fine.
    (r, (a.se * a.se + r * r * b.se * b.se).sqrt() / b.value)
}

/// Asserts that the ratio of `wrong` to `right` is `factor` within `z`
/// standard errors.
pub fn assert_ratio(label: &str, wrong: Mean, right: Mean, factor: f64, alpha: f64) {
    let (r, se) = ratio(wrong, right);
    let z = z_two_sided(alpha);
    eprintln!("{label}: ratio {r:.4} (se {se:.4}) against {factor:.4}");
    assert!(
        (r - factor).abs() <= z * se,
        "{label}: ratio {r:.4} is not {factor:.4} (se {se:.4}, {:.1} standard errors off)",
        (r - factor) / se
    );
}

/// Asserts that the ratio of `wrong` to `right` lies in `range`, and that
/// the range's nearest end is more than `z` standard errors away.
pub fn assert_ratio_in(
    label: &str,
    wrong: Mean,
    right: Mean,
    range: std::ops::Range<f64>,
    alpha: f64,
) {
    let (value, se) = ratio(wrong, right);
    assert_ratio_safely_in(label, Mean { value, se }, range, alpha);
}

/// Asserts that `ratio` lies in `range`, its nearest end more than `z`
/// standard errors away.
pub fn assert_ratio_safely_in(label: &str, ratio: Mean, range: std::ops::Range<f64>, alpha: f64) {
    let (r, se) = (ratio.value, ratio.se);
    let z = z_two_sided(alpha);
    eprintln!("{label}: ratio {r:.4} (se {se:.4}) in {range:?}");
    let margin = (r - range.start).min(range.end - r);
    assert!(
        margin > z * se,
        "{label}: ratio {r:.4} (se {se:.4}) is not safely in {range:?}"
    );
}
