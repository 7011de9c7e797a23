//! The parameters of the mathematical shapes (polynomials, isosurfaces, parametric
//! surfaces, fractals, sweeps, lathes, prisms, blobs, height fields, text), as the scene
//! writes them. The renderer builds their runtime forms; nothing here knows how to trace.

use crate::function::Function;
use glam::{DVec2, DVec3, DVec4};
use std::sync::Arc;

/// `poly`, `cubic`, `quartic` and `polynomial`: the surface Σ c·xⁱyʲzᵏ = 0.
#[derive(Debug, Clone, PartialEq)]
pub struct Polynomial {
    pub order: u32,
    /// Non-zero terms, each power triple at most once.
    pub terms: Vec<PolyTerm>,
    pub sturm: bool,
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PolyTerm {
    /// The powers of x, y and z.
    pub powers: [u8; 3],
    pub coefficient: f64,
}

impl Polynomial {
    /// The power triples of a `poly` of `order`, in the order its coefficients are
    /// written: x's power descending, then y's, then z's.
    pub fn term_powers(order: u32) -> Vec<[u8; 3]> {
        let n = order as u8;
        let mut powers = Vec::new();
        for i in (0..=n).rev() {
            for j in (0..=n - i).rev() {
                for k in (0..=n - i - j).rev() {
                    powers.push([i, j, k]);
                }
            }
        }
        powers
    }
}

/// The region an isosurface or parametric surface is searched in.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Container {
    Box { corner1: DVec3, corner2: DVec3 },
    Sphere { center: DVec3, radius: f64 },
}

impl Default for Container {
    fn default() -> Self {
        Container::Box {
            corner1: DVec3::splat(-1.0),
            corner2: DVec3::splat(1.0),
        }
    }
}

/// `isosurface { function { } ... }`: the points where the function equals the threshold.
#[derive(Debug, Clone, PartialEq)]
pub struct Isosurface {
    /// A function of x, y and z.
    pub function: Arc<Function>,
    pub container: Container,
    pub threshold: f64,
    pub accuracy: f64,
    pub max_gradient: f64,
    /// `evaluate P0, P1, P2`: an adaptive max_gradient.
    pub evaluate: Option<[f64; 3]>,
    /// Without the container's surface where it cuts the isosurface.
    pub open: bool,
    /// How many crossings a ray looks for (`all_intersections`: unlimited).
    pub max_trace: u32,
    /// `polarity on` (POV-Ray 3.8): the inside is where the function exceeds the threshold.
    pub polarity: bool,
}

/// `parametric { function {x(u,v)} function {y(u,v)} function {z(u,v)} <u1,v1>, <u2,v2> }`.
#[derive(Debug, Clone, PartialEq)]
pub struct Parametric {
    /// Functions of u and v (their first two parameters).
    pub functions: [Arc<Function>; 3],
    pub u_range: (f64, f64),
    pub v_range: (f64, f64),
    pub container: Container,
    pub accuracy: f64,
    pub max_gradient: f64,
    /// `precompute Depth, x, y, z`: the subdivision depth and which coordinates it bounds.
    pub precompute: Option<(u32, [bool; 3])>,
}

/// The algebra a julia fractal iterates in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum JuliaAlgebra {
    Quaternion,
    Hypercomplex,
}

/// The function a julia fractal iterates, h ← f(h) + p.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum JuliaFunction {
    Sqr,
    Cube,
    Reciprocal,
    Exp,
    Ln,
    Sin,
    Asin,
    Cos,
    Acos,
    Tan,
    Atan,
    Sinh,
    Asinh,
    Cosh,
    Acosh,
    Tanh,
    Atanh,
    /// `pwr(X, Y)`: the complex power with exponent X + iY.
    Pwr(f64, f64),
}

/// `julia_fractal { <p> ... }`: a 3-D slice of a 4-D Julia set.
#[derive(Debug, Clone, PartialEq)]
pub struct JuliaFractal {
    pub parameter: DVec4,
    pub algebra: JuliaAlgebra,
    pub function: JuliaFunction,
    pub max_iteration: u32,
    /// `precision`, at least 1.
    pub precision: f64,
    /// The slice's 4-D normal (its fourth component non-zero) and distance.
    pub slice: DVec4,
    pub slice_distance: f64,
}

