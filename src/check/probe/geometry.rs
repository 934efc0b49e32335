//! The exact answers the geometry probes compare with, in double
//! precision as the course's C++ computes, and the text of vectors and
//! rays for the driver and for the report.
//!
//! - a line `o + t d` meets the triangle `p1 p2 p3` where
//!   `o + t d = (1 - b1 - b2) p1 + b1 p2 + b2 p3`, solved by Cramer's rule
//!   (Möller and Trumbore, "Fast, minimum storage ray/triangle
//!   intersection", 1997): with `e1 = p2 - p1`, `e2 = p3 - p1`,
//!   `s = o - p1`, `s1 = d x e2`, `s2 = s x e1`,
//!   `(t, b1, b2) = (s2 . e2, s1 . s, s2 . d) / (s1 . e1)`;
//! - it meets the sphere of centre `c` and radius `R` at the roots of
//!   `|o + t d - c|^2 = R^2`: `t = (-b -+ sqrt(b^2 - 4 a c')) / 2a` with
//!   `a = d.d`, `b = 2 (o - c).d`, `c' = |o - c|^2 - R^2`;
//! - it is inside the box `[min, max]` for `t` between the largest entry
//!   and the smallest exit of the three slabs, `t = (p - o) / d` per axis
//!   (Kay and Kajiya's slabs).

use glam::DVec3;

/// A ray as the course's `Ray` holds it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ray64 {
    pub o: DVec3,
    pub d: DVec3,
    pub min_t: f64,
    pub max_t: f64,
}

impl Ray64 {
    /// A ray over `[0, inf)`, the course's `Ray(o, d)`.
    pub fn new(o: DVec3, d: DVec3) -> Self {
        Ray64 {
            o,
            d,
            min_t: 0.0,
            max_t: f64::INFINITY,
        }
    }

    /// The same ray over `[min_t, max_t]`.
    pub fn between(self, min_t: f64, max_t: f64) -> Self {
        Ray64 {
            min_t,
            max_t,
            ..self
        }
    }

    /// The ray's eight numbers for the driver.
    pub fn tokens(&self) -> String {
        format!(
            "{} {} {} {}",
            tokens(self.o),
            tokens(self.d),
            self.min_t,
            self.max_t
        )
    }

    /// The ray as a student reads it in a report.
    pub fn show(&self) -> String {
        format!(
            "o = {}, d = {}, min_t = {}, max_t = {}",
            show(self.o),
            show(self.d),
            num(self.min_t),
            num(self.max_t)
        )
    }
}

/// A vector's three numbers for the driver (Rust's shortest exact form).
pub fn tokens(v: DVec3) -> String {
    format!("{} {} {}", v.x, v.y, v.z)
}

/// A vector for a reader: `(x, y, z)` to 6 significant digits.
pub fn show(v: DVec3) -> String {
    format!("({}, {}, {})", num(v.x), num(v.y), num(v.z))
}

/// A number to 6 significant digits (`inf`, `nan` as they are).
pub fn num(x: f64) -> String {
    if !x.is_finite() || x == 0.0 {
        return format!("{x}");
    }
    let digits = (5 - x.abs().log10().floor() as i32).clamp(0, 12) as usize;
    let s = format!("{x:.digits$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        s
    }
}

/// A vector from three numbers of an answer, starting at `at`.
pub fn vec_at(v: &[f64], at: usize) -> DVec3 {
    DVec3::new(v[at], v[at + 1], v[at + 2])
}

/// Where the line `o + t d` meets the triangle's plane: `(t, b1, b2)`,
/// `None` when the line is parallel to it.
pub fn triangle_line(r: &Ray64, p: [DVec3; 3]) -> Option<(f64, f64, f64)> {
    let (e1, e2, s) = (p[1] - p[0], p[2] - p[0], r.o - p[0]);
    let s1 = r.d.cross(e2);
    let s2 = s.cross(e1);
    let det = s1.dot(e1);
    if det.abs() < 1e-12 * e1.length() * e2.length() * r.d.length() {
        return None;
    }
    Some((s2.dot(e2) / det, s1.dot(s) / det, s2.dot(r.d) / det))
}

/// The two roots `t1 <= t2` of the line and the sphere, `None` when the
/// line misses it.
pub fn sphere_roots(r: &Ray64, centre: DVec3, radius: f64) -> Option<(f64, f64)> {
    let oc = r.o - centre;
    let a = r.d.dot(r.d);
    let b = 2.0 * oc.dot(r.d);
    let c = oc.dot(oc) - radius * radius;
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return None;
    }
    let q = disc.sqrt();
    Some(((-b - q) / (2.0 * a), (-b + q) / (2.0 * a)))
}

/// The slabs' interval `(entry, exit)` of the line in the box; empty
/// (entry > exit) when the line misses it.
pub fn slab(r: &Ray64, min: DVec3, max: DVec3) -> (f64, f64) {
    let (mut enter, mut exit) = (f64::NEG_INFINITY, f64::INFINITY);
    for axis in 0..3 {
        let (o, d) = (r.o[axis], r.d[axis]);
        if d == 0.0 {
            if o < min[axis] || o > max[axis] {
                return (f64::INFINITY, f64::NEG_INFINITY);
            }
            continue;
        }
        let (a, b) = ((min[axis] - o) / d, (max[axis] - o) / d);
        enter = enter.max(a.min(b));
        exit = exit.min(a.max(b));
    }
    (enter, exit)
}

/// Whether two numbers agree to `rel` of the larger (or `rel` near 0).
pub fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs()).max(1.0)
}

/// Whether two directions agree in angle to `rad` radians.
pub fn same_direction(a: DVec3, b: DVec3, rad: f64) -> bool {
    let (a, b) = (a.normalize_or_zero(), b.normalize_or_zero());
    a != DVec3::ZERO && a.dot(b) >= rad.cos() && (a - b).length() <= 2.0 * rad
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_line_meets_a_triangle_at_its_barycentrics() {
        let p = [DVec3::ZERO, DVec3::X, DVec3::Y];
        let r = Ray64::new(DVec3::new(0.2, 0.3, 2.0), DVec3::new(0.0, 0.0, -2.0));
        let (t, b1, b2) = triangle_line(&r, p).unwrap();
        assert!(close(t, 1.0, 1e-15) && close(b1, 0.2, 1e-15) && close(b2, 0.3, 1e-15));
        let parallel = Ray64::new(DVec3::Z, DVec3::X);
        assert_eq!(triangle_line(&parallel, p), None);
    }

    #[test]
    fn sphere_roots_and_slabs() {
        let r = Ray64::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z);
        assert_eq!(sphere_roots(&r, DVec3::ZERO, 2.0), Some((3.0, 7.0)));
        assert_eq!(sphere_roots(&r, DVec3::X * 3.0, 2.0), None);
        assert_eq!(slab(&r, DVec3::splat(-1.0), DVec3::ONE), (4.0, 6.0));
        let (a, b) = slab(&r, DVec3::new(2.0, -1.0, -1.0), DVec3::new(3.0, 1.0, 1.0));
        assert!(a > b);
    }

    #[test]
    fn numbers_read_well() {
        assert_eq!(num(0.5), "0.5");
        assert_eq!(num(1.0 / 3.0), "0.333333");
        assert_eq!(num(1234.5678), "1234.57");
        assert_eq!(num(f64::INFINITY), "inf");
        assert_eq!(show(DVec3::new(1.0, -2.0, 0.0)), "(1, -2, 0)");
    }
}
