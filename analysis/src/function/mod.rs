//! User functions (`function { }`): float expressions compiled once into a compact stack
//! bytecode that isosurfaces, patterns and parse-time calls evaluate many times, and the
//! special functions built from a pattern, a pigment, a spline or a transform. The code is
//! checked at compile time (stack depth, argument counts), so evaluation cannot fail:
//! domain errors give NaN or infinities, which callers treat as "no surface here".

mod internal;

pub use internal::{INTERNALS, Internal};

use crate::pattern;
use crate::scene::{Pattern, Pigment, Transform};
use crate::spline::Spline;
use glam::DVec3;
use std::sync::Arc;

/// One instruction of the stack machine.
#[derive(Debug, Clone, PartialEq)]
pub enum Op {
    Const(f64),
    Param(u8),
    Neg,
    Add,
    Sub,
    Mul,
    Div,
    Lt,
    Le,
    Eq,
    Ne,
    Ge,
    Gt,
    And,
    Or,
    Not,
    Unary(Unary),
    Pow,
    Atan2,
    Mod,
    Div2,
    Select3,
    Select4,
    Min(u8),
    Max(u8),
    Call(Arc<Function>, u8),
    /// `sum()`/`prod()`: pops the bounds, runs `body` with the loop variable as one more
    /// parameter for each integer step from the lower bound up to the upper.
    Sum {
        body: Arc<[Op]>,
        product: bool,
    },
    /// A call of a vector-valued function and one component of its value (5: gray).
    CallPart(Arc<Function>, u8, u8),
    Internal(Internal, u8),
}

/// Functions of one argument.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Unary {
    Abs,
    Acos,
    Acosh,
    Asin,
    Asinh,
    Atan,
    Atanh,
    Ceil,
    Cos,
    Cosh,
    Degrees,
    Exp,
    Floor,
    Int,
    Ln,
    Log,
    Radians,
    Sin,
    Sinh,
    Sqr,
    Sqrt,
    Tan,
    Tanh,
}

impl Unary {
    fn apply(self, v: f64) -> f64 {
        match self {
            Unary::Abs => v.abs(),
            Unary::Acos => v.acos(),
            Unary::Acosh => v.acosh(),
            Unary::Asin => v.asin(),
            Unary::Asinh => v.asinh(),
            Unary::Atan => v.atan(),
            Unary::Atanh => v.atanh(),
            Unary::Ceil => v.ceil(),
            Unary::Cos => v.cos(),
            Unary::Cosh => v.cosh(),
            Unary::Degrees => v.to_degrees(),
            Unary::Exp => v.exp(),
            Unary::Floor => v.floor(),
            Unary::Int => v.trunc(),
            Unary::Ln => v.ln(),
            Unary::Log => v.log10(),
            Unary::Radians => v.to_radians(),
            Unary::Sin => v.sin(),
            Unary::Sinh => v.sinh(),
            Unary::Sqr => v * v,
            Unary::Sqrt => v.sqrt(),
            Unary::Tan => v.tan(),
            Unary::Tanh => v.tanh(),
        }
    }
}

/// The deepest evaluation stack a function may need; deeper expressions are rejected when
/// they are compiled.
pub const MAX_STACK: usize = 64;

/// The most terms one `sum()` or `prod()` adds up, so that a runaway range cannot hang.
pub const SUM_STEPS: u32 = 1_000_000;

/// A user function of float parameters.
#[derive(Debug, Clone, PartialEq)]
pub struct Function {
    pub params: Vec<String>,
    pub body: Body,
}

/// What a function computes.
#[derive(Debug, Clone, PartialEq)]
pub enum Body {
    /// A float expression, compiled.
    Code(Vec<Op>),
    /// `function { pattern { ... } }`: the pattern's value at (x, y, z).
    Pattern(Box<Pattern>),
    /// `function { pigment { ... } }`: the colour at (x, y, z), five components.
    Pigment(Box<Pigment>),
    /// `function { Spline }`: the spline at the first argument.
    Spline(Arc<Spline>),
    /// `function { transform { ... } }`: the transformed point (x, y, z).
    Transform(Transform),
}

impl Function {
    /// A float function from compiled code.
    pub fn code(params: Vec<String>, code: Vec<Op>) -> Function {
        Function {
            params,
            body: Body::Code(code),
        }
    }

