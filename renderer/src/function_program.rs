//! User functions compiled for tracing. An isosurface evaluates its function tens of
//! millions of times, so the evaluator's stack code is turned once into straight-line
//! register code: calls of other code functions are inlined, constant operands folded,
//! repeated subexpressions computed once, `sin` and `cos` of one argument fused into one
//! range reduction, and registers reused so that evaluation runs in a small array on the
//! stack. Functions built from patterns, pigments, splines and transforms stay calls.

use crate::fast_math;
use analysis::function::{Body, Function, Internal, Op, Unary};
use std::collections::HashMap;
use std::sync::Arc;

/// The most instructions inlining may produce; past it calls stay calls.
const MAX_INLINED: usize = 20_000;

/// Registers available on the stack during evaluation; larger programs use the heap.
const STACK_REGISTERS: usize = 32;

#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
enum Binary {
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
    Pow,
    Atan2,
    Mod,
    Div2,
}

impl Binary {
    fn from_op(op: &Op) -> Option<Binary> {
        Some(match op {
            Op::Add => Binary::Add,
            Op::Sub => Binary::Sub,
            Op::Mul => Binary::Mul,
            Op::Div => Binary::Div,
            Op::Lt => Binary::Lt,
            Op::Le => Binary::Le,
            Op::Eq => Binary::Eq,
            Op::Ne => Binary::Ne,
            Op::Ge => Binary::Ge,
            Op::Gt => Binary::Gt,
            Op::And => Binary::And,
            Op::Or => Binary::Or,
            Op::Pow => Binary::Pow,
            Op::Atan2 => Binary::Atan2,
            Op::Mod => Binary::Mod,
            Op::Div2 => Binary::Div2,
            _ => return None,
        })
    }

    #[inline]
    fn apply(self, a: f64, b: f64) -> f64 {
        let truth = |c: bool| if c { 1.0 } else { 0.0 };
        match self {
            Binary::Add => a + b,
            Binary::Sub => a - b,
            Binary::Mul => a * b,
            Binary::Div => a / b,
            Binary::Lt => truth(a < b),
            Binary::Le => truth(a <= b),
            Binary::Eq => truth(a == b),
            Binary::Ne => truth(a != b),
            Binary::Ge => truth(a >= b),
            Binary::Gt => truth(a > b),
            Binary::And => truth(a != 0.0 && b != 0.0),
            Binary::Or => truth(a != 0.0 || b != 0.0),
            Binary::Pow => pow(a, b),
            Binary::Atan2 => a.atan2(b),
            Binary::Mod => a % b,
            Binary::Div2 => (a / b).trunc(),
        }
    }

    fn commutes(self) -> bool {
        matches!(
            self,
            Binary::Add | Binary::Mul | Binary::Eq | Binary::Ne | Binary::And | Binary::Or
        )
    }
}

/// `a^b`, with the small integer powers scenes write most as multiplications.
#[inline]
fn pow(a: f64, b: f64) -> f64 {
    if b == 2.0 {
        a * a
    } else if b == 3.0 {
        a * a * a
    } else if b == 0.5 {
        a.sqrt()
    } else {
        a.powf(b)
    }
}

#[inline]
fn unary(f: Unary, v: f64) -> f64 {
    match f {
        Unary::Abs => v.abs(),
        Unary::Acos => v.acos(),
        Unary::Acosh => v.acosh(),
        Unary::Asin => v.asin(),
        Unary::Asinh => v.asinh(),
        Unary::Atan => v.atan(),
        Unary::Atanh => v.atanh(),
        Unary::Ceil => v.ceil(),
        Unary::Cos => fast_math::sin_cos(v).1,
        Unary::Cosh => v.cosh(),
        Unary::Degrees => v.to_degrees(),
        Unary::Exp => v.exp(),
        Unary::Floor => v.floor(),
        Unary::Int => v.trunc(),
        Unary::Ln => v.ln(),
        Unary::Log => v.log10(),
        Unary::Radians => v.to_radians(),
        Unary::Sin => fast_math::sin_cos(v).0,
        Unary::Sinh => v.sinh(),
        Unary::Sqr => v * v,
        Unary::Sqrt => v.sqrt(),
        Unary::Tan => v.tan(),
        Unary::Tanh => v.tanh(),
    }
}

