//! The mixture of cones at one vertex ([`Cones`]): its casters' cones
//! and the light images in the mirror-like ones, sampled and weighed as
//! the module [`super`] describes.

use glam::{Vec2, Vec3};

use super::cone::Cone;
use super::{images, Casters, CASTER_PROBABILITY, MAX_CONES};
use crate::math::float::ONE_BELOW_ONE;

/// One component of the casters' mixture at a vertex.
#[derive(Clone, Copy, Debug)]
enum Member {
    /// A caster's cone.
    Sphere(Cone),
    /// The image of light `light` in caster `caster` (indices into
    /// [`Casters`]), whose own cone is member `sphere_member`: found only
    /// where it is needed ([`Cones::image`]).
    Image {
        sphere_member: u8,
        caster: u8,
        light: u8,
    },
}

/// The cones of the casters eligible at one vertex.
///
/// A light image's cone costs more to find than a sphere's (a few
/// fixed-point steps), and most vertices never need it: it matters only
/// for a continuation drawn from it, or a direction whose density is
/// asked for inside its caster's cone. So it is found then, and its
/// component is restricted to the caster's cone: a sample of the image's
/// cone outside the caster's cone is refused (the path ends there), and
/// the density of a direction outside the caster's cone has no image
/// term. Both sides apply the same restriction, so they agree. Where a
/// vertex has no image ([`images::image_cone`] gives none) the component
/// is the caster's cone itself.
#[derive(Clone, Copy, Debug)]
pub struct Cones {
    members: [Member; MAX_CONES],
    count: usize,
    /// The vertex.
    p: Vec3,
}

impl Cones {
    /// No cone: the continuation is the BSDF's.
    pub const NONE: Cones = Cones {
        members: [Member::Sphere(Cone::EMPTY); MAX_CONES],
        count: 0,
        p: Vec3::ZERO,
    };

    pub fn len(&self) -> usize {
        self.count
    }

    pub fn is_empty(&self) -> bool {
        self.count == 0
    }

    /// No cone yet, at the vertex `p`.
    pub(super) fn at(p: Vec3) -> Self {
        Cones { p, ..Cones::NONE }
    }

    /// Adds `member` and returns its index, unless there are
    /// [`MAX_CONES`] already.
    fn push(&mut self, member: Member) -> Option<u8> {
        if self.count == MAX_CONES {
            return None;
        }
        self.members[self.count] = member;
        self.count += 1;
        Some(self.count as u8 - 1)
    }

    /// Adds a caster's cone; its index, unless the list is full.
    pub(super) fn push_sphere(&mut self, cone: Cone) -> Option<u8> {
        self.push(Member::Sphere(cone))
    }

    /// Adds the image of light `light` in caster `caster`, whose cone is
    /// member `sphere_member`, unless the list is full.
    /// Whether it was added (`false`: the list is full).
    pub(super) fn push_image(&mut self, sphere_member: u8, caster: usize, light: usize) -> bool {
        self.push(Member::Image {
            sphere_member,
            caster: caster as u8,
            light: light as u8,
        })
        .is_some()
    }

    /// The cone of member `j`, a caster's.
    fn sphere(&self, j: u8) -> Cone {
        match self.members[j as usize] {
            Member::Sphere(cone) => cone,
            Member::Image { .. } => unreachable!("an image's caster is a sphere member"),
        }
    }

    /// The cone of an image member: the image's, or where the vertex has
    /// none, its caster's.
    fn image(&self, casters: &Casters, sphere_member: u8, caster: u8, light: u8) -> Cone {
        let caster = &casters.spheres[caster as usize];
        let light = &casters.lights[light as usize];
        caster
            .image_spread
            .and_then(|spread| images::image_cone(self.p, caster, light, spread))
            .unwrap_or_else(|| self.sphere(sphere_member))
    }

    /// A direction (world space) from cone `j = min(floor(u.x k), k - 1)`,
    /// with `u.x` stretched back to `[0, 1)` within the cone's share,
    /// `(u.x k - j, u.y)`, choosing the direction: so the directions of
    /// each cone are a stratified set when the 2D points `u` are, as they
    /// would not be if a separate number chose the cone. `None` for an
    /// image's direction outside its caster's cone. Panics if there is
    /// no cone.
    pub fn sample(&self, u: Vec2, casters: &Casters) -> Option<Vec3> {
        let scaled = u.x * self.count as f32;
        let pick = (scaled as usize).min(self.count - 1);
        let u = Vec2::new((scaled - pick as f32).min(ONE_BELOW_ONE), u.y);
        match self.members[pick] {
            Member::Sphere(cone) => Some(cone.sample(u)),
            Member::Image {
                sphere_member,
                caster,
                light,
            } => {
                let w = self.image(casters, sphere_member, caster, light).sample(u);
                (self.sphere(sphere_member).pdf(w) > 0.0).then_some(w)
            }
        }
    }

    /// The continuation's density for the unit direction `w` (world
    /// space): `(1 - c) bsdf_pdf + c pdf(w)`.
    pub fn mixture_pdf(&self, bsdf_pdf: f32, w: Vec3, casters: &Casters) -> f32 {
        (1.0 - CASTER_PROBABILITY) * bsdf_pdf + CASTER_PROBABILITY * self.pdf(w, casters)
    }

    /// The mixture of the cones' densities, each with weight `1 / k`.
    pub fn pdf(&self, w: Vec3, casters: &Casters) -> f32 {
        if self.count == 0 {
            return 0.0;
        }
        let members = &self.members[..self.count];
        let sum: f32 = members
            .iter()
            .map(|member| match *member {
                Member::Sphere(cone) => cone.pdf(w),
                Member::Image {
                    sphere_member,
                    caster,
                    light,
                } => {
                    if self.sphere(sphere_member).pdf(w) > 0.0 {
                        self.image(casters, sphere_member, caster, light).pdf(w)
                    } else {
                        0.0
                    }
                }
            })
            .sum();
        sum / self.count as f32
    }
}
