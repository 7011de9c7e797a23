//! The scene's bounded objects in a bounding volume hierarchy ([`tree::Tree`]), built once
//! before tracing. Unbounded objects (planes and what contains them) are kept beside it and
//! tested for every ray.

pub mod tree;
pub mod vista;

use crate::bounds::Aabb;
use crate::camera::View;
use crate::object::{Hit, Object, Query};
use crate::ray::RayKind;
use crate::reach::{self, Span};
use crate::shapes::Shape;
use glam::DVec3;
use tree::Tree;
use vista::Vista;

/// Objects in one leaf of the tree at most: an object's own test costs about what a box
/// test does, so small leaves pay.
const LEAF_SIZE: usize = 2;

/// The scene's objects with their acceleration structure.
#[derive(Debug, Clone)]
pub struct Bvh {
    tree: Tree,
    /// The bounded objects, in the order of the tree's leaves.
    objects: Vec<Object>,
    /// The objects with an infinite box, which every search tests.
    unbounded: Vec<Object>,
    /// The kinds of rays that may meet some object (a set of
    /// [`RayKind::bit`](crate::ray::RayKind::bit)s).
    kinds: u8,
    /// The objects each ray from a perspective or orthographic camera may meet, when the
    /// camera is known (see [`Bvh::view_from`]).
    vista: Option<Vista>,
    /// A box that holds every object's surface: how far they all reach along each axis
    /// (see [`crate::reach`]), grown by its margin.
    reach: Aabb,
}

impl Bvh {
    /// The hierarchy over `objects`; those with an empty box, which no ray meets, are left
    /// out.
    pub fn build(objects: Vec<Object>) -> Bvh {
        let (mut bounded, unbounded): (Vec<Object>, Vec<Object>) = objects
            .into_iter()
            .filter(|o| !o.bounds().is_empty())
            .partition(|o| o.bounds().is_finite());
        let boxes: Vec<Aabb> = bounded.iter().map(Object::bounds).collect();
        let planes: Vec<Option<(DVec3, f64)>> =
            unbounded.iter().map(reach::unbounded_plane).collect();
        // How far every object reaches along each axis: the box whose sides shadow rays
        // may leave them all behind across.
        let all = boxes.iter().fold(Aabb::EMPTY, |all, b| all.union(b));
        let spans = [DVec3::X, DVec3::Y, DVec3::Z]
            .map(|axis| reach::along(&all, planes.iter().copied(), axis));
        mark_reach_sides(&mut bounded, &spans, &planes);
        let (mut tree, order) = Tree::build(&boxes, LEAF_SIZE);
        let mut slots: Vec<Option<Object>> = bounded.into_iter().map(Some).collect();
        let objects: Vec<Object> = order
            .iter()
            .filter_map(|&i| slots[i as usize].take())
            .collect();
        tree.restrict_kinds(|i| objects[i].kinds());
        let kinds = objects
            .iter()
            .chain(&unbounded)
            .fold(0, |set, o| set | o.kinds());
        let grown = spans.map(Span::grown);
        let reach = Aabb {
            min: DVec3::from_array(grown.map(|s| s.low)),
            max: DVec3::from_array(grown.map(|s| s.high)),
        };
        Bvh {
            tree,
            objects,
            unbounded,
            kinds,
            vista: None,
            reach,
        }
    }

    /// Whether the ray from `origin` along `direction` meets no object from `tmin` on, as
    /// a search would find, told without one: along some axis the ray moves away from
    /// every object, across a side among `sides` of the box they all reach (grown by the
    /// margin [`crate::reach`] explains), beyond which it already is at `tmin`. Shadow
    /// rays from the faces of a scene's objects that all stand on one plane, towards a
    /// light in front of it, go this way. `sides` are bits, low x, y, z then high x, y, z:
    /// those a leaf's box reaches ([`crate::object::OpenSides::reach`]), which a ray from
    /// its surface may cross at once.
    pub fn left_behind(&self, sides: u8, origin: DVec3, direction: DVec3, tmin: f64) -> bool {
        let start = origin + direction * tmin;
        let below = start.cmplt(self.reach.min) & direction.cmplt(DVec3::ZERO);
        let above = start.cmpgt(self.reach.max) & direction.cmpgt(DVec3::ZERO);
        (below.bitmask() | above.bitmask() << 3) & u32::from(sides) != 0
    }

