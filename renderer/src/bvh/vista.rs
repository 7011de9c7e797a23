//! The objects a ray from a perspective camera's eye, or along an orthographic camera's
//! direction, may meet, by where the ray crosses the image: each bounded object's box, seen
//! from the camera, covers a rectangle of the image, and a grid of cells over the image
//! lists the objects whose rectangles reach each cell, nearest first. A camera ray then
//! tests its cell's few objects instead of walking the hierarchy, whose boxes overlap
//! heavily in scenes of a few large, tilted objects (the rings of hopf.pov) and which a
//! ray crosses node by node even in a row of small ones (the tiles of the pattern scenes).
//! POV-Ray kept such a "vista buffer" for the same reason.
//!
//! The lists hold for any ray from the eye, whatever traced it: a point `p` is seen along
//! the direction `d` when `p - eye = t d`, so in the camera's frame (`right`, `up`,
//! `direction`) both have the same image position, and `p`'s depth there bounds `t` from
//! below. Objects partly behind the eye are listed everywhere; those wholly behind it,
//! which no ray from the eye meets forwards, nowhere. Through an orthographic camera the
//! image position is the frame's across and up themselves, the same for every point of a
//! ray along the camera's direction wherever it starts, and depth grows along the ray
//! from that of its origin.

use crate::bounds::Aabb;
use crate::camera::View;
use crate::fast_math;
use crate::object::Object;
use crate::ray::{Ray, RayKind};
use glam::{DMat3, DVec2, DVec3};

/// Cells along each side of the image.
const CELLS: usize = 96;

/// The most entries the lists may hold together; beyond it (thousands of objects, or
/// many covering the whole image) the hierarchy serves camera rays instead.
const MAX_ENTRIES: usize = 1 << 18;

/// The most objects worth listing: many small objects are what the hierarchy is for.
const MAX_OBJECTS: usize = 4096;

/// A slack on image positions and depths, far beyond rounding, so that an object is
/// listed in every cell a ray meeting it may fall into.
const SLACK: f64 = 1e-9;

/// One listed object: its index among the hierarchy's objects and a lower bound of its
/// depth in the camera's frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Entry {
    pub depth: f64,
    pub index: u32,
}

#[derive(Debug, Clone, PartialEq)]
pub struct Vista {
    /// A perspective camera's eye, or the point an orthographic camera's image is centred on.
    origin: DVec3,
    /// An orthographic camera's rays' direction; `None` for a perspective camera.
    parallel: Option<DVec3>,
    /// World vectors to the camera's frame: image position across, up, and depth.
    to_frame: DMat3,
    /// The largest depth, either side of the origin, of any listed object: orthographic
    /// rays from beyond it are left to the hierarchy.
    deepest: f64,
    /// Where each cell's entries start in `entries`, row by row; one more at the end.
    starts: Vec<u32>,
    entries: Vec<Entry>,
}

/// The cell a ray falls into, the depth of its origin and the depth share of its
/// direction, which turn a depth into a ray parameter.
pub struct Cell<'v> {
    pub entries: &'v [Entry],
    pub origin_depth: f64,
    pub depth_per_t: f64,
}

