//! `projected_through`: a light that shines only along the rays that cross an object, as
//! through a slide or a stencil. The object itself is invisible; only what lies between a
//! surface point and the object casts shadows for that light.

use super::Tracer;
use crate::light::Light;
use crate::object::Query;
use crate::ray::{Ray, RayKind};
use glam::DVec3;

impl Tracer<'_> {
    /// `colour` from `light` reaching `p` along `direction` (`distance` to the light) past
    /// the shadow-casting objects and through the light's projection object if it has one.
    pub(super) fn shadowed(
        &mut self,
        light: &Light,
        p: DVec3,
        direction: DVec3,
        distance: f64,
        colour: DVec3,
    ) -> DVec3 {
        match self.projected_reach(light, p, direction, distance) {
            Some(reach) => {
                let stop = self.photons_stop(light);
                self.filtered(p, direction, reach, colour, stop)
            }
            None => DVec3::ZERO,
        }
    }

    /// How far from `p` towards the light shadows are sought: the whole `distance`, or for
    /// a light projected through an object, up to where the ray first meets the object;
    /// `None` when the ray misses it and the light does not reach `p`.
    pub(super) fn projected_reach(
        &self,
        light: &Light,
        p: DVec3,
        direction: DVec3,
        distance: f64,
    ) -> Option<f64> {
        let Some(through) = &light.projected_through else {
            return Some(distance);
        };
        let eps = self.tolerance(p);
        // Transmitted rays see every object, whatever its no_shadow or no_image flags.
        let q = Query::new(
            Ray::new(p, direction),
            RayKind::Transmitted,
            eps,
            distance - eps,
        );
        // Only intersections and differences collect hits in the scratch list; leaves and
        // unions, the common projections, leave it empty and unallocated.
        through.nearest(&q, &mut Vec::new()).map(|hit| hit.t)
    }
}
