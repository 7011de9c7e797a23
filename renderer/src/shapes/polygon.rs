//! `polygon`: outlines in the plane z = 0 of its frame, filled by the even-odd rule, so
//! that where an even number of outlines overlap there is a hole. A polygon has no inside.

use super::Roots;
use crate::bounds::Aabb;
use crate::ray::Ray;
use glam::{DAffine3, DMat3, DVec2, DVec3};

#[derive(Debug, Clone, PartialEq)]
pub struct Polygon {
    /// Every edge of every outline, in the plane of the polygon.
    edges: Vec<(DVec2, DVec2)>,
    /// The corners of the box around the outlines in their plane, where z is 0: kept as
    /// two points of the plane, so that the shape stays within the room the `Shape` enum
    /// has for the world normal beside them.
    low: DVec2,
    high: DVec2,
    /// The unit normal in the world, which the leaf placing the shape works out once
    /// (`Leaf::new`, through [`Polygon::place`]); zero until then, or where its frame
    /// flattens the shape.
    world_normal: DVec3,
}

impl Polygon {
    /// The polygon over `outlines` (closed, in one plane) with the frame that takes its
    /// plane to z = 0; `None` when the outlines span no area.
    pub fn new(outlines: &[Vec<DVec3>]) -> Option<(Polygon, DAffine3)> {
        let normal = outlines
            .iter()
            .flat_map(|outline| {
                (0..outline.len()).map(|i| {
                    let (a, b) = (outline[i], outline[(i + 1) % outline.len()]);
                    (a - b).cross(a + b)
                })
            })
            .sum::<DVec3>()
            .try_normalize()?;
        let origin = outlines.first()?.first().copied()?;
        let (u, v) = normal.any_orthonormal_pair();
        let frame = DAffine3::from_mat3_translation(DMat3::from_cols(u, v, normal), origin);
        let to_plane = frame.inverse();
        let mut edges = Vec::new();
        let (mut lo, mut hi) = (DVec2::INFINITY, DVec2::NEG_INFINITY);
        for outline in outlines {
            let flat: Vec<DVec2> = outline
                .iter()
                .map(|p| to_plane.transform_point3(*p).truncate())
                .collect();
            for (i, a) in flat.iter().enumerate() {
                edges.push((*a, flat[(i + 1) % flat.len()]));
                lo = lo.min(*a);
                hi = hi.max(*a);
            }
        }
        let polygon = Polygon {
            edges,
            low: lo,
            high: hi,
            world_normal: DVec3::ZERO,
        };
        Some((polygon, frame))
    }

    /// The unit normal in the world that [`Polygon::place`] kept, or zero.
    pub fn world_normal(&self) -> DVec3 {
        self.world_normal
    }

    /// Keeps the unit normal in the world of the leaf that places the shape.
    pub fn place(&mut self, world_normal: DVec3) {
        self.world_normal = world_normal;
    }

    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        if ray.direction.z == 0.0 {
            return;
        }
        let t = -ray.origin.z / ray.direction.z;
        let p = ray.at(t).truncate();
        if self.contains(p) {
            roots.push(t, 0);
        }
    }

    /// The even-odd rule: a ray from `p` along +x crosses an odd number of edges.
    fn contains(&self, p: DVec2) -> bool {
        if p.cmplt(self.low).any() || p.cmpgt(self.high).any() {
            return false;
        }
        let mut odd = false;
        for (a, b) in &self.edges {
            // Each edge counts from its lower end up to, not including, its upper end,
            // so that a vertex shared by two edges is crossed once.
            if (a.y > p.y) != (b.y > p.y) {
                let x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
                if x > p.x {
                    odd = !odd;
                }
            }
        }
        odd
    }

    pub fn bounds(&self) -> Aabb {
        Aabb::new(self.low.extend(0.0), self.high.extend(0.0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn holes_follow_the_even_odd_rule() {
        // The letter P of POV-Ray's manual: an outline with a rectangular hole.
        let outer = [(0, 0), (0, 6), (4, 6), (4, 3), (1, 3), (1, 0)];
        let hole = [(1, 4), (1, 5), (3, 5), (3, 4)];
        let outline = |points: &[(i32, i32)]| -> Vec<DVec3> {
            points
                .iter()
                .map(|&(x, y)| DVec3::new(x as f64, y as f64, 2.0))
                .collect()
        };
        let (polygon, frame) = Polygon::new(&[outline(&outer), outline(&hole)]).unwrap();
        let hits = |x: f64, y: f64| {
            let local = frame.inverse();
            let ray = Ray::new(
                local.transform_point3(DVec3::new(x, y, -5.0)),
                local.transform_vector3(DVec3::Z),
            );
            let mut roots = Roots::new();
            polygon.intersect(&ray, &mut roots);
            roots.as_slice().first().map(|r| r.t)
        };
        assert_eq!(hits(0.5, 0.5), Some(7.0));
        assert_eq!(hits(2.0, 4.5), None, "inside the hole");
        assert_eq!(hits(2.0, 3.5), Some(7.0));
        assert_eq!(hits(2.0, 1.0), None, "right of the stem");
        assert!(Polygon::new(&[vec![DVec3::ZERO, DVec3::X, DVec3::X * 2.0]]).is_none());
    }
}