impl Vista {
    /// The lists for `objects` seen through the camera `view`; `None` when its frame is
    /// degenerate or the lists would grow too long.
    pub fn build(objects: &[Object], view: View) -> Option<Vista> {
        let (origin, frame, parallel) = match view {
            View::Perspective { eye, frame } => (eye, frame, None),
            View::Orthographic {
                location,
                frame,
                ray_direction,
            } => (location, frame, Some(ray_direction)),
        };
        if objects.is_empty() || objects.len() > MAX_OBJECTS || frame.determinant() == 0.0 {
            return None;
        }
        let to_frame = frame.inverse();
        if !to_frame.is_finite() {
            return None;
        }
        // Objects nearest first, ties in their order: each cell's list keeps this order,
        // so that a ray stops at the first object deeper than its nearest crossing so far.
        let mut seen: Vec<(u32, Seen)> = objects
            .iter()
            .enumerate()
            .filter(|(_, object)| object.kinds() & RayKind::Primary.bit() != 0)
            .filter_map(|(index, object)| {
                Some((index as u32, seen_from(object, origin, to_frame, parallel)?))
            })
            .collect();
        let deepest = seen
            .iter()
            .map(|(_, seen)| seen.deepest())
            .fold(0.0, f64::max);
        if let Some(direction) = parallel
            && !stays_in_its_cells(to_frame * direction, deepest)
        {
            return None;
        }
        seen.sort_by(|(i, a), (j, b)| a.rect.min.z.total_cmp(&b.rect.min.z).then(i.cmp(j)));
        // Each cell's entries, counted and then placed.
        let mut listed: Vec<(u32, Entry)> = Vec::new();
        for (index, seen) in &seen {
            let (x0, x1) = cell_range(seen.rect.min.x, seen.rect.max.x);
            let (y0, y1) = cell_range(seen.rect.min.y, seen.rect.max.y);
            let entry = Entry {
                depth: seen.rect.min.z,
                index: *index,
            };
            for y in y0..y1 {
                let (x0, x1) = seen.row(y, (x0, x1));
                if seen.pieces.is_empty() {
                    listed.extend((x0..x1).map(|x| ((y * CELLS + x) as u32, entry)));
                    continue;
                }
                let mut covered = [false; CELLS];
                for piece in &seen.pieces {
                    if let Some((a, b)) = band(piece, y) {
                        covered[a.max(x0)..b.min(x1).max(a.max(x0))].fill(true);
                    }
                }
                listed.extend(
                    (x0..x1)
                        .filter(|&x| covered[x])
                        .map(|x| ((y * CELLS + x) as u32, entry)),
                );
            }
            if listed.len() > MAX_ENTRIES {
                return None;
            }
        }
        let mut starts = vec![0u32; CELLS * CELLS + 1];
        for &(cell, _) in &listed {
            starts[cell as usize + 1] += 1;
        }
        for cell in 0..CELLS * CELLS {
            starts[cell + 1] += starts[cell];
        }
        let mut next = starts.clone();
        let mut entries = vec![
            Entry {
                depth: 0.0,
                index: 0
            };
            listed.len()
        ];
        for (cell, entry) in listed {
            entries[next[cell as usize] as usize] = entry;
            next[cell as usize] += 1;
        }
        Some(Vista {
            origin,
            parallel,
            to_frame,
            deepest,
            starts,
            entries,
        })
    }

    /// The cell of a ray the camera may trace (from the eye, or along the orthographic
    /// camera's direction from not too far), whose objects are the only ones it may meet
    /// at a positive parameter; `None` for any other ray.
    #[inline]
    pub fn cell(&self, ray: &Ray) -> Option<Cell<'_>> {
        let (x, y, origin_depth, depth_per_t) = match self.parallel {
            None => {
                if ray.origin != self.origin {
                    return None;
                }
                let v = self.to_frame * ray.direction;
                if v.z.is_nan() || v.z <= 0.0 {
                    return None;
                }
                (v.x / v.z, v.y / v.z, 0.0, v.z)
            }
            Some(direction) => {
                if ray.direction != direction {
                    return None;
                }
                let o = self.to_frame * (ray.origin - self.origin);
                if o.z.is_nan() || o.z.abs() > self.deepest {
                    return None;
                }
                (o.x, o.y, o.z, (self.to_frame * direction).z)
            }
        };
        let x = (x + 0.5) * CELLS as f64;
        let y = (y + 0.5) * CELLS as f64;
        // Also false for NaN.
        if !(x >= 0.0 && x < CELLS as f64 && y >= 0.0 && y < CELLS as f64) {
            return None;
        }
        // Through `u32`, whose conversion from a float is cheaper than `usize`'s.
        let cell = y as u32 as usize * CELLS + x as u32 as usize;
        let (start, end) = (self.starts[cell] as usize, self.starts[cell + 1] as usize);
        Some(Cell {
            entries: &self.entries[start..end],
            origin_depth,
            depth_per_t,
        })
    }
}

/// Whether rays along `v` (a direction in the camera's frame) from no deeper than the
/// deepest listed object (`deepest`) stay within the slack of their image position until
/// they have passed every object: a direction tilted by rounding, not by the camera.
fn stays_in_its_cells(v: DVec3, deepest: f64) -> bool {
    v.z > 0.0 && 2.0 * deepest * (v.x.abs() + v.y.abs()) / v.z <= 0.5 * SLACK
}

