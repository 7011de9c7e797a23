//! The patterns that depend on how the surface faces rather than on where the point is:
//! `slope` (the surface normal against a direction or a point, optionally blended with a
//! gradient) and `aoi` (the angle between the ray and the normal). Measured on POV-Ray
//! 3.7's renders at 16 bits: both take the normal the lighting uses (turned towards the
//! ray and perturbed by the layer's `normal`), in world space whatever the pattern's
//! transform; angles map linearly to values, `slope` as `1 - angle / pi` (1 where the
//! normal points along the direction) and `aoi` as `angle / pi` (1 where the ray meets
//! the surface head-on, 0.5 where it grazes it). Off a surface (in a function or a
//! density) both are 0 before the wave shaping, as in POV-Ray.

use crate::scene::{Slope, SlopeTarget};
use glam::DVec3;
use std::f64::consts::PI;

/// The surface under a pattern, for the patterns that depend on it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Facing {
    /// The surface point in the world.
    pub point: DVec3,
    /// The unit normal the lighting uses there, facing the ray.
    pub normal: DVec3,
    /// The unit direction of the ray that reached the point.
    pub ray: DVec3,
}

/// The angle between two unit vectors as a fraction of a half turn.
fn half_turns(a: DVec3, b: DVec3) -> f64 {
    a.dot(b).clamp(-1.0, 1.0).acos() / PI
}

/// Where `v` falls from `lo` (0) to `hi` (1), unclamped: the wave shaping wraps it.
fn stretch(v: f64, (lo, hi): (f64, f64)) -> f64 {
    (v - lo) / (hi - lo)
}

/// The raw value of `slope` at pattern-space point `p` (after warps and turbulence, which
/// only the altitude term feels).
pub fn slope(slope: &Slope, facing: Option<&Facing>, p: DVec3) -> f64 {
    let Some(facing) = facing else {
        return 0.0;
    };
    let towards = match slope.towards {
        SlopeTarget::Direction(d) => d,
        SlopeTarget::Point(at) => (at - facing.point).normalize_or_zero(),
    };
    let mut value = 1.0 - half_turns(facing.normal, towards);
    if let Some(range) = slope.range {
        value = stretch(value, range);
    }
    match &slope.altitude {
        Some(altitude) => {
            let height = stretch(p.dot(altitude.axis), altitude.range);
            (value * slope.weight + height * altitude.weight) / (slope.weight + altitude.weight)
        }
        None => value,
    }
}

/// The raw value of `aoi`.
pub fn aoi(facing: Option<&Facing>) -> f64 {
    facing.map_or(0.0, |f| half_turns(f.normal, f.ray))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Altitude;

    fn on(normal: DVec3) -> Facing {
        Facing {
            point: DVec3::new(0.0, 2.0, 0.0),
            normal: normal.normalize(),
            ray: DVec3::Z,
        }
    }

    fn towards_y() -> Slope {
        Slope {
            towards: SlopeTarget::Direction(DVec3::Y),
            weight: 1.0,
            range: None,
            altitude: None,
        }
    }

    fn assert_close(ours: f64, povray: f64) {
        assert!((ours - povray).abs() < 1e-9, "{ours} is not {povray}");
    }

    #[test]
    fn slope_maps_the_angle_to_the_direction_linearly() {
        let s = towards_y();
        assert_close(slope(&s, Some(&on(DVec3::Y)), DVec3::ZERO), 1.0);
        assert_close(slope(&s, Some(&on(DVec3::X)), DVec3::ZERO), 0.5);
        assert_close(slope(&s, Some(&on(-DVec3::Y)), DVec3::ZERO), 0.0);
        // 45 degrees from the direction: three quarters, not 0.5 + 0.5 cos.
        assert_close(
            slope(&s, Some(&on(DVec3::new(1.0, 1.0, 0.0))), DVec3::ZERO),
            0.75,
        );
        assert_close(slope(&s, None, DVec3::ZERO), 0.0);
    }

    #[test]
    fn slope_ranges_and_altitude_blend_by_the_vectors_lengths() {
        let mut s = towards_y();
        s.range = Some((0.25, 0.75));
        assert_close(slope(&s, Some(&on(DVec3::X)), DVec3::ZERO), 0.5);
        assert_close(slope(&s, Some(&on(DVec3::Y)), DVec3::ZERO), 1.5);
        s.weight = 2.0;
        s.altitude = Some(Altitude {
            axis: DVec3::X,
            weight: 1.0,
            range: (-1.0, 1.0),
        });
        // (2 * 1.5 + 1 * 0.75) / 3 at x = 0.5.
        let p = DVec3::new(0.5, 9.0, 9.0);
        assert_close(slope(&s, Some(&on(DVec3::Y)), p), 1.25);
    }

    #[test]
    fn slope_point_at_looks_from_the_surface_point() {
        let s = Slope {
            towards: SlopeTarget::Point(DVec3::new(0.0, 2.0, 5.0)),
            ..towards_y()
        };
        assert_close(slope(&s, Some(&on(DVec3::Z)), DVec3::ZERO), 1.0);
        assert_close(slope(&s, Some(&on(DVec3::Y)), DVec3::ZERO), 0.5);
    }

    #[test]
    fn aoi_is_half_where_the_ray_grazes_and_one_head_on() {
        assert_close(aoi(Some(&on(-DVec3::Z))), 1.0);
        assert_close(aoi(Some(&on(DVec3::X))), 0.5);
        assert_close(aoi(None), 0.0);
    }
}