    /// Lists the objects the rays of a perspective or orthographic camera may meet, by
    /// where they cross the image, for the camera rays' searches; `None` for another
    /// camera.
    pub fn view_from(&mut self, view: Option<View>) {
        self.vista = view.and_then(|view| Vista::build(&self.objects, view));
    }

    /// Whether rays of `kind` may meet some object: shadow rays meet none in a scene
    /// whose every object is `no_shadow`.
    pub fn seen_by(&self, kind: RayKind) -> bool {
        self.kinds & kind.bit() != 0
    }

    /// Whether `p` is inside any object.
    pub fn contains(&self, p: DVec3) -> bool {
        self.objects().any(|o| o.inside(p))
    }

    /// Every object, bounded or not.
    pub fn objects(&self) -> impl Iterator<Item = &Object> {
        self.objects.iter().chain(&self.unbounded)
    }

    /// The bytes of the hierarchy's nodes.
    pub fn memory(&self) -> usize {
        self.tree.memory()
    }

    /// Whether some object is unbounded (a plane, say).
    pub fn has_unbounded(&self) -> bool {
        !self.unbounded.is_empty()
    }

    /// Bounds of every bounded object; empty when there is none.
    pub fn bounds(&self) -> Aabb {
        self.tree.bounds()
    }

    /// The nearest crossing of any object inside the query's interval.
    pub fn nearest<'a>(&'a self, q: &Query, scratch: &mut Vec<Hit<'a>>) -> Option<Hit<'a>> {
        if q.kind == RayKind::Primary
            && q.tmin >= 0.0
            && let Some(vista) = &self.vista
            && let Some(cell) = vista.cell(&q.ray)
        {
            return self.nearest_listed(q, scratch, &cell);
        }
        self.search(q, scratch, false)
    }

    /// [`Bvh::nearest`] for a ray the camera may trace, among the unbounded objects and
    /// those its cell of the vista lists, nearest first, until the next lies beyond the
    /// nearest crossing found.
    fn nearest_listed<'a>(
        &'a self,
        q: &Query,
        scratch: &mut Vec<Hit<'a>>,
        cell: &vista::Cell<'_>,
    ) -> Option<Hit<'a>> {
        let mut tmax = q.tmax;
        let mut best = None;
        for object in &self.unbounded {
            if let Some(hit) = nearest_of(object, q, tmax, scratch) {
                take(&mut best, hit, &mut tmax, false);
            }
        }
        for entry in cell.entries {
            if entry.depth >= cell.origin_depth + tmax * cell.depth_per_t {
                break;
            }
            if let Some(hit) = nearest_of(&self.objects[entry.index as usize], q, tmax, scratch) {
                take(&mut best, hit, &mut tmax, false);
            }
        }
        best
    }

    /// What a shadow ray meets inside the query's interval: a crossing of an opaque leaf
    /// when there is one (the first found, not necessarily the nearest: it blocks the light
    /// wherever it lies), otherwise the nearest crossing, which filters the light.
    pub fn occluder<'a>(&'a self, q: &Query, scratch: &mut Vec<Hit<'a>>) -> Option<Hit<'a>> {
        self.search(q, scratch, true)
    }

    /// The nearest crossing inside the query's interval or, with `opaque_ends`, the first
    /// crossing of an opaque leaf found. Such a search cannot narrow the interval to the
    /// nearest transparent crossing, since an opaque one may lie beyond it. Kept out of
    /// line, so that the interpreted plugin's calls of [`Bvh::nearest`] for camera rays,
    /// which the vista serves, set up no room for it; and called by `nearest` itself,
    /// not through a function of its own, which cost every other ray a second call.
    #[inline(never)]
    fn search<'a>(
        &'a self,
        q: &Query,
        scratch: &mut Vec<Hit<'a>>,
        opaque_ends: bool,
    ) -> Option<Hit<'a>> {
        let mut tmax = q.tmax;
        let mut best = None;
        for object in &self.unbounded {
            if let Some(hit) = nearest_of(object, q, tmax, scratch)
                && take(&mut best, hit, &mut tmax, opaque_ends)
            {
                return best;
            }
        }
        self.tree.traverse(
            &q.ray,
            q.inv_dir,
            q.tmin,
            tmax,
            q.kind.bit(),
            |range, end| {
                tmax = end;
                for object in &self.objects[range] {
                    if let Some(hit) = nearest_of(object, q, tmax, scratch)
                        && take(&mut best, hit, &mut tmax, opaque_ends)
                    {
                        return f64::NEG_INFINITY;
                    }
                }
                tmax
            },
        );
        best
    }
}

