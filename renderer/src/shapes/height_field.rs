//! `height_field`: a grid of heights over the unit square, each cell of four neighbouring
//! samples split into two triangles. A ray walks the cells it passes over in order (a 2-D
//! digital differential analyser), first over blocks of cells whose lowest and highest
//! samples let it skip the blocks it passes above or below, then over the cells of the
//! blocks it may hit; the first triangle crossed ends the walk. `smooth` interpolates
//! normals made from the neighbouring samples; `water_level` drops what lies below it.
//!
//! The walk happens in grid space, where cells are unit squares: x and z scaled by the
//! number of cells, which keeps the ray parameter unchanged.

use super::{Root, Roots};
use crate::bounds::Aabb;
use crate::ray::Ray;
use analysis::scene::math_shapes;
use glam::DVec3;
use std::ops::ControlFlow;

/// Cells per side of a block of the coarse level.
const BLOCK: usize = 8;

#[derive(Debug, Clone, PartialEq)]
pub struct HeightField {
    /// Samples across (x) and along (z).
    columns: usize,
    rows: usize,
    heights: std::sync::Arc<[f32]>,
    smooth: bool,
    water_level: f64,
    /// The lowest and highest sample of each block, when the field has more than one.
    blocks: Option<Blocks>,
    /// The box the surface lies in, in grid space.
    low: f64,
    high: f64,
}

#[derive(Debug, Clone, PartialEq)]
struct Blocks {
    across: usize,
    along: usize,
    ranges: Vec<(f32, f32)>,
}

