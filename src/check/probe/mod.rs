//! `check --source DIR`: each function a student writes, probed in their
//! own C++.
//!
//! A driver of this project's (`driver.cpp`, a command interpreter that
//! constructs the course's objects and calls the student's functions; it
//! holds none of the assignment's solutions) is compiled with the
//! student's sources through their own CMake ([`build`]), then fed
//! scripts of inputs ([`driver`], protocol in `PROTOCOL.md`). Each probe
//! compares the answers with exact ones computed here and concludes
//! ([`verdict`]) pass, not written yet (the starter's stub behaviour),
//! fail (the first failing input, what was expected, what came back, and
//! the catalogued mistake it is), or broken (a crash or a hang, at the
//! command that caused it).
//!
//! - [`camera`] tests `Camera::generate_ray`;
//! - [`triangle`], [`sphere`]: the primitives' `intersect`,
//!   `has_intersection` and `Sphere::test`;
//! - [`bbox`] tests `BBox::intersect`;
//! - [`bvh_tree`]: `BVHAccel::construct_bvh` by its tree; [`bvh`](mod@bvh):
//!   `intersect` and `has_intersection` against a scan of every triangle,
//!   then on the course's bunny, their work per ray ([`bvh_race`]);
//! - [`diffuse`]: `DiffuseBSDF::f` and `sample_f`, its directions by
//!   [`warp`]'s chi-square test against the pdfs it returns;
//! - [`direct`]: the two direct-lighting estimators, their means under
//!   an area light against the light reflected; [`bounces`]:
//!   `at_least_one_bounce_radiance` in a furnace; [`pixel`]:
//!   `raytrace_pixel` in a black one;
//! - [`reflection`]: `BSDF::reflect` and `BSDF::refract`; [`specular`]:
//!   `MirrorBSDF::sample_f` and `RefractionBSDF::sample_f`; [`glass`]:
//!   `GlassBSDF::sample_f`, its choice of lobe by a binomial test;
//! - [`microfacet`]: `MicrofacetBSDF::D` and `f`; [`conductor`]: its `F`;
//!   [`microfacet_sample`]: its `sample_f`, the directions by
//!   [`density`]'s chi-square test (cells integrated numerically);
//! - [`environment`]: `EnvironmentLight::sample_dir`, [`env_init`]: the
//!   tables its `init` fills, [`env_sample`]: its `sample_L`, all on
//!   [`envmap`]'s map;
//! - [`lens`](mod@lens): `Camera::generate_ray_for_thin_lens`.

pub mod bbox;
pub mod bounces;
pub mod build;
pub mod bvh;
pub mod bvh_race;
pub mod bvh_tree;
pub mod camera;
pub mod conductor;
pub mod density;
pub mod diffuse;
pub mod direct;
pub mod driver;
pub mod env_init;
pub mod env_sample;
pub mod environment;
pub mod envmap;
pub mod geometry;
pub mod glass;
pub mod lens;
pub mod means;
pub mod microfacet;
pub mod microfacet_sample;
pub mod picture;
pub mod pixel;
pub mod reflection;
pub mod report;
pub mod specular;
pub mod sphere;
pub mod triangle;
pub mod verdict;
pub mod warp;

use std::path::Path;
use std::time::Duration;

pub use driver::Driver;
pub use verdict::Verdict;

/// One probe: the function it tests and how.
#[derive(Debug)]
pub struct Probe {
    /// The function, as the starter names it.
    pub function: &'static str,
    /// Its file in the starter.
    pub file: &'static str,
    pub part: u8,
    /// The functions it calls: when one of them fails, so may this.
    pub needs: &'static [&'static str],
    pub run: fn(&Driver) -> Verdict,
}

