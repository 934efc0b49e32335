//! The render plan: which effects the scene calls for, decided once from
//! the scene, its lights and the flags, so that the integrator simulates
//! only those (`--info` prints it, one `plan:` line per decision).
//!
//! | decision | when | what it saves |
//! | --- | --- | --- |
//! | light sampling | some light can be sampled and some surface scatters non-deltas | nothing: the integrator skips it at delta vertices anyway; the plan reports it |
//! | multiple importance sampling | a light BSDF rays can find (area, emissive triangles, sky) and a non-delta BSDF | the BSDF density per light sample and the last ray of every path |
//! | lens | `-b > 0` | the lens sample and its disk warp per camera ray |
//! | environment samples ([`light_samples`]) | an environment map lights the scene and `-l` is not given | nothing: four samples of the map instead of one at a vertex whose BSDF is no sharper than the map (and not diffuse in a scene that casts caustics), less noise per second |
//! | glass splits | glass (that reflects and refracts) in the scene, and not `--course` | nothing: it costs time, to lower the noise more: at the first [`GLASS_SPLITS`] glass vertices of the camera's chain of delta bounces the path follows both lobes instead of a coin's choice, more paths and less noise where the lobe the coin rarely takes sees a light |
//! | glint samples ([`crate::glints`]) | an environment map, a mirror or glass, a pinhole camera, and not `--glints off` or `--course` | nothing: a pilot of five rays a pixel, then more samples (up to 16 times `-s`) for the pixels whose chains of mirror and glass bounces may see a small bright part of the map, at most half again the render's cost; from `-s 16`, not with `-a` |
//! | caustic casters | a mirror, glass or smooth conductor sphere, or a mirror-like mesh (and not `--casters off`) | nothing: it adds a sampling strategy where a scene has caustics, and costs nothing where it has none |
//!
//! Specialising changes no expectation: the plan only drops work whose
//! result is zero or whose weight is 1 (MIS with no second strategy),
//! splits a light's sample into several whose mean estimates the same,
//! or follows both of glass's lobes, each weighted by the probability the
//! coin would have given it; glint samples change how many samples a pixel
//! takes, by a rule that depends on the scene alone. The
//! plan also says when a flag hides an effect the scene has: a mirror shows
//! lit surfaces only from `-m 2`, glass shows light through it from `-m 3`.

pub mod light_samples;

use crate::depth_of_field::ThinLens;
use crate::direct::DirectLights;
use crate::glints;
use crate::global::{
    DirectStrategy, PathTracer, Roulette, GLASS_SPLITS, THROUGHPUT_ROULETTE_AFTER,
};
use crate::lights::{Light, LightSet};
use crate::materials::{Bsdf, BsdfOptions};
use crate::math::{luminance, Rgb};
use crate::sampling::SamplerKind;
use crate::scene::{Material, Scene};
use crate::world::casters::images::{self, IMAGE_ALPHA};
use crate::world::casters::{Casters, CASTER_PROBABILITY, SMOOTH_ALPHA};

/// The kinds of scattering a scene's used materials have.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BsdfKinds {
    pub diffuse: bool,
    /// Mirror, refraction or glass: every lobe a delta.
    pub delta: bool,
    /// Microfacet: a non-delta lobe that is not diffuse.
    pub glossy: bool,
    pub mirror: bool,
    /// Glass or refraction.
    pub transmission: bool,
    /// Glass that both reflects and refracts (not the refraction-only
    /// material): its lobes are chosen by a coin ([`crate::materials::Glass`]).
    pub glass: bool,
    /// A conductor near a mirror, mirror-like as the caustic casters
    /// count it ([`images::image_spread`]: `alpha` at most [`IMAGE_ALPHA`]).
    pub near_mirror: bool,
}

