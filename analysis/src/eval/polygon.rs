//! `polygon { N, <p1>, <p2>, ... }`: the points split into closed outlines (sub-polygons),
//! each closed by repeating its first point, as POV-Ray reads them.

use super::tokens::Token;
use super::{Evaluator, Result};
use crate::scene::Shape;
use crate::scene::mesh::Polygon;
use glam::DVec3;
use syntax::SyntaxKind::*;

/// The most points one polygon may have, so that a runaway count is an error rather than
/// an allocation that never ends.
const MAX_POINTS: i64 = 1 << 24;

/// How far, relative to its size, a point may stray from the polygon's plane. POV-Ray
/// draws nothing of a polygon whose points are not in one plane, and its tolerance is
/// about this.
const PLANE_TOLERANCE: f64 = 1e-10;

impl Evaluator<'_> {
    /// The points of `polygon`, read from after its opening brace.
    pub fn polygon(&mut self, keyword: &Token) -> Result<Shape> {
        let count_at = self.next()?;
        self.unget(count_at.clone());
        let count = self.int()?;
        if !(3..=MAX_POINTS).contains(&count) {
            return Err(self.error_at(
                &count_at,
                format!("a polygon needs from 3 to {MAX_POINTS} points, not {count}"),
            ));
        }
        let mut outlines = Vec::new();
        let mut current: Vec<DVec3> = Vec::new();
        for _ in 0..count {
            self.eat(COMMA)?;
            let p = self.vector()?;
            if current.len() > 1 && current[0] == p {
                outlines.push(std::mem::take(&mut current));
            } else {
                current.push(p);
            }
        }
        if !current.is_empty() {
            self.warn_at(keyword, "the polygon is not closed; closing it");
            outlines.push(current);
        }
        if !lies_in_one_plane(&outlines) {
            self.warn_at(
                keyword,
                "the polygon's points do not lie in one plane; like POV-Ray, nothing of it is drawn",
            );
            outlines.clear();
        }
        Ok(Shape::Polygon(Box::new(Polygon { outlines })))
    }
}

/// Whether every point lies in the plane of the outlines (found by Newell's method, which
/// weighs every edge). Outlines without area count as planar: they have nothing to draw.
fn lies_in_one_plane(outlines: &[Vec<DVec3>]) -> bool {
    let mut normal = DVec3::ZERO;
    let mut centre = DVec3::ZERO;
    let mut count = 0.0;
    let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
    for outline in outlines {
        for (i, a) in outline.iter().enumerate() {
            let b = outline[(i + 1) % outline.len()];
            normal += (*a - b).cross(*a + b);
            centre += *a;
            count += 1.0;
            lo = lo.min(*a);
            hi = hi.max(*a);
        }
    }
    let Some(normal) = normal.try_normalize() else {
        return true;
    };
    let centre = centre / count;
    let size = (hi - lo).max_element();
    outlines
        .iter()
        .flatten()
        .all(|p| (*p - centre).dot(normal).abs() <= PLANE_TOLERANCE * size)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::files::MemoryFiles;
    use crate::{EvalOptions, evaluate};

    #[test]
    fn repeated_first_points_close_outlines() {
        let files = MemoryFiles::new().with(
            "scene.pov",
            "#version 3.7;\npolygon { 9, <0,0>, <4,0>, <0,4>, <0,0> <1,1> <2,1> <1,2> <1,1> <3,3> }",
        );
        let evaluation = evaluate("scene.pov", &files, &EvalOptions::default());
        let Shape::Polygon(polygon) = &evaluation.scene.unwrap().objects[0].shape else {
            panic!("a polygon");
        };
        let sizes: Vec<usize> = polygon.outlines.iter().map(Vec::len).collect();
        assert_eq!(sizes, vec![3, 3, 1]);
        // The last outline is left open and closed with a warning, as POV-Ray does.
        let warnings: Vec<&str> = evaluation
            .diagnostics
            .iter()
            .map(|d| d.message.as_str())
            .filter(|m| m.contains("closing"))
            .collect();
        assert_eq!(warnings, vec!["the polygon is not closed; closing it"]);
    }

    #[test]
    fn planes_are_found_across_outlines() {
        let square = vec![
            DVec3::new(0.0, 0.0, 1.0),
            DVec3::new(1.0, 0.0, 1.0),
            DVec3::new(1.0, 1.0, 1.0),
            DVec3::new(0.0, 1.0, 1.0),
        ];
        let hole: Vec<DVec3> = square.iter().map(|p| *p * 0.5 + DVec3::Z * 0.5).collect();
        assert!(lies_in_one_plane(&[square.clone(), hole]));
        let mut bent = square.clone();
        bent[3].z += 1e-6;
        assert!(!lies_in_one_plane(&[bent]));
        let line = vec![DVec3::ZERO, DVec3::X, DVec3::X * 2.0];
        assert!(lies_in_one_plane(&[line]));
    }
}
