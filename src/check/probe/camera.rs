//! The probe of `Camera::generate_ray` (part 1): exact rays for known
//! cameras and pixels.
//!
//! The course's camera, after `configure` and `place`, has its position
//! `pos`, the frame `c2w = [x y z]` with `z` pointing from the target to
//! the camera and `y` its `up_dir()`, and fields of view with
//! `tan(hFov / 2) = ar tan(vFov / 2)`. The ray through the film point
//! `(x, y)` in `[0, 1]^2` starts at `pos` with the direction
//! `c2w ((2x - 1) tan(hFov / 2), (2y - 1) tan(vFov / 2), -1)`, normalised,
//! and covers `[nClip, fClip]`.

use glam::DVec3;

use super::driver::{Driver, Transcript};
use super::geometry::{close, same_direction, show, vec_at};
use super::verdict::{failure, Cases, Failure, Verdict};
use crate::mistakes::Mistake;

/// A camera as `configure` and `place` take it (the thin lens's probe,
/// [`lens`](super::lens), places these too).
pub(super) struct Setup {
    pub(super) hfov: f64,
    pub(super) vfov: f64,
    pub(super) size: (u32, u32),
    pub(super) target: DVec3,
    pub(super) phi: f64,
    pub(super) theta: f64,
    pub(super) r: f64,
    pub(super) clip: (f64, f64),
}

impl Setup {
    /// The driver's `camera` command, which configures and places it.
    pub(super) fn command(&self) -> String {
        format!(
            "camera {} {} {} {} {} {} {} {} {} {} {} {}",
            self.hfov,
            self.vfov,
            self.size.0,
            self.size.1,
            self.target.x,
            self.target.y,
            self.target.z,
            self.phi,
            self.theta,
            self.r,
            self.clip.0,
            self.clip.1
        )
    }
}

/// The cameras, simplest first: one looking down -z as the course's
/// boxes do, then two turned and tilted, one wide and one tall.
pub(super) fn setups() -> [Setup; 3] {
    [
        Setup {
            hfov: 50.0,
            vfov: 35.0,
            size: (480, 360),
            target: DVec3::ZERO,
            phi: std::f64::consts::FRAC_PI_2,
            theta: 0.0,
            r: 4.0,
            clip: (0.01, 100.0),
        },
        Setup {
            hfov: 50.0,
            vfov: 35.0,
            size: (480, 360),
            target: DVec3::new(0.5, -0.25, 1.0),
            phi: 1.2,
            theta: 0.7,
            r: 3.0,
            clip: (0.1, 40.0),
        },
        Setup {
            hfov: 30.0,
            vfov: 60.0,
            size: (200, 400),
            target: DVec3::new(1.0, 2.0, -3.0),
            phi: 2.1,
            theta: -1.9,
            r: 7.5,
            clip: (0.5, 50.0),
        },
    ]
}

/// The film points, the centre first, then the corners and a few inside.
const PIXELS: [(f64, f64); 8] = [
    (0.5, 0.5),
    (0.0, 0.0),
    (1.0, 1.0),
    (1.0, 0.0),
    (0.0, 1.0),
    (0.25, 0.75),
    (0.9, 0.3),
    (0.125, 0.625),
];

/// The camera the driver reports after `configure` and `place`.
pub(super) struct Placed {
    pub(super) pos: DVec3,
    pub(super) c2w: [DVec3; 3],
    /// `tan(hFov / 2)`, `tan(vFov / 2)`.
    pub(super) tan_half: (f64, f64),
    pub(super) vfov_deg: f64,
    pub(super) clip: (f64, f64),
}

impl Placed {
    /// The camera command `i` of `t` placed, looking at `target`; or the
    /// verdict when its answer is not the 10 numbers of one.
    pub(super) fn read(t: &Transcript, i: usize, target: DVec3) -> Result<Placed, Verdict> {
        t.exactly(i, 10)
            .map(|v| Placed::from_answer(&v, target))
            .map_err(|stop| Verdict::stopped(&stop, t.command(i)))
    }

    /// From the answer `POS UP VFOV AR NCLIP FCLIP` to a camera placed
    /// looking at `target`.
    fn from_answer(v: &[f64], target: DVec3) -> Placed {
        let pos = vec_at(v, 0);
        let y = vec_at(v, 3);
        let z = (pos - target).normalize();
        let tan_v = (v[6].to_radians() / 2.0).tan();
        Placed {
            pos,
            c2w: [y.cross(z).normalize(), y, z],
            tan_half: (tan_v * v[7], tan_v),
            vfov_deg: v[6],
            clip: (v[8], v[9]),
        }
    }

    /// The camera-space direction through `(x, y)` for sensor half-sizes
    /// `tan_half`.
    pub(super) fn sensor(x: f64, y: f64, tan_half: (f64, f64)) -> DVec3 {
        DVec3::new(
            (2.0 * x - 1.0) * tan_half.0,
            (2.0 * y - 1.0) * tan_half.1,
            -1.0,
        )
    }