impl HeightField {
    /// The runtime field; `None` when no part of it lies above the water level.
    pub fn new(field: &math_shapes::HeightField) -> Option<HeightField> {
        let (columns, rows) = (field.columns, field.rows);
        if columns < 2 || rows < 2 || field.heights.len() != columns * rows {
            return None;
        }
        let (low, high) = field
            .heights
            .iter()
            .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), &h| {
                (lo.min(h), hi.max(h))
            });
        let (low, high) = (f64::from(low).max(field.water_level), f64::from(high));
        if high < field.water_level {
            return None;
        }
        let mut shape = HeightField {
            columns,
            rows,
            heights: field.heights.clone(),
            smooth: field.smooth,
            water_level: field.water_level,
            blocks: None,
            low,
            high,
        };
        let cells = (columns - 1).max(rows - 1);
        if field.hierarchy && cells > BLOCK {
            shape.blocks = Some(shape.block_ranges());
        }
        Some(shape)
    }

    fn block_ranges(&self) -> Blocks {
        let across = (self.columns - 1).div_ceil(BLOCK);
        let along = (self.rows - 1).div_ceil(BLOCK);
        let mut ranges = Vec::with_capacity(across * along);
        for bz in 0..along {
            for bx in 0..across {
                let mut range = (f32::INFINITY, f32::NEG_INFINITY);
                // A block's cells reach one sample past its last cell.
                for z in bz * BLOCK..=((bz + 1) * BLOCK).min(self.rows - 1) {
                    for x in bx * BLOCK..=((bx + 1) * BLOCK).min(self.columns - 1) {
                        let h = self.height(x, z);
                        range = (range.0.min(h), range.1.max(h));
                    }
                }
                ranges.push(range);
            }
        }
        Blocks {
            across,
            along,
            ranges,
        }
    }

    fn height(&self, x: usize, z: usize) -> f32 {
        self.heights[z * self.columns + x]
    }

    /// The sample at grid point (x, z) as a point of grid space.
    fn vertex(&self, x: usize, z: usize) -> DVec3 {
        DVec3::new(x as f64, f64::from(self.height(x, z)), z as f64)
    }

    fn cells(&self) -> (usize, usize) {
        (self.columns - 1, self.rows - 1)
    }

    /// The ray in grid space.
    fn to_grid(&self, ray: &Ray) -> (DVec3, DVec3) {
        let (cx, cz) = self.cells();
        let scale = DVec3::new(cx as f64, 1.0, cz as f64);
        (ray.origin * scale, ray.direction * scale)
    }

    pub fn bounds(&self) -> Aabb {
        Aabb::new(
            DVec3::new(0.0, self.low, 0.0),
            DVec3::new(1.0, self.high, 1.0),
        )
    }

    /// Calls `hit` with each crossing in order along the ray until it breaks.
    fn walk(&self, ray: &Ray, tmin: f64, tmax: f64, hit: &mut impl FnMut(f64) -> ControlFlow<()>) {
        let (origin, direction) = self.to_grid(ray);
        let (cx, cz) = self.cells();
        let inverse = direction.recip();
        let grid_box = Aabb::new(
            DVec3::new(0.0, self.low, 0.0),
            DVec3::new(cx as f64, self.high, cz as f64),
        );
        let grid_ray = Ray::new(origin, direction);
        let Some((t0, t1)) = grid_box.clip(&grid_ray, inverse, tmin, tmax) else {
            return;
        };
        let spans = |t0: f64, t1: f64, low: f32, high: f32| {
            let (y0, y1) = (origin.y + direction.y * t0, origin.y + direction.y * t1);
            y0.min(y1) <= f64::from(high) && y0.max(y1) >= f64::from(low)
        };
        let mut in_cells = |x0: usize, z0: usize, x1: usize, z1: usize, t0: f64, t1: f64| {
            cell_walk(
                origin,
                direction,
                t0,
                t1,
                1.0,
                (x0, z0),
                (x1, z1),
                &mut |x, z, ta, tb| {
                    let (a, b, c, d) = (
                        self.height(x, z),
                        self.height(x + 1, z),
                        self.height(x, z + 1),
                        self.height(x + 1, z + 1),
                    );
                    if !spans(ta, tb, a.min(b).min(c).min(d), a.max(b).max(c).max(d)) {
                        return ControlFlow::Continue(());
                    }
                    self.cell_crossings(origin, direction, x, z, ta, tb, hit)
                },
            )
        };
        match &self.blocks {
            None => {
                let _ = in_cells(0, 0, cx, cz, t0, t1);
            }
            Some(blocks) => {
                let _ = cell_walk(
                    origin,
                    direction,
                    t0,
                    t1,
                    BLOCK as f64,
                    (0, 0),
                    (blocks.across, blocks.along),
                    &mut |bx, bz, ta, tb| {
                        let (low, high) = blocks.ranges[bz * blocks.across + bx];
                        if !spans(ta, tb, low, high) {
                            return ControlFlow::Continue(());
                        }
                        let x1 = ((bx + 1) * BLOCK).min(cx);
                        let z1 = ((bz + 1) * BLOCK).min(cz);
                        in_cells(bx * BLOCK, bz * BLOCK, x1, z1, ta, tb)
                    },
                );
            }
        }
    }

    /// The crossings with the two triangles of cell (x, z) within `[ta, tb]`, nearest first.
    #[allow(clippy::too_many_arguments)]
    fn cell_crossings(
        &self,
        origin: DVec3,
        direction: DVec3,
        x: usize,
        z: usize,
        ta: f64,
        tb: f64,
        hit: &mut impl FnMut(f64) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        let p00 = self.vertex(x, z);
        let p10 = self.vertex(x + 1, z);
        let p01 = self.vertex(x, z + 1);
        let p11 = self.vertex(x + 1, z + 1);
        let mut found = [f64::NAN; 2];
        // Each cell is split along its diagonal from (x + 1, z) to (x, z + 1), as POV-Ray
        // splits it (measured with trace()).
        for (slot, [a, b, c]) in [[p00, p10, p01], [p10, p11, p01]].into_iter().enumerate() {
            if let Some(t) = triangle_crossing(origin, direction, a, b, c)
                // A little slack keeps crossings on the cell's edges in one of the cells.
                && t >= ta - 1e-9
                && t <= tb + 1e-9
                && origin.y + direction.y * t >= self.water_level
            {
                found[slot] = t;
            }
        }
        if found[0] > found[1] {
            found.swap(0, 1);
        }
        for t in found {
            if t.is_finite() {
                hit(t)?;
            }
        }
        ControlFlow::Continue(())
    }

    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        self.walk(ray, f64::NEG_INFINITY, f64::INFINITY, &mut |t| {
            roots.push(t, 0);
            ControlFlow::Continue(())
        });
    }

    pub fn first_hit(&self, ray: &Ray, tmin: f64, tmax: f64) -> Option<Root> {
        let mut first = None;
        self.walk(ray, tmin, tmax, &mut |t| {
            if t > tmin && t < tmax {
                first = Some(Root { t, part: 0 });
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        });
        first
    }

    /// Below the surface, over the unit square.
    pub fn inside(&self, p: DVec3) -> bool {
        if !(0.0..=1.0).contains(&p.x) || !(0.0..=1.0).contains(&p.z) || p.y < 0.0 {
            return false;
        }
        let (x, z, fx, fz) = self.locate(p);
        let (h00, h10, h01, h11) = (
            f64::from(self.height(x, z)),
            f64::from(self.height(x + 1, z)),
            f64::from(self.height(x, z + 1)),
            f64::from(self.height(x + 1, z + 1)),
        );
        let surface = if fx + fz <= 1.0 {
            h00 + (h10 - h00) * fx + (h01 - h00) * fz
        } else {
            h11 + (h11 - h01) * (fx - 1.0) + (h11 - h10) * (fz - 1.0)
        };
        p.y < surface
    }

    /// The cell of a local point and the position within it.
    fn locate(&self, p: DVec3) -> (usize, usize, f64, f64) {
        let (cx, cz) = self.cells();
        let gx = (p.x * cx as f64).clamp(0.0, cx as f64);
        let gz = (p.z * cz as f64).clamp(0.0, cz as f64);
        let x = (gx.floor() as usize).min(cx - 1);
        let z = (gz.floor() as usize).min(cz - 1);
        (x, z, gx - x as f64, gz - z as f64)
    }

    /// The normal at a surface point: the triangle's, or with `smooth` the sample normals
    /// interpolated across it.
    pub fn normal(&self, p: DVec3) -> DVec3 {
        let (cx, cz) = self.cells();
        let (x, z, fx, fz) = self.locate(p);
        let grid_normal = if self.smooth {
            let n = |x: usize, z: usize| self.sample_normal(x, z);
            let (n00, n10, n01, n11) = (n(x, z), n(x + 1, z), n(x, z + 1), n(x + 1, z + 1));
            if fx + fz <= 1.0 {
                n00 * (1.0 - fx - fz) + n10 * fx + n01 * fz
            } else {
                n11 * (fx + fz - 1.0) + n01 * (1.0 - fx) + n10 * (1.0 - fz)
            }
        } else {
            let (p10, p01) = (self.vertex(x + 1, z), self.vertex(x, z + 1));
            if fx + fz <= 1.0 {
                let p00 = self.vertex(x, z);
                (p01 - p00).cross(p10 - p00)
            } else {
                let p11 = self.vertex(x + 1, z + 1);
                (p10 - p11).cross(p01 - p11)
            }
        };
        // Normals of grid space back to the unit square: the transpose of the scaling.
        let n = DVec3::new(
            grid_normal.x * cx as f64,
            grid_normal.y,
            grid_normal.z * cz as f64,
        );
        if n.y < 0.0 { -n } else { n }
    }

    /// The normal at a sample, from its neighbours' heights, in grid space.
    fn sample_normal(&self, x: usize, z: usize) -> DVec3 {
        let h = |x: usize, z: usize| f64::from(self.height(x, z));
        let (x0, x1) = (x.saturating_sub(1), (x + 1).min(self.columns - 1));
        let (z0, z1) = (z.saturating_sub(1), (z + 1).min(self.rows - 1));
        let dx = (h(x1, z) - h(x0, z)) / (x1 - x0) as f64;
        let dz = (h(x, z1) - h(x, z0)) / (z1 - z0) as f64;
        DVec3::new(-dx, 1.0, -dz)
    }
}

