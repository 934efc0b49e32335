//! The probe of `Camera::generate_ray_for_thin_lens` (part 8).
//!
//! The course's thin lens (handout 3-2, part 4) is a disk of radius
//! `b = lensRadius` in the plane `z = 0` of camera space, focused on the
//! plane `z = -d` (`d = focalDistance`). For the film point `(x, y)`, whose
//! pinhole direction is `w = ((2x - 1) tan(hFov / 2), (2y - 1) tan(vFov / 2), -1)`,
//! every ray passes through `p_focus = d w`, where the pinhole ray meets
//! the plane of focus, from a point `p_lens` of the disk:
//!
//! ```text
//! origin = pos + c2w p_lens,     |p_lens| <= b, p_lens.z = 0
//! dir    = normalize(c2w (p_focus - p_lens)),     over [nClip, fClip]
//! ```
//!
//! The handout draws `p_lens = b sqrt(rndR) (cos t, sin t, 0)`, with
//! `t = rndTheta` or `2 pi rndTheta` by the caller's convention, so the
//! probe holds the radius to `b sqrt(rndR)` only to tell the catalogue's
//! `lens-radius-unscaled` (`sqrt(rndR)`, the unit disk) and a radius of
//! `b rndR` (not uniform on the disk) apart; any point of the disk passes.
//! A ray through `pos + c2w (d w / |w|)`, at distance `d` along the
//! pinhole ray, is `focus-on-a-sphere`.

use glam::DVec3;

use super::camera::{self, Placed};
use super::driver::Driver;
use super::geometry::{close, num, same_direction, show, vec_at};
use super::verdict::{failure, Cases, Failure, Verdict};
use crate::mistakes::Mistake;

/// A camera (`configure`, `place`) and its lens.
struct Setup {
    camera: camera::Setup,
    radius: f64,
    focal: f64,
}

/// [`camera`]'s first two cameras: the one looking down -z, and the
/// turned and tilted one with a narrower, taller film.
fn setups() -> [Setup; 2] {
    let [down_z, turned, _] = camera::setups();
    [
        Setup {
            camera: down_z,
            radius: 0.25,
            focal: 3.0,
        },
        Setup {
            camera: camera::Setup {
                hfov: 40.0,
                vfov: 60.0,
                size: (300, 400),
                ..turned
            },
            radius: 0.5,
            focal: 6.5,
        },
    ]
}

/// `(x, y, rndR, rndTheta)`: the film's centre first, then its corners
/// and inside, lens samples near the rim (`rndR` = 0.81: the unit disk's
/// radius 0.9 lies outside either lens) and inside.
const SAMPLES: [(f64, f64, f64, f64); 8] = [
    (0.5, 0.5, 0.81, 0.1),
    (0.5, 0.5, 0.25, 0.7),
    (0.0, 0.0, 0.81, 0.35),
    (1.0, 1.0, 0.64, 0.9),
    (0.1, 0.9, 0.81, 0.55),
    (0.9, 0.2, 0.5, 0.2),
    (0.3, 0.7, 0.0, 0.0),
    (0.75, 0.4, 0.99, 0.8),
];

/// Probes `Camera::generate_ray_for_thin_lens`.
pub fn thin_lens(driver: &Driver) -> Verdict {
    let mut commands = Vec::new();
    for s in setups() {
        commands.push(format!("lens {} {}", s.radius, s.focal));
        commands.push(s.camera.command());
        commands.extend(
            SAMPLES
                .iter()
                .map(|(x, y, r, t)| format!("lens_ray {x} {y} {r} {t}")),
        );
    }
    let t = match driver.run("thin_lens", commands) {
        Ok(t) => t,
        Err(e) => return Verdict::Broken(e),
    };
    let mut cases = Cases::default();
    let mut stub_like = true;
    let mut centred = true;
    let mut i = 0;
    for s in setups() {
        i += 1;
        let placed = match Placed::read(&t, i, s.camera.target) {
            Ok(p) => p,
            Err(v) => return v,
        };
        i += 1;
        for sample in SAMPLES {
            let got = match t.exactly(i, 8) {
                Ok(v) => v,
                Err(stop) => return Verdict::stopped(&stop, t.command(i)),
            };
            i += 1;
            let (o, d) = (vec_at(&got, 0), vec_at(&got, 3));
            stub_like &= o == placed.pos && d == DVec3::new(0.0, 0.0, -1.0);
            centred &= (o - placed.pos).length() <= 1e-12 * placed.pos.length().max(1.0);
            cases.record(judge(&s, &placed, sample, &got));
        }
    }
    if stub_like {
        return Verdict::NotWritten(
            "every ray starts at pos along (0, 0, -1), the starter's `Ray(pos, Vector3D(0, 0, -1))`".into(),
        );
    }
    if centred {
        return Verdict::Fail(failure(
            format!(
                "{} rays with lens samples rndR up to 0.99",
                2 * SAMPLES.len()
            ),
            "origins spread over the lens, pos + c2w (b sqrt(rndR) cos t, b sqrt(rndR) sin t, 0)",
            "every ray starts at pos",
            "the lens is not sampled: every ray starts at its centre, a pinhole camera",
            None,
        ));
    }
    cases.verdict(None)
}

