//! How far objects reach along a direction: the least and the greatest of `direction · x`
//! over the points of their surfaces. A ray that starts beyond that, moving further
//! away, meets none of them, which spares two kinds of search: rays leaving a flat
//! surface into a side of its plane that no other object reaches ([`crate::open_sides`]),
//! and shadow rays leaving the box of every object across one of its sides
//! ([`crate::bvh::Bvh::left_behind`]).
//!
//! A bounded object reaches as far as its box. An unbounded object's box is infinite
//! (along every axis, or every axis but one for a plane along an axis), so only a plane's
//! own equation tells how far it reaches: to its place along its normal, either way,
//! and everywhere along any other direction, however near; any other unbounded object
//! reaches everywhere.

use crate::bounds::Aabb;
use crate::object::Object;
use glam::DVec3;

/// How far, relative to `1 + |end|`, a place must lie beyond the end of a span to count
/// as beyond every surface the span holds. Far above the rounding of a point on one of
/// those surfaces (some 1e-16 relative to its coordinates), so that no such point lies
/// beyond; and far below the step a ray from a surface takes before its search starts
/// (the tracer's tolerance, 1e-9 relative to the point and the scene's size), so that a
/// shadow ray from a box's face on an end of the reach has crossed that end when its
/// search would start, unless it runs within about 1% of the face's plane. Along a
/// tilted plane's normal, a point found on the plane some ten thousand times farther out
/// than the end may lie off it by more; only a ray from there grazing the plane could then
/// meet an object lying that close to it.
const MARGIN: f64 = 1e-11;

/// A stretch of `direction · x` along some direction, from `low` to `high`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Span {
    pub low: f64,
    pub high: f64,
}

impl Span {
    /// What nothing reaches: beyond it is everywhere.
    pub const NOWHERE: Span = Span {
        low: f64::INFINITY,
        high: f64::NEG_INFINITY,
    };

    /// What reaches everywhere: nothing lies beyond it.
    pub const EVERYWHERE: Span = Span {
        low: f64::NEG_INFINITY,
        high: f64::INFINITY,
    };

    /// The span of both.
    pub fn union(self, other: Span) -> Span {
        Span {
            low: self.low.min(other.low),
            high: self.high.max(other.high),
        }
    }

    /// The span grown at each finite end by [`MARGIN`]: the places beyond it lie beyond
    /// every surface the span holds by far more than a rounding.
    pub fn grown(self) -> Span {
        let margin = |end: f64| MARGIN * (1.0 + end.abs());
        Span {
            low: if self.low.is_finite() {
                self.low - margin(self.low)
            } else {
                self.low
            },
            high: if self.high.is_finite() {
                self.high + margin(self.high)
            } else {
                self.high
            },
        }
    }
}

/// How far the bounded objects within `bounded` (the union of their boxes, finite or
/// empty) and the unbounded objects `unbounded` (each one's plane, or `None`, see
/// [`unbounded_plane`]) reach along the unit vector `direction`.
pub fn along(
    bounded: &Aabb,
    unbounded: impl IntoIterator<Item = Option<(DVec3, f64)>>,
    direction: DVec3,
) -> Span {
    unbounded
        .into_iter()
        .fold(box_along(bounded, direction), |span, plane| {
            span.union(plane_along(plane, direction))
        })
}

/// The plane `(normal, offset)` of an unbounded object that is one, which tells how far
/// it reaches; `None` for any other, which reaches everywhere.
pub fn unbounded_plane(object: &Object) -> Option<(DVec3, f64)> {
    match object {
        Object::Leaf(leaf) => leaf.flat_plane(),
        Object::Csg(_) => None,
    }
}

/// The span of a finite or empty box's points along `direction`. Along an axis, the box's
/// sides themselves: the other axes' terms are zeros.
fn box_along(b: &Aabb, direction: DVec3) -> Span {
    if b.is_empty() {
        return Span::NOWHERE;
    }
    let (mut low, mut high) = (0.0, 0.0);
    for axis in 0..3 {
        let (a, c) = (direction[axis] * b.min[axis], direction[axis] * b.max[axis]);
        low += a.min(c);
        high += a.max(c);
    }
    Span { low, high }
}