impl BsdfKinds {
    /// The kinds of the materials some primitive of `scene` uses.
    pub fn of(scene: &Scene) -> Self {
        let mut used = vec![false; scene.materials.len()];
        let ids = scene
            .mesh
            .materials
            .iter()
            .chain(scene.spheres.iter().map(|s| &s.material));
        for &m in ids {
            if let Some(u) = used.get_mut(m as usize) {
                *u = true;
            }
        }
        let mut kinds = BsdfKinds::default();
        for (material, _) in scene.materials.iter().zip(&used).filter(|(_, &u)| u) {
            match Bsdf::new(material, true, BsdfOptions::default()) {
                Bsdf::Black => {}
                Bsdf::Diffuse(d) if d.albedo == Rgb::ZERO => {}
                Bsdf::Diffuse(_) => kinds.diffuse = true,
                Bsdf::Conductor(_) => {
                    kinds.glossy = true;
                    kinds.near_mirror |= images::image_spread(material).is_some();
                }
                bsdf => {
                    kinds.delta |= bsdf.is_delta();
                    kinds.mirror |= matches!(material, Material::Mirror { .. });
                    kinds.transmission |= matches!(
                        material,
                        Material::Glass { .. } | Material::Refraction { .. }
                    );
                    kinds.glass |= matches!(bsdf, Bsdf::Glass(_));
                }
            }
        }
        kinds
    }

    /// Whether some surface scatters light with a non-delta lobe.
    pub fn scatters(&self) -> bool {
        self.diffuse || self.glossy
    }

    /// Whether some surface casts caustics: a delta BSDF (mirror, glass)
    /// or a conductor near a mirror.
    pub fn casts_caustics(&self) -> bool {
        self.delta || self.near_mirror
    }
}

/// What a render simulates, and why.
#[derive(Clone, Debug, PartialEq)]
pub struct Plan {
    pub bsdfs: BsdfKinds,
    /// Names of the kinds of light, in the light set's order, deduplicated.
    pub light_kinds: Vec<&'static str>,
    /// Whether some light is not a delta (so BSDF rays can find light).
    pub area_lights: bool,
    pub light_sampling: bool,
    pub mis: bool,
    pub lens: bool,
    /// [`PathTracer::glass_splits`]: [`GLASS_SPLITS`] where the scene has
    /// glass, else 0.
    pub glass_splits: u32,
    /// Whether pixels that see an environment map along mirror and glass
    /// bounces get more samples where they may see a glint ([`crate::glints`]).
    pub glints: bool,
    /// One line per decision, `plan: ...`.
    pub lines: Vec<String>,
    /// Effects the flags hide, one line each.
    pub warnings: Vec<String>,
}

