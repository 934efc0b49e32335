//! A hit prepared for shading.
//!
//! Surfaces are two-sided for shading (the course's meshes are not
//! consistently wound): the frame's +Z is the shading normal turned towards
//! the viewer, so `wo.z >= 0` for every BSDF. Which side the ray arrived
//! from is kept apart, from the geometric normal (outward for spheres,
//! the winding's for triangles): glass needs it to know whether the ray
//! enters (`eta = ior`) or leaves (`eta = 1 / ior`).

use glam::Vec3;

use super::casters::Cones;
use crate::intersect::Hit;
use crate::materials::{Bsdf, BsdfOptions};
use crate::math::{Frame, Rgb};
use crate::scene::Material;

/// A hit with its frame, outgoing direction, BSDF and emission.
#[derive(Clone, Copy, Debug)]
pub struct ShadingPoint {
    pub hit: Hit,
    /// Local frame, +Z the shading normal on the viewer's side.
    pub frame: Frame,
    /// Direction towards the viewer, local frame (`wo.z >= 0`).
    pub wo: Vec3,
    /// Whether the viewer is on the side the geometric normal points to
    /// (outside a sphere or a consistently wound closed mesh).
    pub front_face: bool,
    pub bsdf: Bsdf,
    /// Radiance emitted towards the viewer.
    pub emission: Rgb,
    /// The cones of the caustic casters the continuation mixes in at this
    /// point ([`super::casters`]), found once for the continuation and the
    /// light samples' weights; none unless [`World::shade`](super::World::shade)
    /// or [`World::add_caster_cones`](super::World::add_caster_cones)
    /// finds some.
    pub cones: Cones,
}

impl ShadingPoint {
    /// Prepares `hit` seen from the unit direction `wo` (world space).
    pub fn new(hit: Hit, wo: Vec3, material: &Material, options: BsdfOptions) -> Self {
        let n = if hit.n.dot(wo) < 0.0 { -hit.n } else { hit.n };
        let frame = Frame::from_z(n);
        let front_face = hit.ng.dot(wo) >= 0.0;
        ShadingPoint {
            hit,
            frame,
            wo: frame.to_local(wo),
            front_face,
            bsdf: Bsdf::new(material, front_face, options),
            emission: material.emission(),
            cones: Cones::NONE,
        }
    }
}
