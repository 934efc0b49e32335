//! Where a camera ray's chain of delta bounces leaves the scene: the
//! directions in which it escapes to the environment, with their
//! throughputs, one *leaf* for each way through the chain.
//!
//! A mirror or a refraction-only surface sends the chain one way; glass
//! both ways (its reflection with weight `R F`, its refraction with
//! `T (1 - F) / eta^2`, as the glass splits do); the first surface that
//! is not a delta BSDF ends it without a leaf. Each leaf carries a key,
//! the sequence of lobes that led to it, so that the chains of nearby
//! camera rays can be matched leaf to leaf. Nothing here is random.

use glam::{Vec2, Vec3};

use crate::intersect::{Intersector, Ray};
use crate::materials::{Bsdf, BsdfSample};
use crate::math::color::luminance;
use crate::world::World;

/// The most leaves a chain has: glass vertices past the first
/// `MAX_GLASS_FORKS` follow their likelier lobe alone.
pub const MAX_LEAVES: usize = 1 << MAX_GLASS_FORKS;
const MAX_GLASS_FORKS: u32 = 3;

/// Where a way through a chain of delta bounces escapes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Leaf {
    /// The lobes taken: 1 then, per vertex, 0 reflected or 1 refracted
    /// (a mirror reflects).
    pub key: u32,
    /// The unit direction of escape.
    pub dir: Vec3,
    /// Luminance of the chain's throughput.
    pub weight: f32,
}

/// A chain's leaves (at most [`MAX_LEAVES`]), and what a camera sample
/// that starts along it costs.
#[derive(Clone, Copy, Debug, Default)]
pub struct Leaves {
    leaves: [Option<Leaf>; MAX_LEAVES],
    len: usize,
    /// Rays the chain traced, the camera ray included.
    pub rays: u32,
    /// Ways that met a surface that is not a delta BSDF, where a path
    /// goes on with light samples and further bounces.
    pub scattered: u32,
}

impl Leaves {
    pub fn iter(&self) -> impl Iterator<Item = &Leaf> {
        self.leaves[..self.len].iter().flatten()
    }

    fn push(&mut self, leaf: Leaf) {
        if self.len < MAX_LEAVES {
            self.leaves[self.len] = Some(leaf);
            self.len += 1;
        }
    }
}

#[derive(Clone, Copy)]
struct Way {
    ray: Ray,
    key: u32,
    weight: f32,
    bounces: u32,
    forks: u32,
}

/// The leaves of the chain of delta bounces that starts with `camera_ray`,
/// up to `max_bounces` bounces.
pub fn chain_leaves<I: Intersector>(
    world: &World<I>,
    camera_ray: &Ray,
    max_bounces: u32,
) -> Leaves {
    let mut leaves = Leaves::default();
    // Depth first: a fork pushes two ways and the next pops one, so at
    // most one more than the forks wait.
    let mut waiting = [None; MAX_GLASS_FORKS as usize + 2];
    let mut len = 0;
    let mut way = Way {
        ray: *camera_ray,
        key: 1,
        weight: 1.0,
        bounces: 0,
        forks: 0,
    };
    loop {
        leaves.rays += 1;
        match world.intersector.intersect(&way.ray) {
            Some(hit) if way.bounces < max_bounces => {
                let point = world.shade_surface(hit, -way.ray.dir);
                let lobes = match point.bsdf {
                    Bsdf::Glass(glass) if way.forks < MAX_GLASS_FORKS => glass
                        .both_lobes(point.wo)
                        .map(|[r, t]| [Some((r, 0)), Some((t, 1))]),
                    _ => None,
                };
                let forks = way.forks + u32::from(lobes.is_some());
                let lobes = lobes.unwrap_or([one_lobe(&point.bsdf, point.wo), None]);
                if lobes[0].is_none() && !point.bsdf.is_black() {
                    leaves.scattered += 1;
                }
                for (sample, bit) in lobes.into_iter().flatten() {
                    let weight = way.weight * luminance(sample.weight());
                    if weight > 0.0 && weight.is_finite() {
                        waiting[len] = Some(Way {
                            ray: point.hit.spawn_ray(point.frame.to_world(sample.wi)),
                            key: (way.key << 1) | bit,
                            weight,
                            bounces: way.bounces + 1,
                            forks,
                        });
                        len += 1;
                    }
                }
            }
            Some(_) => {}
            None if way.bounces > 0 => leaves.push(Leaf {
                key: way.key,
                dir: way.ray.dir.normalize(),
                weight: way.weight,
            }),
            None => {}
        }
        if len == 0 {
            return leaves;
        }
        len -= 1;
        way = waiting[len].take().expect("a waiting way");
    }
}

/// A delta BSDF's one lobe (for glass past its forks, the likelier), and
/// whether it is refracted; `None` for a BSDF that is not all deltas.
fn one_lobe(bsdf: &Bsdf, wo: Vec3) -> Option<(BsdfSample, u32)> {
    match bsdf {
        Bsdf::Glass(glass) => match glass.both_lobes(wo) {
            Some([r, t]) if luminance(r.weight()) >= luminance(t.weight()) => Some((r, 0)),
            Some([_, t]) => Some((t, 1)),
            // Total internal reflection: the one lobe there is.
            None => glass
                .sample(wo, 0.5)
                .map(|s| (s, u32::from(s.transmission))),
        },
        Bsdf::Mirror(_) | Bsdf::Refraction(_) => bsdf
            .sample(wo, 0.5, Vec2::splat(0.5))
            .map(|s| (s, u32::from(s.transmission))),
        _ => None,
    }
}