/// One instruction in value-numbered form: operands are the indices of earlier values.
#[derive(Debug, Clone, PartialEq)]
enum Node {
    Const(f64),
    Param(u8),
    Neg(u32),
    Unary(Unary, u32),
    Binary(Binary, u32, u32),
    Select3(u32, u32, u32),
    Select4(u32, u32, u32, u32),
    Min(Vec<u32>),
    Max(Vec<u32>),
    /// A function that is not plain code (pattern, pigment, spline, transform).
    Call(Arc<Function>, Vec<u32>),
    CallPart(Arc<Function>, Vec<u32>, u8),
    Internal(Internal, Vec<u32>),
    /// `sum`/`prod`: the body runs with the caller's parameters plus the loop variable.
    Sum {
        body: Arc<Program>,
        from: u32,
        to: u32,
        product: bool,
        params: Vec<u32>,
    },
}

/// A key for common subexpressions: the node with its float bits.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
enum Key {
    Const(u64),
    Param(u8),
    Neg(u32),
    Unary(Unary, u32),
    Binary(Binary, u32, u32),
    Select3(u32, u32, u32),
    Select4(u32, u32, u32, u32),
    Min(Vec<u32>),
    Max(Vec<u32>),
    Internal(u16, Vec<u32>),
}

/// An instruction over registers.
#[derive(Debug, Clone, PartialEq)]
enum Inst {
    Const(u16, f64),
    Param(u16, u8),
    Neg(u16, u16),
    Unary(u16, Unary, u16),
    /// Both of one argument: sine to the first register, cosine to the second.
    SinCos(u16, u16, u16),
    Binary(u16, Binary, u16, u16),
    Select3(u16, [u16; 3]),
    Select4(u16, [u16; 4]),
    Min(u16, Box<[u16]>),
    Max(u16, Box<[u16]>),
    Call(u16, Arc<Function>, Box<[u16]>),
    CallPart(u16, Arc<Function>, Box<[u16]>, u8),
    Internal(u16, Internal, Box<[u16]>),
    Sum {
        out: u16,
        body: Arc<Program>,
        from: u16,
        to: u16,
        product: bool,
        params: Box<[u16]>,
    },
}

/// A compiled float function of `params` parameters.
#[derive(Debug, Clone, PartialEq)]
pub struct Program {
    code: Vec<Inst>,
    registers: usize,
    result: u16,
}

/// Builds value-numbered nodes from stack code.
struct Builder {
    nodes: Vec<Node>,
    known: HashMap<Key, u32>,
}

impl Builder {
    fn push(&mut self, node: Node) -> u32 {
        let node = self.fold(node);
        let key = match &node {
            Node::Const(v) => Some(Key::Const(v.to_bits())),
            Node::Param(i) => Some(Key::Param(*i)),
            Node::Neg(a) => Some(Key::Neg(*a)),
            Node::Unary(f, a) => Some(Key::Unary(*f, *a)),
            Node::Binary(op, a, b) => {
                let (a, b) = if op.commutes() && b < a {
                    (*b, *a)
                } else {
                    (*a, *b)
                };
                Some(Key::Binary(*op, a, b))
            }
            Node::Select3(a, b, c) => Some(Key::Select3(*a, *b, *c)),
            Node::Select4(a, b, c, d) => Some(Key::Select4(*a, *b, *c, *d)),
            Node::Min(v) => Some(Key::Min(v.clone())),
            Node::Max(v) => Some(Key::Max(v.clone())),
            Node::Internal(i, v) => Some(Key::Internal(i.0, v.clone())),
            Node::Call(..) | Node::CallPart(..) | Node::Sum { .. } => None,
        };
        if let Some(key) = &key
            && let Some(&index) = self.known.get(key)
        {
            return index;
        }
        let index = self.nodes.len() as u32;
        self.nodes.push(node);
        if let Some(key) = key {
            self.known.insert(key, index);
        }
        index
    }

    fn constant(&self, i: u32) -> Option<f64> {
        match self.nodes[i as usize] {
            Node::Const(v) => Some(v),
            _ => None,
        }
    }

