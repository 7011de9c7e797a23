//! Where a ray is inside a convex shape: one stretch between the crossing where it enters
//! and the one where it leaves. CSG reads a child's inside along the ray from it instead of
//! testing each point of the other children's surfaces.

use super::{Root, Roots, Shape};
use crate::ray::Ray;

/// The stretch of a ray strictly inside a convex shape. Either end is infinite for a
/// plane's half-space; the stretch is empty (`enter.t > exit.t`) when the ray stays
/// outside.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Span {
    pub enter: Root,
    pub exit: Root,
}

impl Span {
    /// The stretch of a ray that never enters.
    pub const NOWHERE: Span = Span {
        enter: Root {
            t: f64::INFINITY,
            part: 0,
        },
        exit: Root {
            t: f64::NEG_INFINITY,
            part: 0,
        },
    };

    /// The stretch of a ray inside all along (one parallel to a plane, below it).
    const EVERYWHERE: Span = Span {
        enter: Root {
            t: f64::NEG_INFINITY,
            part: 0,
        },
        exit: Root {
            t: f64::INFINITY,
            part: 0,
        },
    };

    /// Whether the parameter lies strictly between the ends.
    pub fn holds(&self, t: f64) -> bool {
        self.enter.t < t && t < self.exit.t
    }

    /// The stretch between the nearest and the farthest crossing of a closed convex
    /// surface; `None` for an odd number of crossings, which only a ray grazing an edge
    /// gives (a cylinder's rim, where rounding may keep a side crossing and drop the
    /// cap's), so that its inside is tested point by point there instead.
    fn between_crossings(roots: &Roots) -> Option<Span> {
        let roots = roots.as_slice();
        if roots.len() % 2 == 1 {
            return None;
        }
        let mut span = Span::NOWHERE;
        for &r in roots {
            if r.t < span.enter.t {
                span.enter = r;
            }
            if r.t > span.exit.t {
                span.exit = r;
            }
        }
        Some(span)
    }
}

impl Shape {
    /// Whether [`Shape::convex_span`] gives the shape's stretches.
    pub fn has_convex_span(&self) -> bool {
        match self {
            Shape::Sphere(_) | Shape::Cuboid(_) | Shape::Plane(_) => true,
            Shape::Cylinder(s) => !s.open,
            Shape::Cone(s) => !s.open,
            _ => false,
        }
    }

    /// The stretch of the ray inside the shape, from the crossings [`Shape::intersect`]
    /// gives, for shapes whose inside meets every line in one stretch: a sphere, a box, a
    /// closed cylinder or cone, a plane's half-space. `None` for other shapes, whose
    /// inside must be tested point by point.
    #[inline]
    pub fn convex_span(&self, ray: &Ray) -> Option<Span> {
        match self {
            Shape::Sphere(s) => Some(s.span(ray).map_or(Span::NOWHERE, |(t1, t2)| Span {
                enter: Root { t: t1, part: 0 },
                exit: Root { t: t2, part: 0 },
            })),
            Shape::Cuboid(s) => Some(
                s.crossings(ray)
                    .map_or(Span::NOWHERE, |(enter, exit)| Span { enter, exit }),
            ),
            Shape::Cylinder(s) if !s.open => {
                let mut roots = Roots::new();
                s.intersect(ray, &mut roots);
                Span::between_crossings(&roots)
            }
            Shape::Cone(s) if !s.open => {
                let mut roots = Roots::new();
                s.intersect(ray, &mut roots);
                Span::between_crossings(&roots)
            }
            Shape::Plane(s) => Some(match s.crossing(ray) {
                // The inside is below the plane: the ray enters it when heading against
                // the normal.
                Some(t) if s.normal.dot(ray.direction) < 0.0 => Span {
                    enter: Root { t, part: 0 },
                    exit: Span::EVERYWHERE.exit,
                },
                Some(t) => Span {
                    enter: Span::EVERYWHERE.enter,
                    exit: Root { t, part: 0 },
                },
                None if s.inside(ray.origin) => Span::EVERYWHERE,
                None => Span::NOWHERE,
            }),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shapes::{Cone, Cuboid, Cylinder, Plane, Sphere};
    use glam::DVec3;

    /// Every shape that gives a span agrees with its own inside test along rays in many
    /// directions, away from the ends, and its ends are its crossings.
    #[test]
    fn spans_agree_with_inside_tests() {
        let shapes = [
            Shape::Sphere(Sphere),
            Shape::Cuboid(Cuboid::new(DVec3::new(-1.0, -0.5, -2.0), DVec3::ONE)),
            Shape::Cylinder(Cylinder { open: false }),
            Shape::Cone(Cone {
                base_radius: 1.0,
                cap_radius: 0.25,
                open: false,
            }),
            Shape::Plane(Plane::new(DVec3::new(0.6, 0.0, 0.8), 0.3)),
        ];
        let mut rays = 0;
        for shape in &shapes {
            for k in 0..200 {
                let a = k as f64 * 0.37;
                let origin = DVec3::new(3.0 * a.cos(), 0.3 * a.sin(), -3.0 + 0.01 * k as f64);
                let target = DVec3::new(0.2 * (a * 3.0).sin(), 0.1, 0.5 + 0.2 * a.cos());
                let ray = Ray::new(origin, target - origin);
                let span = shape.convex_span(&ray).expect("a convex shape");
                let mut roots = Roots::new();
                shape.intersect(&ray, &mut roots);
                if span.enter.t <= span.exit.t {
                    rays += 1;
                    for end in [span.enter, span.exit]
                        .into_iter()
                        .filter(|r| r.t.is_finite())
                    {
                        assert!(roots.as_slice().contains(&end), "{shape:?} {end:?}");
                    }
                } else {
                    assert!(roots.as_slice().is_empty(), "{shape:?}");
                }
                for i in 0..=40 {
                    let t = -2.0 + 0.2 * i as f64;
                    let near_end = [span.enter.t, span.exit.t]
                        .iter()
                        .any(|e| (e - t).abs() < 1e-9);
                    if !near_end {
                        assert_eq!(span.holds(t), shape.inside(ray.at(t)), "{shape:?} {t}");
                    }
                }
            }
        }
        assert!(rays > 300, "most rays meet the shapes: {rays}");
    }

    #[test]
    fn open_and_non_convex_shapes_give_no_span() {
        let ray = Ray::new(DVec3::new(0.0, 0.0, -3.0), DVec3::Z);
        assert!(
            Shape::Cylinder(Cylinder { open: true })
                .convex_span(&ray)
                .is_none()
        );
        let open_cone = Cone {
            base_radius: 1.0,
            cap_radius: 0.5,
            open: true,
        };
        assert!(Shape::Cone(open_cone).convex_span(&ray).is_none());
    }

    #[test]
    fn a_ray_along_a_plane_is_inside_below_it_and_outside_above() {
        let plane = Shape::Plane(Plane::new(DVec3::Y, 0.0));
        let below = Ray::new(DVec3::new(0.0, -1.0, 0.0), DVec3::X);
        let above = Ray::new(DVec3::new(0.0, 1.0, 0.0), DVec3::X);
        assert_eq!(plane.convex_span(&below), Some(Span::EVERYWHERE));
        assert_eq!(plane.convex_span(&above), Some(Span::NOWHERE));
    }
}
