//! What a ray knows of the matter it travels through, and how it bends at a surface: the
//! interiors it is inside (innermost last, compared by identity, as POV-Ray keeps them),
//! the band of the spectrum it carries once dispersion has split it, and Snell's law.
//! The tracer and the photon pass both follow rays through interiors with it.

use crate::dispersion;
use crate::interior::Interior;
use glam::DVec3;

/// The interiors a ray is inside and its spectral band.
#[derive(Debug, Clone, Default)]
pub struct Inside<'w> {
    interiors: Vec<&'w Interior>,
    /// Where in the spectrum the ray lies, from -0.5 (red) to 0.5 (violet), once a
    /// dispersing interior has split it; `None` for white light.
    pub band: Option<f64>,
}

impl<'w> Inside<'w> {
    /// Inside `interiors` (outermost first), in white light.
    pub fn start_in(&mut self, interiors: impl Iterator<Item = &'w Interior>) {
        self.interiors.clear();
        self.interiors.extend(interiors);
        self.band = None;
    }

    /// Becomes a copy of `saved`, keeping its own storage: a ray's state is restored after
    /// every refraction, and a fresh copy would allocate each time.
    pub fn restore(&mut self, saved: &Inside<'w>) {
        self.interiors.clear();
        self.interiors.extend_from_slice(&saved.interiors);
        self.band = saved.band;
    }

    /// The interiors, innermost last.
    pub fn interiors(&self) -> &[&'w Interior] {
        &self.interiors
    }

    /// The index of refraction of `interior` for this ray's band.
    fn ior(&self, interior: &Interior) -> f64 {
        match self.band {
            Some(band) => dispersion::ior(interior, band),
            None => interior.ior,
        }
    }

    /// The relative index of refraction at a surface of `interior`, as the ray sees it
    /// before crossing: for Fresnel reflection.
    pub fn relative_ior(&self, interior: &Interior) -> f64 {
        match self.interiors.as_slice() {
            [] => self.ior(interior),
            [.., outer, last] if std::ptr::eq(*last, interior) => {
                self.ior(outer) / self.ior(interior)
            }
            [last] if std::ptr::eq(*last, interior) => 1.0 / self.ior(interior),
            [.., last] => self.ior(interior) / self.ior(last),
        }
    }

    /// Whether `interior` is the innermost one: the ray is leaving it at its surface.
    pub fn is_innermost(&self, interior: &Interior) -> bool {
        self.interiors
            .last()
            .is_some_and(|i| std::ptr::eq(*i, interior))
    }

    /// Crosses a surface of `interior`, entering or leaving it, and returns the ratio of
    /// the indices of refraction behind and ahead, for Snell's law. Inlined into its two
    /// callers: a refracting surface crosses at every sample, and a call costs the
    /// interpreted plugin a frame.
    #[inline(always)]
    pub fn cross(&mut self, interior: &'w Interior) -> f64 {
        let position = self
            .interiors
            .iter()
            .position(|i| std::ptr::eq(*i, interior));
        match (self.interiors.last(), position) {
            (None, _) => {
                self.interiors.push(interior);
                1.0 / self.ior(interior)
            }
            (Some(last), _) if std::ptr::eq(*last, interior) => {
                self.interiors.pop();
                match self.interiors.last() {
                    None => self.ior(interior),
                    Some(outer) => self.ior(interior) / self.ior(outer),
                }
            }
            (Some(_), Some(pos)) => {
                // Leaving an overlap of two interiors: no bend, as POV-Ray has it.
                self.interiors.remove(pos);
                1.0
            }
            (Some(outer), None) => {
                let ior = self.ior(outer) / self.ior(interior);
                self.interiors.push(interior);
                ior
            }
        }
    }
}

/// The direction of a unit ray `direction` refracted at a surface with unit normal
/// `normal` (either side), for the ratio `ior` of the indices behind and ahead; `None`
/// when the light is totally reflected instead.
pub fn refract(direction: DVec3, normal: DVec3, ior: f64) -> Option<DVec3> {
    if (ior - 1.0).abs() < 1e-10 {
        return Some(direction);
    }
    let mut n = direction.dot(normal);
    let local = if n <= 0.0 {
        n = -n;
        normal
    } else {
        -normal
    };
    let t = 1.0 + ior * ior * (n * n - 1.0);
    if t < 0.0 {
        return None;
    }
    Some((ior * direction + (ior * n - t.sqrt()) * local).normalize_or_zero())
}

/// The mirror image of `direction` in a surface with unit normal `normal`.
pub fn reflect(direction: DVec3, normal: DVec3) -> DVec3 {
    (direction - 2.0 * direction.dot(normal) * normal).normalize_or_zero()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn snell_and_total_internal_reflection() {
        let down = DVec3::new(1.0, -1.0, 0.0).normalize();
        // Into glass: sin 45° / 1.5.
        let into = refract(down, DVec3::Y, 1.0 / 1.5).unwrap();
        assert!((into.x - 45f64.to_radians().sin() / 1.5).abs() < 1e-12);
        assert!(into.y < 0.0);
        // Out of glass at 45°: beyond the critical angle of 41.8°.
        assert!(refract(down, DVec3::Y, 1.5).is_none());
        assert_eq!(refract(down, DVec3::Y, 1.0), Some(down));
    }

    #[test]
    fn crossing_a_surface_twice_leaves_the_interior() {
        let glass = Interior {
            ior: 1.5,
            ..Interior::default()
        };
        let water = Interior {
            ior: 1.33,
            ..Interior::default()
        };
        let mut inside = Inside::default();
        assert_eq!(inside.cross(&glass), 1.0 / 1.5);
        assert!(inside.is_innermost(&glass));
        assert_eq!(inside.cross(&water), 1.5 / 1.33);
        assert_eq!(inside.cross(&water), 1.33 / 1.5);
        assert_eq!(inside.cross(&glass), 1.5);
        assert!(!inside.is_innermost(&glass));
    }
}