/// Where an object may show in the image: a box of image positions (x, y) and depths (z),
/// the convex outlines of its boxes' images, counter-clockwise, in all of which it lies,
/// and those of its pieces' boxes, in one of which each of its points lies (none when it
/// is not divided into pieces).
struct Seen {
    rect: Aabb,
    outlines: Vec<Vec<DVec2>>,
    pieces: Vec<Vec<DVec2>>,
}

impl Seen {
    /// The largest depth, either side of the camera, at which the object may lie.
    fn deepest(&self) -> f64 {
        self.rect.min.z.abs().max(self.rect.max.z.abs())
    }

    /// The cells `[first, end)` of row `y`, among `cells`, that the outlines may reach.
    fn row(&self, y: usize, cells: (usize, usize)) -> (usize, usize) {
        let (mut first, mut end) = cells;
        for outline in &self.outlines {
            let Some((x0, x1)) = band(outline, y) else {
                return (0, 0);
            };
            first = first.max(x0);
            end = end.min(x1);
        }
        (first, end.max(first))
    }
}

/// The cells `[first, end)` of row `y` that a convex outline may reach; `None` when it
/// stays out of the row.
fn band(outline: &[DVec2], y: usize) -> Option<(usize, usize)> {
    let n = CELLS as f64;
    let (lo, hi) = (y as f64 / n - 0.5, (y + 1) as f64 / n - 0.5);
    let pad = SLACK * (1.0 + lo.abs().max(hi.abs()));
    let (lo, hi) = (lo - pad, hi + pad);
    // The outline's part in the row's band is convex, and its corners lie on the
    // outline's sides: its reach across is that of the sides' parts in the band.
    let (mut left, mut right) = (f64::INFINITY, f64::NEG_INFINITY);
    for (i, &a) in outline.iter().enumerate() {
        let b = outline[(i + 1) % outline.len()];
        let (mut t0, mut t1) = (0.0, 1.0);
        if a.y == b.y {
            if a.y < lo || a.y > hi {
                continue;
            }
        } else {
            let (ta, tb) = ((lo - a.y) / (b.y - a.y), (hi - a.y) / (b.y - a.y));
            t0 = fast_math::max(t0, fast_math::min(ta, tb));
            t1 = fast_math::min(t1, fast_math::max(ta, tb));
            if t0 > t1 {
                continue;
            }
        }
        for t in [t0, t1] {
            let x = a.x + (b.x - a.x) * t;
            left = fast_math::min(left, x);
            right = fast_math::max(right, x);
        }
    }
    if left > right {
        return None;
    }
    let pad = SLACK * (1.0 + left.abs().max(right.abs()));
    Some(cell_range(left - pad, right + pad))
}

/// Where `object` may show through the camera at `origin` (the eye, or the orthographic
/// camera's location when its rays are `parallel`): for a perspective camera the whole
/// image at depth -∞ for an object reaching behind the eye, `None` for one wholly behind
/// it.
fn seen_from(
    object: &Object,
    origin: DVec3,
    to_frame: DMat3,
    parallel: Option<DVec3>,
) -> Option<Seen> {
    // A leaf's own box, tilted with it, may cover less of the image than its world box;
    // the object lies in both, and so does its image.
    let tilted = match object {
        Object::Leaf(leaf) => leaf.frame_corners(),
        Object::Csg(_) => None,
    };
    let mut seen = Seen {
        rect: Aabb::INFINITE,
        outlines: Vec::new(),
        pieces: Vec::new(),
    };
    let image = |corners: &[DVec3; 8]| match parallel {
        None => project(corners, origin, to_frame),
        Some(_) => Some(project_parallel(corners, origin, to_frame)),
    };
    for corners in [Some(object.bounds().corners()), tilted]
        .into_iter()
        .flatten()
    {
        let (rect, points) = image(&corners)?;
        seen.rect = seen.rect.intersection(&rect);
        if let Some(points) = points {
            seen.outlines.push(convex_hull(&points));
        }
    }
    // A ring's arcs, seen one by one, leave out the cells of its hole and of the space
    // around it that its boxes cover. A piece wholly behind the eye shows nowhere; one
    // reaching behind it, everywhere, and then the pieces are not worth their outlines.
    if let Object::Leaf(leaf) = object
        && let Some(pieces) = leaf.piece_corners()
    {
        let mut around = Aabb::EMPTY;
        let mut outlines = Vec::with_capacity(pieces.len());
        for corners in &pieces {
            let Some((rect, points)) = image(corners) else {
                continue;
            };
            let Some(points) = points else {
                outlines.clear();
                break;
            };
            around = around.union(&rect);
            outlines.push(convex_hull(&points));
        }
        if !outlines.is_empty() {
            seen.rect = seen.rect.intersection(&around);
            seen.pieces = outlines;
        }
    }
    (!seen.rect.is_empty()).then_some(seen)
}

