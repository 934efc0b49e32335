//! Emissive triangles as one light: light sampling of surfaces that emit
//! but stand in for no scene light (the course samples only
//! `scene->lights`; without this, such surfaces light the scene only when
//! a BSDF-sampled ray happens to hit them, which is very noisy for small
//! emitters).
//!
//! A triangle `i` is picked with probability proportional to its power,
//! `P_i = A_i Y(L_i)` (area times luminance of its radiance), then a point
//! uniform on it ([`sample_uniform_triangle`]), density `1 / A_i` per area.
//! Seen from `p` at distance `r` under the emitter's cosine
//! `cos_e = |n_i . wi|` (emission is two-sided), the density per steradian is
//!
//! ```text
//! p_w = (P_i / P) r^2 / (A_i cos_e)
//! ```
//!
//! The same density, evaluated at the point where a BSDF-sampled ray hit
//! triangle `i`, weighs that hit in multiple importance sampling. Power:
//! `Phi = sum_i 2 pi A_i L_i` (both sides emit).

use glam::{Vec2, Vec3};

use super::{LightSample, SurfacePoint};
use crate::math::warp::{sample_uniform_triangle, uniform_triangle_pdf};
use crate::math::{luminance, Rgb};
use crate::scene::Scene;

/// One emissive triangle.
#[derive(Clone, Copy, Debug, PartialEq)]
struct EmissiveTriangle {
    corners: [Vec3; 3],
    /// Unit normal (either side emits).
    normal: Vec3,
    area: f32,
    radiance: Rgb,
    /// Probability of picking this triangle.
    pmf: f32,
}

impl EmissiveTriangle {
    fn point(&self, q: Vec3) -> SurfacePoint {
        SurfacePoint {
            q,
            normal: self.normal,
            two_sided: true,
            radiance: self.radiance,
            area_pdf: self.pmf * uniform_triangle_pdf(self.area),
        }
    }
}

/// The emissive triangles of a scene with a power-proportional pmf.
#[derive(Clone, Debug, Default)]
pub struct EmissiveTriangles {
    emitters: Vec<EmissiveTriangle>,
    /// Running sums of the emitters' powers; the last is the total.
    cdf: Vec<f32>,
    /// The scene's triangle index of each emitter.
    triangle_ids: Vec<u32>,
}

impl EmissiveTriangles {
    /// The triangles of `scene` whose material `sampled[m]` says to sample,
    /// leaving out those with no area or no emission.
    pub fn new(scene: &Scene, sampled: &[bool]) -> Self {
        let mut set = EmissiveTriangles::default();
        let mut total = 0.0;
        let mesh = &scene.mesh;
        for (t, (&[a, b, c], &m)) in mesh.triangles.iter().zip(&mesh.materials).enumerate() {
            let Some(material) = scene.materials.get(m as usize) else {
                continue;
            };
            let radiance = material.emission();
            if !sampled.get(m as usize).copied().unwrap_or(false) || luminance(radiance) <= 0.0 {
                continue;
            }
            let corners = [a, b, c].map(|v| mesh.positions[v as usize]);
            let cross = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
            let area = 0.5 * cross.length();
            if !(area > 0.0 && area.is_finite()) {
                continue;
            }
            total += area * luminance(radiance);
            set.cdf.push(total);
            set.triangle_ids.push(t as u32);
            set.emitters.push(EmissiveTriangle {
                corners,
                normal: cross.normalize(),
                area,
                radiance,
                pmf: 0.0,
            });
        }
        for e in &mut set.emitters {
            e.pmf = e.area * luminance(e.radiance) / total;
        }
        set
    }

    pub fn is_empty(&self) -> bool {
        self.emitters.is_empty()
    }

    pub fn len(&self) -> usize {
        self.emitters.len()
    }

    /// The scene's triangle index of each member, in member order.
    pub fn triangle_ids(&self) -> &[u32] {
        &self.triangle_ids
    }

    /// Light arriving at `p` from a point sampled on the emitters, with
    /// `pick` in `[0, 1)` choosing the triangle and `u` the point on it.
    #[doc(alias = "sample_L")]
    pub fn sample_li(&self, p: Vec3, pick: f32, u: Vec2) -> Option<LightSample> {
        let total = *self.cdf.last()?;
        let i = self
            .cdf
            .partition_point(|&c| c <= pick * total)
            .min(self.emitters.len() - 1);
        let e = &self.emitters[i];
        let b = sample_uniform_triangle(u);
        let q = b.x * e.corners[0] + b.y * e.corners[1] + b.z * e.corners[2];
        e.point(q).seen_from(p)
    }

    /// Density per steradian with which [`Self::sample_li`] picks the
    /// point `q` of member `member` from `p` (0 for an unknown member).
    pub fn pdf_li(&self, p: Vec3, member: u32, q: Vec3) -> f32 {
        let Some(e) = self.emitters.get(member as usize) else {
            return 0.0;
        };
        let to_light = q - p;
        let distance_squared = to_light.length_squared();
        let wi = to_light / distance_squared.sqrt();
        e.point(q)
            .solid_angle_pdf(wi, distance_squared)
            .unwrap_or(0.0)
    }

