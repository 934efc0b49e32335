//! The BVH on a mesh of the course's size, against a scan of every
//! triangle: the last step of the traversal probes ([`bvh`](mod@super::bvh)),
//! taken once they pass on the small mesh.
//!
//! The mesh is the course's `CBbunny.dae` (the bunny and its Cornell box,
//! about 28,600 triangles), found under `--scenes`, the tree's own `dae/`
//! or `CS184_SCENES`; without one, a generated ball of the same size
//! ([`bumpy_ball`]). The student's tree of it (leaf size 4) must answer
//! every ray as the scan does, and its work per ray is measured two ways:
//! the triangle tests a ray costs (counted by the driver, exact and the
//! same on every machine), and the time of a pass over the rays against a
//! scan's (reported, not judged: it depends on the machine). A tree whose
//! rays test more than a tenth of the triangles on average is not doing a
//! BVH's job, whatever its answers: its traversal visits boxes the ray
//! misses, or its splits do not divide the triangles.

use std::f64::consts::PI;
use std::path::PathBuf;

use glam::DVec3;

use super::bvh::{judge, nearest, rays};
use super::bvh_tree;
use super::driver::Driver;
use super::geometry::num;
use super::verdict::{failure, Cases, Verdict};
use crate::scene::course_files;

/// The course file raced on, where found.
pub const COURSE_MESH: &str = "CBbunny.dae";
/// The rays judged against the scan and raced.
const RAYS: usize = 400;
/// The largest share of the triangles a ray may test on average.
const MOST_TESTED: f64 = 0.1;

/// A mesh to race on and what to call it.
pub struct RaceMesh {
    pub name: String,
    pub triangles: Vec<[DVec3; 3]>,
}

/// The course's bunny from the first of `roots` that has it, else
/// [`bumpy_ball`].
pub fn race_mesh(roots: &[PathBuf]) -> RaceMesh {
    let loaded = course_files::find_in(roots, COURSE_MESH)
        .and_then(|path| crate::scene::load(&path).ok().map(|s| (path, s)));
    match loaded {
        Some((path, scene)) if !scene.mesh.triangles.is_empty() => {
            let m = &scene.mesh;
            let p = |i: u32| m.positions[i as usize].as_dvec3();
            RaceMesh {
                name: path.display().to_string(),
                triangles: m
                    .triangles
                    .iter()
                    .map(|t| [p(t[0]), p(t[1]), p(t[2])])
                    .collect(),
            }
        }
        _ => RaceMesh {
            name: format!("a generated ball (no {COURSE_MESH} found)"),
            triangles: bumpy_ball(120),
        },
    }
}

/// A unit ball of `2 n (n - 1)` triangles (`n` rings of `n` segments, one
/// triangle of each quad at a pole being none), its radius rippled by 10 %
/// so that no two triangles are alike.
pub fn bumpy_ball(n: usize) -> Vec<[DVec3; 3]> {
    let point = |ring: usize, seg: usize| {
        let theta = PI * ring as f64 / n as f64;
        let phi = 2.0 * PI * seg as f64 / n as f64;
        let r = 1.0 + 0.1 * (5.0 * theta).sin() * (3.0 * phi).cos();
        r * DVec3::new(
            theta.sin() * phi.cos(),
            theta.sin() * phi.sin(),
            theta.cos(),
        )
    };
    let mut out = Vec::with_capacity(2 * n * n);
    for ring in 0..n {
        for seg in 0..n {
            let (a, b) = (point(ring, seg), point(ring, seg + 1));
            let (c, d) = (point(ring + 1, seg), point(ring + 1, seg + 1));
            if ring + 1 < n {
                out.push([a, c, d]);
            }
            if ring > 0 {
                out.push([a, d, b]);
            }
        }
    }
    out
}

