//! # pathtracer: the CS184 PathTracer, step by step
//!
//! A test-driven Rust reference for the UC Berkeley CS184 PathTracer
//! assignment (parts 3-1 and 3-2). Each module mirrors a part:
//!
//! | part | module | binary | doc |
//! | --- | --- | --- | --- |
//! | 1 ray generation | [`raygen`] (pinhole camera) | `part1-raygen` | `docs/01-raygen.md` |
//! | 1 intersection | [`intersect`] (ray, hit, triangle, sphere) | `part1-raygen` | `docs/02-intersect.md` |
//! | 2 BVH | [`bvh`] (build, traverse, validate; `bvh::wide`, the fast one) | `part2-bvh` | `docs/03-bvh.md` |
//! | 3 direct lighting | [`direct`] (hemisphere, light sampling) | `part3-direct` | `docs/04-direct.md` |
//! | 4 global illumination | [`global`] (path tracing, Russian roulette) | `part4-global` | `docs/05-global.md` |
//! | 5 adaptive sampling | [`adaptive`] | `part5-adaptive` | `docs/06-adaptive.md` |
//! | 3-2 mirror, glass, microfacet | [`materials`] (BSDFs, Fresnel, Beckmann) | `part6-materials` | `docs/07-materials.md` |
//! | 3-2 environment light | [`environment`] (lat-long map, its sampling), [`math::distribution`] | `part7-environment` | `docs/08-environment.md` |
//! | 3-2 depth of field | [`depth_of_field`] (thin lens) | `part8-dof` | `docs/09-depth-of-field.md` |
//!
//! Support modules: [`math`] (colours, frames, warps, MIS weights,
//! piecewise-constant distributions, floating-point helpers), [`lights`] (the light set every part samples:
//! one interface for every kind of light, built once per render),
//! [`world`] (the scene as the renderer sees it: intersector, shading
//! points, which light a surface belongs to, how a path continues from a
//! surface, with caustic casters), [`sampling`] (the sampler
//! interface: independent and Owen-scrambled Sobol' numbers), [`plan`] (which effects a
//! scene calls for, and the integrator specialised to them), [`scene`] (scene model, the
//! COLLADA loader, built-in scenes), [`render`] (film, tiles, threads,
//! progress, PNG/EXR output), [`cli`] (the course's flags and what each
//! binary does), [`course`] (the image a correct course solution renders:
//! `--course-exact`), [`mistakes`] (a catalogue of students' mistakes,
//! each renderable: `--mistake NAME`).
//!
//! Conventions are in `docs/00-conventions.md`.

pub mod adaptive;
pub mod bvh;
pub mod check;
pub mod cli;
pub mod course;
pub mod depth_of_field;
pub mod direct;
pub mod environment;
pub mod glints;
pub mod global;
pub mod intersect;
pub mod lights;
pub mod materials;
pub mod math;
pub mod mistakes;
pub mod plan;
pub mod raygen;
pub mod render;
pub mod sampling;
pub mod scene;
pub mod world;