/// The box around the image positions and depths of a box's corners, and the positions
/// themselves; none when the box reaches behind the eye.
fn project(
    corners: &[DVec3; 8],
    eye: DVec3,
    to_frame: DMat3,
) -> Option<(Aabb, Option<[DVec2; 8]>)> {
    let everywhere = Aabb::new(
        DVec3::new(-1.0, -1.0, f64::NEG_INFINITY),
        DVec3::new(1.0, 1.0, f64::INFINITY),
    );
    let frame: [DVec3; 8] = corners.map(|c| to_frame * (c - eye));
    if frame.iter().all(|v| v.z <= 0.0) {
        return None;
    }
    // A corner at or behind the eye's plane, or so near it that its image position is
    // unreliable, leaves the box's image unbounded.
    if frame
        .iter()
        .any(|v| !v.is_finite() || v.z <= SLACK * v.length())
    {
        return Some((everywhere, None));
    }
    let points = frame.map(|v| DVec2::new(v.x / v.z, v.y / v.z));
    let mut seen = Aabb::EMPTY;
    for (p, v) in points.iter().zip(&frame) {
        let p = DVec3::new(p.x, p.y, v.z);
        seen.min = seen.min.min(p);
        seen.max = seen.max.max(p);
    }
    let pad = DVec3::new(
        SLACK * (1.0 + seen.min.x.abs().max(seen.max.x.abs())),
        SLACK * (1.0 + seen.min.y.abs().max(seen.max.y.abs())),
        SLACK * seen.min.z,
    );
    let rect = Aabb {
        min: seen.min - pad,
        max: DVec3::new(seen.max.x + pad.x, seen.max.y + pad.y, seen.max.z),
    };
    Some((rect, Some(points)))
}

/// The box around the image positions and depths of a box's corners through an
/// orthographic camera, centred on `origin`, and the positions themselves.
fn project_parallel(
    corners: &[DVec3; 8],
    origin: DVec3,
    to_frame: DMat3,
) -> (Aabb, Option<[DVec2; 8]>) {
    let frame: [DVec3; 8] = corners.map(|c| to_frame * (c - origin));
    let mut seen = Aabb::EMPTY;
    for v in &frame {
        seen.min = seen.min.min(*v);
        seen.max = seen.max.max(*v);
    }
    let pad = SLACK * (DVec3::ONE + seen.min.abs().max(seen.max.abs()));
    let rect = Aabb {
        min: seen.min - pad,
        max: seen.max + pad,
    };
    (rect, Some(frame.map(|v| DVec2::new(v.x, v.y))))
}

