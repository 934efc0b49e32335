//! Built-in scenes made in code (no course data): the default Cornell box,
//! the materials box of part 6, two spheres on a floor for the environment
//! light of part 7, and the bumpy sphere of the ray-throughput benchmark.

use std::f32::consts::PI;

use glam::Vec3;

use super::normals::area_weighted_vertex_normals;
use super::{CameraInfo, Light, Material, MaterialId, Scene, Sphere, TriangleMesh};

/// The name under which [`cornell_box`] appears in messages.
pub const CORNELL_BOX: &str = "built-in: cornell-box";

/// The name under which [`materials_box`] appears in messages.
pub const MATERIALS_BOX: &str = "built-in: materials-box";

/// A Cornell box with two spheres, as the course frames its `CB*.dae`
/// scenes: a box `[-1, 1] x [0, 1.5] x [-1, 1]` open towards +Z, red wall
/// at -X, blue wall at +X, a 0.6 x 0.8 area light of radiance 10 under the
/// ceiling (and an emissive quad in the same place, as the course files
/// have), and two diffuse spheres of radius 0.3, one white, one pale
/// yellow.
pub fn cornell_box() -> Scene {
    let mut builder = MeshBuilder::default();
    let materials = builder.ball_materials();
    let balls: Vec<_> = BALL_CENTRES
        .into_iter()
        .zip(materials)
        .map(|(centre, material)| (centre, BALL_RADIUS, material))
        .collect();
    box_with_spheres(builder, CORNELL_BOX, &balls)
}

/// The centres of [`cornell_box`]'s balls: the yellow one left and back,
/// the white one right and front.
pub const BALL_CENTRES: [Vec3; 2] = [Vec3::new(-0.45, 0.3, -0.35), Vec3::new(0.45, 0.3, 0.25)];

/// The radius of [`cornell_box`]'s balls.
pub const BALL_RADIUS: f32 = 0.3;

/// The Cornell box of [`cornell_box`] with the materials of assignment
/// 3-2: a mirror sphere (left, back), a glass sphere (right, front; index
/// 1.5) and a rough copper sphere (centre, back; Beckmann roughness 0.15).
/// Copper's index of refraction at the wavelengths 650, 550 and 450 nm is
/// `eta = (0.200, 0.924, 1.102)`, `k = (3.913, 2.453, 2.142)` (Palik,
/// *Handbook of Optical Constants of Solids*, 1985, as Mitsuba's `Cu` preset
/// gives it in RGB).
pub fn materials_box() -> Scene {
    let mut builder = MeshBuilder::default();
    let mirror = builder.material(Material::Mirror {
        reflectance: Vec3::splat(0.95),
    });
    let glass = builder.material(Material::Glass {
        reflectance: Vec3::ONE,
        transmittance: Vec3::ONE,
        roughness: 0.0,
        ior: 1.5,
    });
    let copper = builder.material(Material::Microfacet {
        alpha: 0.15,
        eta: COPPER_ETA,
        k: COPPER_K,
    });
    box_with_spheres(
        builder,
        MATERIALS_BOX,
        &[
            (Vec3::new(-0.5, 0.3, -0.4), 0.3, mirror),
            (Vec3::new(0.45, 0.3, 0.3), 0.3, glass),
            (Vec3::new(0.15, 0.22, -0.55), 0.22, copper),
        ],
    )
}

/// Copper's index of refraction at 650, 550 and 450 nm, real part
/// ([`materials_box`] gives the source).
pub const COPPER_ETA: Vec3 = Vec3::new(0.200, 0.924, 1.102);

/// Copper's extinction coefficient at 650, 550 and 450 nm.
pub const COPPER_K: Vec3 = Vec3::new(3.913, 2.453, 2.142);

/// The name under which [`environment_spheres`] appears in messages.
pub const ENVIRONMENT_SPHERES: &str = "built-in: environment-spheres";

/// Part 7's scene, lit only by an environment map: a diffuse sphere
/// (albedo 0.75, left) and a rough copper sphere (Beckmann roughness 0.2,
/// right; copper as in [`materials_box`]), both of radius 0.5, resting on
/// a grey floor `[-2, 2] x {0} x [-2, 2]` (albedo 0.5). No light of its
/// own; the camera looks from +Z, a little from above.
pub fn environment_spheres() -> Scene {
    let mut builder = MeshBuilder::default();
    let floor = builder.material(Material::Diffuse {
        albedo: Vec3::splat(0.5),
    });
    let diffuse = builder.material(Material::Diffuse {
        albedo: Vec3::splat(0.75),
    });
    let copper = builder.material(Material::Microfacet {
        alpha: 0.2,
        eta: COPPER_ETA,
        k: COPPER_K,
    });
    builder.quad(
        floor,
        [
            Vec3::new(-2.0, 0.0, 2.0),
            Vec3::new(2.0, 0.0, 2.0),
            Vec3::new(2.0, 0.0, -2.0),
            Vec3::new(-2.0, 0.0, -2.0),
        ],
    );
    let mut scene = builder.finish(ENVIRONMENT_SPHERES);
    scene.spheres = vec![
        Sphere {
            center: Vec3::new(-0.6, 0.5, 0.0),
            radius: 0.5,
            material: diffuse,
        },
        Sphere {
            center: Vec3::new(0.6, 0.5, -0.2),
            radius: 0.5,
            material: copper,
        },
    ];
    scene.camera = CameraInfo {
        dir_to_camera: Vec3::new(0.0, 0.15, 1.0).normalize(),
        hfov_deg: 49.13434,
        vfov_deg: 37.8493,
        znear: 0.1,
        zfar: 100.0,
    };
    scene
}

