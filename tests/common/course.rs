//! The course's CBbunny scene and its reference render, as the tests that
//! compare against the course need them.

use image::DynamicImage;
use pathtracer::bvh::BvhAccel;
use pathtracer::intersect::Primitives;
use pathtracer::raygen::Camera;
use pathtracer::scene::Scene;

use super::course_dir;

/// `CBbunny.dae` with the course's camera for its reference render's size,
/// a BVH over it, and the reference render itself.
pub struct CbbunnyReference {
    pub reference: DynamicImage,
    pub width: u32,
    pub height: u32,
    pub scene: Scene,
    pub camera: Camera,
    pub accel: BvhAccel,
}

/// `None` (with a note) when the course's scenes are absent.
pub fn cbbunny_reference() -> Option<CbbunnyReference> {
    let dir = course_dir()?;
    let reference = image::open(dir.join("CBbunny_reference_480x360.png")).unwrap();
    let (width, height) = (reference.width(), reference.height());
    assert_eq!((width, height), (480, 360));
    let scene = pathtracer::scene::load(&dir.join("CBbunny.dae")).unwrap();
    let primitives = Primitives::from_scene(&scene);
    let camera = Camera::course_placement(&scene.camera, &primitives.bounds(), width, height);
    let accel = BvhAccel::new(primitives);
    Some(CbbunnyReference {
        reference,
        width,
        height,
        scene,
        camera,
        accel,
    })
}
