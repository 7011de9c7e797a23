//! The statements of the mathematical shapes: `poly`, `cubic`, `quartic`, `polynomial`,
//! `isosurface`, `parametric`, `julia_fractal`, `sphere_sweep`, `lathe`, `sor`, `prism`,
//! `blob`, `superellipsoid`, `ovus`, `lemon` and `height_field` with a function. Each parser
//! reads from after the opening brace up to the object modifiers, as POV-Ray's does: the
//! shape's own items first, then whatever the object statement reads after them.

use super::tokens::Token;
use super::{Evaluator, Result};
use crate::function::Function;
use crate::scene::math_shapes::{
    Blob, BlobComponent, BlobShape, Container, Isosurface, JuliaAlgebra, JuliaFractal,
    JuliaFunction, Lathe, Lemon, Parametric, PolyTerm, Polynomial, Prism, PrismSweep, Sor,
    SphereSweep, SplineKind,
};
use crate::scene::{Shape, Transform};
use glam::{DVec2, DVec3, DVec4};
use std::sync::Arc;
use syntax::SyntaxKind::{self, *};

/// The shapes this module reads.
pub const MATH_SHAPES: &[SyntaxKind] = &[
    BLOB_KW,
    CUBIC_KW,
    HEIGHT_FIELD_KW,
    ISOSURFACE_KW,
    JULIA_FRACTAL_KW,
    LATHE_KW,
    LEMON_KW,
    OVUS_KW,
    PARAMETRIC_KW,
    POLY_KW,
    POLYNOMIAL_KW,
    PRISM_KW,
    QUARTIC_KW,
    SOR_KW,
    SPHERE_SWEEP_KW,
    SUPERELLIPSOID_KW,
];

/// The most points one lathe, sor, prism or sweep may have, so that a runaway count is an
/// error rather than an allocation that never ends.
const MAX_POINTS: i64 = 1 << 24;