impl Plan {
    /// The plan for rendering `scene` with `lights` by `tracer` through `lens`.
    pub fn new(scene: &Scene, lights: &LightSet, tracer: &PathTracer, lens: &ThinLens) -> Self {
        let bsdfs = BsdfKinds::of(scene);
        let mut light_kinds: Vec<&'static str> = Vec::new();
        for light in &lights.lights {
            if !light_kinds.contains(&light.kind()) {
                light_kinds.push(light.kind());
            }
        }
        let area_lights = lights.lit().any(|(_, l)| !l.is_delta());
        let light_sampling = matches!(tracer.direct, DirectStrategy::Lights(_))
            && lights.lit().next().is_some()
            && bsdfs.scatters();
        let mis = light_sampling && tracer.direct.mis() && area_lights;
        let mut lines = vec![
            format!(
                "plan: lights: {} ({})",
                if light_kinds.is_empty() {
                    "none".to_string()
                } else {
                    light_kinds.join(", ")
                },
                if area_lights {
                    "some have an area or are at infinity: BSDF rays can find them"
                } else {
                    "delta lights only: only light sampling finds them"
                }
            ),
            format!("plan: materials: {}", bsdf_summary(&bsdfs)),
        ];
        if !lights.lights.is_empty() {
            let powers: Vec<String> = lights
                .lights
                .iter()
                .map(|l| {
                    let watts = luminance(l.power(lights.scene_radius()));
                    format!("{} {watts:.4}", l.kind())
                })
                .collect();
            lines.push(format!(
                "plan: light power (luminance of W, lights at infinity through the scene's bounding sphere): {}",
                powers.join(", ")
            ));
        }
        lines.push(match tracer.direct {
            DirectStrategy::Lights(_) if light_sampling => format!(
                "plan: light sampling: on (lights to sample and surfaces that scatter); lights that emit: {}; samples: {}",
                lights.lit().count(),
                lights.choice().describe()
            ),
            DirectStrategy::Lights(_) => {
                "plan: light sampling: off (no light to sample or no surface that scatters non-delta)"
                    .into()
            }
            DirectStrategy::Hemisphere(_) => "plan: light sampling: off (-H: hemisphere rays)".into(),
            DirectStrategy::BsdfOnly => "plan: light sampling: off (--bsdf-only)".into(),
        });
        lines.push(if mis {
            "plan: MIS: on (lights with an area and surfaces that scatter non-delta)".into()
        } else if tracer.direct.mis() {
            "plan: MIS: off (no second strategy could find the lights: no BSDF density per light sample, no last ray)".into()
        } else {
            "plan: MIS: off (not asked for)".into()
        });
        lines.push(if lens.is_pinhole() {
            "plan: camera: pinhole (-b 0: no lens sample)".into()
        } else {
            format!(
                "plan: camera: thin lens of radius {} focused at {}",
                lens.radius, lens.focal_distance
            )
        });
        lines.push(match tracer.roulette {
            Roulette::Off => "plan: roulette: off (paths go on to -m bounces)".into(),
            Roulette::Fixed => {
                "plan: roulette: fixed (continue with probability 0.65 from the second vertex: the course's)".into()
            }
            Roulette::Throughput => {
                format!("plan: roulette: throughput (continue with probability min(1, max channel of the path's throughput) after {THROUGHPUT_ROULETTE_AFTER} bounces)")
            }
        });
        let glass_splits = if bsdfs.glass { GLASS_SPLITS } else { 0 };
        lines.push(glass_splits_line(glass_splits, bsdfs.glass, "the plan's"));
        let environment = lights
            .infinite()
            .any(|(_, l)| matches!(l, Light::Environment(_)));
        let glints = glints::Decision::new(environment, bsdfs.delta, lens.is_pinhole());
        lines.push(glints.line());
        let mut warnings = Vec::new();
        let m = tracer.max_depth;
        if bsdfs.mirror && m < 2 {
            warnings.push(format!(
                "-m {m}: a mirror shows lit surfaces only from -m 2 on"
            ));
        }
        if bsdfs.transmission && m < 3 {
            warnings.push(format!(
                "-m {m}: glass shows light through it only from -m 3 on"
            ));
        }
        if matches!(tracer.direct, DirectStrategy::Hemisphere(_))
            && lights.lit().any(|(_, l)| l.is_delta())
        {
            warnings.push("-H: hemisphere rays cannot find point or directional lights".into());
        }
        Plan {
            bsdfs,
            light_kinds,
            area_lights,
            light_sampling,
            mis,
            lens: !lens.is_pinhole(),
            glass_splits,
            glints: glints.on(),
            lines,
            warnings,
        }
    }

    /// The plan without glint samples where the flags turn them off, and
    /// why (`off`: [`glints::Decision::off_by_flags`]).
    pub fn with_glints(mut self, off: Option<glints::Decision>) -> Self {
        if let (true, Some(why)) = (self.glints, off) {
            self.glints = false;
            if let Some(old) = self.lines.iter_mut().find(|l| l.starts_with(glints::LINE)) {
                *old = why.line();
            }
        }
        self
    }

    /// The plan with a line saying where the render's numbers come from.
    pub fn with_sampler(mut self, sampler: SamplerKind) -> Self {
        self.lines.push(match sampler {
            SamplerKind::Independent => {
                "plan: sampler: independent (uniform numbers, a PCG32 stream per pixel: the course's)".into()
            }
            SamplerKind::ZSobol => {
                "plan: sampler: zsobol (Owen-scrambled Sobol' points in Morton order over pixels)".into()
            }
        });
        self
    }