/// Every probe, in the order of the assignment.
pub const PROBES: &[Probe] = &[
    Probe {
        function: "Camera::generate_ray",
        file: "src/pathtracer/camera.cpp",
        part: 1,
        needs: &[],
        run: camera::generate_ray,
    },
    Probe {
        function: "Triangle::has_intersection",
        file: "src/scene/triangle.cpp",
        part: 1,
        needs: &[],
        run: triangle::has_intersection,
    },
    Probe {
        function: "Triangle::intersect",
        file: "src/scene/triangle.cpp",
        part: 1,
        needs: &[],
        run: triangle::intersect,
    },
    Probe {
        function: "Sphere::test",
        file: "src/scene/sphere.cpp",
        part: 1,
        needs: &[],
        run: sphere::test,
    },
    Probe {
        function: "Sphere::has_intersection",
        file: "src/scene/sphere.cpp",
        part: 1,
        needs: &["Sphere::test"],
        run: sphere::has_intersection,
    },
    Probe {
        function: "Sphere::intersect",
        file: "src/scene/sphere.cpp",
        part: 1,
        needs: &["Sphere::test"],
        run: sphere::intersect,
    },
    Probe {
        function: "BBox::intersect",
        file: "src/scene/bbox.cpp",
        part: 2,
        needs: &[],
        run: bbox::intersect,
    },
    Probe {
        function: "BVHAccel::construct_bvh",
        file: "src/scene/bvh.cpp",
        part: 2,
        needs: &[],
        run: bvh_tree::construct,
    },
    Probe {
        function: "BVHAccel::has_intersection",
        file: "src/scene/bvh.cpp",
        part: 2,
        needs: &[
            "Triangle::has_intersection",
            "BBox::intersect",
            "BVHAccel::construct_bvh",
        ],
        run: bvh::has_intersection,
    },
    Probe {
        function: "BVHAccel::intersect",
        file: "src/scene/bvh.cpp",
        part: 2,
        needs: &[
            "Triangle::intersect",
            "BBox::intersect",
            "BVHAccel::construct_bvh",
        ],
        run: bvh::intersect,
    },
    Probe {
        function: "DiffuseBSDF::f",
        file: "src/pathtracer/bsdf.cpp",
        part: 3,
        needs: &[],
        run: diffuse::f,
    },
    Probe {
        function: "DiffuseBSDF::sample_f",
        file: "src/pathtracer/bsdf.cpp",
        part: 3,
        needs: &["DiffuseBSDF::f"],
        run: diffuse::sample_f,
    },
    Probe {
        function: "PathTracer::estimate_direct_lighting_hemisphere",
        file: "src/pathtracer/pathtracer.cpp",
        part: 3,
        needs: &["BVHAccel::intersect", "DiffuseBSDF::f"],
        run: direct::hemisphere,
    },
    Probe {
        function: "PathTracer::estimate_direct_lighting_importance",
        file: "src/pathtracer/pathtracer.cpp",
        part: 3,
        needs: &[
            "BVHAccel::intersect",
            "BVHAccel::has_intersection",
            "DiffuseBSDF::f",
        ],
        run: direct::importance,
    },
    Probe {
        function: "PathTracer::at_least_one_bounce_radiance",
        file: "src/pathtracer/pathtracer.cpp",
        part: 4,
        needs: &[
            "BVHAccel::intersect",
            "DiffuseBSDF::sample_f",
            "PathTracer::estimate_direct_lighting_hemisphere",
        ],
        run: bounces::at_least_one_bounce,
    },
    Probe {
        function: "PathTracer::raytrace_pixel",
        file: "src/pathtracer/pathtracer.cpp",
        part: 5,
        needs: &[
            "Camera::generate_ray",
            "BVHAccel::intersect",
            "PathTracer::estimate_direct_lighting_hemisphere",
            "PathTracer::at_least_one_bounce_radiance",
        ],
        run: pixel::raytrace_pixel,
    },
    Probe {
        function: "BSDF::reflect",
        file: "src/pathtracer/advanced_bsdf.cpp",
        part: 6,
        needs: &[],
        run: reflection::reflect_probe,
    },
    Probe {
        function: "BSDF::refract",
        file: "src/pathtracer/advanced_bsdf.cpp",
        part: 6,
        needs: &[],
        run: reflection::refract_probe,
    },
    Probe {
        function: "MirrorBSDF::sample_f",
        file: "src/pathtracer/advanced_bsdf.cpp",
        part: 6,
        needs: &["BSDF::reflect"],
        run: specular::mirror,
    },
    Probe {
        function: "RefractionBSDF::sample_f",
        file: "src/pathtracer/advanced_bsdf.cpp",
        part: 6,
        needs: &["BSDF::refract"],
        run: specular::refraction,
    },
    Probe {
        function: "GlassBSDF::sample_f",
        file: "src/pathtracer/advanced_bsdf.cpp",
        part: 6,
        needs: &["BSDF::refract", "BSDF::reflect"],
        run: glass::sample_f,
    },
    Probe {
        function: "MicrofacetBSDF::D",
        file: "src/pathtracer/advanced_bsdf.cpp",
        part: 6,
        needs: &[],
        run: microfacet::d,
    },
    Probe {
        function: "MicrofacetBSDF::F",
        file: "src/pathtracer/advanced_bsdf.cpp",
        part: 6,
        needs: &[],
        run: conductor::f_fresnel,
    },
    Probe {
        function: "MicrofacetBSDF::f",
        file: "src/pathtracer/advanced_bsdf.cpp",
        part: 6,
        needs: &["MicrofacetBSDF::F", "MicrofacetBSDF::D"],
        run: microfacet::f,
    },
    Probe {
        function: "MicrofacetBSDF::sample_f",
        file: "src/pathtracer/advanced_bsdf.cpp",
        part: 6,
        needs: &["MicrofacetBSDF::f", "MicrofacetBSDF::D"],
        run: microfacet_sample::sample_f,
    },
    Probe {
        function: "EnvironmentLight::sample_dir",
        file: "src/scene/environment_light.cpp",
        part: 7,
        needs: &[],
        run: environment::sample_dir,
    },
    Probe {
        function: "EnvironmentLight::init",
        file: "src/scene/environment_light.cpp",
        part: 7,
        needs: &[],
        run: env_init::init,
    },
    Probe {
        function: "EnvironmentLight::sample_L",
        file: "src/scene/environment_light.cpp",
        part: 7,
        needs: &["EnvironmentLight::init"],
        run: env_sample::sample_l,
    },
    Probe {
        function: "Camera::generate_ray_for_thin_lens",
        file: "src/pathtracer/camera_lens.cpp",
        part: 8,
        needs: &[],
        run: lens::thin_lens,
    },
];