    /// Replaces a node whose operands are all constants by its value.
    fn fold(&self, node: Node) -> Node {
        let c = |i: &u32| self.constant(*i);
        let value = match &node {
            Node::Neg(a) => c(a).map(|v| -v),
            Node::Unary(f, a) => c(a).map(|v| unary(*f, v)),
            Node::Binary(op, a, b) => c(a).zip(c(b)).map(|(x, y)| op.apply(x, y)),
            _ => None,
        };
        value.map_or(node, Node::Const)
    }

    /// Appends the nodes of `code`, whose parameters are the values `args`; returns the
    /// value of the result, or `None` when the code is malformed or too large to inline.
    fn code(&mut self, code: &[Op], args: &[u32]) -> Option<u32> {
        let mut stack: Vec<u32> = Vec::new();
        for op in code {
            if self.nodes.len() > MAX_INLINED {
                return None;
            }
            let value = match op {
                Op::Const(v) => self.push(Node::Const(*v)),
                Op::Param(i) => match args.get(usize::from(*i)) {
                    Some(&a) => a,
                    None => self.push(Node::Const(0.0)),
                },
                Op::Neg => {
                    let a = stack.pop()?;
                    self.push(Node::Neg(a))
                }
                Op::Not => {
                    let a = stack.pop()?;
                    let zero = self.push(Node::Const(0.0));
                    self.push(Node::Binary(Binary::Eq, a, zero))
                }
                Op::Unary(f) => {
                    let a = stack.pop()?;
                    self.push(Node::Unary(*f, a))
                }
                Op::Select3 => {
                    let c = stack.pop()?;
                    let b = stack.pop()?;
                    let a = stack.pop()?;
                    self.push(Node::Select3(a, b, c))
                }
                Op::Select4 => {
                    let d = stack.pop()?;
                    let c = stack.pop()?;
                    let b = stack.pop()?;
                    let a = stack.pop()?;
                    self.push(Node::Select4(a, b, c, d))
                }
                Op::Min(n) | Op::Max(n) => {
                    let n = usize::from(*n);
                    let operands = stack.split_off(stack.len().checked_sub(n)?);
                    if matches!(op, Op::Min(_)) {
                        self.push(Node::Min(operands))
                    } else {
                        self.push(Node::Max(operands))
                    }
                }
                Op::Call(function, argc) => {
                    let n = usize::from(*argc);
                    let operands = stack.split_off(stack.len().checked_sub(n)?);
                    match &function.body {
                        Body::Code(inner) => match self.code(inner, &operands) {
                            Some(v) => v,
                            None => self.push(Node::Call(function.clone(), operands)),
                        },
                        _ => self.push(Node::Call(function.clone(), operands)),
                    }
                }
                Op::CallPart(function, argc, part) => {
                    let n = usize::from(*argc);
                    let operands = stack.split_off(stack.len().checked_sub(n)?);
                    self.push(Node::CallPart(function.clone(), operands, *part))
                }
                Op::Internal(internal, argc) => {
                    let n = usize::from(*argc);
                    let operands = stack.split_off(stack.len().checked_sub(n)?);
                    self.push(Node::Internal(*internal, operands))
                }
                Op::Sum { body, product } => {
                    let to = stack.pop()?;
                    let from = stack.pop()?;
                    let body = Program::compile_code(body, args.len() + 1)?;
                    self.push(Node::Sum {
                        body: Arc::new(body),
                        from,
                        to,
                        product: *product,
                        params: args.to_vec(),
                    })
                }
                binary => {
                    let b = stack.pop()?;
                    let a = stack.pop()?;
                    self.push(Node::Binary(Binary::from_op(binary)?, a, b))
                }
            };
            stack.push(value);
        }
        if stack.len() == 1 { stack.pop() } else { None }
    }
}

impl Program {
    /// Compiles a float function of `params` parameters; `None` for a function that is
    /// not code (the caller evaluates those through the function itself).
    pub fn compile(function: &Function, params: usize) -> Option<Program> {
        match &function.body {
            Body::Code(code) => Program::compile_code(code, params),
            _ => None,
        }
    }

    fn compile_code(code: &[Op], params: usize) -> Option<Program> {
        let mut builder = Builder {
            nodes: Vec::new(),
            known: HashMap::new(),
        };
        let args: Vec<u32> = (0..params)
            .map(|i| builder.push(Node::Param(i as u8)))
            .collect();
        let result = builder.code(code, &args)?;
        Some(Program::from_nodes(builder.nodes, result))
    }

