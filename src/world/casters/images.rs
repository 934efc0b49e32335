//! Light images in mirror-like casters: a narrow cone for the caustic
//! that a mirror sphere throws on a diffuse surface.
//!
//! From a diffuse point `x`, the directions towards a mirror sphere
//! (centre `c`, radius `R`) whose reflection reaches a light are the
//! light's image in the sphere: a small patch of the sphere's disc, since
//! a convex mirror shrinks what it shows. Sampling the sphere's whole cone
//! finds it rarely; so next to the sphere's cone, each vertex gets a cone
//! around the image of each rectangle light, aimed at the reflection
//! point of the light's centre.
//!
//! **The reflection point** of `x` and the light's centre `y` is the
//! point `s = c + R n` whose normal bisects the directions to both
//! (Alhazen's problem; Glaeser 1999 gives its closed form, a quartic). A
//! cone only needs it roughly, so it is found by the fixed-point iteration
//!
//! ```text
//! n_0 = normalize(normalize(x - c) + normalize(y - c))
//! n_{k+1} = normalize(u_k + v_k),  u_k = normalize(x - s_k),  v_k = normalize(y - s_k)
//! ```
//!
//! for [`ITERATIONS`] steps, and accepted when the last step moved `n` by
//! less than [`SETTLED`] and both `x` and `y` are above the tangent plane
//! at `s` (near the sphere, where the iteration does not settle, the
//! vertex has the sphere's cone alone).
//!
//! **The cone's half-angle.** Paraxial optics of a convex mirror: turning
//! the direction from `x` by a small angle `phi` out of the plane of
//! incidence moves the reflection point by `a phi` (`a = |x - s|`), turns
//! the normal by `a phi / R`, and turns the reflected direction by
//! `phi (1 + 2 a cos(theta_i) / R)`; within the plane the factor is
//! `1 + 2 a / (R cos(theta_i))`, larger. So a light seen from `s` within
//! an angle `alpha` of its centre is seen in the mirror from `x` within
//!
//! ```text
//! phi = alpha / (1 + 2 a cos(theta_i) / R),   alpha = atan(rho / b) + spread
//! ```
//!
//! (computed with sines for angles: [`image_cone`])
//!
//! with `rho` the radius of the disc around the light's centre that holds
//! it, `b = |y - s|`, and `spread` the reflected lobe's width for a glossy
//! conductor ([`IMAGE_LOBE`] `alpha`; 0 for a mirror). On a grid of 96
//! points on the floor and walls of `CBspheres.dae`, at the 93 where the
//! iteration settled ([`SETTLED`]), this cone held every
//! direction that reaches the light (counted by brute force, 2e5
//! directions per point), and a direction uniform in it reached the light
//! 8.7 times as often as one uniform in the sphere's cone (the median;
//! 2.2 times at the least).
//!
//! The cone depends on the vertex alone, so the mixture's sampling and
//! density agree whatever these approximations are: they decide only how
//! well the cone covers the image, not whether the estimate is unbiased.

use glam::Vec3;

use super::cone::Cone;
use super::Caster;
use crate::lights::{Light, LightSet};

/// Fixed-point steps towards the reflection point: the start is already
/// close where the light and the point are a few radii from the sphere,
/// and two steps settle it at 93 of the 96 points of the grid above
/// (more steps changed no cone there).
pub const ITERATIONS: usize = 2;

/// The largest last step of the iteration (the length of the change of
/// `n`, about the angle in radians) that counts as settled: on the grid
/// above, `3e-2` after two steps gave a cone at 93 of the 96 points
/// (`1e-2` at 76).
pub const SETTLED: f32 = 3e-2;

/// The narrowest image cone, by the sine of its half-angle: in a narrower
/// one (a tiny light, or a tiny sphere far away) the rounding of its own
/// samples' directions (about `1e-7` in the sine), and the margin of
/// `5e-7` radians that [`super::cone`] adds at its edge for it, would be
/// a larger share of the cone; such a vertex has the sphere's cone instead.
pub const MIN_IMAGE_SINE: f32 = 1e-2;

