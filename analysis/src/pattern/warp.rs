//! `warp { }`: geometric remappings of the point a pattern is evaluated at — repeat,
//! black hole, the cylindrical, spherical and toroidal wraps, planar — and the turbulence
//! warp, following POV-Ray's reference (section 3.4.7.5.5).

use super::cells;
use crate::noise;
use crate::scene::{Turbulence, Warp};
use glam::DVec3;
use std::f64::consts::{PI, TAU};

/// Where `p` goes under the warps, the last written first (the order in which they act on
/// the point a pattern is evaluated at).
pub fn through_all(warps: &[Warp], p: DVec3) -> DVec3 {
    warps.iter().rev().fold(p, |p, warp| apply(warp, p))
}

/// Where `p` goes under the warp.
pub fn apply(warp: &Warp, p: DVec3) -> DVec3 {
    match warp {
        Warp::Turbulence(t) => turbulent(t, p),
        Warp::Transform(t) => t.inverse.transform_point3(p),
        Warp::Repeat {
            direction,
            offset,
            flip,
        } => repeat(p, *direction, *offset, *flip),
        Warp::BlackHole {
            center,
            radius,
            strength,
            falloff,
            inverse,
            repeat,
            jitter,
        } => {
            let centre = black_hole_centre(p, *center, *repeat, *jitter);
            black_hole(p, centre, *radius, *strength, *falloff, *inverse)
        }
        Warp::Cylindrical {
            orientation,
            dist_exp,
        } => {
            let Some((angle, len)) = turn_xz(p) else {
                return p;
            };
            let x = angle * distance_power(len, *dist_exp);
            orient(DVec3::new(x, p.y, len), *orientation)
        }
        Warp::Spherical {
            orientation,
            dist_exp,
        } => spherical(p, *orientation, *dist_exp),
        Warp::Toroidal {
            orientation,
            dist_exp,
            major_radius,
        } => toroidal(p, *orientation, *dist_exp, *major_radius),
        Warp::Planar {
            orientation,
            distance,
        } => orient(DVec3::new(p.x, p.y, *distance), *orientation),
    }
}

/// Where turbulence moves `p`. Inlined: a call around the call of the turbulence itself
/// costs the interpreted plugin a frame for one addition.
#[inline(always)]
pub fn turbulent(t: &Turbulence, p: DVec3) -> DVec3 {
    p + displacement(t, p)
}

/// How far turbulence moves `p`.
#[inline(always)]
fn displacement(t: &Turbulence, p: DVec3) -> DVec3 {
    noise::turbulence(p, t.octaves, t.omega, t.lambda) * t.amount
}

fn repeat(p: DVec3, direction: DVec3, offset: DVec3, flip: DVec3) -> DVec3 {
    let axis = if direction.x != 0.0 {
        0
    } else if direction.y != 0.0 {
        1
    } else if direction.z != 0.0 {
        2
    } else {
        return p;
    };
    let width = direction[axis];
    let block = (p[axis] / width).floor();
    let mut q = p;
    q[axis] -= block * width;
    if block.rem_euclid(2.0) == 1.0 {
        // `flip` names the axes to mirror in every other block; a mirrored repeat axis
        // stays within the block.
        let signs = DVec3::select(flip.cmpne(DVec3::ZERO), -DVec3::ONE, DVec3::ONE);
        q *= signs;
        if signs[axis] < 0.0 {
            q[axis] += width;
        }
    }
    q + offset * block
}

/// The centre of the black hole nearest in its repeat pattern: the block `p` lies in, plus
/// a fixed pseudo-random offset per block scaled by `jitter`.
fn black_hole_centre(p: DVec3, center: DVec3, repeat: DVec3, jitter: DVec3) -> DVec3 {
    if repeat == DVec3::ZERO {
        return center;
    }
    let mut block = DVec3::ZERO;
    for i in 0..3 {
        if repeat[i] >= 1e-10 {
            block[i] = (p[i] / repeat[i]).floor();
        }
    }
    let mut centre = center + repeat * block;
    if jitter != DVec3::ZERO {
        centre += (cells::nucleus(block.as_ivec3()) - block) * jitter;
    }
    centre
}

fn black_hole(
    p: DVec3,
    centre: DVec3,
    radius: f64,
    strength: f64,
    falloff: f64,
    inverse: bool,
) -> DVec3 {
    let delta = p - centre;
    let length = delta.length();
    if length >= radius {
        return p;
    }
    // How close to the centre, from 0 on the rim to 1 at the centre, raised to the falloff.
    let closeness = (radius - length) / radius;
    let force = (closeness.powf(falloff) * strength).min(1.0);
    p + delta * if inverse { -force } else { force }
}