/// The race for `intersect` (`nearest_hit`) or `has_intersection`: the
/// note a pass adds, or the verdict that stops it.
pub fn race(driver: &Driver, nearest_hit: bool) -> Result<String, Verdict> {
    let mesh = race_mesh(&driver.scenes);
    let rays = rays(&mesh.triangles, RAYS, 11);
    let (name, verb, answers) = if nearest_hit {
        ("bvh_race_intersect", "bvh_hit", 4)
    } else {
        ("bvh_race_has_intersection", "bvh_any", 2)
    };
    let mut commands = vec!["tests".to_owned()];
    for r in &rays {
        commands.push(format!("{verb} {}", r.tokens()));
        commands.push("tests".into());
    }
    commands.extend(rays.iter().map(|r| format!("race_ray {}", r.tokens())));
    let how = if nearest_hit { "hit" } else { "any" };
    commands.push(format!("race {how}"));
    let (t, nodes) = bvh_tree::run(driver, name, &mesh.triangles, commands)?;
    let leaves = bvh_tree::leaf_of(&nodes, mesh.triangles.len());
    let first = mesh.triangles.len() + 3;
    let function = if nearest_hit {
        "intersect"
    } else {
        "has_intersection"
    };
    let mut cases = Cases::default();
    let mut tests = 0.0;
    for (k, ray) in rays.iter().enumerate() {
        let at = first + 2 * k;
        let got = t
            .exactly(at, answers)
            .map_err(|stop| Verdict::stopped(&stop, t.command(at)))?;
        tests += t
            .exactly(at + 1, 1)
            .map_err(|stop| Verdict::stopped(&stop, t.command(at + 1)))?[0];
        let Ok(want) = nearest(&mesh.triangles, ray, |_| true) else {
            continue;
        };
        let found = (got[0] == 1.0).then(|| (got[1], got.get(2).map_or(-1, |i| *i as i64)));
        let call = format!("{function} on {} with the ray {}", mesh.name, ray.show());
        cases.record(judge(&call, want, found, nearest_hit, 0, &leaves));
    }
    if !cases.all_pass() {
        return Err(cases.verdict(None));
    }
    let count = mesh.triangles.len();
    let per_ray = tests / rays.len() as f64;
    if per_ray > MOST_TESTED * count as f64 {
        let what = if nearest_hit && per_ray >= count as f64 {
            "the answers are right but every ray tests every triangle: the traversal never skips a node whose box the ray misses"
        } else {
            "the answers are right but the tree saves little work: the traversal visits boxes the ray misses, or the splits do not divide the triangles"
        };
        return Err(Verdict::Fail(failure(
            format!("{function} on {} ({count} triangles), {} rays", mesh.name, rays.len()),
            format!(
                "at most a tenth of the triangles tested a ray, {} (a BVH of leaf size 4 tests tens)",
                num((MOST_TESTED * count as f64).round())
            ),
            format!("{} triangle tests a ray", num(per_ray)),
            what,
            None,
        )));
    }
    let at = first + 3 * rays.len();
    let seconds = t
        .exactly(at, 2)
        .map_err(|stop| Verdict::stopped(&stop, t.command(at)))?;
    Ok(format!(
        "on {} ({count} triangles) {} rays answer as a scan does, at {} triangle tests a ray; a pass over them takes {} ms, a scan {} ms ({}x)",
        mesh.name,
        rays.len(),
        num((per_ray * 10.0).round() / 10.0),
        num((seconds[0] * 1e4).round() / 10.0),
        num((seconds[1] * 1e4).round() / 10.0),
        num((seconds[1] / seconds[0].max(1e-9)).round())
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn without_the_course_the_race_is_on_the_generated_ball() {
        let mesh = race_mesh(&[]);
        assert!(mesh.name.contains("generated"), "{}", mesh.name);
        assert_eq!(mesh.triangles, bumpy_ball(120));
    }

    #[test]
    fn the_generated_ball_is_of_the_courses_size_without_slivers() {
        let ball = bumpy_ball(120);
        assert_eq!(ball.len(), 28_560);
        let areas: Vec<f64> = ball
            .iter()
            .map(|t| (t[1] - t[0]).cross(t[2] - t[0]).length() / 2.0)
            .collect();
        assert!(areas.iter().all(|a| *a > 1e-6));
        // The area of a unit ball, give or take the ripple.
        let area: f64 = areas.iter().sum();
        assert!((area / (4.0 * PI) - 1.0).abs() < 0.1, "{area}");
    }
}