/// The box, its light and its camera around the given spheres
/// `(centre, radius, material)`; `builder` may already hold materials.
fn box_with_spheres(
    mut builder: MeshBuilder,
    name: &str,
    spheres: &[(Vec3, f32, MaterialId)],
) -> Scene {
    let white = builder.material(Material::Diffuse {
        albedo: Vec3::splat(0.6),
    });
    let red = builder.material(Material::Diffuse {
        albedo: Vec3::new(0.6, 0.2, 0.2),
    });
    let blue = builder.material(Material::Diffuse {
        albedo: Vec3::new(0.2, 0.2, 0.6),
    });
    let light = builder.material(Material::Emission {
        radiance: Vec3::splat(10.0),
    });
    let (x0, x1, y0, y1, z0, z1) = (-1.0, 1.0, 0.0, 1.5, -1.0, 1.0);
    let ly = 1.49;
    // Each quad's corners run counter-clockwise seen from inside the box.
    let quads = [
        (
            white,
            [(x0, y0, z1), (x1, y0, z1), (x1, y0, z0), (x0, y0, z0)],
        ), // floor
        (
            white,
            [(x0, y1, z0), (x1, y1, z0), (x1, y1, z1), (x0, y1, z1)],
        ), // ceiling
        (
            white,
            [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0)],
        ), // back
        (
            red,
            [(x0, y0, z1), (x0, y0, z0), (x0, y1, z0), (x0, y1, z1)],
        ), // left
        (
            blue,
            [(x1, y0, z0), (x1, y0, z1), (x1, y1, z1), (x1, y1, z0)],
        ), // right
        (
            light,
            [
                (-0.3, ly, -0.4),
                (0.3, ly, -0.4),
                (0.3, ly, 0.4),
                (-0.3, ly, 0.4),
            ],
        ),
    ];
    for (material, corners) in quads {
        builder.quad(material, corners.map(|(x, y, z)| Vec3::new(x, y, z)));
    }
    let mut scene = builder.finish(name);
    scene.spheres = spheres
        .iter()
        .map(|&(center, radius, material)| Sphere {
            center,
            radius,
            material,
        })
        .collect();
    scene.lights = vec![Light::Area {
        radiance: Vec3::splat(10.0),
        center: Vec3::new(0.0, ly, 0.0),
        direction: -Vec3::Y,
        dim_x: Vec3::new(0.6, 0.0, 0.0),
        dim_y: Vec3::new(0.0, 0.0, 0.8),
    }];
    scene.camera = CameraInfo {
        dir_to_camera: Vec3::Z,
        hfov_deg: 49.13434,
        vfov_deg: 37.8493,
        znear: 0.1,
        zfar: 100.0,
    };
    scene
}

/// The benchmark's bumpy sphere: vertices `(r sin t cos p, r cos t, r sin t sin p)`
/// with `r = 1 + 0.08 sin 7t sin 9p + 0.03 sin 23t cos 31p + 0.01 cos 97t sin 89p`
/// on a grid of `phi_steps` in `p` over `[0, 2 pi]` and `theta_steps` in `t`
/// over `[0, pi]`. Cell `(i, j)` gives `(v[i,j], v[i+1,j], v[i,j+1])` unless
/// `j` is the first row and `(v[i+1,j], v[i+1,j+1], v[i,j+1])` unless it is
/// the last, so no triangle degenerates at the poles:
/// `2 phi_steps (theta_steps - 1)` triangles (1,046,528 for 1024 x 512).
pub fn bumpy_sphere(phi_steps: u32, theta_steps: u32) -> Scene {
    let mut builder = MeshBuilder::default();
    let material = builder.material(Material::DEFAULT);
    builder.sphere_grid(material, phi_steps, theta_steps, |t, p| {
        let r = 1.0
            + 0.08 * (7.0 * t).sin() * (9.0 * p).sin()
            + 0.03 * (23.0 * t).sin() * (31.0 * p).cos()
            + 0.01 * (97.0 * t).cos() * (89.0 * p).sin();
        r * Vec3::new(t.sin() * p.cos(), t.cos(), t.sin() * p.sin())
    });
    builder.finish("built-in: bumpy-sphere")
}

