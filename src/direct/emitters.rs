//! Emissive triangles as lights: light sampling of surfaces that emit but
//! stand in for no scene light (the course samples only `scene->lights`;
//! without this, such surfaces light the scene only when a BSDF-sampled
//! ray happens to hit them, which is very noisy for small emitters).
//!
//! A triangle `i` is picked with probability proportional to its power,
//! `P_i = A_i Y(L_i)` (area times luminance of its radiance), then a point
//! uniform on it: with `sqrt(u1) = s`, barycentrics `(1 - s, s (1 - u2), s u2)`
//! (pbrt-v4, section 6.5.4), density `1 / A_i` per area. Seen from `p` at
//! distance `r` under the emitter's cosine `cos_e = |n_i . wi|` (emission
//! is two-sided), the density per steradian is
//!
//! ```text
//! p_w = (P_i / P) r^2 / (A_i cos_e)
//! ```

use glam::{Vec2, Vec3};

use super::lights::{LightSample, SurfacePoint};
use crate::math::{luminance, Rgb};
use crate::scene::Scene;

/// One emissive triangle.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Emitter {
    p0: Vec3,
    p1: Vec3,
    p2: Vec3,
    /// Unit normal (either side emits).
    normal: Vec3,
    area: f32,
    radiance: Rgb,
}

/// The emissive triangles of a scene with a power-proportional pmf.
#[derive(Clone, Debug, Default)]
pub struct EmissiveTriangles {
    emitters: Vec<Emitter>,
    /// Running sums of the emitters' powers; the last is the total.
    cdf: Vec<f32>,
}

impl EmissiveTriangles {
    /// The triangles of `scene` whose material `sampled[m]` says to sample,
    /// leaving out those with no area or no emission.
    pub fn new(scene: &Scene, sampled: &[bool]) -> Self {
        let mut emitters = Vec::new();
        let mut cdf = Vec::new();
        let mut total = 0.0;
        for (&[a, b, c], &m) in scene.mesh.triangles.iter().zip(&scene.mesh.materials) {
            let Some(material) = scene.materials.get(m as usize) else {
                continue;
            };
            let radiance = material.emission();
            if !sampled.get(m as usize).copied().unwrap_or(false) || luminance(radiance) <= 0.0 {
                continue;
            }
            let [p0, p1, p2] = [a, b, c].map(|v| scene.mesh.positions[v as usize]);
            let cross = (p1 - p0).cross(p2 - p0);
            let area = 0.5 * cross.length();
            if !(area > 0.0 && area.is_finite()) {
                continue;
            }
            total += area * luminance(radiance);
            cdf.push(total);
            emitters.push(Emitter {
                p0,
                p1,
                p2,
                normal: cross.normalize(),
                area,
                radiance,
            });
        }
        EmissiveTriangles { emitters, cdf }
    }

    pub fn is_empty(&self) -> bool {
        self.emitters.is_empty()
    }

    pub fn len(&self) -> usize {
        self.emitters.len()
    }

    /// Light arriving at `p` from a point sampled on the emitters, with
    /// `pick` in `[0, 1)` choosing the triangle and `u` the point on it.
    pub fn sample(&self, p: Vec3, pick: f32, u: Vec2) -> Option<LightSample> {
        let total = *self.cdf.last()?;
        let target = pick * total;
        let i = self
            .cdf
            .partition_point(|&c| c <= target)
            .min(self.emitters.len() - 1);
        let e = &self.emitters[i];
        let pmf = e.area * luminance(e.radiance) / total;
        // Uniform point on the triangle.
        let s = u.x.sqrt();
        let q = (1.0 - s) * e.p0 + s * (1.0 - u.y) * e.p1 + s * u.y * e.p2;
        let point = SurfacePoint {
            q,
            normal: e.normal,
            two_sided: true,
            radiance: e.radiance,
            area_pdf: pmf / e.area,
        };
        point.seen_from(p)
    }
}
