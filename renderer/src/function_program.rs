//! User functions compiled for tracing. An isosurface evaluates its function tens of
//! millions of times, so the evaluator's stack code is turned once into straight-line
//! register code: calls of other code functions are inlined, constant operands folded,
//! repeated subexpressions computed once, `sin` and `cos` of one argument fused into one
//! range reduction, and registers reused so that evaluation runs in a small array on the
//! stack. Functions built from patterns, pigments, splines and transforms stay calls.

use crate::fast_math;
use analysis::function::{Body, Function, Internal, Op, Unary};
use analysis::trig;
use std::collections::HashMap;
use std::sync::Arc;

/// The most instructions inlining may produce; past it calls stay calls.
const MAX_INLINED: usize = 20_000;

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
        Unary::Cos => trig::sin_cos(v).1,
        Unary::Cosh => v.cosh(),
        Unary::Degrees => v.to_degrees(),
        Unary::Exp => v.exp(),
        Unary::Floor => v.floor(),
        Unary::Int => v.trunc(),
        Unary::Ln => v.ln(),
        Unary::Log => v.log10(),
        Unary::Radians => v.to_radians(),
        Unary::Sin => trig::sin_cos(v).0,
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
    /// A binary operation with a constant operand: `a op k`, or `k op a` when `swapped`.
    WithConstant(Binary, u32, f64, bool),
    /// a·b + c, and a·b - c: a product used once, fused into the sum that uses it.
    MulAdd(u32, u32, u32),
    MulSub(u32, u32, u32),
    /// a·b + c·d: two products used once, summed.
    MulMulAdd([u32; 4]),
    /// a·b + (c·d + e·f): the sum of three products, as dot products and sums of
    /// squares are written.
    Dot3([u32; 6]),
    /// sin(a·k) or cos(a·k), when the product serves only a sine and cosine pair.
    ScaledTrig(Unary, u32, f64),
    /// a·b + k, √a + k and (a + b)·k: a product, root or sum used once, and the constant
    /// added to it or multiplied with it.
    MulAddK(u32, u32, f64),
    SqrtAddK(u32, f64),
    AddMulK(u32, u32, f64),
    /// a·k1 + k2: a scaled value used once, and the constant added to it.
    MulKAddK(u32, f64, f64),
    /// √(a·b + k): a product plus a constant used once, under a root.
    SqrtMulAddK(u32, u32, f64),
    /// |a| - b: an absolute value used once, and what is taken from it.
    AbsSub(u32, u32),
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

/// An instruction over registers. The operations scenes use most are instructions of
/// their own, so that an interpreter running the interpreter (the plugin in wasmi)
/// dispatches once per operation; rare ones with lists of operands live in a side table.
#[derive(Debug, Clone, PartialEq)]
enum Inst {
    Const(u8, f64),
    Neg(u8, u8),
    Abs(u8, u8),
    Sqrt(u8, u8),
    Unary(u8, Unary, u8),
    /// Both of one argument: sine to the first register, cosine to the second.
    SinCos(u8, u8, u8),
    /// Both of the argument times k.
    SinCosK(u8, u8, u8, f64),
    Add(u8, u8, u8),
    Sub(u8, u8, u8),
    Mul(u8, u8, u8),
    Div(u8, u8, u8),
    /// o = a·b + c and o = a·b - c.
    MulAdd(u8, [u8; 3]),
    MulSub(u8, [u8; 3]),
    /// o = a·b + c·d and o = a·b + (c·d + e·f).
    MulMulAdd(u8, [u8; 4]),
    Dot3(u8, [u8; 6]),
    /// o = a·a + (b·b + c·c): a Dot3 of squares, each operand read once.
    SumOfSquares(u8, [u8; 3]),
    /// Both a + b, to the first register, and a - b, to the second.
    SumDifference([u8; 2], [u8; 2]),
    /// o = a·b + k, √a + k and (a + b)·k.
    MulAddK(u8, [u8; 2], f64),
    SqrtAddK(u8, u8, f64),
    AddMulK(u8, [u8; 2], f64),
    /// o = a·k1 + k2, √(a·b + k) and |a| - b.
    MulKAddK(u8, u8, [f64; 2]),
    SqrtMulAddK(u8, [u8; 2], f64),
    /// o = √(a·a + k): a SqrtMulAddK of a square, its operand read once.
    SqrtSquareAddK(u8, u8, f64),
    AbsSub(u8, [u8; 2]),
    /// o = a + k, a·k, k - a, a / k and k / a.
    AddK(u8, u8, f64),
    MulK(u8, u8, f64),
    KSub(u8, u8, f64),
    DivK(u8, u8, f64),
    KDiv(u8, u8, f64),
    Binary(u8, Binary, u8, u8),
    Select3(u8, [u8; 3]),
    Select4(u8, [u8; 4]),
    /// One of the rare instructions, by its index in the side table.
    Rare(u8, u16),
}

/// Instructions with lists of operands or nested code.
#[derive(Debug, Clone, PartialEq)]
enum Rare {
    Min(Box<[u8]>),
    Max(Box<[u8]>),
    Call(Arc<Function>, Box<[u8]>),
    CallPart(Arc<Function>, Box<[u8]>, u8),
    Internal(Internal, Box<[u8]>),
    Sum {
        body: Arc<Program>,
        from: u8,
        to: u8,
        product: bool,
        params: Box<[u8]>,
    },
}

/// A register file for evaluating programs many times in a row, such as along one ray:
/// large enough for any program, so that register numbers index it without masks or
/// bounds checks, and cleared once instead of at every evaluation. What a register held
/// before does not matter: code writes each register before it reads it.
#[derive(Debug, Clone)]
pub struct Registers([f64; 256]);