    /// Keeps the nodes the result depends on, pairs sines with cosines of one argument,
    /// and gives each value a register that is reused after its last use.
    fn from_nodes(nodes: Vec<Node>, result: u32) -> Program {
        let n = nodes.len();
        let operands = |node: &Node| -> Vec<u32> {
            match node {
                Node::Const(_) | Node::Param(_) => Vec::new(),
                Node::Neg(a) | Node::Unary(_, a) => vec![*a],
                Node::Binary(_, a, b) => vec![*a, *b],
                Node::Select3(a, b, c) => vec![*a, *b, *c],
                Node::Select4(a, b, c, d) => vec![*a, *b, *c, *d],
                Node::Min(v) | Node::Max(v) => v.clone(),
                Node::Call(_, v) | Node::CallPart(_, v, _) | Node::Internal(_, v) => v.clone(),
                Node::Sum {
                    from, to, params, ..
                } => {
                    let mut v = vec![*from, *to];
                    v.extend(params);
                    v
                }
            }
        };
        // Live nodes, from the result back.
        let mut live = vec![false; n];
        live[result as usize] = true;
        for i in (0..n).rev() {
            if live[i] {
                for a in operands(&nodes[i]) {
                    live[a as usize] = true;
                }
            }
        }
        // A sine and a cosine of one argument: the later one is filled by the earlier.
        let mut partner: Vec<Option<u32>> = vec![None; n];
        let mut trig: HashMap<u32, (Option<u32>, Option<u32>)> = HashMap::new();
        for (i, node) in nodes.iter().enumerate() {
            if !live[i] {
                continue;
            }
            if let Node::Unary(f @ (Unary::Sin | Unary::Cos), a) = node {
                let entry = trig.entry(*a).or_default();
                if *f == Unary::Sin {
                    entry.0.get_or_insert(i as u32);
                } else {
                    entry.1.get_or_insert(i as u32);
                }
            }
        }
        for (sin, cos) in trig.values() {
            if let (Some(s), Some(c)) = (sin, cos) {
                let (first, second) = if s < c { (*s, *c) } else { (*c, *s) };
                partner[first as usize] = Some(second);
            }
        }
        let filled: Vec<bool> = {
            let mut f = vec![false; n];
            for p in partner.iter().flatten() {
                f[*p as usize] = true;
            }
            f
        };
        // Last use of each value.
        let mut last_use = vec![0usize; n];
        for (i, node) in nodes.iter().enumerate() {
            if live[i] {
                for a in operands(node) {
                    last_use[a as usize] = i;
                }
            }
        }
        last_use[result as usize] = usize::MAX;
        let mut register = vec![0u16; n];
        let mut free: Vec<u16> = Vec::new();
        let mut count = 0u16;
        let mut take = |free: &mut Vec<u16>| {
            free.pop().unwrap_or_else(|| {
                count += 1;
                count - 1
            })
        };
        let mut code = Vec::new();
        for i in 0..n {
            if !live[i] {
                continue;
            }
            if !filled[i] {
                register[i] = take(&mut free);
            }
            if let Some(p) = partner[i] {
                register[p as usize] = take(&mut free);
            }
            let r = |a: &u32| register[*a as usize];
            let out = register[i];
            let inst = match &nodes[i] {
                _ if filled[i] => None,
                Node::Const(v) => Some(Inst::Const(out, *v)),
                Node::Param(p) => Some(Inst::Param(out, *p)),
                Node::Neg(a) => Some(Inst::Neg(out, r(a))),
                Node::Unary(f, a) => match partner[i] {
                    Some(p) => {
                        let other = register[p as usize];
                        Some(if *f == Unary::Sin {
                            Inst::SinCos(out, other, r(a))
                        } else {
                            Inst::SinCos(other, out, r(a))
                        })
                    }
                    None => Some(Inst::Unary(out, *f, r(a))),
                },
                Node::Binary(op, a, b) => Some(Inst::Binary(out, *op, r(a), r(b))),
                Node::Select3(a, b, c) => Some(Inst::Select3(out, [r(a), r(b), r(c)])),
                Node::Select4(a, b, c, d) => Some(Inst::Select4(out, [r(a), r(b), r(c), r(d)])),
                Node::Min(v) => Some(Inst::Min(out, v.iter().map(r).collect())),
                Node::Max(v) => Some(Inst::Max(out, v.iter().map(r).collect())),
                Node::Call(f, v) => Some(Inst::Call(out, f.clone(), v.iter().map(r).collect())),
                Node::CallPart(f, v, part) => Some(Inst::CallPart(
                    out,
                    f.clone(),
                    v.iter().map(r).collect(),
                    *part,
                )),
                Node::Internal(f, v) => Some(Inst::Internal(out, *f, v.iter().map(r).collect())),
                Node::Sum {
                    body,
                    from,
                    to,
                    product,
                    params,
                } => Some(Inst::Sum {
                    out,
                    body: body.clone(),
                    from: r(from),
                    to: r(to),
                    product: *product,
                    params: params.iter().map(r).collect(),
                }),
            };
            if let Some(inst) = inst {
                code.push(inst);
            }
            // Operands whose last use is here go back to the pool, after this
            // instruction's own register was taken so that none is overwritten early.
            let mut released: Vec<u16> = Vec::new();
            for a in operands(&nodes[i]) {
                if last_use[a as usize] == i {
                    released.push(register[a as usize]);
                }
            }
            released.sort_unstable();
            released.dedup();
            free.extend(released);
        }
        Program {
            code,
            registers: usize::from(count).max(1),
            result: register[result as usize],
        }
    }