    /// The camera-space vector `d` in world space, `c2w d`.
    pub(super) fn rotate(&self, d: DVec3) -> DVec3 {
        self.c2w[0] * d.x + self.c2w[1] * d.y + self.c2w[2] * d.z
    }

    /// The camera-space direction `d` in world space, normalised.
    fn to_world(&self, d: DVec3) -> DVec3 {
        self.rotate(d).normalize()
    }

    /// The camera-space coordinates of the world point `p`.
    pub(super) fn to_camera(&self, p: DVec3) -> DVec3 {
        let q = p - self.pos;
        DVec3::new(q.dot(self.c2w[0]), q.dot(self.c2w[1]), q.dot(self.c2w[2]))
    }

    /// The catalogued mistakes' directions through `(x, y)`.
    fn mistaken(&self, x: f64, y: f64) -> [(Mistake, DVec3); 3] {
        let hfov_deg = 2.0 * self.tan_half.0.atan().to_degrees();
        let full = (
            (2.0 * self.tan_half.0.atan()).tan(),
            (2.0 * self.tan_half.1.atan()).tan(),
        );
        let degrees = ((hfov_deg / 2.0).tan(), (self.vfov_deg / 2.0).tan());
        [
            (
                Mistake::FovFullAngle,
                self.to_world(Self::sensor(x, y, full)),
            ),
            (
                Mistake::FovInDegrees,
                self.to_world(Self::sensor(x, y, degrees)),
            ),
            (
                Mistake::RayInCameraSpace,
                Self::sensor(x, y, self.tan_half).normalize(),
            ),
        ]
    }
}

/// Probes `Camera::generate_ray`.
pub fn generate_ray(driver: &Driver) -> Verdict {
    let mut commands = Vec::new();
    for s in setups() {
        commands.push(s.command());
        commands.extend(PIXELS.iter().map(|(x, y)| format!("ray {x} {y}")));
    }
    let transcript = match driver.run("generate_ray", commands) {
        Ok(t) => t,
        Err(e) => return Verdict::Broken(e),
    };
    let mut cases = Cases::default();
    let mut stub_like = true;
    let mut i = 0;
    for s in setups() {
        let placed = match Placed::read(&transcript, i, s.target) {
            Ok(p) => p,
            Err(v) => return v,
        };
        i += 1;
        for &(x, y) in &PIXELS {
            let got = match transcript.exactly(i, 8) {
                Ok(v) => v,
                Err(stop) => return Verdict::stopped(&stop, transcript.command(i)),
            };
            i += 1;
            let d = vec_at(&got, 3);
            stub_like &= d == DVec3::new(0.0, 0.0, -1.0);
            cases.record(judge_ray(&s, &placed, (x, y), &got));
        }
    }
    if stub_like {
        return Verdict::NotWritten(
            "every ray points along (0, 0, -1), the starter's `Ray(pos, Vector3D(0, 0, -1))`"
                .into(),
        );
    }
    cases.verdict(None)
}

/// One ray against the exact one.
fn judge_ray(s: &Setup, placed: &Placed, (x, y): (f64, f64), got: &[f64]) -> Option<Failure> {
    let input = format!(
        "generate_ray({x}, {y}) for hFov {} and vFov {} degrees at {} x {}, the camera at {} looking at {}",
        s.hfov,
        s.vfov,
        s.size.0,
        s.size.1,
        show(placed.pos),
        show(s.target)
    );
    let expected = placed.to_world(Placed::sensor(x, y, placed.tan_half));
    let (o, d, min_t, max_t) = (vec_at(got, 0), vec_at(got, 3), got[6], got[7]);
    let ray = |o: DVec3, d: DVec3, a: f64, b: f64| {
        format!("o = {}, d = {}, [{a}, {b}]", show(o), show(d))
    };
    let fail = |what: &str, mistake| {
        Some(failure(
            input.clone(),
            ray(placed.pos, expected, placed.clip.0, placed.clip.1),
            ray(o, d, min_t, max_t),
            what,
            mistake,
        ))
    };
    if (o - placed.pos).length() > 1e-9 * placed.pos.length().max(1.0) {
        return fail(
            "the ray does not start at the camera's position `pos`",
            None,
        );
    }
    if !same_direction(d, expected, 1e-7) {
        let mistake = placed
            .mistaken(x, y)
            .into_iter()
            .find(|(_, m)| same_direction(d, *m, 1e-6))
            .map(|(m, _)| m);
        return fail(
            "the direction is not the one through that film point",
            mistake,
        );
    }
    if !close(d.length(), 1.0, 1e-9) {
        return fail("the direction is not normalised (`.unit()`)", None);
    }
    if !close(min_t, placed.clip.0, 1e-6) || !close(max_t, placed.clip.1, 1e-6) {
        return fail("the ray's range is not [nClip, fClip]", None);
    }
    None
}