    /// The plan with a line saying which spheres diffuse surfaces sample
    /// towards for caustics ([`crate::world::casters`]).
    pub fn with_casters(mut self, casters: &Casters) -> Self {
        let n = casters.spheres.len();
        let spheres = n - casters.meshes;
        self.lines.push(if n == 0 {
            "plan: caustic casters: none (no mirror, glass or smooth conductor sphere, \
             no mirror-like mesh, or --casters off)"
                .into()
        } else if !self.bsdfs.diffuse {
            format!("plan: caustic casters: {n} sphere(s), unused: no surface is diffuse")
        } else {
            let mut kinds = Vec::new();
            if spheres > 0 {
                kinds.push(format!(
                    "{spheres} sphere(s) (mirror, glass, conductor with alpha <= {SMOOTH_ALPHA})"
                ));
            }
            if casters.meshes > 0 {
                kinds.push(format!(
                    "{} sphere(s) around mirror-like meshes (mirror, conductor with alpha <= {IMAGE_ALPHA})",
                    casters.meshes
                ));
            }
            let images = match casters.images() {
                0 => String::new(),
                k => format!(
                    ", and {k} light image(s) in mirror-like spheres (mirror, conductor with alpha <= {IMAGE_ALPHA})"
                ),
            };
            format!(
                "plan: caustic casters: {}{images}: \
                 diffuse surfaces draw {CASTER_PROBABILITY} of their continuations towards them",
                kinds.join(", ")
            )
        });
        self
    }

    /// The plan with the glass splits a flag asks for (`--glass-splits N`,
    /// or 0 for `--course`), where one does.
    pub fn with_glass_splits(mut self, asked: Option<u32>) -> Self {
        if let Some(n) = asked {
            self.glass_splits = n;
            let line = glass_splits_line(n, self.bsdfs.glass, "asked");
            if let Some(old) = self
                .lines
                .iter_mut()
                .find(|l| l.starts_with(GLASS_SPLITS_LINE))
            {
                *old = line;
            }
        }
        self
    }

    /// `tracer` specialised to the plan: MIS off where no second strategy
    /// could find the lights, and the glass splits. The estimate's
    /// expectation does not change.
    pub fn specialise(&self, tracer: &PathTracer) -> PathTracer {
        let mut t = *tracer;
        t.glass_splits = self.glass_splits;
        if let DirectStrategy::Lights(d) = tracer.direct {
            t.direct = DirectStrategy::Lights(DirectLights {
                mis: d.mis && self.mis,
                ..d
            });
        }
        t
    }
}

const GLASS_SPLITS_LINE: &str = "plan: glass splits:";

/// The plan's line for `n` glass splits, decided by `whose` rule.
fn glass_splits_line(n: u32, glass: bool, whose: &str) -> String {
    match (n, glass) {
        (0, false) => format!("{GLASS_SPLITS_LINE} none (no glass)"),
        (0, true) => format!(
            "{GLASS_SPLITS_LINE} none ({whose}): a coin chooses reflection or refraction at every glass vertex (the course's)"
        ),
        (n, _) => format!(
            "{GLASS_SPLITS_LINE} {n} ({whose}): at the first {n} glass vertices of the camera's chain of mirror and glass bounces, paths follow both reflection and refraction"
        ),
    }
}

fn bsdf_summary(k: &BsdfKinds) -> String {
    let mut kinds = Vec::new();
    if k.diffuse {
        kinds.push("diffuse");
    }
    if k.glossy {
        kinds.push("glossy");
    }
    if k.delta {
        kinds.push("delta (mirror, glass)");
    }
    if kinds.is_empty() {
        "nothing scatters".into()
    } else {
        kinds.join(", ")
    }
}