/// Marks each box among `objects` with the ends of `spans` (how far every object reaches
/// along x, y and z) that one of its faces lies on, to within far more than the step a
/// ray from its surface takes to its `tmin`: the sides of the reach that rays from that
/// face may leave every object behind across. The nearness is generous, since a mark only
/// lets [`Bvh::left_behind`] be asked, which tells exactly on its own. Other shapes touch
/// a side of their box at a point or a line at most, where few rays start, and are not
/// marked: their shadow rays would pay for the test and never gain. Nor are the sides
/// where one of the unbounded objects' `planes` lies: a face on a floor is covered by it.
fn mark_reach_sides(objects: &mut [Object], spans: &[Span; 3], planes: &[Option<(DVec3, f64)>]) {
    // Only a finite side is one to leave every object behind across; by this measure every
    // place would be near an infinite one.
    let near = |a: f64, b: f64| b.is_finite() && (a - b).abs() <= 1e-6 * (1.0 + b.abs());
    // Where along each axis a plane lies: those whose normal is that axis, either way.
    let places: [Vec<f64>; 3] = [DVec3::X, DVec3::Y, DVec3::Z].map(|axis| {
        planes
            .iter()
            .map(|&plane| reach::along(&Aabb::EMPTY, [plane], axis))
            .filter(|span| span.low == span.high)
            .map(|span| span.low)
            .collect()
    });
    for object in objects {
        let Object::Leaf(leaf) = object else {
            continue;
        };
        if !matches!(leaf.shape, Shape::Cuboid(_)) {
            continue;
        }
        // A box with a frame of its own has a face on a side when four of its corners lie
        // there; without one, it is its own world box.
        let corners = leaf.frame_corners();
        let face_on = |axis: usize, side: f64| {
            corners.is_none_or(|c| c.iter().filter(|c| near(c[axis], side)).count() >= 4)
                && !places[axis].iter().any(|&place| near(place, side))
        };
        let mut sides = 0;
        for (axis, span) in spans.iter().enumerate() {
            if near(leaf.bounds.min[axis], span.low) && face_on(axis, span.low) {
                sides |= 1 << axis;
            }
            if near(leaf.bounds.max[axis], span.high) && face_on(axis, span.high) {
                sides |= 8 << axis;
            }
        }
        leaf.open_sides = leaf.open_sides.with_reach(sides);
    }
}

/// [`Object::nearest`] inside the query's interval ended at `tmax` (the searches keep
/// the end they narrow apart from the query, which they do not copy), with a leaf, most
/// objects, tested here without a call: the call's frame, sized for CSG nodes, costs the
/// interpreted plugin more than a leaf's own test. A clip by convex shapes goes to its
/// own search directly, for the same reason. A CSG node's search takes the query itself
/// while its end is not narrowed, as for the first object a ray meets, and a narrowed
/// copy only after that.
#[inline(always)]
fn nearest_of<'a>(
    object: &'a Object,
    q: &Query,
    tmax: f64,
    scratch: &mut Vec<Hit<'a>>,
) -> Option<Hit<'a>> {
    let csg = match object {
        Object::Leaf(leaf) => return leaf.nearest_in(q, q.tmin, tmax),
        Object::Csg(csg) => csg,
    };
    let narrowed;
    let q = if tmax == q.tmax {
        q
    } else {
        narrowed = Query { tmax, ..*q };
        &narrowed
    };
    if csg.convex_clip {
        csg.nearest_clipped(q, scratch)
    } else {
        object.nearest(q, scratch)
    }
}

/// Keeps `hit` in `best` if it is nearer, narrowing the interval's end `tmax` to it
/// unless `opaque_ends`; `true` when the search ends with it.
#[inline]
fn take<'a>(best: &mut Option<Hit<'a>>, hit: Hit<'a>, tmax: &mut f64, opaque_ends: bool) -> bool {
    if opaque_ends && !hit.leaf.transmits {
        *best = Some(hit);
        return true;
    }
    if best.is_none_or(|b| hit.t < b.t) {
        *best = Some(hit);
        if !opaque_ends {
            *tmax = hit.t;
        }
    }
    false
}

