//! Where and how the gallery shows each mistake: the built-in scene
//! ([`Stage`]), the course's flags ([`Showing`]), and the command that
//! renders it with a binary.

use pathtracer::bvh::WideBvhAccel;
use pathtracer::depth_of_field::ThinLens;
use pathtracer::environment::{builtin_sky, EnvironmentLight, EnvironmentSampling};
use pathtracer::intersect::Primitives;
use pathtracer::mistakes::Mistake;
use pathtracer::raygen::Camera;
use pathtracer::scene::{builtin, Light, Material, Scene};
use std::fmt::Write as _;

use super::Result;

/// Where [`Stage::TurnedCamera`] looks from: the box's upper left front.
const TURNED_CAMERA: glam::Vec3 = glam::Vec3::new(-0.5, 0.4, 1.0);

/// The built-in scene a mistake is shown on.
#[derive(Clone, Copy)]
pub enum Stage {
    /// The Cornell box (`part3-direct`, `part4-global` with no scene).
    CornellBox,
    /// The Cornell box with its lamp hung 0.3 lower (made in code).
    LoweredLamp,
    /// The materials box (`part6-materials`).
    MaterialsBox,
    /// Two balls on a floor under the built-in sky (`part7-environment`).
    Sky,
    /// The Cornell box seen from the upper left (the camera turned, in code).
    TurnedCamera,
    /// The Cornell box with balls of triangles, smooth normals (made in code).
    MeshBalls,
    /// The Cornell box with balls of rough copper, Beckmann alpha 0.15
    /// and 0.4 (part 6's check, [`pathtracer::check::scenes::microfacet_box`]).
    CopperBalls,
}

/// How a mistake is shown: where, and with which of the course's flags.
pub struct Showing {
    pub stage: Stage,
    pub hemisphere: bool,
    pub light_samples: u32,
    pub max_depth: u32,
    pub accumulate: bool,
    pub spp: u32,
    /// `-b` and `-d`.
    pub lens: Option<ThinLens>,
    /// `-a 32 0.05`, and the rate images shown.
    pub adaptive: bool,
}

pub fn showing(m: Mistake) -> Showing {
    use Mistake::*;
    let direct = |stage| Showing {
        stage,
        hemisphere: false,
        light_samples: 1,
        max_depth: 1,
        accumulate: true,
        spp: 64,
        lens: None,
        adaptive: false,
    };
    let paths = |stage, max_depth| Showing {
        max_depth,
        ..direct(stage)
    };
    match m {
        NoPdf | HemispherePdfOneOverPi => Showing {
            hemisphere: true,
            spp: 256,
            ..direct(Stage::CornellBox)
        },
        LightFromBehind => direct(Stage::LoweredLamp),
        LightSamplesNotAveraged => Showing {
            light_samples: 4,
            ..direct(Stage::CornellBox)
        },
        RayInCameraSpace => direct(Stage::TurnedCamera),
        BarycentricsPermuted | TraversalReturnsFirstHit => direct(Stage::MeshBalls),
        FovFullAngle
        | FovInDegrees
        | TriangleChainedComparison
        | SphereFarRoot
        | BoxMissesRaysFromInside
        | MaxTNotShrunk
        | NoCosine
        | BrdfIsAlbedo
        | ShadowAcne
        | ShadowRayReachesLight
        | DepthOffByOne => direct(Stage::CornellBox),
        AdaptiveNotSquareRooted | AdaptiveCountNotUpdated | AdaptivePopulationVariance => Showing {
            spp: 128,
            adaptive: true,
            ..direct(Stage::CornellBox)
        },
        LensRadiusUnscaled => Showing {
            lens: Some(ThinLens {
                radius: 0.02,
                focal_distance: 2.0,
            }),
            spp: 128,
            ..direct(Stage::CornellBox)
        },
        FocusOnASphere => Showing {
            lens: Some(ThinLens {
                radius: 0.3,
                focal_distance: 5.0,
            }),
            spp: 128,
            ..direct(Stage::CornellBox)
        },
        NoAccumulationSumsAll => Showing {
            accumulate: false,
            ..paths(Stage::CornellBox, 3)
        },
        RouletteNotDivided | EmissionEveryBounce | ThroughputWithoutCosPdf => {
            paths(Stage::CornellBox, 5)
        }
        ReflectWrongAxis
        | RefractionRatioInverted
        | NoEtaSquared
        | NoTotalInternalReflection
        | SchlickR0NotSquared => Showing {
            spp: 128,
            ..paths(Stage::MaterialsBox, 5)
        },
        MicrofacetNoFour | MicrofacetDNoCos4 | MicrofacetPdfNoJacobian => Showing {
            spp: 128,
            ..paths(Stage::CopperBalls, 5)
        },
        EnvPdfNoSin | EnvPdfNoJacobian | EnvMapUFlipped | EnvMapVFlipped => paths(Stage::Sky, 5),
    }
}