impl Evaluator<'_> {
    /// The shape of a mathematical shape statement whose keyword is `keyword`, read from
    /// after its opening brace.
    pub fn math_shape(&mut self, keyword: &Token) -> Result<Shape> {
        match keyword.kind {
            CUBIC_KW => self.poly_coefficients(keyword, 3),
            QUARTIC_KW => self.poly_coefficients(keyword, 4),
            POLY_KW => {
                let order = self.order(keyword)?;
                self.eat(COMMA)?;
                self.poly_coefficients(keyword, order)
            }
            POLYNOMIAL_KW => self.polynomial(keyword),
            ISOSURFACE_KW => self.isosurface(),
            PARAMETRIC_KW => self.parametric(keyword),
            JULIA_FRACTAL_KW => self.julia_fractal(keyword),
            SPHERE_SWEEP_KW => self.sphere_sweep(keyword),
            LATHE_KW => self.lathe(keyword),
            SOR_KW => self.sor(keyword),
            PRISM_KW => self.prism(keyword),
            BLOB_KW => self.blob(keyword),
            SUPERELLIPSOID_KW => {
                let v = self.vector_of(2)?;
                if !(v.c[0] > 0.0 && v.c[1] > 0.0 && v.c[0].is_finite() && v.c[1].is_finite()) {
                    return Err(self.error_at(
                        keyword,
                        format!(
                            "a superellipsoid's exponents must be positive, not <{}, {}>",
                            v.c[0], v.c[1]
                        ),
                    ));
                }
                Ok(Shape::Superellipsoid {
                    e: v.c[0],
                    n: v.c[1],
                })
            }
            OVUS_KW => {
                let bottom_radius = self.float()?;
                self.eat(COMMA)?;
                let top_radius = self.float()?;
                Ok(Shape::Ovus {
                    bottom_radius,
                    top_radius,
                })
            }
            LEMON_KW => self.lemon(),
            _ => self.height_field(keyword),
        }
    }

    /// A polynomial's order, 2 to 15.
    fn order(&mut self, keyword: &Token) -> Result<u32> {
        let order = self.int()?;
        if !(2..=15).contains(&order) {
            return Err(self.error_at(
                keyword,
                format!("a polynomial's order must be 2 to 15, not {order}"),
            ));
        }
        Ok(order as u32)
    }

    /// `<c1, c2, ...>` with every coefficient of a polynomial of `order`, then `sturm`.
    fn poly_coefficients(&mut self, keyword: &Token, order: u32) -> Result<Shape> {
        let powers = Polynomial::term_powers(order);
        let open = self.expect(LT, "'<' to start the coefficients")?;
        let mut terms = Vec::new();
        for (i, p) in powers.iter().enumerate() {
            if i > 0 && !self.eat(COMMA)? && self.peek_kind()? == GT {
                break;
            }
            let coefficient = self.float()?;
            if coefficient != 0.0 {
                terms.push(PolyTerm {
                    powers: *p,
                    coefficient,
                });
            }
            if i + 1 == powers.len() {
                self.eat(COMMA)?;
            }
        }
        if !self.eat(GT)? {
            let mut error = self.error_at(
                keyword,
                format!(
                    "a polynomial of order {order} has {} coefficients",
                    powers.len()
                ),
            );
            error.related.push(syntax::Related {
                span: self.span(&open),
                message: "the coefficients start here".into(),
            });
            return Err(error);
        }
        let sturm = self.sturm_flag()?;
        Ok(Shape::Polynomial(Box::new(Polynomial {
            order,
            terms,
            sturm,
        })))
    }

    /// `polynomial { order, xyz(i, j, k): c, ... }`: unlisted terms are zero, and a term
    /// given twice keeps its last value.
    fn polynomial(&mut self, keyword: &Token) -> Result<Shape> {
        let order = self.order(keyword)?;
        self.eat(COMMA)?;
        let mut terms: Vec<PolyTerm> = Vec::new();
        loop {
            let token = self.next()?;
            if !(token.kind == IDENT && self.text(&token) == "xyz") {
                self.unget(token);
                break;
            }
            let args = self.float_args()?;
            let powers: Vec<i64> = args.iter().map(|a| a.trunc() as i64).collect();
            if powers.len() != 3
                || powers.iter().any(|p| *p < 0)
                || powers.iter().sum::<i64>() > i64::from(order)
            {
                return Err(self.error_at(
                    &token,
                    format!(
                        "xyz() takes three powers from 0 whose sum is at most the order {order}"
                    ),
                ));
            }
            self.expect(COLON, "':' after xyz(...)")?;
            let coefficient = self.float()?;
            self.eat(COMMA)?;
            let powers = [powers[0] as u8, powers[1] as u8, powers[2] as u8];
            terms.retain(|t| t.powers != powers);
            if coefficient != 0.0 {
                terms.push(PolyTerm {
                    powers,
                    coefficient,
                });
            }
        }
        let sturm = self.sturm_flag()?;
        Ok(Shape::Polynomial(Box::new(Polynomial {
            order,
            terms,
            sturm,
        })))
    }

    /// An optional `sturm [bool]`.
    fn sturm_flag(&mut self) -> Result<bool> {
        if self.eat(STURM_KW)? {
            self.optional_bool()
        } else {
            Ok(false)
        }
    }

    /// `function { } [contained_by { }] [threshold] [accuracy] ...` inside `isosurface`.
    fn isosurface(&mut self) -> Result<Shape> {
        let function = self.xyz_function()?;
        let mut iso = Isosurface {
            function,
            container: Container::default(),
            threshold: 0.0,
            accuracy: 0.001,
            max_gradient: 1.1,
            evaluate: None,
            open: false,
            max_trace: 1,
            polarity: false,
        };
        loop {
            let token = self.next()?;
            match token.kind {
                CONTAINED_BY_KW => iso.container = self.container(&token)?,
                THRESHOLD_KW => iso.threshold = self.float()?,
                ACCURACY_KW => iso.accuracy = self.positive(&token, "accuracy")?,
                MAX_GRADIENT_KW => iso.max_gradient = self.positive(&token, "max_gradient")?,
                EVALUATE_KW => {
                    let p0 = self.float()?;
                    self.eat(COMMA)?;
                    let p1 = self.float()?;
                    self.eat(COMMA)?;
                    let p2 = self.float()?;
                    iso.evaluate = Some([p0, p1.max(1.0), p2.clamp(0.0, 1.0)]);
                }
                OPEN_KW => iso.open = self.optional_bool()?,
                MAX_TRACE_KW => iso.max_trace = self.int()?.clamp(1, i64::from(u32::MAX)) as u32,
                ALL_INTERSECTIONS_KW => iso.max_trace = u32::MAX,
                IDENT if self.text(&token) == "polarity" => iso.polarity = self.optional_bool()?,
                _ => {
                    self.unget(token);
                    break;
                }
            }
        }
        Ok(Shape::Isosurface(Box::new(iso)))
    }

    /// A `function { }` of x, y and z (or of u and v): declared functions of other
    /// parameters are called with their first parameters.
    fn xyz_function(&mut self) -> Result<Arc<Function>> {
        let token = self.next()?;
        if token.kind != FUNCTION_KW {
            return Err(self.error_at(
                &token,
                format!("expected 'function', found {}", self.describe(&token)),
            ));
        }
        self.unget(token.clone());
        let function = self.function_value()?;
        if let Some(missing) = function.unsupported() {
            return Err(self.unsupported(&token, missing.trim_start_matches("not supported yet: ")));
        }
        Ok(Arc::new(function))
    }

    /// A float that must be greater than zero.
    pub(super) fn positive(&mut self, keyword: &Token, what: &str) -> Result<f64> {
        let v = self.float()?;
        if v > 0.0 && v.is_finite() {
            Ok(v)
        } else {
            Err(self.error_at(keyword, format!("{what} must be positive, not {v}")))
        }
    }

    /// `{ sphere { c, r } }` or `{ box { a, b } }` after `contained_by`.
    fn container(&mut self, keyword: &Token) -> Result<Container> {
        self.expect(L_BRACE, "'{'")?;
        let shape = self.next()?;
        self.expect(L_BRACE, "'{'")?;
        let container = match shape.kind {
            SPHERE_KW => {
                let center = self.vector()?;
                self.eat(COMMA)?;
                let radius = self.float()?.abs();
                Container::Sphere { center, radius }
            }
            BOX_KW => {
                let a = self.vector()?;
                self.eat(COMMA)?;
                let b = self.vector()?;
                Container::Box {
                    corner1: a.min(b),
                    corner2: a.max(b),
                }
            }
            _ => {
                return Err(self.error_at(
                    &shape,
                    format!(
                        "{} must be a sphere or a box, not {}",
                        self.text(keyword),
                        self.describe(&shape)
                    ),
                ));
            }
        };
        self.expect(R_BRACE, "'}' to close the container's shape")?;
        self.expect(R_BRACE, "'}'")?;
        Ok(container)
    }

    /// `function {x} function {y} function {z} <u1, v1>, <u2, v2> ...` inside `parametric`.
    fn parametric(&mut self, keyword: &Token) -> Result<Shape> {
        let fx = self.xyz_function()?;
        let fy = self.xyz_function()?;
        let fz = self.xyz_function()?;
        let low = self.vector_of(2)?;
        self.eat(COMMA)?;
        let high = self.vector_of(2)?;
        if !(low.c[0] < high.c[0] && low.c[1] < high.c[1]) {
            return Err(self.error_at(
                keyword,
                "the parametric's ranges must grow: <u1, v1> below <u2, v2>",
            ));
        }
        let mut shape = Parametric {
            functions: [fx, fy, fz],
            u_range: (low.c[0], high.c[0]),
            v_range: (low.c[1], high.c[1]),
            container: Container::default(),
            accuracy: 0.001,
            max_gradient: 1.0,
            precompute: None,
        };
        loop {
            let token = self.next()?;
            match token.kind {
                CONTAINED_BY_KW => shape.container = self.container(&token)?,
                ACCURACY_KW => shape.accuracy = self.positive(&token, "accuracy")?,
                MAX_GRADIENT_KW => shape.max_gradient = self.positive(&token, "max_gradient")?,
                PRECOMPUTE_KW => {
                    let depth = self.int()?.clamp(0, 20) as u32;
                    let mut axes = [false; 3];
                    loop {
                        self.eat(COMMA)?;
                        match self.peek_kind()? {
                            X_KW => axes[0] = true,
                            Y_KW => axes[1] = true,
                            Z_KW => axes[2] = true,
                            _ => break,
                        }
                        self.next()?;
                    }
                    shape.precompute = Some((depth, axes));
                }
                _ => {
                    self.unget(token);
                    break;
                }
            }
        }
        Ok(Shape::Parametric(Box::new(shape)))
    }

    /// `<p> [quaternion|hypercomplex] [function] [max_iteration] [precision] [slice]`.
    fn julia_fractal(&mut self, keyword: &Token) -> Result<Shape> {
        let p = self.vector_of(4)?;
        let mut julia = JuliaFractal {
            parameter: DVec4::from_slice(&p.c[..4]),
            algebra: JuliaAlgebra::Quaternion,
            function: JuliaFunction::Sqr,
            max_iteration: 20,
            precision: 20.0,
            slice: DVec4::new(0.0, 0.0, 0.0, 1.0),
            slice_distance: 0.0,
        };
        let mut function_at: Option<Token> = None;
        loop {
            let token = self.next()?;
            let function = match token.kind {
                QUATERNION_KW => {
                    julia.algebra = JuliaAlgebra::Quaternion;
                    continue;
                }
                HYPERCOMPLEX_KW => {
                    julia.algebra = JuliaAlgebra::Hypercomplex;
                    continue;
                }
                MAX_ITERATION_KW => {
                    julia.max_iteration = self.int()?.clamp(1, 1 << 20) as u32;
                    continue;
                }
                PRECISION_KW => {
                    julia.precision = self.float()?.max(1.0);
                    continue;
                }
                SLICE_KW => {
                    let normal = self.vector_of(4)?;
                    self.eat(COMMA)?;
                    let distance = self.float()?;
                    let n = DVec4::from_slice(&normal.c[..4]);
                    if n.length() < 1e-10 || n.w.abs() < 1e-10 {
                        return Err(self.error_at(
                            &token,
                            "the slice's normal must be non-zero, with a non-zero fourth component",
                        ));
                    }
                    // POV-Ray normalises the normal but keeps the distance as written.
                    julia.slice = n / n.length();
                    julia.slice_distance = distance;
                    continue;
                }
                SQR_KW => JuliaFunction::Sqr,
                CUBE_KW => JuliaFunction::Cube,
                RECIPROCAL_KW => JuliaFunction::Reciprocal,
                EXP_KW => JuliaFunction::Exp,
                LN_KW => JuliaFunction::Ln,
                SIN_KW => JuliaFunction::Sin,
                ASIN_KW => JuliaFunction::Asin,
                COS_KW => JuliaFunction::Cos,
                ACOS_KW => JuliaFunction::Acos,
                TAN_KW => JuliaFunction::Tan,
                ATAN_KW => JuliaFunction::Atan,
                SINH_KW => JuliaFunction::Sinh,
                ASINH_KW => JuliaFunction::Asinh,
                COSH_KW => JuliaFunction::Cosh,
                ACOSH_KW => JuliaFunction::Acosh,
                TANH_KW => JuliaFunction::Tanh,
                ATANH_KW => JuliaFunction::Atanh,
                PWR_KW => {
                    let args = self.float_args()?;
                    if args.len() != 2 {
                        return Err(self.error_at(&token, "pwr takes two arguments: pwr(X, Y)"));
                    }
                    JuliaFunction::Pwr(args[0], args[1])
                }
                _ => {
                    self.unget(token);
                    break;
                }
            };
            julia.function = function;
            function_at = Some(token);
        }
        if julia.algebra == JuliaAlgebra::Quaternion
            && !matches!(julia.function, JuliaFunction::Sqr | JuliaFunction::Cube)
        {
            let at = function_at.as_ref().unwrap_or(keyword);
            return Err(self.error_at(
                at,
                "a quaternion julia_fractal supports only sqr and cube; use hypercomplex for the others",
            ));
        }
        Ok(Shape::JuliaFractal(Box::new(julia)))
    }

    /// `linear_spline|b_spline|cubic_spline N, <c>, r, ... [tolerance t]`.
    fn sphere_sweep(&mut self, keyword: &Token) -> Result<Shape> {
        let kind_token = self.next()?;
        let kind = match kind_token.kind {
            LINEAR_SPLINE_KW => SplineKind::Linear,
            B_SPLINE_KW => SplineKind::BSpline,
            CUBIC_SPLINE_KW => SplineKind::Cubic,
            _ => {
                return Err(self.error_at(
                    &kind_token,
                    format!(
                        "expected linear_spline, b_spline or cubic_spline, found {}",
                        self.describe(&kind_token)
                    ),
                ));
            }
        };
        let count = self.count(keyword)?;
        let least = if kind == SplineKind::Linear { 2 } else { 4 };
        if count < least {
            return Err(self.error_at(
                &kind_token,
                format!(
                    "a {} sphere_sweep needs at least {least} spheres, not {count}",
                    self.text(&kind_token)
                ),
            ));
        }
        self.eat(COMMA)?;
        let mut spheres = Vec::with_capacity(count);
        for _ in 0..count {
            let center = self.vector()?;
            self.eat(COMMA)?;
            let radius = self.float()?;
            self.eat(COMMA)?;
            spheres.push((center, radius));
        }
        let mut tolerance = 1e-6;
        if self.eat(TOLERANCE_KW)? {
            tolerance = self.float()?.abs();
        }
        Ok(Shape::SphereSweep(Box::new(SphereSweep {
            kind,
            spheres: spheres.into(),
            tolerance,
        })))
    }

    /// A count of points: a positive integer below the limit.
    fn count(&mut self, keyword: &Token) -> Result<usize> {
        let n = self.int()?;
        if !(0..=MAX_POINTS).contains(&n) {
            return Err(self.error_at(
                keyword,
                format!("{n} points are more than {} can take", self.text(keyword)),
            ));
        }
        Ok(n as usize)
    }

    /// `N, <p1>, <p2>, ...`: 2-D points.
    fn points_2d(&mut self, keyword: &Token) -> Result<Vec<DVec2>> {
        let count = self.count(keyword)?;
        self.eat(COMMA)?;
        let mut points = Vec::with_capacity(count);
        for _ in 0..count {
            let p = self.vector_of(2)?;
            self.eat(COMMA)?;
            points.push(DVec2::new(p.c[0], p.c[1]));
        }
        Ok(points)
    }

    /// An optional spline keyword of a lathe or prism.
    fn spline_keyword(kind: SyntaxKind) -> Option<SplineKind> {
        match kind {
            LINEAR_SPLINE_KW => Some(SplineKind::Linear),
            QUADRATIC_SPLINE_KW => Some(SplineKind::Quadratic),
            CUBIC_SPLINE_KW => Some(SplineKind::Cubic),
            BEZIER_SPLINE_KW => Some(SplineKind::Bezier),
            _ => None,
        }
    }

    /// `[spline] N, <p>... [sturm]` inside `lathe`.
    fn lathe(&mut self, keyword: &Token) -> Result<Shape> {
        let mut kind = SplineKind::Linear;
        if let Some(k) = Self::spline_keyword(self.peek_kind()?) {
            self.next()?;
            kind = k;
        }
        let points = self.points_2d(keyword)?;
        check_spline_points(kind, points.len())
            .map_err(|message| self.error_at(keyword, format!("lathe: {message}")))?;
        let sturm = self.sturm_flag()?;
        Ok(Shape::Lathe(Box::new(Lathe {
            kind,
            points: points.into(),
            sturm,
        })))
    }

    /// `N, <p>... [open] [sturm]` inside `sor`.
    fn sor(&mut self, keyword: &Token) -> Result<Shape> {
        let points = self.points_2d(keyword)?;
        if points.len() < 4 {
            return Err(self.error_at(keyword, "a sor needs at least 4 points"));
        }
        // The first and last points only set the slopes at the ends (the manual's vase
        // starts with two points at one height); the points on the curve must climb.
        if let Some(message) = sor_points_problem(&points) {
            return Err(self.error_at(keyword, message));
        }
        let (mut open, mut sturm) = (false, false);
        loop {
            match self.peek_kind()? {
                OPEN_KW => {
                    self.next()?;
                    open = self.optional_bool()?;
                }
                STURM_KW => {
                    self.next()?;
                    sturm = self.optional_bool()?;
                }
                _ => break,
            }
        }
        Ok(Shape::Sor(Box::new(Sor {
            points: points.into(),
            open,
            sturm,
        })))
    }

    /// `[sweep] [spline] h1, h2, N, <p>... [open] [sturm]` inside `prism`.
    fn prism(&mut self, keyword: &Token) -> Result<Shape> {
        let mut kind = SplineKind::Linear;
        let mut sweep = PrismSweep::Linear;
        loop {
            let next = self.peek_kind()?;
            if let Some(k) = Self::spline_keyword(next) {
                kind = k;
            } else if next == LINEAR_SWEEP_KW {
                sweep = PrismSweep::Linear;
            } else if next == CONIC_SWEEP_KW {
                sweep = PrismSweep::Conic;
            } else {
                break;
            }
            self.next()?;
        }
        let height1 = self.float()?;
        self.eat(COMMA)?;
        let height2 = self.float()?;
        self.eat(COMMA)?;
        let points = self.points_2d(keyword)?;
        check_spline_points(kind, points.len())
            .map_err(|message| self.error_at(keyword, format!("prism: {message}")))?;
        let (mut open, mut sturm) = (false, false);
        loop {
            match self.peek_kind()? {
                OPEN_KW => {
                    self.next()?;
                    open = self.optional_bool()?;
                }
                STURM_KW => {
                    self.next()?;
                    sturm = self.optional_bool()?;
                }
                _ => break,
            }
        }
        Ok(Shape::Prism(Box::new(Prism {
            kind,
            sweep,
            height1,
            height2,
            points: points.into(),
            open,
            sturm,
        })))
    }

    /// `threshold t`, `sphere { }`, `cylinder { }`, `component s, r, <c>`, `sturm`,
    /// `hierarchy` inside `blob`.
    fn blob(&mut self, keyword: &Token) -> Result<Shape> {
        let mut blob = Blob {
            threshold: 1.0,
            components: Vec::new(),
            sturm: false,
            hierarchy: true,
        };
        loop {
            let token = self.next()?;
            match token.kind {
                THRESHOLD_KW => blob.threshold = self.float()?,
                STURM_KW => blob.sturm = self.optional_bool()?,
                HIERARCHY_KW => blob.hierarchy = self.optional_bool()?,
                COMPONENT_KW => {
                    let strength = self.float()?;
                    self.eat(COMMA)?;
                    let radius = self.float()?;
                    self.eat(COMMA)?;
                    let center = self.vector()?;
                    blob.components.push(BlobComponent {
                        kind: BlobShape::Sphere { center },
                        radius,
                        strength,
                        transform: Transform::IDENTITY,
                        texture: None,
                    });
                }
                SPHERE_KW | CYLINDER_KW => {
                    let component = self.blob_component(&token)?;
                    blob.components.push(component);
                }
                _ => {
                    self.unget(token);
                    break;
                }
            }
        }
        if blob.components.is_empty() {
            return Err(self.error_at(keyword, "a blob needs at least one component"));
        }
        if blob.threshold <= 0.0 {
            return Err(self.error_at(keyword, "a blob's threshold must be positive"));
        }
        Ok(Shape::Blob(Box::new(blob)))
    }

    /// `{ c, r, [strength] s [modifiers] }` or `{ a, b, r, [strength] s [modifiers] }`
    /// after a blob's `sphere` or `cylinder`.
    fn blob_component(&mut self, keyword: &Token) -> Result<BlobComponent> {
        self.expect(L_BRACE, "'{'")?;
        let kind = if keyword.kind == SPHERE_KW {
            let center = self.vector()?;
            BlobShape::Sphere { center }
        } else {
            let end1 = self.vector()?;
            self.eat(COMMA)?;
            let end2 = self.vector()?;
            BlobShape::Cylinder { end1, end2 }
        };
        self.eat(COMMA)?;
        let radius = self.float()?;
        self.eat(COMMA)?;
        self.eat(STRENGTH_KW)?;
        let strength = self.float()?;
        let mut component = BlobComponent {
            kind,
            radius,
            strength,
            transform: Transform::IDENTITY,
            texture: None,
        };
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => return Ok(component),
                kind if Self::starts_transform(kind) => {
                    let t = self.transformation(&token)?;
                    component.transform = component.transform.then(&t);
                    if let Some(texture) = &mut component.texture {
                        super::texture::transform_texture(Arc::make_mut(texture), &t);
                    }
                }
                TEXTURE_KW => {
                    let texture = self.texture_body()?;
                    component.texture = Some(Arc::new(texture));
                }
                PIGMENT_KW | NORMAL_KW | FINISH_KW => {
                    let mut holder = crate::scene::Object::new(
                        Shape::Sphere {
                            center: DVec3::ZERO,
                            radius: 1.0,
                        },
                        None,
                    );
                    holder.texture = component.texture.take();
                    self.texture_part(&mut holder, &token)?;
                    component.texture = holder.texture;
                }
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected a texture, a transformation or '}}' in a blob component, found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
    }

    /// `<base>, base_radius, <cap>, cap_radius, inner_radius [open]` inside `lemon`.
    fn lemon(&mut self) -> Result<Shape> {
        let base = self.vector()?;
        self.eat(COMMA)?;
        let base_radius = self.float()?;
        self.eat(COMMA)?;
        let cap = self.vector()?;
        self.eat(COMMA)?;
        let cap_radius = self.float()?;
        self.eat(COMMA)?;
        let inner_radius = self.float()?;
        let open = if self.eat(OPEN_KW)? {
            self.optional_bool()?
        } else {
            false
        };
        Ok(Shape::Lemon(Box::new(Lemon {
            base,
            base_radius,
            cap,
            cap_radius,
            inner_radius,
            open,
        })))
    }

    /// A function body `{ ... }` of x, y, z, the `function` keyword already read.
    pub(super) fn function_body_after_keyword(&mut self, keyword: &Token) -> Result<Function> {
        self.unget(keyword.clone());
        let function = self.function_value()?;
        if let Some(missing) = function.unsupported() {
            return Err(
                self.unsupported(keyword, missing.trim_start_matches("not supported yet: "))
            );
        }
        Ok(function)
    }

    /// Sets `sturm` on a shape that takes it, after the shape's own items.
    pub fn set_sturm(shape: &mut Shape, on: bool) {
        match shape {
            Shape::Polynomial(p) => p.sturm = on,
            Shape::Lathe(l) => l.sturm = on,
            Shape::Sor(s) => s.sturm = on,
            Shape::Prism(p) => p.sturm = on,
            Shape::Blob(b) => b.sturm = on,
            _ => {}
        }
    }

    /// Whether `open` applies to one of these shapes.
    pub fn takes_open(shape: &Shape) -> bool {
        matches!(
            shape,
            Shape::Isosurface(_) | Shape::Sor(_) | Shape::Prism(_) | Shape::Lemon(_)
        )
    }

    /// Sets `open` on a shape that takes it, after the shape's own items.
    pub fn set_open(shape: &mut Shape, on: bool) {
        match shape {
            Shape::Isosurface(i) => i.open = on,
            Shape::Sor(s) => s.open = on,
            Shape::Prism(p) => p.open = on,
            Shape::Lemon(l) => l.open = on,
            _ => {}
        }
    }
}

