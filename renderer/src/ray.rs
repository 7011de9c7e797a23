//! Rays, and what a ray is traced for, since objects may hide from some kinds
//! (`no_image`, `no_reflection`, `no_shadow`).

use glam::DVec3;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ray {
    pub origin: DVec3,
    /// Not necessarily of unit length: object-space rays keep the world parameter `t`.
    pub direction: DVec3,
}

impl Ray {
    pub fn new(origin: DVec3, direction: DVec3) -> Ray {
        Ray { origin, direction }
    }

    pub fn at(&self, t: f64) -> DVec3 {
        self.origin + self.direction * t
    }
}

/// Why a ray is traced.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RayKind {
    /// From the camera.
    Primary,
    Reflected,
    /// Refracted or transmitted through a surface.
    Transmitted,
    /// Towards a light, to find what blocks it.
    Shadow,
    /// Gathering indirect light for radiosity.
    Radiosity,
}

impl RayKind {
    /// The kind's bit in a set of kinds (see [`Visibility::kinds`](crate::object::Visibility::kinds)).
    pub fn bit(self) -> u8 {
        1 << self as u8
    }
}