impl Showing {
    /// The flags that render it with a binary (its built-in scene), and a
    /// note where the figure's scene differs.
    pub fn command(&self, m: Mistake) -> String {
        let binary = match self.stage {
            _ if self.lens.is_some() => "part8-dof",
            _ if self.adaptive => "part5-adaptive",
            Stage::MaterialsBox => "part6-materials",
            Stage::Sky => "part7-environment",
            _ if self.max_depth == 1 => "part3-direct",
            _ => "part4-global",
        };
        let mut flags = format!("-r 480 360 -s {} -l {}", self.spp, self.light_samples);
        if binary != "part3-direct" {
            write!(flags, " -m {}", self.max_depth).unwrap();
        }
        if !self.accumulate {
            flags += " -o 0";
        }
        if self.hemisphere {
            flags += " -H";
        }
        if let Some(lens) = self.lens {
            write!(flags, " -b {} -d {}", lens.radius, lens.focal_distance).unwrap();
        }
        if self.adaptive {
            flags += " -a 32 0.05";
        }
        let lowered = match self.stage {
            Stage::LoweredLamp => " (the figure lowers the lamp by 0.3, in code)",
            Stage::TurnedCamera => " (the figure turns the camera, in code)",
            Stage::MeshBalls => " (the figure's balls are meshes, in code)",
            Stage::CopperBalls => " (the figure's balls are rough copper, in code)",
            _ => "",
        };
        format!(
            "`cargo run --release --bin {binary} -- {flags} --mistake {}`{lowered}",
            m.info().name
        )
    }
}

/// A built-in scene with its camera, BVH and light.
pub struct Staged {
    pub scene: Scene,
    pub camera: Camera,
    pub accel: WideBvhAccel,
    pub environment: Option<EnvironmentLight>,
}

pub fn stage(how: &Showing) -> Result<Staged> {
    let stage = how.stage;
    let mut scene = match stage {
        Stage::CornellBox | Stage::LoweredLamp | Stage::TurnedCamera => builtin::cornell_box(),
        Stage::MeshBalls => builtin::mesh_balls_box(),
        Stage::CopperBalls => pathtracer::check::scenes::microfacet_box(),
        Stage::MaterialsBox => builtin::materials_box(),
        Stage::Sky => builtin::environment_spheres(),
    };
    match stage {
        Stage::LoweredLamp => lower_lamp(&mut scene, 0.3),
        Stage::TurnedCamera => scene.camera.dir_to_camera = TURNED_CAMERA.normalize(),
        _ => {}
    }
    let environment = match stage {
        Stage::Sky => Some(EnvironmentLight::new(
            builtin_sky()?,
            EnvironmentSampling::Importance,
        )),
        _ => None,
    };
    let primitives = Primitives::from_scene(&scene);
    let camera = Camera::course_placement(&scene.camera, &primitives.bounds(), 480, 360);
    let camera = match how.lens {
        Some(lens) => camera.with_lens(lens),
        None => camera,
    };
    Ok(Staged {
        accel: WideBvhAccel::new(primitives),
        scene,
        camera,
        environment,
    })
}

/// Moves the area lights and the emissive triangles down by `drop`.
fn lower_lamp(scene: &mut Scene, drop: f32) {
    for light in &mut scene.lights {
        if let Light::Area { center, .. } = light {
            center.y -= drop;
        }
    }
    let mut moved = vec![false; scene.mesh.positions.len()];
    for (t, &m) in scene.mesh.triangles.iter().zip(&scene.mesh.materials) {
        if matches!(scene.materials[m as usize], Material::Emission { .. }) {
            for &v in t {
                if !std::mem::replace(&mut moved[v as usize], true) {
                    scene.mesh.positions[v as usize].y -= drop;
                }
            }
        }
    }
}