    /// The value at `args` (one per parameter; missing ones are 0).
    pub fn eval(&self, args: &[f64]) -> f64 {
        if self.registers <= STACK_REGISTERS {
            let mut regs = [0.0f64; STACK_REGISTERS];
            self.run(&mut regs, args)
        } else {
            let mut regs = vec![0.0f64; self.registers];
            self.run(&mut regs, args)
        }
    }

    /// Three-parameter evaluation, the common case of isosurfaces.
    pub fn eval3(&self, x: f64, y: f64, z: f64) -> f64 {
        self.eval(&[x, y, z])
    }

    fn run(&self, r: &mut [f64], args: &[f64]) -> f64 {
        let arg = |i: u8| args.get(usize::from(i)).copied().unwrap_or(0.0);
        for inst in &self.code {
            match inst {
                Inst::Const(o, v) => r[*o as usize] = *v,
                Inst::Param(o, p) => r[*o as usize] = arg(*p),
                Inst::Neg(o, a) => r[*o as usize] = -r[*a as usize],
                Inst::Unary(o, f, a) => r[*o as usize] = unary(*f, r[*a as usize]),
                Inst::SinCos(s, c, a) => {
                    let (sin, cos) = fast_math::sin_cos(r[*a as usize]);
                    r[*s as usize] = sin;
                    r[*c as usize] = cos;
                }
                Inst::Binary(o, op, a, b) => {
                    r[*o as usize] = op.apply(r[*a as usize], r[*b as usize])
                }
                Inst::Select3(o, [c, a, b]) => {
                    r[*o as usize] = if r[*c as usize] < 0.0 {
                        r[*a as usize]
                    } else {
                        r[*b as usize]
                    }
                }
                Inst::Select4(o, [c, a, b, d]) => {
                    let v = r[*c as usize];
                    r[*o as usize] = if v < 0.0 {
                        r[*a as usize]
                    } else if v == 0.0 {
                        r[*b as usize]
                    } else {
                        r[*d as usize]
                    }
                }
                Inst::Min(o, v) => {
                    r[*o as usize] = v
                        .iter()
                        .map(|a| r[*a as usize])
                        .fold(f64::INFINITY, fast_math::min)
                }
                Inst::Max(o, v) => {
                    r[*o as usize] = v
                        .iter()
                        .map(|a| r[*a as usize])
                        .fold(f64::NEG_INFINITY, fast_math::max)
                }
                Inst::Call(o, f, v) => {
                    let values: Vec<f64> = v.iter().map(|a| r[*a as usize]).collect();
                    r[*o as usize] = f.eval(&values);
                }
                Inst::CallPart(o, f, v, part) => {
                    let values: Vec<f64> = v.iter().map(|a| r[*a as usize]).collect();
                    let c = f.eval_vector(&values);
                    r[*o as usize] = match part {
                        5 => c[0] * 0.297 + c[1] * 0.589 + c[2] * 0.114,
                        i => c[usize::from(*i).min(4)],
                    };
                }
                Inst::Internal(o, f, v) => {
                    let mut values = [0.0f64; 16];
                    let n = v.len().min(16);
                    for (slot, a) in values.iter_mut().zip(v.iter()) {
                        *slot = r[*a as usize];
                    }
                    r[*o as usize] = f.eval(&values[..n]);
                }
                Inst::Sum {
                    out,
                    body,
                    from,
                    to,
                    product,
                    params,
                } => {
                    let (lo, hi) = (r[*from as usize], r[*to as usize]);
                    let mut inner: Vec<f64> = params.iter().map(|a| r[*a as usize]).collect();
                    inner.push(lo);
                    let last = inner.len() - 1;
                    let mut total = if *product { 1.0 } else { 0.0 };
                    let mut i = lo;
                    let mut steps = 0u32;
                    while i <= hi && steps < analysis::function::SUM_STEPS {
                        inner[last] = i;
                        let v = body.eval(&inner);
                        total = if *product { total * v } else { total + v };
                        i += 1.0;
                        steps += 1;
                    }
                    r[*out as usize] = total;
                }
            }
        }
        r[self.result as usize]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn code(params: &[&str], code: Vec<Op>) -> Function {
        Function::code(params.iter().map(|p| p.to_string()).collect(), code)
    }

    #[test]
    fn agrees_with_the_evaluator_through_inlined_calls() {
        // g(a, b) = sin(a) * cos(a) + b; f(x, y, z) = g(x, y) - g(x, z) + max(x, y, z)
        let g = Arc::new(code(
            &["a", "b"],
            vec![
                Op::Param(0),
                Op::Unary(Unary::Sin),
                Op::Param(0),
                Op::Unary(Unary::Cos),
                Op::Mul,
                Op::Param(1),
                Op::Add,
            ],
        ));
        let f = code(
            &["x", "y", "z"],
            vec![
                Op::Param(0),
                Op::Param(1),
                Op::Call(g.clone(), 2),
                Op::Param(0),
                Op::Param(2),
                Op::Call(g, 2),
                Op::Sub,
                Op::Param(0),
                Op::Param(1),
                Op::Param(2),
                Op::Max(3),
                Op::Add,
            ],
        );
        let program = Program::compile(&f, 3).unwrap();
        for p in [[0.3, -1.2, 2.5], [10.0, 0.0, -4.0], [-7.5, 3.3, 3.3]] {
            let want = f.eval(&p);
            let got = program.eval(&p);
            assert!((want - got).abs() < 1e-12, "{p:?}: {want} {got}");
        }
        // sin(x) and cos(x) share one instruction; the two calls share sin(x)·cos(x).
        let fused = program
            .code
            .iter()
            .filter(|i| matches!(i, Inst::SinCos(..)))
            .count();
        assert_eq!(fused, 1, "{:#?}", program.code);
    }

    #[test]
    fn deep_expressions_reuse_registers() {
        // ((((x + 1) * x + 2) * x + 3) ...): a long chain needs few registers.
        let mut ops = vec![Op::Param(0)];
        for k in 0..200 {
            ops.push(Op::Const(f64::from(k)));
            ops.push(Op::Add);
            ops.push(Op::Param(0));
            ops.push(Op::Mul);
        }
        let f = code(&["x"], ops);
        let program = Program::compile(&f, 1).unwrap();
        assert!(program.registers <= 4, "{}", program.registers);
        assert_eq!(program.eval(&[0.5]), f.eval(&[0.5]));
    }

    #[test]
    fn sums_and_selects_match() {
        // sum(i, 1, 4, i * x) + select(y, 1, 2)
        let f = code(
            &["x", "y"],
            vec![
                Op::Const(1.0),
                Op::Const(4.0),
                Op::Sum {
                    body: vec![Op::Param(2), Op::Param(0), Op::Mul].into(),
                    product: false,
                },
                Op::Param(1),
                Op::Const(1.0),
                Op::Const(2.0),
                Op::Select3,
                Op::Add,
            ],
        );
        let program = Program::compile(&f, 2).unwrap();
        for p in [[2.0, -1.0], [0.5, 3.0]] {
            assert_eq!(program.eval(&p), f.eval(&p));
        }
    }
}