/// How a sequence of points is interpolated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SplineKind {
    Linear,
    Quadratic,
    Cubic,
    Bezier,
    /// Uniform cubic B-spline (sphere sweeps).
    BSpline,
}

/// `sphere_sweep { kind N, c1, r1, ... }`: the space a sphere fills moving along a spline.
#[derive(Debug, Clone, PartialEq)]
pub struct SphereSweep {
    /// `Linear`, `BSpline` or `Cubic` (POV-Ray's cubic_spline, Catmull-Rom).
    pub kind: SplineKind,
    pub spheres: Arc<[(DVec3, f64)]>,
    pub tolerance: f64,
}

/// `lathe { kind N, <p>... }`: a 2-D spline in the x-y plane turned around the y axis.
#[derive(Debug, Clone, PartialEq)]
pub struct Lathe {
    pub kind: SplineKind,
    pub points: Arc<[DVec2]>,
    pub sturm: bool,
}

/// `sor { N, <p>... }`: a surface of revolution through the points (r, y).
#[derive(Debug, Clone, PartialEq)]
pub struct Sor {
    pub points: Arc<[DVec2]>,
    pub open: bool,
    pub sturm: bool,
}

/// How a prism's outline is swept.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PrismSweep {
    Linear,
    /// From a point at the origin to the outline at height 1.
    Conic,
}

/// `prism { height1, height2, N, <p>... }`: closed outlines in the x-z plane, swept along y.
#[derive(Debug, Clone, PartialEq)]
pub struct Prism {
    pub kind: SplineKind,
    pub sweep: PrismSweep,
    pub height1: f64,
    pub height2: f64,
    pub points: Arc<[DVec2]>,
    pub open: bool,
    pub sturm: bool,
}

/// One field of a blob: a sphere or a capsule around a segment, with its own placement.
#[derive(Debug, Clone, PartialEq)]
pub struct BlobComponent {
    pub kind: BlobShape,
    pub radius: f64,
    pub strength: f64,
    /// From the component's coordinates to the blob's.
    pub transform: super::Transform,
    /// A texture of its own, blended with the others' near the surface.
    pub texture: Option<Arc<super::Texture>>,
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BlobShape {
    Sphere { center: DVec3 },
    Cylinder { end1: DVec3, end2: DVec3 },
}

/// `blob { threshold t  components... }`.
#[derive(Debug, Clone, PartialEq)]
pub struct Blob {
    pub threshold: f64,
    pub components: Vec<BlobComponent>,
    pub sturm: bool,
    pub hierarchy: bool,
}

/// `lemon { <base>, r1, <cap>, r2, inner_radius }` (POV-Ray 3.8): the inside of a torus's
/// spindle, between two discs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lemon {
    pub base: DVec3,
    pub base_radius: f64,
    pub cap: DVec3,
    pub cap_radius: f64,
    pub inner_radius: f64,
    pub open: bool,
}

/// A height field's samples: heights 0..1 on a grid over x, z in 0..1.
#[derive(Debug, Clone, PartialEq)]
pub struct HeightField {
    pub columns: usize,
    pub rows: usize,
    /// Row-major, the first row at z = 0, each row from x = 0 to 1.
    pub heights: Arc<[f32]>,
    pub smooth: bool,
    pub water_level: f64,
    pub hierarchy: bool,
}

/// One piece of a glyph's outline: a line, or a quadratic or cubic Bézier curve, from its
/// first point to its last.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum OutlineSegment {
    Line(DVec2, DVec2),
    Quad(DVec2, DVec2, DVec2),
    Cubic(DVec2, DVec2, DVec2, DVec2),
}

impl OutlineSegment {
    /// The end and control points.
    pub fn points(&self) -> Vec<DVec2> {
        match *self {
            OutlineSegment::Line(a, b) => vec![a, b],
            OutlineSegment::Quad(a, b, c) => vec![a, b, c],
            OutlineSegment::Cubic(a, b, c, d) => vec![a, b, c, d],
        }
    }
}

/// `text { ttf "font" "string", thickness, offset }`: glyph outlines extruded along z from
/// 0 to the thickness.
#[derive(Debug, Clone, PartialEq)]
pub struct Text {
    /// Each glyph's closed contours in ems (1 = the font's em) in the x-y plane, already
    /// laid out along the string. Inside is where the contours wind around a point.
    pub glyphs: Arc<[Vec<OutlineSegment>]>,
    pub thickness: f64,
}
