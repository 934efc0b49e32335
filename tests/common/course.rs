//! The course's own scene files, as the tests find them: by file name
//! under `$CS184_SCENES` (the starter repository's `dae/` folder), else
//! under `../shared/scenes/cs184` when it exists
//! ([`pathtracer::scene::course_files`]). A test that needs a file that is
//! not there says so on the test run's output, with how to enable it, and
//! returns (it cannot check what it does not have); under CI (`CI=true`)
//! it fails instead.
//!
//! Also the CBbunny scene and the course's reference render of it, as the
//! tests that compare against the course need them.

use std::io::Write;
use std::path::PathBuf;

use image::DynamicImage;
use pathtracer::bvh::BvhAccel;
use pathtracer::intersect::Primitives;
use pathtracer::raygen::Camera;
use pathtracer::scene::{course_files, Scene};

/// Says on the test run's output (not the captured output, which `cargo
/// test` hides for a passing test) that the running test skipped because
/// `what` was not found, and how to enable it. Under CI (`CI=true`) a
/// missing course file fails the test instead: the checks against the
/// course's scenes and render must not pass there by skipping.
pub fn skipped(what: &str) {
    let ci = std::env::var("CI").is_ok_and(|v| v == "true" || v == "1");
    assert!(
        !ci,
        "{what} not found ({}) under CI, where the course's scenes must be: {}",
        course_files::searched(),
        course_files::HOW_TO_ENABLE
    );
    let thread = std::thread::current();
    let test = thread
        .name()
        .filter(|n| *n != "main")
        .map_or(String::new(), |n| format!("{n}: "));
    // Straight to the process's stderr: libtest captures only `eprintln!`.
    let _ = writeln!(
        std::io::stderr(),
        "{test}skipped: {what} not found ({}); {}",
        course_files::searched(),
        course_files::HOW_TO_ENABLE
    );
}

/// The course file `name` (for example `CBbunny.dae`), or `None` after
/// saying that the test skipped.
pub fn course_file(name: &str) -> Option<PathBuf> {
    let found = course_files::find(name);
    if found.is_none() {
        skipped(name);
    }
    found
}

/// The course scene `name`, loaded (a load error fails the test), or
/// `None` after saying that the test skipped.
pub fn course_scene(name: &str) -> Option<Scene> {
    let path = course_file(name)?;
    Some(pathtracer::scene::load(&path).unwrap_or_else(|e| panic!("{e}")))
}

/// Every course `.dae` file found, sorted by name, or `None` after saying
/// that the test skipped.
pub fn course_scenes() -> Option<Vec<PathBuf>> {
    let scenes = course_files::all_scenes();
    if scenes.is_empty() {
        skipped("no course scene (.dae)");
        return None;
    }
    Some(scenes)
}

/// The course's 480 x 360 render of CBbunny: `CBbunny_reference_480x360.png`
/// under the scene folders, else the starter's `docs/images/example_image.png`
/// beside its `dae/` folder.
fn cbbunny_reference_image() -> Option<PathBuf> {
    course_files::find("CBbunny_reference_480x360.png").or_else(|| {
        course_files::roots().into_iter().find_map(|root| {
            let beside = root.parent()?.join("docs/images/example_image.png");
            beside.is_file().then_some(beside)
        })
    })
}

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

/// `None` (saying that the test skipped) when the scene or the render is
/// not found.
pub fn cbbunny_reference() -> Option<CbbunnyReference> {
    let Some(path) = cbbunny_reference_image() else {
        skipped("the course's CBbunny render (CBbunny_reference_480x360.png, or docs/images/example_image.png beside dae/)");
        return None;
    };
    let scene = course_scene("CBbunny.dae")?;
    let reference = image::open(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let (width, height) = (reference.width(), reference.height());
    assert_eq!((width, height), (480, 360), "{}", path.display());
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