    /// What this function uses that cannot be evaluated yet (a pattern not written yet),
    /// directly or through the functions it calls, as "not supported yet" names it.
    pub fn unsupported(&self) -> Option<String> {
        match &self.body {
            Body::Code(code) => unsupported_in(code),
            Body::Pattern(p) => pattern::check(p).err(),
            Body::Pigment(p) => pattern::check_pigment(p).err(),
            Body::Spline(_) | Body::Transform(_) => None,
        }
    }

    /// How many components a call returns: 1 for float functions.
    pub fn result_len(&self) -> u8 {
        match &self.body {
            Body::Code(_) | Body::Pattern(_) => 1,
            Body::Pigment(_) => 5,
            Body::Spline(spline) => spline.points.iter().map(|(_, p)| p.len).max().unwrap_or(3),
            Body::Transform(_) => 3,
        }
    }

    /// The float value; for vector-valued functions, the first component.
    pub fn eval(&self, args: &[f64]) -> f64 {
        match &self.body {
            Body::Code(code) => run(code, args),
            _ => self.eval_vector(args)[0],
        }
    }

    /// All components of the value (unused ones zero).
    pub fn eval_vector(&self, args: &[f64]) -> [f64; 5] {
        let arg = |i: usize| args.get(i).copied().unwrap_or(0.0);
        let point = DVec3::new(arg(0), arg(1), arg(2));
        match &self.body {
            Body::Code(code) => [run(code, args), 0.0, 0.0, 0.0, 0.0],
            Body::Pattern(pattern) => [pattern::value(pattern, point), 0.0, 0.0, 0.0, 0.0],
            Body::Pigment(pigment) => pattern::pigment_colour(pigment, point).to_array(),
            Body::Spline(spline) => spline.at(arg(0), spline.kind).promoted(5).c,
            Body::Transform(t) => {
                let p = t.point(point);
                [p.x, p.y, p.z, 0.0, 0.0]
            }
        }
    }
}

/// What a function's code calls that cannot be evaluated yet, looking into `sum`/`prod`
/// bodies without copying them.
fn unsupported_in(code: &[Op]) -> Option<String> {
    code.iter().find_map(|op| match op {
        Op::Call(f, _) | Op::CallPart(f, _, _) => f.unsupported(),
        Op::Sum { body, .. } => unsupported_in(body),
        _ => None,
    })
}