/// The largest Beckmann roughness of a conductor sphere that gets light
/// images: past it the reflected lobe is as wide as the sphere's cone.
pub const IMAGE_ALPHA: f32 = 0.05;

/// A glossy conductor's reflected directions spread about `IMAGE_LOBE
/// alpha` around the mirror direction (the half vector's slopes have a
/// standard deviation of `alpha / sqrt 2` per axis, twice that after
/// reflection: 2.8 standard deviations).
pub const IMAGE_LOBE: f32 = 4.0;

/// The extra width of the light that a caster of `material`'s kind
/// reflects: `Some(0)` for a mirror, `Some(IMAGE_LOBE alpha)` for a
/// conductor up to [`IMAGE_ALPHA`], `None` for the rest (glass bends
/// light through the sphere: no image cone).
pub fn image_spread(material: &crate::scene::Material) -> Option<f32> {
    use crate::scene::Material;
    match *material {
        Material::Mirror { .. } => Some(0.0),
        Material::Microfacet { alpha, .. } if alpha <= IMAGE_ALPHA => Some(IMAGE_LOBE * alpha),
        _ => None,
    }
}

/// A light as its image cones see it: the disc around its centre that
/// holds it, and the side it emits to.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImagedLight {
    pub center: Vec3,
    /// Unit normal of the emitting side.
    pub normal: Vec3,
    /// Radius of the disc around `center` that holds the light.
    pub radius: f32,
}

impl ImagedLight {
    /// The rectangle lights of `lights` that emit.
    pub fn of(lights: &LightSet) -> Vec<ImagedLight> {
        lights
            .lights
            .iter()
            .filter_map(|light| match light {
                Light::Rect(rect) if rect.radiance.max_element() > 0.0 => Some(ImagedLight {
                    center: rect.center,
                    normal: rect.normal,
                    radius: 0.5 * rect.diagonal(),
                }),
                _ => None,
            })
            .collect()
    }
}

/// The unit normal of the point of the sphere `(c, r)` that reflects `x`
/// towards `y`, both outside it, or `None` where the iteration has not
/// settled (its last step moved `n` by more than [`SETTLED`]) or a side
/// is below the tangent plane there.
pub fn reflection_normal(x: Vec3, y: Vec3, c: Vec3, r: f32) -> Option<Vec3> {
    let mut n = ((x - c).normalize() + (y - c).normalize()).normalize();
    let mut step = f32::INFINITY;
    for _ in 0..ITERATIONS {
        let s = c + r * n;
        let next = ((x - s).normalize() + (y - s).normalize()).normalize();
        step = (next - n).length_squared();
        n = next;
    }
    let s = c + r * n;
    let above = (x - s).dot(n) > 0.0 && (y - s).dot(n) > 0.0;
    (step < SETTLED * SETTLED && above).then_some(n)
}