#[cfg(test)]
mod tests {
    use crate::build::world_of_source as world;
    use crate::object::Query;
    use crate::ray::{Ray, RayKind};
    use crate::tracer::World;
    use glam::DVec3;

    #[test]
    fn rays_leave_every_object_behind_only_beyond_their_reach() {
        const ALL: u8 = 0b11_1111;
        let objects = "box { <0, 0, 0>, <1, 1, 1> pigment { rgb 1 } }
                       sphere { <3, 0.5, 0.5>, 0.5 pigment { rgb 1 } }";
        let bvh = &world(objects).bvh;
        // The box lies on every side but high x, where the sphere lies; the sphere is
        // not marked.
        let sides: Vec<u8> = bvh
            .objects()
            .filter_map(|o| match o {
                crate::object::Object::Leaf(leaf) => Some(leaf.open_sides.reach()),
                crate::object::Object::Csg(_) => None,
            })
            .collect();
        assert!(
            sides.contains(&0b11_0111) && sides.contains(&0),
            "{sides:?}"
        );
        // A box turned about z lies on the sides across z only.
        let turned = world(
            "box { <0, 0, 0>, <1, 1, 1> rotate z * 30 pigment { rgb 1 } }
             sphere { <3, 0.5, 0.5>, 0.5 pigment { rgb 1 } }",
        );
        assert!(turned.bvh.objects().any(|o| matches!(
            o,
            crate::object::Object::Leaf(leaf) if leaf.open_sides.reach() == 0b10_0100
        )));
        let (tmin, face) = (1e-9, DVec3::new(0.5, 0.5, 0.0));
        // From the face at z = 0, which every object stands behind, away from them.
        let away = DVec3::new(0.1, 0.2, -1.0).normalize();
        assert!(bvh.left_behind(ALL, face, away, tmin));
        // The reach is grown by the margin of `crate::reach`: a ray that starts within it
        // of the face is left to the search.
        assert!(bvh.left_behind(ALL, face, away, 1e-10));
        assert!(!bvh.left_behind(ALL, face - DVec3::Z * 1e-12, away, 0.0));
        // Along the face or into it, the search decides; so it does from the other side.
        assert!(!bvh.left_behind(ALL, face, DVec3::X, tmin));
        assert!(!bvh.left_behind(ALL, face, DVec3::Z, tmin));
        assert!(!bvh.left_behind(ALL, DVec3::new(0.5, 0.5, 1.0), -DVec3::Z, tmin));
        // A floor reaches everywhere along x and z, and only to its height along y; the
        // box's face on it is not marked.
        // The sides a floor makes infinite are not marked either: only the box's top is.
        let floored = world(&format!("{objects} plane {{ y, 0 pigment {{ rgb 1 }} }}"));
        assert!(floored.bvh.objects().all(|o| match o {
            crate::object::Object::Leaf(leaf) => leaf.open_sides.reach() & !0b01_0000 == 0,
            crate::object::Object::Csg(_) => true,
        }));
        let bvh = &world(&format!("{objects} plane {{ y, 0 pigment {{ rgb 1 }} }}")).bvh;
        assert!(!bvh.left_behind(ALL, face, away, tmin));
        assert!(bvh.left_behind(ALL, DVec3::new(0.5, 1.0, 0.5), DVec3::Y, tmin));
        // A tilted plane reaches everywhere, and no side is marked.
        let bvh = &world(&format!(
            "{objects} plane {{ <0, 1, 0.1>, 0 pigment {{ rgb 1 }} }}"
        ))
        .bvh;
        assert!(bvh.objects().all(|o| match o {
            crate::object::Object::Leaf(leaf) => leaf.open_sides.reach() == 0,
            crate::object::Object::Csg(_) => true,
        }));
        assert!(!bvh.left_behind(ALL, DVec3::new(0.5, 1.0, 0.5), DVec3::Y, tmin));
    }

