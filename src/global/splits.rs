//! Glass splits: the paths a glass vertex sends on both of its lobes,
//! and the stack where the reflected ones wait.
//!
//! At a glass vertex the path chooses reflection with
//! probability `F` and refraction with `1 - F`, the course's coin. Along
//! the camera's chain of delta bounces (every vertex so far a mirror,
//! glass or refraction-only surface), at its first
//! [`super::PathTracer::glass_splits`] glass vertices that both reflect and
//! refract (total internal reflection does not count), it follows both
//! instead: the reflection as a path of its own with
//! throughput `beta R F`, the refraction on with `beta T (1 - F) / eta^2`.
//! The sum of the two is the coin's expectation, so the image's does not
//! change; what goes is the coin's variance, which is large where the
//! lobe the coin rarely takes sees something bright: the sun in a glint,
//! or through the glass after a reflection inside it. Each split costs a
//! path, so the number is small (two: up to four branches).
//!
//! ```text
//! coin:   L = R L_r  with probability F,  (T / eta^2) L_t  with probability 1 - F
//! split:  L = R F L_r  +  T (1 - F) / eta^2 L_t
//! ```
//!
//! Splitting is Russian roulette's counterpart (Arvo and Kirk 1990,
//! "Particle Transport and Image Synthesis"); following both rays at
//! every surface is Whitted's ray tracer (1980).

use super::{PathWeight, PrevVertex};
use crate::intersect::Ray;

/// The glass splits the render plan asks for where glass is seen
/// ([`super::PathTracer::glass_splits`]): up to four branches a camera ray.
pub const GLASS_SPLITS: u32 = 2;

/// The most glass splits a path makes (`--glass-splits` up to this): up
/// to `2^8` branches a camera ray.
pub const MAX_GLASS_SPLITS: u32 = 8;

/// A path between vertices: the ray it follows and what it carries.
#[derive(Clone, Copy, Debug)]
pub(super) struct PathState {
    pub ray: Ray,
    pub path: PathWeight,
    pub prev: PrevVertex,
    /// Vertices so far: the light the next ray finds has this many bounces.
    pub bounces: u32,
    /// Glass vertices left at which the path follows both lobes.
    pub splits: u32,
}

/// Paths waiting to be traced: the reflected branches of split glass
/// vertices, last in first out. At most [`MAX_GLASS_SPLITS`] wait at
/// once: a path with a budget of `n` splits pushes at most `n` branches,
/// each with a smaller budget than the last, and a branch popped from
/// place `k` (below it `k` others) has a budget of at most `n - 1 - k`. A
/// fixed array, so a path that splits allocates nothing.
#[derive(Default)]
pub(super) struct Branches {
    waiting: [Option<PathState>; MAX_GLASS_SPLITS as usize],
    len: usize,
}

impl Branches {
    pub fn push(&mut self, state: PathState) {
        self.waiting[self.len] = Some(state);
        self.len += 1;
    }

    pub fn pop(&mut self) -> Option<PathState> {
        self.len = self.len.checked_sub(1)?;
        self.waiting[self.len].take()
    }
}

/// What a path does past a vertex.
pub(super) enum Step {
    On(PathState),
    End,
    /// A non-finite throughput: the sample is rejected.
    Invalid,
}