/// The cone, from `x`, around the image of `light` in `caster`, whose
/// reflection widens the light by the angle `spread`; `None` where there
/// is no image ([`reflection_normal`], or the light faces away from the
/// reflection point), or the cone would be no narrower than the sphere's
/// or narrower than [`MIN_IMAGE_SINE`].
///
/// Sines stand for the angles of the module's formula (`sin(atan(rho /
/// b)) = rho / sqrt(rho^2 + b^2)`, and `sin(phi)` from `sin(alpha)`), so
/// that the cone needs no trigonometric function; for the angles of a
/// light image they differ by a few per cent at most, and `sin(alpha) /
/// m <= sin(alpha / m)` errs on the narrow side, covered by the bounding
/// disc's margin.
pub fn image_cone(x: Vec3, caster: &Caster, light: &ImagedLight, spread: f32) -> Option<Cone> {
    let (c, r) = (caster.center, caster.radius);
    let n = reflection_normal(x, light.center, c, r)?;
    let s = c + r * n;
    let to_light = light.center - s;
    if light.normal.dot(to_light) >= 0.0 {
        return None;
    }
    let to_s = s - x;
    let a = to_s.length();
    let cos_i = -to_s.dot(n) / a;
    let rho = light.radius;
    let sin_alpha = rho / (rho * rho + to_light.length_squared()).sqrt() + spread;
    let sin_phi = sin_alpha / (1.0 + 2.0 * a * cos_i / r);
    // The sphere's own cone: sin^2(theta) = r^2 / |c - x|^2.
    let sin2_sphere = r * r / (c - x).length_squared();
    (sin_phi >= MIN_IMAGE_SINE && sin_phi * sin_phi < sin2_sphere)
        .then(|| Cone::around(to_s / a, sin_phi))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A light rectangle of `CBspheres.dae`: centre (0, 1.49, 0), facing
    /// down, 0.6 x 0.8.
    fn ceiling_light() -> (ImagedLight, Vec3, Vec3) {
        let light = ImagedLight {
            center: Vec3::new(0.0, 1.49, 0.0),
            normal: Vec3::NEG_Y,
            radius: 0.5,
        };
        (light, Vec3::new(0.3, 0.0, 0.0), Vec3::new(0.0, 0.0, 0.4))
    }

    /// A mirror sphere of radius 0.3 on the floor under
    /// [`ceiling_light`], off its centre.
    fn cornell_mirror() -> Caster {
        Caster {
            center: Vec3::new(-0.4, 0.3, -0.3),
            radius: 0.3,
            image_spread: Some(0.0),
        }
    }

    fn reflect(d: Vec3, n: Vec3) -> Vec3 {
        d - 2.0 * d.dot(n) * n
    }

    /// Which casters show light images, as [`image_spread`] states it:
    /// images change the variance, not the mean, so no estimator test
    /// sees a sphere get one it should not (checked with mutants: every
    /// kind given `Some(0)`, `Some(1)` or `Some(-1)`, or the roughness
    /// limit dropped, fails).
    #[test]
    fn mirrors_and_smooth_conductors_show_images_glass_and_rough_metal_not() {
        use crate::scene::Material;
        let metal = |alpha| Material::Microfacet {
            alpha,
            eta: Vec3::splat(0.2),
            k: Vec3::splat(3.0),
        };
        let mirror = Material::Mirror {
            reflectance: Vec3::ONE,
        };
        assert_eq!(image_spread(&mirror), Some(0.0));
        assert_eq!(image_spread(&metal(0.02)), Some(IMAGE_LOBE * 0.02));
        assert_eq!(
            image_spread(&metal(IMAGE_ALPHA)),
            Some(IMAGE_LOBE * IMAGE_ALPHA)
        );
        assert_eq!(image_spread(&metal(0.2)), None);
        let glass = Material::Glass {
            reflectance: Vec3::ONE,
            transmittance: Vec3::ONE,
            roughness: 0.0,
            ior: 1.5,
        };
        assert_eq!(image_spread(&glass), None);
        assert_eq!(image_spread(&Material::DEFAULT), None);
    }

    /// The lights that images look for: each rectangle that emits, as the
    /// disc around its centre that holds it (radius half its diagonal),
    /// facing its emitting side; a dark one and a point light have none
    /// (checked with mutants: a dark rectangle kept, or the radius as
    /// `0.5 + diagonal` or `0.5 / diagonal`, fails).
    #[test]
    fn lights_are_imaged_as_the_discs_that_hold_the_emitting_rectangles() {
        use crate::lights::{LightConvention, LightSet};
        use crate::scene::{Light, Scene};
        let rect = |radiance| Light::Area {
            radiance,
            center: Vec3::new(0.5, 2.0, -0.5),
            direction: Vec3::NEG_Y,
            dim_x: Vec3::new(1.2, 0.0, 0.0),
            dim_y: Vec3::new(0.0, 0.0, 1.6),
        };
        let point = Light::Point {
            intensity: Vec3::ONE,
            position: Vec3::Y,
        };
        let scene = Scene {
            lights: vec![rect(Vec3::ZERO), point, rect(Vec3::new(0.0, 0.0, 2.0))],
            ..Scene::default()
        };
        let imaged = ImagedLight::of(&LightSet::new(&scene, LightConvention::Physical));
        assert_eq!(
            imaged,
            vec![ImagedLight {
                center: Vec3::new(0.5, 2.0, -0.5),
                normal: Vec3::NEG_Y,
                radius: 1.0,
            }]
        );
    }

    #[test]
    fn the_reflection_normal_bisects_the_two_directions() {
        let (c, r) = (Vec3::new(-0.4, 0.3, -0.3), 0.3);
        let y = Vec3::new(0.0, 1.49, 0.0);
        for x in [
            Vec3::new(0.5, 0.0, 0.5),
            Vec3::new(-1.0, 0.7, 0.2),
            Vec3::new(0.2, 1.0, -1.0),
        ] {
            let n = reflection_normal(x, y, c, r).expect("an image");
            let s = c + r * n;
            let bisector = ((x - s).normalize() + (y - s).normalize()).normalize();
            assert!(bisector.dot(n) > 1.0 - 1e-4, "{x}: {}", bisector.dot(n));
        }
        // The light behind the sphere as seen from x: no reflection point.
        assert!(reflection_normal(
            Vec3::new(0.0, 0.3, 2.0),
            Vec3::new(0.0, 0.3, -2.0),
            Vec3::new(0.0, 0.3, 0.0),
            0.3
        )
        .is_none());
    }

    /// Where two steps leave the reflection point unsettled, there is no
    /// image: here the last step moved `n` by 0.149, past [`SETTLED`]
    /// (checked with mutants: the test as `step < SETTLED + SETTLED`, `/`,
    /// or `||` with the side test, fails).
    #[test]
    fn an_unsettled_reflection_point_gives_no_image() {
        let x = Vec3::new(1.2, 0.0, 0.0);
        let y = Vec3::new(1.060_660_1, 1.060_660_1, 0.45);
        assert_eq!(reflection_normal(x, y, Vec3::ZERO, 1.0), None);
    }

    /// The reflection point moves with the scene: the same normal, to
    /// rounding, with everything moved 50 units along each axis either
    /// way (checked with mutants: the side test on `x + s` or `y + s`
    /// instead of `x - s`, `y - s`, fails).
    #[test]
    fn the_reflection_normal_does_not_depend_on_where_the_scene_is() {
        let (c, r) = (Vec3::new(-0.4, 0.3, -0.3), 0.3);
        let y = Vec3::new(0.0, 1.49, 0.0);
        for x in [Vec3::new(0.5, 0.0, 0.5), Vec3::new(-1.0, 0.7, 0.2)] {
            let n = reflection_normal(x, y, c, r).expect("an image");
            for axis in [Vec3::X, Vec3::Y, Vec3::Z] {
                for t in [50.0 * axis, -50.0 * axis] {
                    let moved = reflection_normal(x + t, y + t, c + t, r);
                    let moved = moved.unwrap_or_else(|| panic!("{x} moved by {t}: no image"));
                    assert!(
                        (moved - n).length() < 1e-3,
                        "{x} moved by {t}: {moved}, {n}"
                    );
                }
            }
        }
    }

    /// A glossy conductor's image is the mirror's widened by its lobe:
    /// the same axis, a wider cone (checked with a mutant: the spread
    /// subtracted from the light's sine instead of added fails).
    #[test]
    fn a_glossy_casters_image_is_the_mirrors_widened() {
        let caster = cornell_mirror();
        let (light, _, _) = ceiling_light();
        let x = Vec3::new(0.3, 0.0, 0.2);
        let mirror = image_cone(x, &caster, &light, 0.0).expect("an image cone");
        let glossy = image_cone(x, &caster, &light, 0.05).expect("an image cone");
        let axis = mirror.sample(glam::Vec2::ZERO);
        assert!(glossy.pdf(axis) > 0.0 && glossy.solid_angle() > 1.1 * mirror.solid_angle());
    }

    /// Where the light's image would fill more than the sphere's own cone
    /// (a large light in the roughest conductor that gets images, seen
    /// from below the sphere's centre), the vertex keeps the sphere's cone
    /// alone (checked with mutants: the sphere's squared sine as
    /// `r^2 d^2`, `r^2 % d^2` or `r + r / d^2`, which let the image
    /// through, fail).
    #[test]
    fn an_image_wider_than_its_sphere_is_no_image() {
        let caster = Caster {
            image_spread: Some(IMAGE_LOBE * IMAGE_ALPHA),
            ..cornell_mirror()
        };
        let (light, _, _) = ceiling_light();
        let large = ImagedLight {
            radius: 2.0,
            ..light
        };
        let x = Vec3::new(0.5, -0.5, 0.0);
        assert!(reflection_normal(x, light.center, caster.center, caster.radius).is_some());
        assert!(image_cone(x, &caster, &light, 0.0).is_some());
        assert!(image_cone(x, &caster, &large, IMAGE_LOBE * IMAGE_ALPHA).is_none());
    }

    /// Directions uniform in the sphere's cone from points of a Cornell
    /// box's floor and walls, reflected by the mirror sphere: every one
    /// that reaches the light is inside the image cone, which is narrower
    /// than the sphere's and not much wider than those directions.
    #[test]
    fn the_image_cone_holds_the_directions_that_reach_the_light() {
        let caster = cornell_mirror();
        let (light, half_x, half_z) = ceiling_light();
        let points = [
            Vec3::new(0.3, 0.0, 0.2),
            Vec3::new(-0.8, 0.0, 0.6),
            Vec3::new(0.8, 0.0, -0.8),
            Vec3::new(-1.0, 0.5, 0.3),
            Vec3::new(-1.0, 1.2, -0.6),
            Vec3::new(0.4, 0.9, -1.0),
        ];
        for x in points {
            let to_center = caster.center - x;
            let d2 = to_center.length_squared();
            let sphere = Cone::of_sphere(to_center, d2, caster.radius * caster.radius);
            let image = image_cone(x, &caster, &light, 0.0).expect("an image cone");
            assert!(image.solid_angle() < sphere.solid_angle());
            let mut reaching = 0;
            let axis = image.sample(glam::Vec2::ZERO);
            let mut widest = 0.0f32;
            for i in 0..40_000 {
                let u = glam::Vec2::new(
                    (i % 200) as f32 / 200.0 + 0.002,
                    (i / 200) as f32 / 200.0 + 0.001,
                );
                let w = sphere.sample(u);
                // The sphere hit, the reflection, the light's plane.
                let oc = x - caster.center;
                let b = w.dot(oc);
                let disc = b * b - (oc.length_squared() - caster.radius * caster.radius);
                if disc <= 0.0 {
                    continue;
                }
                let s = x + (-b - disc.sqrt()) * w;
                let rdir = reflect(w, (s - caster.center).normalize());
                if rdir.y <= 0.0 {
                    continue;
                }
                let q = s + (light.center.y - s.y) / rdir.y * rdir - light.center;
                if q.x.abs() > half_x.x || q.z.abs() > half_z.z {
                    continue;
                }
                reaching += 1;
                widest = widest.max(w.cross(axis).length());
                assert!(
                    image.pdf(w) > 0.0,
                    "{x}: direction {w} reaches the light outside the image cone"
                );
            }
            assert!(
                reaching > 20,
                "{x}: only {reaching} directions reach the light"
            );
            // Not much wider than the directions that reach the light: 1.1
            // to 1.7 times their cone's solid angle at these points when
            // written (the disc that holds the light, and the sines for
            // angles), under 2.2 here (checked with a mutant: the
            // magnification `1 + 2 a cos / r` as `2 a cos / r` fails).
            let reach = Cone::around(axis, widest).solid_angle();
            let ratio = image.solid_angle() / reach;
            assert!(ratio < 2.2, "{x}: the image cone is {ratio} times too wide");
        }
    }
}