/// The angle of a point around the y axis from +x towards +z as a fraction of a turn,
/// and its distance from the axis; `None` on the axis.
fn turn_xz(p: DVec3) -> Option<(f64, f64)> {
    let len = (p.x * p.x + p.z * p.z).sqrt();
    if len == 0.0 {
        return None;
    }
    let mut angle = if p.z == 0.0 {
        if p.x > 0.0 { 0.0 } else { PI }
    } else {
        (p.x / len).clamp(-1.0, 1.0).acos()
    };
    if p.z < 0.0 {
        angle = TAU - angle;
    }
    Some((angle / TAU, len))
}

fn distance_power(distance: f64, exponent: f64) -> f64 {
    if exponent == 0.0 {
        1.0
    } else if exponent == 1.0 {
        distance
    } else {
        distance.powf(exponent)
    }
}

/// The warped coordinates (u along x, v along y, distance along z) turned so that the
/// distance runs along `orientation`, which POV-Ray takes component by component.
fn orient(q: DVec3, o: DVec3) -> DVec3 {
    if o == DVec3::Z {
        return q;
    }
    DVec3::new(
        o.x * q.z + o.y * q.x + o.z * q.x,
        o.x * q.y - o.y * q.z + o.z * q.y,
        -o.x * q.x + o.y * q.y + o.z * q.z,
    )
}

fn spherical(p: DVec3, orientation: DVec3, dist_exp: f64) -> DVec3 {
    let dist = p.length();
    if dist == 0.0 {
        return p;
    }
    let u = p / dist;
    let mut latitude = 0.5 + u.y.clamp(-1.0, 1.0).asin() / PI;
    let mut longitude = turn_xz(u).map_or(0.0, |(angle, _)| angle);
    let scale = distance_power(dist, dist_exp);
    latitude *= scale;
    longitude *= scale;
    orient(DVec3::new(longitude, latitude, dist), orientation)
}

fn toroidal(p: DVec3, orientation: DVec3, dist_exp: f64, major_radius: f64) -> DVec3 {
    let Some((around, len)) = turn_xz(p) else {
        return p;
    };
    // The point in the plane of its cross-section through the tube.
    let x = len - major_radius;
    let tube = (x * x + p.y * p.y).sqrt();
    if tube == 0.0 {
        return p;
    }
    let mut section = (-x / tube).clamp(-1.0, 1.0).acos();
    if p.y > 0.0 {
        section = TAU - section;
    }
    let scale = distance_power(tube, dist_exp);
    let u = around * scale;
    let v = section / TAU * scale;
    orient(DVec3::new(u, v, tube), orientation)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn black_holes_pull_points_towards_their_centre() {
        let warp = Warp::BlackHole {
            center: DVec3::ZERO,
            radius: 2.0,
            strength: 1.0,
            falloff: 2.0,
            inverse: false,
            repeat: DVec3::ZERO,
            jitter: DVec3::ZERO,
        };
        // Halfway in: closeness 0.5, force 0.25, so the point moves out by a quarter of its
        // offset (POV-Ray adds the scaled offset).
        assert_eq!(apply(&warp, DVec3::X), DVec3::X * 1.25);
        assert_eq!(apply(&warp, DVec3::X * 3.0), DVec3::X * 3.0);
    }

    #[test]
    fn cylindrical_warp_unrolls_around_y() {
        let warp = Warp::Cylindrical {
            orientation: DVec3::Z,
            dist_exp: 0.0,
        };
        let q = apply(&warp, DVec3::new(0.0, 0.5, 2.0));
        assert!((q - DVec3::new(0.25, 0.5, 2.0)).length() < 1e-12, "{q}");
    }

    #[test]
    fn repeat_copies_and_flips_blocks() {
        let warp = Warp::Repeat {
            direction: DVec3::X,
            offset: DVec3::ZERO,
            flip: DVec3::X,
        };
        assert_eq!(
            apply(&warp, DVec3::new(2.25, 1.0, 0.0)),
            DVec3::new(0.25, 1.0, 0.0)
        );
        assert_eq!(
            apply(&warp, DVec3::new(1.25, 1.0, 0.0)),
            DVec3::new(0.75, 1.0, 0.0)
        );
    }
}
