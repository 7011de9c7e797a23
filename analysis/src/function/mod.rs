//! User functions (`function { }`), compiled once into a compact stack bytecode that
//! isosurfaces, patterns and parse-time calls evaluate many times. The code is checked at
//! compile time (stack depth, argument counts), so evaluation cannot fail: domain errors
//! give NaN or infinities, which callers treat as "no surface here".

mod internal;

pub use internal::{INTERNALS, Internal};

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
    Internal(Internal, u8),
}

/// Functions of one argument.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
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

/// A compiled user function of float parameters returning a float.
#[derive(Debug, Clone, PartialEq)]
pub struct Function {
    pub params: Vec<String>,
    pub code: Vec<Op>,
}

impl Function {
    /// Evaluates the function; `args` must have one value per parameter.
    pub fn eval(&self, args: &[f64]) -> f64 {
        let mut stack = [0.0f64; MAX_STACK];
        let mut top = 0usize;
        for op in &self.code {
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

    /// The stack depth the code needs, or `None` when it is malformed.
    pub fn stack_depth(code: &[Op]) -> Option<usize> {
        let mut depth = 0isize;
        let mut max = 0isize;
        for op in code {
            let (pops, pushes) = match op {
                Op::Const(_) | Op::Param(_) => (0, 1),
                Op::Neg | Op::Not | Op::Unary(_) => (1, 1),
                Op::Select3 => (3, 1),
                Op::Select4 => (4, 1),
                Op::Min(n) | Op::Max(n) => (isize::from(*n), 1),
                Op::Call(_, n) | Op::Internal(_, n) => (isize::from(*n), 1),
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
        let square = Arc::new(Function {
            params: vec!["a".into()],
            code: vec![Op::Param(0), Op::Unary(Unary::Sqr)],
        });
        let f = Function {
            params: vec!["x".into(), "y".into()],
            code: vec![
                Op::Param(0),
                Op::Call(square, 1),
                Op::Param(1),
                Op::Const(10.0),
                Op::Const(20.0),
                Op::Select3,
                Op::Add,
            ],
        };
        assert_eq!(Function::stack_depth(&f.code), Some(4));
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
