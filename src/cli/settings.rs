//! What the course's flags ask for, in the library's terms: the defaults
//! that apply, the image size, the render settings, the world's options,
//! the sampler and roulette, the lens, adaptive sampling.

use std::path::{Path, PathBuf};

use super::args::*;
use crate::adaptive::Adaptive;
use crate::course::pixel::StopRule;
use crate::course::{Assignment, Choices, CourseExact};
use crate::depth_of_field::ThinLens;
use crate::global::Roulette;
use crate::lights::LightConvention;
use crate::materials::{BsdfOptions, FresnelModel};
use crate::mistakes::{Mistake, Mistakes};
use crate::render::RenderSettings;
use crate::sampling::SamplerKind;
use crate::scene::{Scene, SceneError};
use crate::world::{CasterRule, WorldOptions};

impl CourseArgs {
    /// The defaults that apply: the course's ([`COURSE_DEFAULTS`]) when a
    /// scene file is given, else the built-in render's ([`BUILTIN_DEFAULTS`]).
    pub fn defaults(&self) -> Defaults {
        if self.scene.is_some() {
            COURSE_DEFAULTS
        } else {
            BUILTIN_DEFAULTS
        }
    }

    /// Camera rays per pixel: `-s`, else [`CourseArgs::defaults`].
    pub fn samples(&self) -> u32 {
        self.samples.unwrap_or(self.defaults().samples)
    }

    /// Light samples a vertex where the plan does not choose them (the
    /// course's modes, `-H`): `-l`, else 1.
    pub fn light_samples(&self) -> u32 {
        self.light_samples.unwrap_or(1)
    }

    /// Maximum ray depth: `-m`, else [`CourseArgs::defaults`].
    pub fn max_depth(&self) -> u32 {
        self.max_depth.unwrap_or(self.defaults().max_depth)
    }

    /// Output width in pixels: `-r`, else [`CourseArgs::defaults`].
    pub fn width(&self) -> u32 {
        self.resolution
            .as_ref()
            .map_or(self.defaults().resolution[0], |r| r[0])
    }

    /// Output height in pixels: `-r`, else [`CourseArgs::defaults`].
    pub fn height(&self) -> u32 {
        self.resolution
            .as_ref()
            .map_or(self.defaults().resolution[1], |r| r[1])
    }

    /// The scene file's contents, or the built-in scene.
    pub fn load_scene(&self) -> Result<Scene, SceneError> {
        match &self.scene {
            Some(path) => crate::scene::load(path),
            None => Ok(self.builtin.scene()),
        }
    }

    /// Where the image goes: `-f`, else `<scene name>.png`.
    pub fn output_path(&self) -> PathBuf {
        self.output.clone().unwrap_or_else(|| {
            let stem = self
                .scene
                .as_deref()
                .and_then(Path::file_stem)
                .map_or(self.builtin.name().into(), |s| {
                    s.to_string_lossy().into_owned()
                });
            PathBuf::from(format!("{stem}.png"))
        })
    }

    /// `-a BATCH TOL` checked: a whole batch size of at least 1 and a
    /// positive tolerance.
    pub fn adaptive_settings(&self) -> Result<Option<Adaptive>, String> {
        let Some(values) = &self.adaptive else {
            return Ok(None);
        };
        let (batch, tolerance) = (values[0], values[1]);
        if !(batch >= 1.0 && batch.fract() == 0.0 && batch <= 1e6) {
            return Err(format!(
                "-a: the batch size must be a whole number from 1, not {batch}"
            ));
        }
        if !(tolerance > 0.0 && tolerance.is_finite()) {
            return Err(format!(
                "-a: the tolerance must be positive, not {tolerance}"
            ));
        }
        Ok(Some(Adaptive {
            batch: batch as u32,
            tolerance,
        }))
    }

    /// The thin lens of `-b` and `-d`.
    pub fn lens(&self) -> ThinLens {
        ThinLens {
            radius: self.lens_radius,
            focal_distance: self.focal_distance,
        }
    }

    /// How the scene's lights and BSDFs behave under these flags.
    pub fn world_options(&self) -> WorldOptions {
        WorldOptions {
            light_convention: if self.course_lights {
                LightConvention::Course
            } else {
                LightConvention::Physical
            },
            bsdf: BsdfOptions {
                fresnel: if self.schlick {
                    FresnelModel::Schlick
                } else {
                    FresnelModel::Exact
                },
                microfacet: self.microfacet_sampling.into(),
                ..BsdfOptions::default()
            },
            light_choice: self.light_choice.into(),
            casters: if self.course {
                CasterRule::Off
            } else {
                self.casters.into()
            },
        }
    }