/// Walks the cells of size `size` (in grid units) that the ray crosses between `t0` and
/// `t1`, within cells `from` (inclusive) to `to` (exclusive), calling `visit` with each
/// cell and the ray's parameters where it enters and leaves it.
#[allow(clippy::too_many_arguments)]
fn cell_walk(
    origin: DVec3,
    direction: DVec3,
    t0: f64,
    t1: f64,
    size: f64,
    from: (usize, usize),
    to: (usize, usize),
    visit: &mut impl FnMut(usize, usize, f64, f64) -> ControlFlow<()>,
) -> ControlFlow<()> {
    if to.0 <= from.0 || to.1 <= from.1 || t1 < t0 {
        return ControlFlow::Continue(());
    }
    let start = origin + direction * t0;
    let cell_of =
        |v: f64, lo: usize, hi: usize| ((v / size).floor().max(lo as f64) as usize).min(hi - 1);
    let mut x = cell_of(start.x, from.0, to.0);
    let mut z = cell_of(start.z, from.1, to.1);
    // The parameter at which the ray next crosses a cell boundary, along each axis.
    let boundary = |cell: usize, o: f64, d: f64| -> (f64, f64) {
        if d > 0.0 {
            ((((cell + 1) as f64) * size - o) / d, size / d)
        } else if d < 0.0 {
            (((cell as f64) * size - o) / d, -size / d)
        } else {
            (f64::INFINITY, f64::INFINITY)
        }
    };
    let (mut next_x, step_x) = boundary(x, origin.x, direction.x);
    let (mut next_z, step_z) = boundary(z, origin.z, direction.z);
    let mut t = t0;
    loop {
        let leave = next_x.min(next_z).min(t1);
        visit(x, z, t, leave)?;
        if leave >= t1 {
            return ControlFlow::Continue(());
        }
        t = leave;
        if next_x <= next_z {
            next_x += step_x;
            if direction.x > 0.0 {
                x += 1;
                if x >= to.0 {
                    return ControlFlow::Continue(());
                }
            } else {
                if x == from.0 {
                    return ControlFlow::Continue(());
                }
                x -= 1;
            }
        } else {
            next_z += step_z;
            if direction.z > 0.0 {
                z += 1;
                if z >= to.1 {
                    return ControlFlow::Continue(());
                }
            } else {
                if z == from.1 {
                    return ControlFlow::Continue(());
                }
                z -= 1;
            }
        }
    }
}

