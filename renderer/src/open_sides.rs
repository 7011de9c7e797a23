//! Flat surfaces with nothing on one side. A ray leaving a point of a flat surface stays on
//! the side of its plane it goes into; when no other object reaches into that side, the ray
//! meets nothing, and its answer is the background (a reflected or transmitted ray) or the
//! whole light (a shadow ray) without a search. A disc of water over a floor is one: its
//! reflections go up into the empty sky, as do its shadow rays towards a light above.
//!
//! Each standalone disc, polygon and plane is marked once, before tracing, with the sides
//! of its plane beyond the reach of all the other objects along its normal, grown by the
//! margin [`crate::reach`] explains, which a ray's point on the surface, off the exact
//! plane by a rounding, does not cross.

use crate::bounds::Aabb;
use crate::object::{Object, OpenSides};
use crate::reach;
use glam::DVec3;

/// Marks each standalone flat leaf among `objects` with the open sides of its plane.
pub fn mark_open_sides(objects: &mut [Object]) {
    // The union of the finite boxes before each object and of those after it, so that
    // each leaf finds the box of all the other bounded objects at once.
    let boxes: Vec<Aabb> = objects
        .iter()
        .map(|o| {
            Some(o.bounds())
                .filter(Aabb::is_finite)
                .unwrap_or(Aabb::EMPTY)
        })
        .collect();
    let mut before = Vec::with_capacity(boxes.len() + 1);
    let mut after = vec![Aabb::EMPTY; boxes.len() + 1];
    before.push(Aabb::EMPTY);
    for (i, b) in boxes.iter().enumerate() {
        before.push(before[i].union(b));
    }
    for (i, b) in boxes.iter().enumerate().rev() {
        after[i] = after[i + 1].union(b);
    }
    // The unbounded objects' planes, with their places among `objects`, so that a leaf
    // leaves itself out.
    let unbounded: Vec<(usize, Option<(DVec3, f64)>)> = objects
        .iter()
        .enumerate()
        .filter(|(_, o)| !o.bounds().is_empty() && !o.bounds().is_finite())
        .map(|(i, o)| (i, reach::unbounded_plane(o)))
        .collect();
    for (i, object) in objects.iter_mut().enumerate() {
        let Object::Leaf(leaf) = object else {
            continue;
        };
        if !leaf.standalone {
            continue;
        }
        let Some((normal, offset)) = leaf.flat_plane() else {
            continue;
        };
        let others = reach::along(
            &before[i].union(&after[i + 1]),
            unbounded
                .iter()
                .filter(|(j, _)| *j != i)
                .map(|&(_, plane)| plane),
            normal,
        )
        .grown();
        // Open in front (where the normal points) when the plane lies above everything
        // else, behind when below.
        leaf.open_sides = OpenSides::new(offset > others.high, offset < others.low);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::build::world_of_source;

    /// The open sides of the first flat leaf of `scene` found among the world's objects.
    fn sides_of_disc(scene: &str) -> OpenSides {
        let world = world_of_source(scene);
        world
            .bvh
            .objects()
            .find_map(|o| match o {
                Object::Leaf(leaf) if leaf.flat_plane().is_some() => Some(leaf.open_sides.flat()),
                _ => None,
            })
            .expect("a flat leaf")
    }

    #[test]
    fn a_disc_over_a_floor_is_open_above() {
        let sides = sides_of_disc(
            "disc { <0, 1, 0>, y, 2 pigment { rgb 1 } }
             sphere { <0, -1, 0>, 1 pigment { rgb 1 } }
             plane { y, -3 pigment { rgb 1 } }",
        );
        assert_eq!(sides, OpenSides::new(true, false));
    }

    #[test]
    fn an_object_reaching_across_the_plane_closes_both_sides() {
        let sides = sides_of_disc(
            "disc { <0, 1, 0>, y, 2 pigment { rgb 1 } }
             sphere { <3, 1.5, 0>, 1 pigment { rgb 1 } }",
        );
        assert_eq!(sides, OpenSides::NONE);
        // A plane tilted ever so little crosses the disc's plane somewhere.
        let sides = sides_of_disc(
            "disc { <0, 1, 0>, y, 2 pigment { rgb 1 } }
             plane { <0.001, 1, 0>, -3 pigment { rgb 1 } }",
        );
        assert_eq!(sides, OpenSides::NONE);
    }

    #[test]
    fn a_lone_disc_is_open_on_both_sides_but_not_past_a_box_touching_it() {
        let sides = sides_of_disc("disc { 0, z, 1 rotate <30, 40, 0> pigment { rgb 1 } }");
        assert_eq!(sides, OpenSides::new(true, true));
        // A box below the disc that touches its plane: the margin closes that side too.
        let sides = sides_of_disc(
            "disc { 0, y, 1 pigment { rgb 1 } }
             box { <-1, -1, -1>, <1, 0, 1> pigment { rgb 1 } }",
        );
        assert_eq!(sides, OpenSides::NONE);
    }

    /// The others' reach is grown by the margin of [`crate::reach`] before the plane is
    /// compared with it: a disc over a box's top counts as beyond it only further up.
    #[test]
    fn a_disc_is_beyond_a_box_under_it_only_past_the_margin() {
        let over = |height: f64| {
            sides_of_disc(&format!(
                "disc {{ <0, {height:e}, 0>, y, 1 pigment {{ rgb 1 }} }}
                 box {{ <-1, 0, -1>, <1, 1, 1> pigment {{ rgb 1 }} }}"
            ))
        };
        assert_eq!(over(1.0 + 1e-10), OpenSides::new(true, false));
        assert_eq!(over(1.0 + 1e-12), OpenSides::NONE);
    }

    /// Rays leaving a disc open above, reflected, refracted or towards the light, give
    /// what they give when a speck far away closes that side and every ray is searched.
    #[test]
    fn open_sides_change_no_pixel() {
        use crate::camera::Camera;
        use crate::ray::RayKind;
        use crate::tracer::Tracer;
        let scene = |speck: &str| {
            format!(
                "camera {{ location <0, 4, -5> look_at <0, -1, 0> }}
                 light_source {{ <-2, 10, -3> rgb 1 }}
                 light_source {{ <3, -10, 1> rgb 0.5 }}
                 background {{ rgb <0.2, 0.3, 0.5> }}
                 plane {{ y, -2 pigment {{ checker rgb 0.1 rgb 0.9 }} }}
                 disc {{ 0, y, 3 pigment {{ rgbt <0.8, 0.9, 1, 0.8> }}
                   finish {{ reflection 0.2 specular 0.4 }} interior {{ ior 1.33 }} }}
                 {speck}"
            )
        };
        let (open_scene, open) = crate::build::scene_and_world_of_source(&scene(""));
        let closed = world_of_source(&scene("sphere { <500, 900, 700>, 0.001 }"));
        let disc_sides = |world: &crate::tracer::World| {
            world.bvh.objects().find_map(|o| match o {
                Object::Leaf(leaf) if leaf.flat_plane().is_some() && leaf.bounds.is_finite() => {
                    Some(leaf.open_sides.flat())
                }
                _ => None,
            })
        };
        assert_eq!(disc_sides(&open), Some(OpenSides::new(true, false)));
        assert_eq!(disc_sides(&closed), Some(OpenSides::NONE));
        let camera = Camera::from_scene(&open_scene.camera).unwrap();
        let (mut a, mut b) = (Tracer::new(&open), Tracer::new(&closed));
        for y in 0..30 {
            for x in 0..40 {
                let ray = camera
                    .ray(x as f64 + 0.5, y as f64 + 0.5, 40.0, 30.0)
                    .unwrap();
                assert!(a.first_hit(&ray, RayKind::Primary).is_some());
                assert_eq!(a.trace_primary(&ray), b.trace_primary(&ray), "({x}, {y})");
            }
        }
    }

    /// Planes tell their side by their equation, whatever their infinite boxes say.
    #[test]
    fn a_plane_facing_down_above_the_disc_closes_only_the_top() {
        let sides = sides_of_disc(
            "disc { 0, y, 1 pigment { rgb 1 } }
             plane { -y, -3 pigment { rgb 1 } }",
        );
        assert_eq!(sides, OpenSides::new(false, true));
    }
}