    /// The course's image settings when `--course-exact` is given: its
    /// assignment, else `default` (the binary's).
    /// `--mistake` or `--course-choice` alone implies it, with the binary's assignment.
    pub fn course_exact(&self, default: Assignment) -> Option<CourseExact> {
        let assignment = match self.course_exact {
            Some(named) => named.map_or(default, Assignment::from),
            None if !self.mistakes.is_empty() || !self.course_choices.is_empty() => default,
            None => return None,
        };
        Some(CourseExact { assignment })
    }

    /// The mistakes `--mistake` names, or an error naming the unknown one
    /// and listing the known ones.
    pub fn mistake_set(&self) -> Result<Mistakes, String> {
        self.mistakes.iter().try_fold(Mistakes::NONE, |set, name| {
            Mistake::from_name(name).map(|m| set.with(m)).ok_or_else(|| {
                let known: Vec<&str> = Mistake::ALL.iter().map(|m| m.info().name).collect();
                format!(
                    "--mistake {name}: no such mistake; the catalogue has {} (--mistake list explains each)",
                    known.join(", ")
                )
            })
        })
    }

    /// The choices of the solution `--course-exact` renders: `assignment`'s
    /// ([`Choices::of`]) with each `--course-choice` applied, or an error
    /// naming the one that is wrong.
    pub fn course_choices(&self, assignment: Assignment) -> Result<Choices, String> {
        self.course_choices
            .iter()
            .try_fold(Choices::of(assignment), |choices, given| {
                let wrong = |why: &str| format!("--course-choice {given}: {why}");
                let (key, value) = given
                    .split_once('=')
                    .ok_or_else(|| wrong("not KEY=VALUE"))?;
                match key {
                    "roulette-q" => match value.parse::<f32>() {
                        Ok(q) if q > 0.0 && q <= 1.0 => Ok(Choices {
                            continue_probability: q,
                            ..choices
                        }),
                        _ => Err(wrong("the probability must be a number in (0, 1]")),
                    },
                    "roulette-from" => match value.parse::<u32>() {
                        Ok(from @ 1..=2) => Ok(Choices {
                            roulette_from: from,
                            ..choices
                        }),
                        _ => Err(wrong("the vertex must be 1 or 2")),
                    },
                    "stop" => match value {
                        "handout" => Ok(Choices {
                            stop_rule: StopRule::EveryBatch,
                            ..choices
                        }),
                        "staff" => Ok(Choices {
                            stop_rule: StopRule::StaffOneLate,
                            ..choices
                        }),
                        _ => Err(wrong("the stop rule must be handout or staff")),
                    },
                    _ => Err(wrong("the keys are roulette-q, roulette-from and stop")),
                }
            })
    }

    /// Whether the flags ask for the catalogue (`--mistake list`).
    pub fn lists_mistakes(&self) -> bool {
        self.mistakes.iter().any(|m| m == "list")
    }

    /// The sampler: `--sampler`, independent with `--course`.
    pub fn sampler_kind(&self) -> SamplerKind {
        if self.course {
            SamplerKind::Independent
        } else {
            self.sampler.into()
        }
    }

    /// The Russian roulette rule: `--roulette`, fixed with `--course`.
    pub fn roulette(&self) -> Roulette {
        if self.course {
            Roulette::Fixed
        } else {
            self.roulette.into()
        }
    }

    /// The glass splits the flags ask for: `--glass-splits`, 0 with
    /// `--course`, or `None` for the render plan's.
    pub fn glass_splits(&self) -> Option<u32> {
        if self.course {
            Some(0)
        } else {
            self.glass_splits
        }
    }

    /// Whether the flags allow glint samples ([`crate::glints`]): not with
    /// `--glints off` or `--course`.
    pub fn glints(&self) -> bool {
        !self.course && self.glints == GlintsArg::Auto
    }

    /// The render settings these flags ask for (progress bar on).
    pub fn render_settings(&self) -> RenderSettings {
        RenderSettings {
            width: self.width(),
            height: self.height(),
            samples_per_pixel: self.samples(),
            threads: self.threads.map(usize::from),
            seed: self.seed,
            sampler: self.sampler_kind(),
            progress: true,
        }
    }
}