/// The span of an unbounded object's points along `direction`: a plane of exactly that
/// normal or its opposite lies at one place; any other plane, tilted ever so little,
/// crosses every place far enough out, and so does anything that is not a plane.
fn plane_along(plane: Option<(DVec3, f64)>, direction: DVec3) -> Span {
    match plane {
        Some((normal, offset)) if normal == direction => Span {
            low: offset,
            high: offset,
        },
        Some((normal, offset)) if normal == -direction => Span {
            low: -offset,
            high: -offset,
        },
        _ => Span::EVERYWHERE,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_box_reaches_its_sides_along_an_axis_and_its_corners_along_a_slant() {
        let b = Aabb::new(DVec3::new(-1.0, 2.0, 0.5), DVec3::new(3.0, 5.0, 0.75));
        assert_eq!(
            along(&b, [], DVec3::Y),
            Span {
                low: 2.0,
                high: 5.0
            }
        );
        assert_eq!(
            along(&b, [], -DVec3::X),
            Span {
                low: -3.0,
                high: 1.0
            }
        );
        let slant = DVec3::new(1.0, -1.0, 0.0).normalize();
        let span = along(&b, [], slant);
        let corner = |c: DVec3| c.dot(slant);
        assert!((span.low - corner(DVec3::new(-1.0, 5.0, 0.0))).abs() < 1e-15);
        assert!((span.high - corner(DVec3::new(3.0, 2.0, 0.0))).abs() < 1e-15);
        assert_eq!(along(&Aabb::EMPTY, [], DVec3::Z), Span::NOWHERE);
    }

    #[test]
    fn a_plane_reaches_its_place_along_its_normal_either_way_and_everywhere_else() {
        let floor = Some((DVec3::Y, -2.0));
        let single = |place| Span {
            low: place,
            high: place,
        };
        assert_eq!(along(&Aabb::EMPTY, [floor], DVec3::Y), single(-2.0));
        assert_eq!(along(&Aabb::EMPTY, [floor], -DVec3::Y), single(2.0));
        assert_eq!(along(&Aabb::EMPTY, [floor], DVec3::X), Span::EVERYWHERE);
        // A normal that only rounds to the direction tilts the plane across every place.
        let nearly = DVec3::new(1e-9, 1.0, 0.0).normalize();
        assert_eq!(nearly.y, 1.0);
        assert_eq!(along(&Aabb::EMPTY, [floor], nearly), Span::EVERYWHERE);
        // Anything unbounded but a plane reaches everywhere, whatever the boxes.
        let b = Aabb::new(DVec3::ZERO, DVec3::ONE);
        assert_eq!(along(&b, [floor, None], DVec3::Y), Span::EVERYWHERE);
        assert_eq!(
            along(&b, [floor], DVec3::Y),
            Span {
                low: -2.0,
                high: 1.0
            }
        );
    }

    /// A point of a surface at an end, off it by a rounding, is not beyond the grown
    /// span; the start of a ray leaving it at a 2% slant, one tolerance along, is.
    #[test]
    fn the_margin_lies_between_rounding_and_a_rays_first_step() {
        for end in [0.0, 1.0, -3.5, 1e3, -1e6] {
            let grown = Span {
                low: end,
                high: end,
            }
            .grown();
            let rounded = 8.0 * f64::EPSILON * (1.0 + f64::abs(end));
            let step = 0.02 * 1e-9 * (1.0 + f64::abs(end));
            assert!(
                end + rounded < grown.high && end + step > grown.high,
                "{end}"
            );
            assert!(end - rounded > grown.low && end - step < grown.low, "{end}");
        }
        assert_eq!(Span::NOWHERE.grown(), Span::NOWHERE);
        assert_eq!(Span::EVERYWHERE.grown(), Span::EVERYWHERE);
    }
}
