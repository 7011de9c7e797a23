use glam::{DAffine3, DMat3, DVec3};

/// An affine transformation with its inverse kept beside it, as every ray needs the inverse.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Transform {
    pub matrix: DAffine3,
    pub inverse: DAffine3,
}

impl Default for Transform {
    fn default() -> Self {
        Transform::IDENTITY
    }
}

impl Transform {
    pub const IDENTITY: Transform = Transform {
        matrix: DAffine3::IDENTITY,
        inverse: DAffine3::IDENTITY,
    };

    /// `None` when the matrix is singular (a `scale 0`, say), which POV-Ray also rejects.
    pub fn from_affine(matrix: DAffine3) -> Option<Transform> {
        let det = matrix.matrix3.determinant();
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        Some(Transform {
            matrix,
            inverse: matrix.inverse(),
        })
    }

    pub fn translate(v: DVec3) -> Transform {
        Transform {
            matrix: DAffine3::from_translation(v),
            inverse: DAffine3::from_translation(-v),
        }
    }

    /// `None` when a component is zero; POV-Ray replaces those by 1 with a warning, which
    /// the evaluator does before calling this.
    pub fn scale(v: DVec3) -> Option<Transform> {
        Transform::from_affine(DAffine3::from_scale(v))
    }

    /// POV-Ray's `rotate <x, y, z>`: degrees, about x first, then y, then z, in a
    /// left-handed system (positive angles turn clockwise looking along the axis).
    pub fn rotate_degrees(v: DVec3) -> Transform {
        let r = v * (std::f64::consts::PI / 180.0);
        let m =
            DMat3::from_rotation_z(r.z) * DMat3::from_rotation_y(r.y) * DMat3::from_rotation_x(r.x);
        let matrix = DAffine3::from_mat3(m);
        Transform {
            matrix,
            inverse: DAffine3::from_mat3(m.transpose()),
        }
    }

    /// First `self`, then `then`.
    pub fn then(&self, then: &Transform) -> Transform {
        Transform {
            matrix: then.matrix * self.matrix,
            inverse: self.inverse * then.inverse,
        }
    }

    pub fn inverted(&self) -> Transform {
        Transform {
            matrix: self.inverse,
            inverse: self.matrix,
        }
    }

    pub fn is_identity(&self) -> bool {
        self.matrix == DAffine3::IDENTITY
    }

    pub fn point(&self, p: DVec3) -> DVec3 {
        self.matrix.transform_point3(p)
    }

    pub fn vector(&self, v: DVec3) -> DVec3 {
        self.matrix.transform_vector3(v)
    }

    /// Normals transform by the inverse transpose.
    pub fn normal(&self, n: DVec3) -> DVec3 {
        self.inverse.matrix3.transpose() * n
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotation_follows_povray_handedness() {
        // POV-Ray: `rotate 90*y` takes +x to -z... in its left-handed frame that is
        // the standard right-handed matrix applied to coordinates.
        let t = Transform::rotate_degrees(DVec3::new(0.0, 90.0, 0.0));
        let p = t.point(DVec3::X);
        assert!((p - DVec3::new(0.0, 0.0, -1.0)).length() < 1e-12, "{p}");
        let back = t.inverted().point(p);
        assert!((back - DVec3::X).length() < 1e-12);
    }

    #[test]
    fn composition_order() {
        let t = Transform::translate(DVec3::X).then(&Transform::scale(DVec3::splat(2.0)).unwrap());
        assert_eq!(t.point(DVec3::ZERO), DVec3::new(2.0, 0.0, 0.0));
        assert!((t.inverse.transform_point3(DVec3::new(2.0, 0.0, 0.0))).length() < 1e-12);
    }
}
