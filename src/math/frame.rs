//! Orthonormal frames: the local shading space with the normal on +Z.

use glam::Vec3;

/// An orthonormal basis `(x, y, z)`; `to_world(v) = v.x x + v.y y + v.z z`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    pub x: Vec3,
    pub y: Vec3,
    pub z: Vec3,
}

impl Frame {
    /// A frame whose +Z is the unit vector `n`, by the branchless
    /// construction of Duff et al., "Building an Orthonormal Basis,
    /// Revisited", JCGT 2017.
    pub fn from_z(n: Vec3) -> Self {
        let sign = 1.0f32.copysign(n.z);
        let a = -1.0 / (sign + n.z);
        let b = n.x * n.y * a;
        Frame {
            x: Vec3::new(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x),
            y: Vec3::new(b, sign + n.y * n.y * a, -n.y),
            z: n,
        }
    }

    pub fn to_world(&self, v: Vec3) -> Vec3 {
        v.x * self.x + v.y * self.y + v.z * self.z
    }

    pub fn to_local(&self, v: Vec3) -> Vec3 {
        Vec3::new(v.dot(self.x), v.dot(self.y), v.dot(self.z))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_are_orthonormal_and_invertible() {
        for n in [
            Vec3::Z,
            -Vec3::Z,
            Vec3::X,
            Vec3::new(0.3, -0.5, 0.8).normalize(),
        ] {
            let f = Frame::from_z(n);
            for (a, b) in [(f.x, f.y), (f.y, f.z), (f.z, f.x)] {
                assert!(a.dot(b).abs() < 1e-6);
            }
            assert!(f.x.cross(f.y).distance(f.z) < 1e-6, "right-handed");
            let v = Vec3::new(0.1, 0.2, 0.3);
            assert!(f.to_local(f.to_world(v)).distance(v) < 1e-6);
        }
    }
}