/// The convex hull of `points`, counter-clockwise (Andrew's monotone chain).
fn convex_hull(points: &[DVec2; 8]) -> Vec<DVec2> {
    let mut sorted = *points;
    sorted.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    let turn = |o: DVec2, a: DVec2, b: DVec2| (a - o).perp_dot(b - o);
    // The lower chain left to right, then the upper one right to left.
    let mut hull: Vec<DVec2> = Vec::with_capacity(16);
    for pass in [sorted, {
        sorted.reverse();
        sorted
    }] {
        let floor = hull.len();
        for p in pass {
            while hull.len() >= floor + 2
                && turn(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0
            {
                hull.pop();
            }
            hull.push(p);
        }
        hull.pop();
    }
    hull
}

/// The cells `[first, end)` along one side that image positions from `lo` to `hi` reach.
fn cell_range(lo: f64, hi: f64) -> (usize, usize) {
    let n = CELLS as f64;
    let first = ((lo + 0.5) * n).floor().clamp(0.0, n);
    let end = ((hi + 0.5) * n).floor().clamp(-1.0, n - 1.0) + 1.0;
    (first as usize, end.max(first) as usize)
}

#[cfg(test)]
mod tests {
    use crate::build::scene_and_world_of_source;
    use crate::camera::Camera;
    use crate::object::Query;
    use crate::ray::RayKind;

    /// The objects of the tests: tilted rings, a box reaching behind a camera at z = -6,
    /// one wholly behind it, a hidden one and a plane.
    const OBJECTS: &str = "
        torus { 1.5, 0.1 rotate <40, 20, 10> translate <-1, 0, 0> }
        torus { 1.2, 0.2 matrix <0.6,0.8,0, -0.8,0.6,0, 0,0,1, 0.5,0.2,1> }
        sphere { <1, 0.5, 0>, 0.7 }
        sphere { <0, 0, -10>, 1 }
        sphere { <0.2, 0.1, 2>, 0.3 no_image }
        box { <-3, -0.5, -8>, <-2, 0, 3> }
        union { sphere { <2, -1, 3>, 0.5 } cylinder { <2, -1, 3>, <3, 0, 4>, 0.2 } }
        plane { y, -1 }";

    /// Every camera ray of `camera` meets the same crossing of [`OBJECTS`] with the vista
    /// as through the hierarchy alone.
    fn camera_rays_meet_what_the_hierarchy_finds(camera: &str) {
        let (scene, mut world) = scene_and_world_of_source(&format!("{camera}\n{OBJECTS}"));
        let camera = Camera::from_scene(&scene.camera).unwrap();
        let plain = world.bvh.clone();
        world.bvh.view_from(camera.view());
        assert!(world.bvh.vista.is_some());
        let (width, height) = (97.0, 61.0);
        let mut scratch = Vec::new();
        let mut hits = 0;
        for y in 0..=61 {
            for x in 0..=97 {
                let ray = camera.ray(x as f64, y as f64, width, height).unwrap();
                let q = Query::new(ray, RayKind::Primary, 1e-9, f64::INFINITY);
                let listed = world.bvh.nearest(&q, &mut scratch);
                let walked = plain.nearest(&q, &mut scratch);
                assert_eq!(
                    listed.map(|h| (h.t, h.leaf.bounds, h.part)),
                    walked.map(|h| (h.t, h.leaf.bounds, h.part)),
                    "pixel ({x}, {y})"
                );
                hits += usize::from(walked.is_some());
            }
        }
        assert!(hits > 1000, "the scene is in view");
    }

    /// A ray through a ring's hole, seen at a slant, has nothing to test: the ring's
    /// arcs cover the cells around the hole, not the hole itself.
    #[test]
    fn a_ring_is_listed_around_its_hole_only() {
        let (scene, mut world) = scene_and_world_of_source(
            "camera { location <0, 0, -6> look_at <0, 0, 0> }
             torus { 1.5, 0.1 rotate <60, 0, 10> }",
        );
        let camera = Camera::from_scene(&scene.camera).unwrap();
        world.bvh.view_from(camera.view());
        let vista = world.bvh.vista.as_ref().unwrap();
        let cell = |x: f64, y: f64| vista.cell(&camera.ray(x, y, 1.0, 1.0).unwrap()).unwrap();
        assert!(cell(0.5, 0.5).entries.is_empty());
        // The ring's point (1.5, 0, 0) before its rotation, and its image.
        let (sin, cos) = 10f64.to_radians().sin_cos();
        let (x, y) = (1.5 * cos / 6.0 / 1.33, 1.5 * sin / 6.0);
        assert_eq!(cell(0.5 + x, 0.5 - y).entries.len(), 1);
    }

    #[test]
    fn perspective_camera_rays_meet_what_the_hierarchy_finds() {
        camera_rays_meet_what_the_hierarchy_finds(
            "camera { location <0, 1, -6> look_at <0, 0, 0> right -1.333*x angle 50 }",
        );
    }

    /// An orthographic camera looking down at a slant, whose rays start in front of some
    /// objects and behind others.
    #[test]
    fn orthographic_camera_rays_meet_what_the_hierarchy_finds() {
        camera_rays_meet_what_the_hierarchy_finds(
            "camera { orthographic location <1, 3, -6> look_at <0, 0, 0> right 8*x up 6*y }",
        );
    }
}