/// Runs compiled code; `args` must have one value per parameter.
fn run(code: &[Op], args: &[f64]) -> f64 {
    let mut stack = [0.0f64; MAX_STACK];
    let mut top = 0usize;
    for op in code {
        match op {
            Op::Const(v) => {
                stack[top] = *v;
                top += 1;
            }
            Op::Param(i) => {
                stack[top] = args.get(usize::from(*i)).copied().unwrap_or(0.0);
                top += 1;
            }
            Op::Neg => stack[top - 1] = -stack[top - 1],
            Op::Not => stack[top - 1] = f64::from(u8::from(stack[top - 1] == 0.0)),
            Op::Unary(f) => stack[top - 1] = f.apply(stack[top - 1]),
            Op::Select3 => {
                top -= 2;
                let c = stack[top - 1];
                stack[top - 1] = if c < 0.0 { stack[top] } else { stack[top + 1] };
            }
            Op::Select4 => {
                top -= 3;
                let c = stack[top - 1];
                stack[top - 1] = if c < 0.0 {
                    stack[top]
                } else if c == 0.0 {
                    stack[top + 1]
                } else {
                    stack[top + 2]
                };
            }
            Op::Min(n) | Op::Max(n) => {
                let n = usize::from(*n);
                let values = &stack[top - n..top];
                let pick = if matches!(op, Op::Min(_)) {
                    values.iter().copied().fold(f64::INFINITY, f64::min)
                } else {
                    values.iter().copied().fold(f64::NEG_INFINITY, f64::max)
                };
                top -= n;
                stack[top] = pick;
                top += 1;
            }
            Op::Call(function, argc) => {
                let n = usize::from(*argc);
                let value = function.eval(&stack[top - n..top]);
                top -= n;
                stack[top] = value;
                top += 1;
            }
            Op::Sum { body, product } => {
                top -= 1;
                let (from, to) = (stack[top - 1], stack[top]);
                let mut inner: Vec<f64> = args.to_vec();
                inner.push(from);
                let last = inner.len() - 1;
                let mut total = if *product { 1.0 } else { 0.0 };
                // Bounded like any loop: a huge range is cut off rather than hanging.
                let mut i = from;
                let mut steps = 0u32;
                while i <= to && steps < SUM_STEPS {
                    inner[last] = i;
                    let v = run(body, &inner);
                    total = if *product { total * v } else { total + v };
                    i += 1.0;
                    steps += 1;
                }
                stack[top - 1] = total;
            }
            Op::CallPart(function, argc, part) => {
                let n = usize::from(*argc);
                let v = function.eval_vector(&stack[top - n..top]);
                top -= n;
                stack[top] = match part {
                    5 => v[0] * 0.297 + v[1] * 0.589 + v[2] * 0.114,
                    i => v[usize::from(*i)],
                };
                top += 1;
            }
            Op::Internal(internal, argc) => {
                let n = usize::from(*argc);
                let value = internal.eval(&stack[top - n..top]);
                top -= n;
                stack[top] = value;
                top += 1;
            }
            binary => {
                top -= 1;
                let (a, b) = (stack[top - 1], stack[top]);
                stack[top - 1] = match binary {
                    Op::Add => a + b,
                    Op::Sub => a - b,
                    Op::Mul => a * b,
                    Op::Div => a / b,
                    Op::Lt => f64::from(u8::from(a < b)),
                    Op::Le => f64::from(u8::from(a <= b)),
                    Op::Eq => f64::from(u8::from(a == b)),
                    Op::Ne => f64::from(u8::from(a != b)),
                    Op::Ge => f64::from(u8::from(a >= b)),
                    Op::Gt => f64::from(u8::from(a > b)),
                    Op::And => f64::from(u8::from(a != 0.0 && b != 0.0)),
                    Op::Or => f64::from(u8::from(a != 0.0 || b != 0.0)),
                    Op::Pow => a.powf(b),
                    Op::Atan2 => a.atan2(b),
                    Op::Mod => a % b,
                    Op::Div2 => (a / b).trunc(),
                    _ => unreachable!("every other op is handled above"),
                };
            }
        }
    }
    stack[0]
}

impl Function {
    /// The stack depth the code needs, or `None` when it is malformed.
    pub fn stack_depth(code: &[Op]) -> Option<usize> {
        let mut depth = 0isize;
        let mut max = 0isize;
        for op in code {
            let (pops, pushes) = match op {
                Op::Const(_) | Op::Param(_) => (0, 1),
                Op::Neg | Op::Not | Op::Unary(_) => (1, 1),
                Op::Select3 => (3, 1),
                Op::Sum { .. } => (2, 1),
                Op::Select4 => (4, 1),
                Op::Min(n) | Op::Max(n) => (isize::from(*n), 1),
                Op::Call(_, n) | Op::CallPart(_, n, _) | Op::Internal(_, n) => (isize::from(*n), 1),
                _ => (2, 1),
            };
            depth -= pops;
            if depth < 0 {
                return None;
            }
            depth += pushes;
            max = max.max(depth);
        }
        (depth == 1).then_some(max as usize)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn evaluates_nested_calls_and_selects() {
        let square = Arc::new(Function::code(
            vec!["a".into()],
            vec![Op::Param(0), Op::Unary(Unary::Sqr)],
        ));
        let f = Function::code(
            vec!["x".into(), "y".into()],
            vec![
                Op::Param(0),
                Op::Call(square, 1),
                Op::Param(1),
                Op::Const(10.0),
                Op::Const(20.0),
                Op::Select3,
                Op::Add,
            ],
        );
        let Body::Code(code) = &f.body else {
            unreachable!("built from code")
        };
        assert_eq!(Function::stack_depth(code), Some(4));
        assert_eq!(f.eval(&[3.0, -1.0]), 19.0);
        assert_eq!(f.eval(&[3.0, 1.0]), 29.0);
    }

    #[test]
    fn malformed_code_is_detected() {
        assert_eq!(Function::stack_depth(&[Op::Add]), None);
        assert_eq!(
            Function::stack_depth(&[Op::Const(1.0), Op::Const(2.0)]),
            None
        );
    }
}