/// Whether a lathe or prism spline of `kind` can be made of `n` points.
fn check_spline_points(kind: SplineKind, n: usize) -> std::result::Result<(), String> {
    let ok = match kind {
        SplineKind::Linear => n >= 2,
        SplineKind::Quadratic => n >= 3,
        SplineKind::Cubic => n >= 4,
        SplineKind::Bezier => n >= 4 && n.is_multiple_of(4),
        SplineKind::BSpline => n >= 4,
    };
    if ok {
        Ok(())
    } else if kind == SplineKind::Bezier {
        Err(format!(
            "a bezier_spline needs a multiple of 4 points, not {n}"
        ))
    } else {
        Err(format!("{n} points are too few for this spline"))
    }
}

/// What POV-Ray 3.7 rejects in a sor's points: the curve's points (all but the first and
/// last, which only steer it) must rise in y, and the slope at the second and next-to-last
/// points, taken across their neighbours, needs neighbours at different heights.
fn sor_points_problem(points: &[DVec2]) -> Option<&'static str> {
    let n = points.len();
    if points[1..n - 1].windows(2).any(|w| w[1].y <= w[0].y) {
        return Some(
            "a sor's points, but for the first and last, must have increasing y coordinates",
        );
    }
    if points[2].y == points[0].y || points[n - 1].y == points[n - 3].y {
        return Some(
            "a sor's first and third points (and its last and third from last) need different y coordinates",
        );
    }
    None
}