/// One ray against the thin lens's.
fn judge(
    s: &Setup,
    placed: &Placed,
    (x, y, rnd_r, rnd_t): (f64, f64, f64, f64),
    got: &[f64],
) -> Option<Failure> {
    let (o, d, min_t, max_t) = (vec_at(got, 0), vec_at(got, 3), got[6], got[7]);
    let input = format!(
        "generate_ray_for_thin_lens({x}, {y}, rndR = {rnd_r}, rndTheta = {rnd_t}) with lensRadius {} and focalDistance {}, hFov {} and vFov {} degrees, the camera at {} looking at {}",
        s.radius, s.focal, s.camera.hfov, s.camera.vfov, show(placed.pos), show(s.camera.target)
    );
    let w = Placed::sensor(x, y, placed.tan_half);
    let focus = placed.pos + placed.rotate(s.focal * w);
    let lens = placed.to_camera(o);
    let radius = lens.truncate().length();
    let b = s.radius;
    let scale = placed.pos.length().max(1.0);
    let said = format!(
        "o = {} (lens point {} in camera space), d = {}, [{}, {}]",
        show(o),
        show(lens),
        show(d),
        num(min_t),
        num(max_t)
    );
    let want_dir = (focus - o).normalize_or_zero();
    let expected = format!(
        "o on the lens disk of radius {b} around {}, d = {} toward the point in focus {}, [{}, {}]",
        show(placed.pos),
        show(want_dir),
        show(focus),
        num(placed.clip.0),
        num(placed.clip.1)
    );
    let fail = |what: &str, mistake| {
        Some(failure(
            input.clone(),
            expected.clone(),
            said.clone(),
            what,
            mistake,
        ))
    };
    if !o.is_finite() || lens.z.abs() > 1e-9 * scale {
        return fail(
            "the origin is not on the lens, the plane z = 0 of camera space through pos",
            None,
        );
    }
    if radius > b * (1.0 + 1e-9) + 1e-12 {
        let unscaled = radius <= 1.0 + 1e-9 && close(radius, rnd_r.sqrt(), 1e-6);
        return fail(
            if unscaled {
                "the lens point is on the unit disk: not scaled by lensRadius"
            } else {
                "the origin lies outside the lens disk of radius lensRadius"
            },
            unscaled.then_some(Mistake::LensRadiusUnscaled),
        );
    }
    if rnd_r > 0.0 && rnd_r < 1.0 && close(radius, b * rnd_r, 1e-6) {
        return fail(
            "the lens point's radius is lensRadius * rndR: not uniform on the disk, which takes sqrt(rndR)",
            None,
        );
    }
    if !same_direction(d, want_dir, 1e-6) {
        let sphere = placed.pos + placed.rotate(s.focal * w.normalize());
        let on_sphere = same_direction(d, sphere - o, 1e-6);
        return fail(
            if on_sphere {
                "the ray aims at distance focalDistance along the pinhole ray, not at the plane of focus z = -focalDistance"
            } else {
                "the ray does not pass through the point where the pinhole ray meets the plane of focus"
            },
            on_sphere.then_some(Mistake::FocusOnASphere),
        );
    }
    if !close(d.length(), 1.0, 1e-9) {
        return fail("the direction is not normalised", None);
    }
    if !close(min_t, placed.clip.0, 1e-6) || !close(max_t, placed.clip.1, 1e-6) {
        return fail("the ray's range is not [nClip, fClip]", None);
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The first setup's camera as the course places it: at (0, 0, 4)
    /// looking down -z, up +y.
    fn placed() -> (Setup, Placed) {
        let [s, _] = setups();
        let c = &s.camera;
        let tan_v = (c.vfov.to_radians() / 2.0).tan();
        let ar = f64::from(c.size.0) / f64::from(c.size.1);
        let placed = Placed {
            pos: DVec3::new(0.0, 0.0, 4.0),
            c2w: [DVec3::X, DVec3::Y, DVec3::Z],
            tan_half: (tan_v * ar, tan_v),
            vfov_deg: c.vfov,
            clip: c.clip,
        };
        (s, placed)
    }

    /// The ray from lens point `(r cos t, r sin t)` toward `target`
    /// (camera space).
    fn ray(p: &Placed, r: f64, t: f64, target: DVec3) -> Vec<f64> {
        let lens = DVec3::new(r * t.cos(), r * t.sin(), 0.0);
        let o = p.pos + p.rotate(lens);
        let d = p.rotate(target - lens).normalize();
        vec![o.x, o.y, o.z, d.x, d.y, d.z, p.clip.0, p.clip.1]
    }

    #[test]
    fn the_thin_lens_passes_and_its_mistakes_are_named() {
        let (s, p) = placed();
        let (x, y, rnd_r, rnd_t): (f64, f64, f64, f64) = (0.1, 0.9, 0.81, 0.55);
        let w = Placed::sensor(x, y, p.tan_half);
        let b = s.radius;
        let focus = s.focal * w;
        // Either angle convention passes.
        for t in [rnd_t, 2.0 * std::f64::consts::PI * rnd_t] {
            let right = ray(&p, b * rnd_r.sqrt(), t, focus);
            assert!(judge(&s, &p, (x, y, rnd_r, rnd_t), &right).is_none());
        }
        let unit = ray(&p, rnd_r.sqrt(), rnd_t, focus);
        let f = judge(&s, &p, (x, y, rnd_r, rnd_t), &unit).unwrap();
        assert_eq!(f.mistake, Some(Mistake::LensRadiusUnscaled));
        let sphere = ray(&p, b * rnd_r.sqrt(), rnd_t, s.focal * w.normalize());
        let f = judge(&s, &p, (x, y, rnd_r, rnd_t), &sphere).unwrap();
        assert_eq!(f.mistake, Some(Mistake::FocusOnASphere));
    }
}