/// Where the ray crosses triangle abc (Möller and Trumbore's test), from either side.
fn triangle_crossing(origin: DVec3, direction: DVec3, a: DVec3, b: DVec3, c: DVec3) -> Option<f64> {
    let e1 = b - a;
    let e2 = c - a;
    let p = direction.cross(e2);
    let det = e1.dot(p);
    if det.abs() < 1e-300 {
        return None;
    }
    let inverse = 1.0 / det;
    let s = origin - a;
    let u = s.dot(p) * inverse;
    if !(-1e-12..=1.0 + 1e-12).contains(&u) {
        return None;
    }
    let q = s.cross(e1);
    let v = direction.dot(q) * inverse;
    if v < -1e-12 || u + v > 1.0 + 1e-12 {
        return None;
    }
    Some(e2.dot(q) * inverse)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn field(
        columns: usize,
        rows: usize,
        f: impl Fn(f64, f64) -> f64,
        hierarchy: bool,
    ) -> HeightField {
        let mut heights = Vec::new();
        for z in 0..rows {
            for x in 0..columns {
                heights.push(f(
                    x as f64 / (columns - 1) as f64,
                    z as f64 / (rows - 1) as f64,
                ) as f32);
            }
        }
        HeightField::new(&math_shapes::HeightField {
            columns,
            rows,
            heights: heights.into(),
            smooth: false,
            water_level: 0.0,
            hierarchy,
        })
        .unwrap()
    }

    #[test]
    fn a_ray_from_above_meets_a_tilted_plane_where_it_should() {
        let f = field(5, 5, |x, _| 0.5 * x, false);
        let ray = Ray::new(DVec3::new(0.3, 2.0, 0.6), DVec3::new(0.0, -1.0, 0.0));
        let hit = f.first_hit(&ray, 0.0, f64::INFINITY).unwrap();
        assert!((hit.t - (2.0 - 0.15)).abs() < 1e-9, "{}", hit.t);
        let n = f.normal(ray.origin + ray.direction * hit.t).normalize();
        assert!(
            (n - DVec3::new(-0.5, 1.0, 0.0).normalize()).length() < 1e-9,
            "{n}"
        );
    }

    #[test]
    fn blocks_and_plain_cells_find_the_same_crossings() {
        let wave = |x: f64, z: f64| 0.5 + 0.4 * (9.0 * x).sin() * (7.0 * z).cos();
        let plain = field(40, 33, wave, false);
        let blocked = field(40, 33, wave, true);
        assert!(blocked.blocks.is_some());
        for i in 0..200 {
            let a = i as f64 * 0.731;
            let origin = DVec3::new(0.5 + 1.5 * a.cos(), 1.2, 0.5 + 1.5 * a.sin());
            let target = DVec3::new(
                0.5 + 0.3 * (a * 3.0).sin(),
                0.3,
                0.5 + 0.3 * (a * 2.0).cos(),
            );
            let ray = Ray::new(origin, target - origin);
            let p = plain.first_hit(&ray, 0.0, f64::INFINITY).map(|r| r.t);
            let b = blocked.first_hit(&ray, 0.0, f64::INFINITY).map(|r| r.t);
            assert_eq!(p, b, "ray {i}");
        }
    }

    #[test]
    fn a_ray_along_a_grid_line_still_hits() {
        let f = field(9, 9, |_, _| 0.25, true);
        let ray = Ray::new(DVec3::new(0.5, 1.0, -1.0), DVec3::new(0.0, -0.5, 1.0));
        let hit = f.first_hit(&ray, 0.0, f64::INFINITY).unwrap();
        assert!((hit.t - 1.5).abs() < 1e-9);
    }
}