impl Default for Registers {
    fn default() -> Self {
        Registers([0.0; 256])
    }
}

/// A compiled float function of `params` parameters.
#[derive(Debug, Clone, PartialEq)]
pub struct Program {
    code: Vec<Inst>,
    rare: Vec<Rare>,
    /// Registers 0..params hold the parameters.
    params: usize,
    registers: usize,
    result: u8,
}

/// Builds value-numbered nodes from stack code.
struct Builder {
    nodes: Vec<Node>,
    known: HashMap<Key, u32>,
}

impl Builder {
    fn push(&mut self, node: Node) -> u32 {
        let node = match self.merged_scales(&node) {
            Some((x, k)) => {
                let k = self.push(Node::Const(k));
                Node::Binary(Binary::Mul, x, k)
            }
            None => node,
        };
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
            Node::Call(..)
            | Node::CallPart(..)
            | Node::Sum { .. }
            | Node::WithConstant(..)
            | Node::MulAdd(..)
            | Node::MulSub(..)
            | Node::MulMulAdd(..)
            | Node::Dot3(..)
            | Node::ScaledTrig(..)
            | Node::MulAddK(..)
            | Node::SqrtAddK(..)
            | Node::AddMulK(..)
            | Node::MulKAddK(..)
            | Node::SqrtMulAddK(..)
            | Node::AbsSub(..) => None,
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

    /// `(x·k1)·k2` or `(x·k1)/k2` as x·k with k = k1·k2 or k1/k2, when k2 is a power of two:
    /// scaling by it rounds nothing (short of leaving the range of floats), so the one
    /// product is the two.
    fn merged_scales(&self, node: &Node) -> Option<(u32, f64)> {
        let Node::Binary(op @ (Binary::Mul | Binary::Div), a, b) = *node else {
            return None;
        };
        let (inner, k2) = match (self.constant(a), self.constant(b)) {
            (_, Some(k)) => (a, k),
            (Some(k), None) if op == Binary::Mul => (b, k),
            _ => return None,
        };
        let Node::Binary(Binary::Mul, x, y) = self.nodes[inner as usize] else {
            return None;
        };
        let (x, k1) = match (self.constant(x), self.constant(y)) {
            (_, Some(k)) => (x, k),
            (Some(k), None) => (y, k),
            _ => return None,
        };
        let scale = exact_reciprocal(k2)?;
        let k = if op == Binary::Mul {
            k1 / scale
        } else {
            k1 * scale
        };
        k.is_normal().then_some((x, k))
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
                // A square is the product a·a, to the bit, so that it fuses as products do.
                Op::Unary(Unary::Sqr) => {
                    let a = stack.pop()?;
                    self.push(Node::Binary(Binary::Mul, a, a))
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
        Program::from_nodes(builder.nodes, result, params)
    }

    /// Keeps the nodes the result depends on, fuses constants and products into the
    /// operations that use them, pairs sines with cosines of one argument, and gives each
    /// value a register that is reused after its last use; `None` past 256 registers.
    /// The first `params` nodes are the parameters: they keep the first registers, which
    /// evaluation fills before the code runs.
    fn from_nodes(mut nodes: Vec<Node>, result: u32, params: usize) -> Option<Program> {
        let n = nodes.len();
        let live = live_nodes(&nodes, result, params);
        fuse(&mut nodes, &live, result);
        let live = live_nodes(&nodes, result, params);
        scale_trig_pairs(&mut nodes, &live, result);
        let live = live_nodes(&nodes, result, params);
        fuse_constant_tails(&mut nodes, &live, result);
        let live = live_nodes(&nodes, result, params);
        // A sine and a cosine of one argument, and a sum and a difference of two: the
        // later one is filled by the earlier.
        let mut partner: Vec<Option<u32>> = vec![None; n];
        for (s, c) in trig_pairs(&nodes, &live)
            .into_iter()
            .chain(sum_difference_pairs(&nodes, &live))
        {
            let (first, second) = if s < c { (s, c) } else { (c, s) };
            partner[first] = Some(second as u32);
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
        let mut register = vec![0u8; n];
        let mut free: Vec<u8> = Vec::new();
        let mut count = 0usize;
        let mut take = |free: &mut Vec<u8>| -> Option<u8> {
            match free.pop() {
                Some(r) => Some(r),
                None => {
                    count += 1;
                    u8::try_from(count - 1).ok()
                }
            }
        };
        let mut code = Vec::new();
        let mut rare = Vec::new();
        for i in 0..n {
            if !live[i] {
                continue;
            }
            if !filled[i] {
                register[i] = take(&mut free)?;
            }
            if let Some(p) = partner[i] {
                register[p as usize] = take(&mut free)?;
            }
            let r = |a: &u32| register[*a as usize];
            let list = |v: &[u32]| -> Box<[u8]> { v.iter().map(r).collect() };
            let out = register[i];
            let mut add_rare = |entry: Rare| -> Option<Inst> {
                rare.push(entry);
                Some(Inst::Rare(out, u16::try_from(rare.len() - 1).ok()?))
            };
            let inst = match &nodes[i] {
                _ if filled[i] => None,
                Node::Const(v) => Some(Inst::Const(out, *v)),
                Node::Param(_) => None,
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
                    None => Some(match f {
                        Unary::Abs => Inst::Abs(out, r(a)),
                        Unary::Sqrt => Inst::Sqrt(out, r(a)),
                        _ => Inst::Unary(out, *f, r(a)),
                    }),
                },
                Node::Binary(op @ (Binary::Add | Binary::Sub), a, b) if partner[i].is_some() => {
                    let other = partner[i].map_or(0, |p| register[p as usize]);
                    // The difference's operands, in its order: a sum's commute.
                    let (x, y) = match nodes[partner[i].map_or(i, |p| p as usize)] {
                        Node::Binary(Binary::Sub, x, y) if *op == Binary::Add => (x, y),
                        _ => (*a, *b),
                    };
                    Some(if *op == Binary::Add {
                        Inst::SumDifference([out, other], [r(&x), r(&y)])
                    } else {
                        Inst::SumDifference([other, out], [r(&x), r(&y)])
                    })
                }
                Node::Binary(op, a, b) => Some(match op {
                    Binary::Add => Inst::Add(out, r(a), r(b)),
                    Binary::Sub => Inst::Sub(out, r(a), r(b)),
                    Binary::Mul => Inst::Mul(out, r(a), r(b)),
                    Binary::Div => Inst::Div(out, r(a), r(b)),
                    _ => Inst::Binary(out, *op, r(a), r(b)),
                }),
                Node::WithConstant(op, a, k, swapped) => Some(match (op, swapped) {
                    (Binary::Add, _) => Inst::AddK(out, r(a), *k),
                    (Binary::Mul, _) => Inst::MulK(out, r(a), *k),
                    (Binary::Sub, false) => Inst::AddK(out, r(a), -*k),
                    (Binary::Sub, true) => Inst::KSub(out, r(a), *k),
                    (Binary::Div, false) => match exact_reciprocal(*k) {
                        Some(inverse) => Inst::MulK(out, r(a), inverse),
                        None => Inst::DivK(out, r(a), *k),
                    },
                    (_, _) => Inst::KDiv(out, r(a), *k),
                }),
                Node::MulAdd(a, b, c) => Some(Inst::MulAdd(out, [r(a), r(b), r(c)])),
                Node::MulSub(a, b, c) => Some(Inst::MulSub(out, [r(a), r(b), r(c)])),
                Node::MulMulAdd(v) => Some(Inst::MulMulAdd(out, v.map(|a| r(&a)))),
                Node::Dot3([a, b, c, d, e, f]) if a == b && c == d && e == f => {
                    Some(Inst::SumOfSquares(out, [r(a), r(c), r(e)]))
                }
                Node::Dot3(v) => Some(Inst::Dot3(out, v.map(|a| r(&a)))),
                Node::MulAddK(a, b, k) => Some(Inst::MulAddK(out, [r(a), r(b)], *k)),
                Node::SqrtAddK(a, k) => Some(Inst::SqrtAddK(out, r(a), *k)),
                Node::AddMulK(a, b, k) => Some(Inst::AddMulK(out, [r(a), r(b)], *k)),
                Node::MulKAddK(a, k1, k2) => Some(Inst::MulKAddK(out, r(a), [*k1, *k2])),
                Node::SqrtMulAddK(a, b, k) if a == b => Some(Inst::SqrtSquareAddK(out, r(a), *k)),
                Node::SqrtMulAddK(a, b, k) => Some(Inst::SqrtMulAddK(out, [r(a), r(b)], *k)),
                Node::AbsSub(a, b) => Some(Inst::AbsSub(out, [r(a), r(b)])),
                Node::ScaledTrig(f, a, k) => match partner[i] {
                    Some(p) => {
                        let other = register[p as usize];
                        Some(if *f == Unary::Sin {
                            Inst::SinCosK(out, other, r(a), *k)
                        } else {
                            Inst::SinCosK(other, out, r(a), *k)
                        })
                    }
                    // Pairs are scaled together; a lone one is its product, then itself.
                    None => {
                        code.push(Inst::MulK(out, r(a), *k));
                        Some(Inst::Unary(out, *f, out))
                    }
                },
                Node::Select3(a, b, c) => Some(Inst::Select3(out, [r(a), r(b), r(c)])),
                Node::Select4(a, b, c, d) => Some(Inst::Select4(out, [r(a), r(b), r(c), r(d)])),
                Node::Min(v) => add_rare(Rare::Min(list(v))),
                Node::Max(v) => add_rare(Rare::Max(list(v))),
                Node::Call(f, v) => add_rare(Rare::Call(f.clone(), list(v))),
                Node::CallPart(f, v, part) => add_rare(Rare::CallPart(f.clone(), list(v), *part)),
                Node::Internal(f, v) => add_rare(Rare::Internal(*f, list(v))),
                Node::Sum {
                    body,
                    from,
                    to,
                    product,
                    params,
                } => add_rare(Rare::Sum {
                    body: body.clone(),
                    from: r(from),
                    to: r(to),
                    product: *product,
                    params: list(params),
                }),
            };
            if let Some(inst) = inst {
                code.push(inst);
            }
            // Operands whose last use is here go back to the pool, after this
            // instruction's own register was taken so that none is overwritten early.
            let mut released: Vec<u8> = Vec::new();
            for a in operands(&nodes[i]) {
                if last_use[a as usize] == i {
                    released.push(register[a as usize]);
                }
            }
            released.sort_unstable();
            released.dedup();
            free.extend(released);
        }
        Some(Program {
            code,
            rare,
            params,
            registers: count.max(1),
            result: register[result as usize],
        })
    }

    /// The value at `args` (one per parameter; missing ones are 0).
    pub fn eval(&self, args: &[f64]) -> f64 {
        // The register file is as small as the program allows: it is cleared at every
        // call. A power of two lets indices be masked instead of bounds-checked.
        match self.registers {
            0..=16 => self.run(&mut self.registers_with::<16>(args)),
            17..=32 => self.run(&mut self.registers_with::<32>(args)),
            33..=64 => self.run(&mut self.registers_with::<64>(args)),
            _ => self.run(&mut self.registers_with::<256>(args)),
        }
    }

    /// Three-parameter evaluation, the common case of isosurfaces: the parameters go
    /// straight into the first registers when the program is small.
    pub fn eval3(&self, x: f64, y: f64, z: f64) -> f64 {
        if self.params == 3 && self.registers <= 16 {
            let mut r = [0.0; 16];
            (r[0], r[1], r[2]) = (x, y, z);
            return self.run(&mut r);
        }
        self.eval(&[x, y, z])
    }

    /// [`Program::eval3`] in registers that the caller keeps from one evaluation to the next.
    pub fn eval3_in(&self, registers: &mut Registers, x: f64, y: f64, z: f64) -> f64 {
        // Parameters past the third would have to be cleared.
        if self.params > 3 {
            return self.eval3(x, y, z);
        }
        let r = &mut registers.0;
        (r[0], r[1], r[2]) = (x, y, z);
        self.run(r)
    }

    /// A cleared register file with the parameters in its first registers.
    fn registers_with<const N: usize>(&self, args: &[f64]) -> [f64; N] {
        let mut r = [0.0; N];
        for (slot, arg) in r.iter_mut().zip(args).take(self.params) {
            *slot = *arg;
        }
        r
    }

    /// Runs the code on registers holding the parameters.
    fn run<const N: usize>(&self, r: &mut [f64; N]) -> f64 {
        let at = |i: u8| usize::from(i) & (N - 1);
        for inst in &self.code {
            match *inst {
                Inst::Const(o, v) => r[at(o)] = v,
                Inst::Neg(o, a) => r[at(o)] = -r[at(a)],
                Inst::Abs(o, a) => r[at(o)] = r[at(a)].abs(),
                Inst::Sqrt(o, a) => r[at(o)] = r[at(a)].sqrt(),
                Inst::Unary(o, f, a) => r[at(o)] = unary(f, r[at(a)]),
                Inst::SinCos(s, c, a) => {
                    let (sin, cos) = trig::sin_cos(r[at(a)]);
                    r[at(s)] = sin;
                    r[at(c)] = cos;
                }
                Inst::SinCosK(s, c, a, k) => {
                    let (sin, cos) = trig::sin_cos(r[at(a)] * k);
                    r[at(s)] = sin;
                    r[at(c)] = cos;
                }
                Inst::Add(o, a, b) => r[at(o)] = r[at(a)] + r[at(b)],
                Inst::Sub(o, a, b) => r[at(o)] = r[at(a)] - r[at(b)],
                Inst::Mul(o, a, b) => r[at(o)] = r[at(a)] * r[at(b)],
                Inst::Div(o, a, b) => r[at(o)] = r[at(a)] / r[at(b)],
                Inst::MulAdd(o, [a, b, c]) => r[at(o)] = r[at(a)] * r[at(b)] + r[at(c)],
                Inst::MulSub(o, [a, b, c]) => r[at(o)] = r[at(a)] * r[at(b)] - r[at(c)],
                Inst::MulMulAdd(o, [a, b, c, d]) => {
                    r[at(o)] = r[at(a)] * r[at(b)] + r[at(c)] * r[at(d)]
                }
                Inst::SumOfSquares(o, [a, b, c]) => {
                    let (a, b, c) = (r[at(a)], r[at(b)], r[at(c)]);
                    r[at(o)] = a * a + (b * b + c * c)
                }
                Inst::SumDifference([s, d], [a, b]) => {
                    let (a, b) = (r[at(a)], r[at(b)]);
                    r[at(s)] = a + b;
                    r[at(d)] = a - b;
                }
                Inst::Dot3(o, [a, b, c, d, e, f]) => {
                    r[at(o)] = r[at(a)] * r[at(b)] + (r[at(c)] * r[at(d)] + r[at(e)] * r[at(f)])
                }
                Inst::MulAddK(o, [a, b], k) => r[at(o)] = r[at(a)] * r[at(b)] + k,
                Inst::SqrtAddK(o, a, k) => r[at(o)] = r[at(a)].sqrt() + k,
                Inst::AddMulK(o, [a, b], k) => r[at(o)] = (r[at(a)] + r[at(b)]) * k,
                Inst::MulKAddK(o, a, [k1, k2]) => r[at(o)] = r[at(a)] * k1 + k2,
                Inst::SqrtMulAddK(o, [a, b], k) => r[at(o)] = (r[at(a)] * r[at(b)] + k).sqrt(),
                Inst::SqrtSquareAddK(o, a, k) => {
                    let a = r[at(a)];
                    r[at(o)] = (a * a + k).sqrt()
                }
                Inst::AbsSub(o, [a, b]) => r[at(o)] = r[at(a)].abs() - r[at(b)],
                Inst::AddK(o, a, k) => r[at(o)] = r[at(a)] + k,
                Inst::MulK(o, a, k) => r[at(o)] = r[at(a)] * k,
                Inst::KSub(o, a, k) => r[at(o)] = k - r[at(a)],
                Inst::DivK(o, a, k) => r[at(o)] = r[at(a)] / k,
                Inst::KDiv(o, a, k) => r[at(o)] = k / r[at(a)],
                Inst::Binary(o, op, a, b) => r[at(o)] = op.apply(r[at(a)], r[at(b)]),
                Inst::Select3(o, [c, a, b]) => {
                    r[at(o)] = if r[at(c)] < 0.0 { r[at(a)] } else { r[at(b)] }
                }
                Inst::Select4(o, [c, a, b, d]) => {
                    let v = r[at(c)];
                    r[at(o)] = if v < 0.0 {
                        r[at(a)]
                    } else if v == 0.0 {
                        r[at(b)]
                    } else {
                        r[at(d)]
                    }
                }
                Inst::Rare(o, index) => {
                    let v = self.run_rare(index, &r[..]);
                    r[at(o)] = v;
                }
            }
        }
        r[at(self.result)]
    }

    /// The value of a rare instruction, from the registers.
    fn run_rare(&self, index: u16, r: &[f64]) -> f64 {
        let get = |a: &u8| r[usize::from(*a)];
        match &self.rare[usize::from(index)] {
            Rare::Min(v) => v.iter().map(get).fold(f64::INFINITY, fast_math::min),
            Rare::Max(v) => v.iter().map(get).fold(f64::NEG_INFINITY, fast_math::max),
            Rare::Call(f, v) => {
                let values: Vec<f64> = v.iter().map(get).collect();
                f.eval(&values)
            }
            Rare::CallPart(f, v, part) => {
                let values: Vec<f64> = v.iter().map(get).collect();
                let c = f.eval_vector(&values);
                match part {
                    5 => c[0] * 0.297 + c[1] * 0.589 + c[2] * 0.114,
                    i => c[usize::from(*i).min(4)],
                }
            }
            Rare::Internal(f, v) => {
                let mut values = [0.0f64; 16];
                let n = v.len().min(16);
                for (slot, a) in values.iter_mut().zip(v.iter()) {
                    *slot = get(a);
                }
                f.eval(&values[..n])
            }
            Rare::Sum {
                body,
                from,
                to,
                product,
                params,
            } => {
                let (lo, hi) = (get(from), get(to));
                let mut inner: Vec<f64> = params.iter().map(get).collect();
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
                total
            }
        }
    }
}

/// The values a node reads.
fn operands(node: &Node) -> Vec<u32> {
    match node {
        Node::Const(_) | Node::Param(_) => Vec::new(),
        Node::Neg(a) | Node::Unary(_, a) | Node::WithConstant(_, a, _, _) => vec![*a],
        Node::Binary(_, a, b) => vec![*a, *b],
        Node::Select3(a, b, c) | Node::MulAdd(a, b, c) | Node::MulSub(a, b, c) => {
            vec![*a, *b, *c]
        }
        Node::Select4(a, b, c, d) => vec![*a, *b, *c, *d],
        Node::MulMulAdd(v) => v.to_vec(),
        Node::Dot3(v) => v.to_vec(),
        Node::ScaledTrig(_, a, _) | Node::SqrtAddK(a, _) | Node::MulKAddK(a, _, _) => vec![*a],
        Node::MulAddK(a, b, _)
        | Node::AddMulK(a, b, _)
        | Node::SqrtMulAddK(a, b, _)
        | Node::AbsSub(a, b) => vec![*a, *b],
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
}

/// The nodes the result depends on, and the parameters.
fn live_nodes(nodes: &[Node], result: u32, params: usize) -> Vec<bool> {
    let mut live = vec![false; nodes.len()];
    live[..params].fill(true);
    live[result as usize] = true;
    for i in (0..nodes.len()).rev() {
        if live[i] {
            for a in operands(&nodes[i]) {
                live[a as usize] = true;
            }
        }
    }
    live
}

/// How many times each value is read by the live nodes, the result counting as one.
fn use_counts(nodes: &[Node], live: &[bool], result: u32) -> Vec<u32> {
    let mut uses = vec![0u32; nodes.len()];
    uses[result as usize] += 1;
    for (i, node) in nodes.iter().enumerate() {
        if live[i] {
            for a in operands(node) {
                uses[a as usize] += 1;
            }
        }
    }
    uses
}

/// Rewrites, in place, arithmetic with a constant operand into one node, and a sum or
/// difference whose operand is a product used nowhere else into a multiply-add (a sum of
/// two or three such products into one node). The arithmetic is the same, operation for
/// operation, so values do not change.
fn fuse(nodes: &mut [Node], live: &[bool], result: u32) {
    let mut uses = use_counts(nodes, live, result);
    let constant = |nodes: &[Node], i: u32| match nodes[i as usize] {
        Node::Const(v) => Some(v),
        _ => None,
    };
    let product = |nodes: &[Node], uses: &[u32], i: u32| match nodes[i as usize] {
        Node::Binary(Binary::Mul, a, b) if uses[i as usize] == 1 => Some((a, b)),
        _ => None,
    };
    for i in 0..nodes.len() {
        if !live[i] {
            continue;
        }
        let Node::Binary(op, a, b) = nodes[i] else {
            continue;
        };
        if !matches!(op, Binary::Add | Binary::Sub | Binary::Mul | Binary::Div) {
            continue;
        }
        // The rewritten node, and the product it swallowed.
        let fused = if let Some(k) = constant(nodes, b) {
            Some((Node::WithConstant(op, a, k, false), None))
        } else if let Some(k) = constant(nodes, a) {
            // k + a and k·a are a + k and a·k: addition and multiplication commute.
            let swapped = matches!(op, Binary::Sub | Binary::Div);
            Some((Node::WithConstant(op, b, k, swapped), None))
        } else if op == Binary::Add {
            if let Some((x, y)) = product(nodes, &uses, a) {
                let (node, inner) = sum_of_products(nodes, &uses, x, y, b);
                if let Some(inner) = inner {
                    uses[inner as usize] = 0;
                }
                Some((node, Some(a)))
            } else if let Some((x, y)) = product(nodes, &uses, b) {
                let (node, inner) = sum_of_products(nodes, &uses, x, y, a);
                if let Some(inner) = inner {
                    uses[inner as usize] = 0;
                }
                Some((node, Some(b)))
            } else {
                None
            }
        } else if op == Binary::Sub {
            product(nodes, &uses, a).map(|(x, y)| (Node::MulSub(x, y, b), Some(a)))
        } else {
            None
        };
        if let Some((node, swallowed)) = fused {
            if let Some(p) = swallowed {
                uses[p as usize] = 0;
            }
            nodes[i] = node;
        }
    }
}

/// x·y + b as one node, and the node it swallowed: b itself when it is a product or a sum
/// of two used only here. The operations and their order stay those of the expression.
fn sum_of_products(nodes: &[Node], uses: &[u32], x: u32, y: u32, b: u32) -> (Node, Option<u32>) {
    match (&nodes[b as usize], uses[b as usize]) {
        (Node::Binary(Binary::Mul, c, d), 1) => (Node::MulMulAdd([x, y, *c, *d]), Some(b)),
        (Node::MulMulAdd([c, d, e, f]), 1) => (Node::Dot3([x, y, *c, *d, *e, *f]), Some(b)),
        _ => (Node::MulAdd(x, y, b), None),
    }
}

/// Rewrites, in place, a constant added to a product, a square root or a scaled value, or
/// multiplied with a sum; the root of a product plus a constant; and the absolute value
/// that a difference starts from: each into one node with its operand when nothing else
/// reads that operand, one instruction instead of two with the same operations in the same
/// order, so values do not change.
fn fuse_constant_tails(nodes: &mut [Node], live: &[bool], result: u32) {
    let mut uses = use_counts(nodes, live, result);
    for i in 0..nodes.len() {
        if !live[i] {
            continue;
        }
        let (a, fused) = match nodes[i] {
            // a + k, and a - k, which is a + (-k) to the bit.
            Node::WithConstant(op @ (Binary::Add | Binary::Sub), a, k, false) => {
                let k = if op == Binary::Sub { -k } else { k };
                let fused = match nodes[a as usize] {
                    Node::Binary(Binary::Mul, x, y) => Some(Node::MulAddK(x, y, k)),
                    Node::Unary(Unary::Sqrt, x) => Some(Node::SqrtAddK(x, k)),
                    ref scaled => scale(scaled).map(|(x, k1)| Node::MulKAddK(x, k1, k)),
                };
                (a, fused)
            }
            ref scaled @ Node::WithConstant(..) => match scale(scaled) {
                Some((a, k)) => match nodes[a as usize] {
                    Node::Binary(Binary::Add, x, y) => (a, Some(Node::AddMulK(x, y, k))),
                    _ => (a, None),
                },
                None => continue,
            },
            Node::Unary(Unary::Sqrt, a) => match nodes[a as usize] {
                Node::MulAddK(x, y, k) => (a, Some(Node::SqrtMulAddK(x, y, k))),
                _ => (a, None),
            },
            Node::Binary(Binary::Sub, a, b) => match nodes[a as usize] {
                Node::Unary(Unary::Abs, x) => (a, Some(Node::AbsSub(x, b))),
                _ => (a, None),
            },
            _ => continue,
        };
        if let Some(node) = fused
            && uses[a as usize] == 1
        {
            uses[a as usize] = 0;
            nodes[i] = node;
        }
    }
}

/// a·k for a node that multiplies by k, or divides by a power of two (exactly a product
/// by its reciprocal): the operand and the factor.
fn scale(node: &Node) -> Option<(u32, f64)> {
    match *node {
        Node::WithConstant(Binary::Mul, a, k, _) => Some((a, k)),
        Node::WithConstant(Binary::Div, a, k, false) => Some((a, exact_reciprocal(k)?)),
        _ => None,
    }
}

/// Rewrites a sine and cosine pair of one product a·k, used by nothing else, into the
/// pair of that product, so that the product is one instruction with them.
fn scale_trig_pairs(nodes: &mut [Node], live: &[bool], result: u32) {
    let uses = use_counts(nodes, live, result);
    for (sin, cos) in trig_pairs(nodes, live) {
        let Node::Unary(_, a) = nodes[sin] else {
            continue;
        };
        if let Node::WithConstant(Binary::Mul, x, k, _) = nodes[a as usize]
            && uses[a as usize] == 2
        {
            nodes[sin] = Node::ScaledTrig(Unary::Sin, x, k);
            nodes[cos] = Node::ScaledTrig(Unary::Cos, x, k);
        }
    }
}

/// The live sines and cosines of one argument (or of one argument times one constant),
/// as (sine, cosine) pairs of node indices.
fn trig_pairs(nodes: &[Node], live: &[bool]) -> Vec<(usize, usize)> {
    // By argument (and the bits of its constant factor): the first sine and cosine.
    type Pair = (Option<usize>, Option<usize>);
    let mut trig: HashMap<(u32, Option<u64>), Pair> = HashMap::new();
    for (i, node) in nodes.iter().enumerate() {
        let (f, key) = match node {
            _ if !live[i] => continue,
            Node::Unary(f @ (Unary::Sin | Unary::Cos), a) => (*f, (*a, None)),
            Node::ScaledTrig(f, a, k) => (*f, (*a, Some(k.to_bits()))),
            _ => continue,
        };
        let entry = trig.entry(key).or_default();
        if f == Unary::Sin {
            entry.0.get_or_insert(i);
        } else {
            entry.1.get_or_insert(i);
        }
    }
    trig.into_values()
        .filter_map(|pair| match pair {
            (Some(sin), Some(cos)) => Some((sin, cos)),
            _ => None,
        })
        .collect()
}

/// The live sums and differences of the same two values, as (sum, difference) pairs of
/// node indices: each pair is one instruction.
fn sum_difference_pairs(nodes: &[Node], live: &[bool]) -> Vec<(usize, usize)> {
    // By operands (a sum's in either order): the first sum and difference.
    let mut found: HashMap<(u32, u32), (Option<usize>, Option<usize>)> = HashMap::new();
    for (i, node) in nodes.iter().enumerate() {
        match *node {
            _ if !live[i] => continue,
            Node::Binary(Binary::Add, a, b) => {
                found.entry((a, b)).or_default().0.get_or_insert(i);
                found.entry((b, a)).or_default().0.get_or_insert(i);
            }
            Node::Binary(Binary::Sub, a, b) => {
                found.entry((a, b)).or_default().1.get_or_insert(i);
            }
            _ => {}
        }
    }
    let mut pairs: Vec<(usize, usize)> = found
        .into_values()
        .filter_map(|pair| match pair {
            (Some(sum), Some(difference)) => Some((sum, difference)),
            _ => None,
        })
        .collect();
    // A sum of a and b is listed under (a, b) and (b, a): it pairs with one difference.
    pairs.sort_unstable();
    pairs.dedup_by_key(|pair| pair.0);
    pairs
}

/// 1/k when it is exact (k a power of two), so that a division by k can be a product.
fn exact_reciprocal(k: f64) -> Option<f64> {
    const MANTISSA: u64 = (1 << 52) - 1;
    let inverse = 1.0 / k;
    (k.is_normal() && inverse.is_normal() && k.to_bits() & MANTISSA == 0).then_some(inverse)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn code(params: &[&str], code: Vec<Op>) -> Function {
        Function::code(params.iter().map(|p| p.to_string()).collect(), code)
    }

    /// Checks how many of the program's instructions `pick` picks.
    fn assert_count(program: &Program, pick: fn(&Inst) -> bool, want: usize) {
        let got = program.code.iter().filter(|i| pick(i)).count();
        assert_eq!(got, want, "{:#?}", program.code);
    }

    #[test]
    fn scales_by_powers_of_two_merge_into_one_product() {
        // (x·0.32)/16 + (y·3)·0.25 + (z·0.3)·3: four products of six, as 3 is no power of
        // two.
        let scaled = |param: u8, k1: f64, op: Op, k2: f64| {
            [Op::Param(param), Op::Const(k1), Op::Mul, Op::Const(k2), op]
        };
        let mut ops = scaled(0, 0.32, Op::Div, 16.0).to_vec();
        ops.extend(scaled(1, 3.0, Op::Mul, 0.25));
        ops.push(Op::Add);
        ops.extend(scaled(2, 0.3, Op::Mul, 3.0));
        ops.push(Op::Add);
        let f = code(&["x", "y", "z"], ops);
        let program = Program::compile(&f, 3).unwrap();
        for p in [[0.3, -1.2, 2.5], [1e-3, 7.0, -4.0], [-7.5, 3.3, 1e5]] {
            assert_eq!(f.eval(&p), program.eval(&p), "{p:?}");
        }
        assert_count(&program, |i| matches!(i, Inst::MulK(..)), 4);
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
    fn constants_and_products_fuse_without_changing_values() {
        // 2·x + y·z - x·y / 4 - 3 / x + (x·x + 0.5)
        let f = code(
            &["x", "y", "z"],
            vec![
                Op::Const(2.0),
                Op::Param(0),
                Op::Mul,
                Op::Param(1),
                Op::Param(2),
                Op::Mul,
                Op::Add,
                Op::Param(0),
                Op::Param(1),
                Op::Mul,
                Op::Const(4.0),
                Op::Div,
                Op::Sub,
                Op::Const(3.0),
                Op::Param(0),
                Op::Div,
                Op::Sub,
                Op::Param(0),
                Op::Param(0),
                Op::Mul,
                Op::Const(0.5),
                Op::Add,
                Op::Add,
            ],
        );
        let program = Program::compile(&f, 3).unwrap();
        for p in [[0.3, -1.2, 2.5], [10.0, 0.0, -4.0], [-7.5, 3.3, 1e-3]] {
            assert_eq!(program.eval(&p).to_bits(), f.eval(&p).to_bits(), "{p:?}");
        }
        assert_count(&program, |i| matches!(i, Inst::Const(..)), 0);
        assert_count(&program, |i| matches!(i, Inst::MulAdd(..)), 1);
        // x / 4 is x · 0.25, exactly; 3 / x stays a division.
        assert_count(
            &program,
            |i| matches!(i, Inst::MulK(_, _, k) if *k == 0.25),
            1,
        );
        assert_count(&program, |i| matches!(i, Inst::KDiv(..)), 1);
    }

    #[test]
    fn scaled_trig_pairs_and_sums_of_products_are_single_instructions() {
        // sin(2x)·cos(2y) + sin(2y)·cos(2z) + sin(2z)·cos(2x) + (x·x + y·y + z·z)
        let trig =
            |f: Unary, axis: u8| vec![Op::Const(2.0), Op::Param(axis), Op::Mul, Op::Unary(f)];
        let mut ops = Vec::new();
        for (s, c) in [(0, 1), (1, 2), (2, 0)] {
            ops.extend(trig(Unary::Sin, s));
            ops.extend(trig(Unary::Cos, c));
            ops.push(Op::Mul);
        }
        ops.extend([Op::Add, Op::Add]);
        for axis in 0..3 {
            ops.extend([Op::Param(axis), Op::Param(axis), Op::Mul]);
        }
        ops.extend([Op::Add, Op::Add, Op::Add]);
        let f = code(&["x", "y", "z"], ops);
        let program = Program::compile(&f, 3).unwrap();
        for p in [[0.3, -1.2, 2.5], [10.0, 0.0, -4.0], [-7.5, 3.3, 3.3]] {
            let (want, got) = (f.eval(&p), program.eval(&p));
            assert!((want - got).abs() < 1e-12, "{p:?}: {want} {got}");
        }
        assert_count(&program, |i| matches!(i, Inst::SinCosK(..)), 3);
        assert_count(&program, |i| matches!(i, Inst::Dot3(..)), 1);
        assert_count(&program, |i| matches!(i, Inst::SumOfSquares(..)), 1);
        assert_count(&program, |_| true, 6);
    }

    #[test]
    fn constants_after_products_roots_and_sums_are_one_instruction() {
        // ((x·y + 0.25) + √z - 4)·0.5, with x·y and √z used nowhere else, but x + y used
        // twice: (x + y)·3 + (x + y).
        let smooth = code(
            &["x", "y", "z"],
            vec![
                Op::Param(0),
                Op::Param(1),
                Op::Mul,
                Op::Const(0.25),
                Op::Add,
                Op::Param(2),
                Op::Unary(Unary::Sqrt),
                Op::Const(4.0),
                Op::Sub,
                Op::Add,
                Op::Const(0.5),
                Op::Mul,
            ],
        );
        let program = Program::compile(&smooth, 3).unwrap();
        for p in [[0.3, -1.2, 2.5], [10.0, 0.0, 4.0], [-7.5, 3.3, 0.1]] {
            assert_eq!(program.eval(&p), smooth.eval(&p), "{p:?}");
        }
        assert_count(&program, |i| matches!(i, Inst::MulAddK(..)), 1);
        assert_count(&program, |i| matches!(i, Inst::SqrtAddK(..)), 1);
        assert_count(&program, |i| matches!(i, Inst::AddMulK(..)), 1);
        assert_count(&program, |_| true, 3);
        let shared = code(
            &["x", "y"],
            vec![
                Op::Param(0),
                Op::Param(1),
                Op::Add,
                Op::Const(3.0),
                Op::Mul,
                Op::Param(0),
                Op::Param(1),
                Op::Add,
                Op::Add,
            ],
        );
        let program = Program::compile(&shared, 2).unwrap();
        assert_eq!(program.eval(&[1.5, -0.25]), shared.eval(&[1.5, -0.25]));
        assert_count(&program, |i| matches!(i, Inst::AddMulK(..)), 0);
    }

    #[test]
    fn scaled_offsets_roots_of_products_and_absolute_differences_are_one_instruction() {
        // a = |x| - (y·0.32/16 + 0.15), b = z; (a + b + √((a - b)·(a - b) + 0.0625)) / 2,
        // where a + b and a - b are one instruction too.
        let f = code(
            &["x", "y", "z"],
            vec![
                Op::Param(0),
                Op::Unary(Unary::Abs),
                Op::Const(0.15),
                Op::Const(0.32),
                Op::Param(1),
                Op::Mul,
                Op::Const(16.0),
                Op::Div,
                Op::Add,
                Op::Sub,
                Op::Param(2),
                Op::Call(
                    Arc::new(code(
                        &["a", "b"],
                        vec![
                            Op::Param(0),
                            Op::Param(1),
                            Op::Add,
                            Op::Param(0),
                            Op::Param(1),
                            Op::Sub,
                            Op::Unary(Unary::Sqr),
                            Op::Const(0.0625),
                            Op::Add,
                            Op::Unary(Unary::Sqrt),
                            Op::Add,
                            Op::Const(2.0),
                            Op::Div,
                        ],
                    )),
                    2,
                ),
            ],
        );
        let program = Program::compile(&f, 3).unwrap();
        for p in [[0.3, -1.2, 2.5], [10.0, 0.0, -4.0], [-7.5, 3.3, 1e-3]] {
            assert_eq!(program.eval(&p).to_bits(), f.eval(&p).to_bits(), "{p:?}");
        }
        assert_count(&program, |i| matches!(i, Inst::MulKAddK(..)), 1);
        assert_count(&program, |i| matches!(i, Inst::AbsSub(..)), 1);
        assert_count(&program, |i| matches!(i, Inst::SqrtSquareAddK(..)), 1);
        assert_count(&program, |i| matches!(i, Inst::SumDifference(..)), 1);
        assert_count(
            &program,
            |i| matches!(i, Inst::AddMulK(_, _, k) if *k == 0.5),
            1,
        );
        assert_count(&program, |_| true, 5);
    }

    #[test]
    fn a_sum_pairs_with_one_difference_of_its_operands() {
        // (y + x)·(x - y) + (y - x): the sum commutes, so either difference could pair.
        let f = code(
            &["x", "y"],
            vec![
                Op::Param(1),
                Op::Param(0),
                Op::Add,
                Op::Param(0),
                Op::Param(1),
                Op::Sub,
                Op::Mul,
                Op::Param(1),
                Op::Param(0),
                Op::Sub,
                Op::Add,
            ],
        );
        let program = Program::compile(&f, 2).unwrap();
        for p in [[0.3, -1.2], [10.0, 0.1], [-7.5, 3.3]] {
            assert_eq!(program.eval(&p).to_bits(), f.eval(&p).to_bits(), "{p:?}");
        }
        assert_count(&program, |i| matches!(i, Inst::SumDifference(..)), 1);
        assert_count(&program, |i| matches!(i, Inst::Sub(..)), 1);
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