    /// Whatever the scene, a ray `left_behind` answers for meets nothing in the search:
    /// planes facing down, inverse, translated or nearly along an axis, CSG, and rays
    /// from all over, most of them from the boxes' faces.
    #[test]
    fn a_ray_left_behind_meets_nothing() {
        const ALL: u8 = 0b11_1111;
        let boxes = "box { <0, 0, 0>, <1, 1, 1> pigment { rgb 1 } }
                     box { <2, 0, 0>, <3, 2, 1> translate <0, 0, 0.5> pigment { rgb 1 } }";
        let extras = [
            "",
            "plane { -y, 0 pigment { rgb 1 } }",
            "plane { y, 0 inverse pigment { rgb 1 } }",
            "plane { y, 0 translate <0, -0.5, 0> pigment { rgb 1 } }",
            "plane { <1e-9, 1, 0>, 0 pigment { rgb 1 } }",
            "union { plane { z, -1 } sphere { <5, 5, 5>, 1 } pigment { rgb 1 } }",
            "difference { box { <-1, -1, -1>, <4, 3, 2> } sphere { <1, 1, 1>, 0.5 } pigment { rgb 1 } }",
        ];
        // A fixed hash of the ray's index, so the test is the same every run.
        let unit = |i: u64, k: u64| {
            let h = (i * 6 + k + 1).wrapping_mul(0x9e37_79b9_7f4a_7c15) >> 11;
            h as f64 / (1u64 << 53) as f64
        };
        for extra in extras {
            let world = world(&format!("{boxes} {extra}"));
            let mut scratch = Vec::new();
            let mut answered = 0;
            for i in 0..4000u64 {
                let corner = DVec3::new(3.0 * unit(i, 0), 2.0 * unit(i, 1), 1.5 * unit(i, 2));
                // Snap one coordinate onto a box face's plane (0 or 1.5, the scene's ends).
                let mut origin = corner;
                let axis = (i % 3) as usize;
                origin[axis] = if i % 2 == 0 {
                    0.0
                } else {
                    [3.0, 2.0, 1.5][axis]
                };
                let direction = DVec3::new(unit(i, 3) - 0.5, unit(i, 4) - 0.5, unit(i, 5) - 0.5)
                    .normalize_or_zero();
                if direction == DVec3::ZERO {
                    continue;
                }
                let tmin = 1e-9;
                if world.bvh.left_behind(ALL, origin, direction, tmin) {
                    answered += 1;
                    let q = Query::new(
                        Ray::new(origin, direction),
                        RayKind::Shadow,
                        tmin,
                        f64::INFINITY,
                    );
                    assert!(
                        world.bvh.nearest(&q, &mut scratch).is_none(),
                        "{extra}: {origin} {direction}"
                    );
                }
            }
            // The scenes without an unbounded object, or with one plane along an axis,
            // do answer for some rays.
            if extra.is_empty() || extra.starts_with("plane { -y") {
                assert!(answered > 0, "{extra}");
            }
        }
    }

    /// Where along +z from z = -10 the search ends, and whether what it met is opaque.
    fn along_z(world: &World, occluder: bool) -> Option<(f64, bool)> {
        let ray = Ray::new(DVec3::new(0.0, 0.0, -10.0), DVec3::Z);
        let q = Query::new(ray, RayKind::Shadow, 1e-9, f64::INFINITY);
        let mut scratch = Vec::new();
        let hit = if occluder {
            world.bvh.occluder(&q, &mut scratch)
        } else {
            world.bvh.nearest(&q, &mut scratch)
        };
        hit.map(|h| (h.t, !h.leaf.transmits))
    }

    #[test]
    fn the_occluder_is_an_opaque_crossing_before_a_nearer_transparent_one() {
        let glass = "sphere { <0, 0, -4>, 1 pigment { rgbf 0.9 } }";
        let wall = "box { <-1, -1, 2>, <1, 1, 3> pigment { rgb 1 } }";
        let both = world(&format!("{glass}\n{wall}"));
        assert_eq!(along_z(&both, false), Some((5.0, false)));
        assert_eq!(along_z(&both, true), Some((12.0, true)));
        // Without an opaque object the occluder is the nearest crossing, and without
        // anything on the way there is none.
        let glass_only = world(glass);
        assert_eq!(along_z(&glass_only, true), Some((5.0, false)));
        assert_eq!(along_z(&world("sphere { <5, 0, 0>, 1 }"), true), None);
    }
}