/// A probe and its verdict.
#[derive(Debug)]
pub struct ProbeResult {
    pub probe: &'static Probe,
    pub verdict: Verdict,
    /// A function it needs that did not pass, if any.
    pub blocked_by: Option<&'static str>,
}

/// Builds the driver against the tree at `source` (in `out/probe`) and
/// runs the probes of `parts` (all when empty), the course's scenes looked
/// for in `scenes`, the tree's `dae/`, then where `CS184_SCENES` says. An
/// error only when the driver cannot be built: the step, the compiler's
/// first error and its file.
pub fn run(
    source: &Path,
    scenes: Option<&Path>,
    out: &Path,
    parts: &[u8],
    jobs: u16,
) -> Result<Vec<ProbeResult>, String> {
    let binary = build::build_driver(source, out, jobs)?;
    let scenes = scenes
        .map(Path::to_path_buf)
        .into_iter()
        .chain([source.join("dae")])
        .filter(|d| d.is_dir())
        .chain(crate::scene::course_files::roots())
        .collect();
    let driver = Driver {
        binary,
        work: std::path::absolute(out.join("probe").join("runs")).map_err(|e| e.to_string())?,
        timeout: Duration::from_secs(60),
        scenes,
    };
    // Pictures of an earlier run must not stand for this one's.
    if let Ok(old) = std::fs::read_dir(&driver.work) {
        for file in old
            .flatten()
            .filter(|f| f.path().extension().is_some_and(|e| e == "png"))
        {
            let _ = std::fs::remove_file(file.path());
        }
    }
    let mut results: Vec<ProbeResult> = Vec::new();
    for probe in PROBES
        .iter()
        .filter(|p| parts.is_empty() || parts.contains(&p.part))
    {
        let verdict = (probe.run)(&driver);
        let blocked_by = probe.needs.iter().copied().find(|need| {
            results
                .iter()
                .any(|r| r.probe.function == *need && !r.verdict.is_pass())
        });
        // A failure that may be the needed function's names no mistake
        // of its own: the one to fix is the other.
        let verdict = match verdict {
            Verdict::Fail(mut f) if blocked_by.is_some() => {
                f.mistake = None;
                Verdict::Fail(f)
            }
            v => v,
        };
        results.push(ProbeResult {
            probe,
            verdict,
            blocked_by,
        });
    }
    Ok(results)
}

/// The summary table: part, function, verdict, the likely mistake.
pub fn table(results: &[ProbeResult]) -> String {
    let mut text = format!(
        "{:<4} {:<48} {:<8} {}\n",
        "part", "function", "verdict", "likely mistake"
    );
    for r in results {
        let mistake = match &r.verdict {
            Verdict::Fail(f) => f.mistake.map_or("-".to_owned(), |m| m.to_string()),
            _ => "-".to_owned(),
        };
        text.push_str(&format!(
            "{:<4} {:<48} {:<8} {}\n",
            r.probe.part,
            r.probe.function,
            r.verdict.word(),
            mistake
        ));
    }
    text
}

/// The details under the table: each probe that did not pass, with its
/// input, the expected and the actual answer.
pub fn details(results: &[ProbeResult]) -> String {
    let mut text = String::new();
    for r in results.iter().filter(|r| !r.verdict.is_pass()) {
        text.push_str(&format!(
            "\n{} ({}): {}\n",
            r.probe.function, r.probe.file, r.verdict
        ));
        if let Some(need) = r.blocked_by {
            text.push_str(&format!(
                "    it calls {need}, which does not pass: fix that first\n"
            ));
        }
    }
    text
}

/// Whether every probe passed.
pub fn all_pass(results: &[ProbeResult]) -> bool {
    results.iter().all(|r| r.verdict.is_pass())
}
