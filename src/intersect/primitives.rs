//! Every shape of a scene, packed for intersection.
//!
//! Primitive ids: triangles `0..T` in mesh order, then spheres `T..T+S`.
//! The hot loop only needs [`Shape`] (a triangle's vertex and edges, or a
//! sphere's centre and radius); the rest of the hit record (point, normals,
//! error bound) is computed once, for the closest hit, by
//! [`Primitives::finish_hit`].

use glam::Vec3;

use crate::math::float::gamma;
use crate::scene::{MaterialId, Scene, Sphere};

use super::sphere::{reproject, SphereShape};
use super::triangle::TriangleShape;
use super::{Aabb, Hit, Ray};

/// A shape stored for intersection.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shape {
    Triangle(TriangleShape),
    Sphere(SphereShape),
}

/// Where a ray meets a shape: `t`, and barycentrics `(u, v)` for triangles.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShapeHit {
    pub t: f32,
    pub u: f32,
    pub v: f32,
}

impl Shape {
    /// The ray's hit with this shape with `t` in `[ray.t_min, t_max]`.
    #[inline(always)]
    pub fn intersect(&self, ray: &Ray, t_max: f32) -> Option<ShapeHit> {
        match self {
            Shape::Triangle(tri) => tri.intersect(ray, t_max).map(|h| ShapeHit {
                t: h.t,
                u: h.u,
                v: h.v,
            }),
            Shape::Sphere(s) => s
                .intersect(ray, t_max)
                .map(|t| ShapeHit { t, u: 0.0, v: 0.0 }),
        }
    }

    /// The shape's bounding box.
    pub fn bounds(&self) -> Aabb {
        match self {
            Shape::Triangle(t) => Aabb::from_points([t.p0, t.p1, t.p2]),
            Shape::Sphere(s) => Aabb {
                min: s.center - Vec3::splat(s.radius),
                max: s.center + Vec3::splat(s.radius),
            },
        }
    }
}

/// The scene's shapes plus what it takes to finish a hit record.
#[derive(Clone, Debug, Default)]
pub struct Primitives {
    /// One shape per primitive id.
    pub shapes: Vec<Shape>,
    positions: Vec<Vec3>,
    normals: Vec<Vec3>,
    triangles: Vec<[u32; 3]>,
    triangle_materials: Vec<MaterialId>,
    spheres: Vec<Sphere>,
}

impl Primitives {
    /// Packs a scene's triangles and spheres.
    pub fn from_scene(scene: &Scene) -> Self {
        let mesh = &scene.mesh;
        let triangles = mesh.triangles.iter().map(|&[a, b, c]| {
            Shape::Triangle(TriangleShape::new(
                mesh.positions[a as usize],
                mesh.positions[b as usize],
                mesh.positions[c as usize],
            ))
        });
        let spheres = scene.spheres.iter().map(|s| {
            Shape::Sphere(SphereShape {
                center: s.center,
                radius: s.radius,
            })
        });
        Primitives {
            shapes: triangles.chain(spheres).collect(),
            positions: mesh.positions.clone(),
            normals: mesh.normals.clone(),
            triangles: mesh.triangles.clone(),
            triangle_materials: mesh.materials.clone(),
            spheres: scene.spheres.clone(),
        }
    }

    pub fn len(&self) -> usize {
        self.shapes.len()
    }

    pub fn is_empty(&self) -> bool {
        self.shapes.is_empty()
    }

    /// Bounding box of every primitive.
    pub fn bounds(&self) -> Aabb {
        self.shapes
            .iter()
            .fold(Aabb::EMPTY, |b, s| b.union(s.bounds()))
    }

    /// The full hit record for primitive `id` hit by `ray` at `hit`.
    pub fn finish_hit(&self, id: u32, ray: &Ray, hit: ShapeHit) -> Hit {
        let index = id as usize;
        if let Some(&[a, b, c]) = self.triangles.get(index) {
            let (a, b, c) = (a as usize, b as usize, c as usize);
            let (p0, p1, p2) = (self.positions[a], self.positions[b], self.positions[c]);
            let w = 1.0 - hit.u - hit.v;
            // Point from barycentrics; error bound from pbrt-v4 eq. 6.49.
            let p = w * p0 + hit.u * p1 + hit.v * p2;
            let p_error = gamma(7) * ((w * p0).abs() + (hit.u * p1).abs() + (hit.v * p2).abs());
            let ng = (p1 - p0).cross(p2 - p0).normalize_or(-ray.dir);
            let n = (w * self.normals[a] + hit.u * self.normals[b] + hit.v * self.normals[c])
                .normalize_or(ng);
            Hit {
                t: hit.t,
                p,
                p_error,
                n,
                ng,
                material: self.triangle_materials[index],
                primitive: id,
            }
        } else {
            let sphere = &self.spheres[index - self.triangles.len()];
            let p = reproject(sphere.center, sphere.radius, ray.at(hit.t));
            let local = p - sphere.center;
            let p_error = gamma(5) * local.abs() + gamma(1) * p.abs();
            let ng = (local / sphere.radius).normalize_or(-ray.dir);
            Hit {
                t: hit.t,
                p,
                p_error,
                n: ng,
                ng,
                material: sphere.material,
                primitive: id,
            }
        }
    }
}