    /// Radiant power of both sides of every member.
    pub fn power(&self) -> Rgb {
        self.emitters
            .iter()
            .map(|e| 2.0 * std::f32::consts::PI * e.area * e.radiance)
            .sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lights::LightPdf;
    use crate::scene::Material;

    /// Four triangles in the plane `y = 2`, facing down: `0` of area 1/2
    /// and radiance 1 (material 0), `1` of area 1/2 and radiance 3
    /// (material 1), `2` with no area (material 1), `3` diffuse
    /// (material 2); material 3, emissive, is not to be sampled.
    fn scene() -> (Scene, Vec<bool>) {
        let mut scene = Scene::default();
        let at = |x: f32, z: f32| Vec3::new(x, 2.0, z);
        scene.mesh.positions = vec![
            at(0.0, 0.0),
            at(1.0, 0.0),
            at(0.0, 1.0),
            at(3.0, 0.0),
            at(4.0, 0.0),
            at(3.0, 1.0),
            at(5.0, 0.0),
            at(6.0, 0.0),
        ];
        scene.mesh.triangles = vec![[0, 1, 2], [3, 4, 5], [6, 7, 6], [0, 2, 1]];
        scene.mesh.materials = vec![0, 1, 1, 2];
        scene.materials = vec![
            Material::Emission {
                radiance: Rgb::splat(1.0),
            },
            Material::Emission {
                radiance: Rgb::splat(3.0),
            },
            Material::Diffuse {
                albedo: Rgb::splat(0.5),
            },
            Material::Emission {
                radiance: Rgb::splat(7.0),
            },
        ];
        (scene, vec![true, true, true, false])
    }

    // Only sampled materials that emit, on triangles with an area, join
    // the light. Fails if the material, emission or area guard goes.
    #[test]
    fn only_emitting_triangles_with_an_area_join_the_light() {
        let (scene, sampled) = scene();
        let light = EmissiveTriangles::new(&scene, &sampled);
        assert_eq!(light.triangle_ids(), &[0, 1]);
        assert_eq!((light.len(), light.is_empty()), (2, false));
        // Both sides of each: 2 pi A L.
        let expected = 2.0 * std::f32::consts::PI * 0.5 * (1.0 + 3.0);
        assert!((light.power() - Rgb::splat(expected)).abs().max_element() < 1e-5);
        let none = EmissiveTriangles::new(&scene, &[false; 4]);
        assert_eq!((none.len(), none.is_empty()), (0, true));
        assert_eq!(none.sample_li(Vec3::ZERO, 0.5, Vec2::splat(0.5)), None);
    }

    // Picks in proportion to power, 1 : 3 here: `pick` below 1/4 takes
    // the first, above it the second (and a pick rounded up to 1, the
    // last, not one past it). The density of a sample, queried
    // where it lands, is the sample's own: `(P_i / P) r^2 / (A_i cos)`.
    // Fails if the pick, the point or the density's pieces change, or an
    // unknown member gets a density.
    #[test]
    fn samples_pick_by_power_and_their_density_is_the_queried_one() {
        let (scene, sampled) = scene();
        let light = EmissiveTriangles::new(&scene, &sampled);
        let p = Vec3::new(1.0, 0.0, 0.5);
        for (pick, member) in [(0.2, 0u32), (0.3, 1), (1.0, 1)] {
            let u = Vec2::new(0.4, 0.7);
            let s = light.sample_li(p, pick, u).unwrap();
            let q = p + s.wi * s.distance;
            let corners =
                if member == 0 { [0, 1, 2] } else { [3, 4, 5] }.map(|v| scene.mesh.positions[v]);
            let b = sample_uniform_triangle(u);
            let expected_q = b.x * corners[0] + b.y * corners[1] + b.z * corners[2];
            assert!((q - expected_q).length() < 1e-5, "{pick}: {q} {expected_q}");
            let share = if member == 0 { 0.25 } else { 0.75 };
            let r2 = (q - p).length_squared();
            let cos = (q - p).normalize().y;
            let expected = share * r2 / (0.5 * cos);
            let LightPdf::SolidAngle(pdf) = s.pdf else {
                panic!("{:?}", s.pdf)
            };
            assert!(
                (pdf - expected).abs() < 1e-4 * expected,
                "{pick}: {pdf} {expected}"
            );
            assert!((light.pdf_li(p, member, q) - pdf).abs() < 1e-4 * pdf);
            assert_eq!(s.radiance, Rgb::splat(if member == 0 { 1.0 } else { 3.0 }));
        }
        assert_eq!(light.pdf_li(p, 2, Vec3::new(5.5, 2.0, 0.0)), 0.0);
    }
}