/// The Cornell box of [`cornell_box`] with its two balls made of
/// triangles (16 x 8 cells each, as [`bumpy_sphere`] lays them out) with
/// smooth vertex normals, where a student's barycentric interpolation of
/// the normals shows.
pub fn mesh_balls_box() -> Scene {
    let mut builder = MeshBuilder::default();
    let materials = builder.ball_materials();
    for (centre, material) in BALL_CENTRES.into_iter().zip(materials) {
        builder.sphere_grid(material, 16, 8, |t, p| {
            centre + BALL_RADIUS * Vec3::new(t.sin() * p.cos(), t.cos(), t.sin() * p.sin())
        });
    }
    box_with_spheres(builder, "built-in: mesh-balls-box", &[])
}

/// Collects triangles and materials, then computes the course's normals.
#[derive(Default)]
struct MeshBuilder {
    mesh: TriangleMesh,
    materials: Vec<Material>,
}

impl MeshBuilder {
    /// The balls' diffuse materials: pale yellow and white.
    fn ball_materials(&mut self) -> [MaterialId; 2] {
        let yellow = self.material(Material::Diffuse {
            albedo: Vec3::new(0.7, 0.65, 0.3),
        });
        let white = self.material(Material::Diffuse {
            albedo: Vec3::splat(0.6),
        });
        [yellow, white]
    }

    fn material(&mut self, m: Material) -> MaterialId {
        self.materials.push(m);
        (self.materials.len() - 1) as MaterialId
    }

    fn triangle(&mut self, material: MaterialId, vertices: [u32; 3]) {
        self.mesh.triangles.push(vertices);
        self.mesh.materials.push(material);
    }

    /// A closed surface over a grid of `phi_steps` in `p` over `[0, 2 pi]`
    /// and `theta_steps` in `t` over `[0, pi]`, vertices `point(t, p)`.
    /// Cell `(i, j)` gives `(v[i,j], v[i+1,j], v[i,j+1])` unless `j` is
    /// the first row and `(v[i+1,j], v[i+1,j+1], v[i,j+1])` unless it is
    /// the last, so no triangle degenerates at the poles:
    /// `2 phi_steps (theta_steps - 1)` triangles. The poles are one vertex
    /// each and the seam is shared (`theta_steps` at least 2).
    fn sphere_grid(
        &mut self,
        material: MaterialId,
        phi_steps: u32,
        theta_steps: u32,
        point: impl Fn(f32, f32) -> Vec3,
    ) {
        // One vertex a pole, rings between, the seam at p = 2 pi the same
        // vertices as p = 0: a closed mesh, without the boundary on which
        // the course's normals go wrong (super::course_normals).
        let base = self.mesh.positions.len() as u32;
        let bottom = base + 1 + phi_steps * (theta_steps - 1);
        let index = |i: u32, j: u32| match j {
            0 => base,
            j if j == theta_steps => bottom,
            j => base + 1 + (j - 1) * phi_steps + i % phi_steps,
        };
        self.mesh.positions.push(point(0.0, 0.0));
        for j in 1..theta_steps {
            let t = PI * j as f32 / theta_steps as f32;
            for i in 0..phi_steps {
                let p = 2.0 * PI * i as f32 / phi_steps as f32;
                self.mesh.positions.push(point(t, p));
            }
        }
        self.mesh.positions.push(point(PI, 0.0));
        for i in 0..phi_steps {
            for j in 0..theta_steps {
                if j != 0 {
                    self.triangle(material, [index(i, j), index(i + 1, j), index(i, j + 1)]);
                }
                if j + 1 != theta_steps {
                    let cell = [index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)];
                    self.triangle(material, cell);
                }
            }
        }
    }

    /// Two triangles over four corners given in order around the quad.
    fn quad(&mut self, material: MaterialId, corners: [Vec3; 4]) {
        let base = self.mesh.positions.len() as u32;
        self.mesh.positions.extend(corners);
        self.triangle(material, [base, base + 1, base + 2]);
        self.triangle(material, [base, base + 2, base + 3]);
    }

    fn finish(mut self, name: &str) -> Scene {
        self.mesh.normals =
            area_weighted_vertex_normals(&self.mesh.positions, &self.mesh.triangles);
        Scene {
            source: name.to_string(),
            mesh: self.mesh,
            materials: self.materials,
            ..Scene::default()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bumpy_sphere_has_the_documented_triangle_count() {
        let s = bumpy_sphere(16, 8);
        assert_eq!(s.mesh.triangles.len(), 2 * 16 * 7);
        assert_eq!(s.mesh.normals.len(), s.mesh.positions.len());
    }

    #[test]
    fn cornell_box_faces_point_inwards() {
        let s = cornell_box();
        let centre = Vec3::new(0.0, 0.75, 0.0);
        for &[a, b, c] in &s.mesh.triangles {
            let p = |i: u32| s.mesh.positions[i as usize];
            let n = (p(b) - p(a)).cross(p(c) - p(a));
            assert!(n.dot(centre - p(a)) > 0.0, "triangle {a} {b} {c} faces out");
        }
    }
}
