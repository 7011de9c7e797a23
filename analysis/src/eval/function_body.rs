//! Compiles `function { }` bodies into [`Function`] bytecode, and calls functions at parse
//! time. Inside a body the full float grammar applies without parentheses (relational and
//! logical operators included); identifiers are parameters, declared floats (captured as
//! constants) or declared functions (called).

use super::tokens::Token;
use super::value::Terms;
use super::value::Value;
use super::{Evaluator, Result};
use crate::function::{Body, Function, Internal, MAX_STACK, Op, Unary};
use crate::scene::{PatternKind, Pigment};
use crate::spline::Spline;
use std::sync::Arc;
use syntax::SyntaxKind::*;

impl Evaluator<'_> {
    /// `function [(a, b, ...)] { body }`.
    pub fn function_value(&mut self) -> Result<Function> {
        let keyword = self.expect(FUNCTION_KW, "'function'")?;
        let mut params = Vec::new();
        let explicit_params = self.peek_kind()? == L_PAREN;
        if self.eat(L_PAREN)? {
            loop {
                let name = self.next_raw()?;
                if name.kind != IDENT && !name.kind.is_keyword() {
                    return Err(self.error_at(
                        &name,
                        format!("expected a parameter name, found {}", self.describe(&name)),
                    ));
                }
                params.push(self.text(&name).to_owned());
                let separator = self.next_raw()?;
                match separator.kind {
                    COMMA => continue,
                    R_PAREN => break,
                    _ => {
                        return Err(self.error_at(
                            &separator,
                            format!("expected ',' or ')', found {}", self.describe(&separator)),
                        ));
                    }
                }
            }
        } else {
            params = vec!["x".into(), "y".into(), "z".into()];
        }
        self.expect(L_BRACE, "'{'")?;
        let first = self.next()?;
        if first.kind == INTERNAL_KW {
            return self.internal_function();
        }
        if let Some(body) = self.special_function_body(&first)? {
            self.expect(R_BRACE, "'}' to close the function")?;
            // A spline function takes the spline's parameter only.
            if matches!(body, Body::Spline(_)) && !explicit_params {
                params.truncate(1);
            }
            return Ok(Function { params, body });
        }
        let mut code = Vec::new();
        self.fn_or(&params, &mut code)?;
        self.expect(R_BRACE, "'}' to close the function")?;
        match Function::stack_depth(&code) {
            Some(depth) if depth <= MAX_STACK => Ok(Function::code(params, code)),
            _ => Err(self.error_at(
                &keyword,
                format!("this function nests deeper than {MAX_STACK} levels"),
            )),
        }
    }

    /// `internal(N) }`, after `internal`.
    fn internal_function(&mut self) -> Result<Function> {
        let first_of_call = self.expect(L_PAREN, "'('")?;
        let number = self.int()?;
        self.expect(R_PAREN, "')'")?;
        self.expect(R_BRACE, "'}'")?;
        let internal = u16::try_from(number).ok().map(Internal);
        let Some(info) = internal.and_then(Internal::info) else {
            return Err(self.error_at(
                &first_of_call,
                format!("unknown internal function {number}"),
            ));
        };
        // An internal without an implementation may be declared (functions.inc declares
        // them all); using it is the error.
        let count = 3 + info.extra_params;
        let mut params: Vec<String> = vec!["x".into(), "y".into(), "z".into()];
        params.extend((0..info.extra_params).map(|i| format!("P{i}")));
        let mut code: Vec<Op> = (0..count).map(Op::Param).collect();
        code.push(Op::Internal(Internal(info.number), count));
        Ok(Function::code(params, code))
    }

    /// `F(a, b, ...)` at parse time.
    pub fn call_function(&mut self, at: &Token, function: &Function) -> Result<Value> {
        if let Some(missing) = function.unsupported() {
            return Err(self.unsupported(at, missing.trim_start_matches("not supported yet: ")));
        }
        let args = self.float_args()?;
        if args.len() != function.params.len() {
            return Err(self.error_at(
                at,
                format!(
                    "function '{}' takes {} arguments, not {}",
                    self.text(at),
                    function.params.len(),
                    args.len()
                ),
            ));
        }
        Ok(match function.result_len() {
            1 => Value::Float(function.eval(&args)),
            5 => Value::colour(Terms::new(&function.eval_vector(&args))),
            len => Value::Vector(Terms::new(&function.eval_vector(&args)[..usize::from(len)])),
        })
    }

    /// The body of a function made from a pattern, pigment, spline or transform, whose first
    /// token is `first`; `None` for an ordinary float expression.
    fn special_function_body(&mut self, first: &Token) -> Result<Option<Body>> {
        let body = match first.kind {
            PATTERN_KW => match self.pigment_body()? {
                Pigment::Pattern { pattern, .. } => {
                    if let Some(refusal) = refused_in_functions(&pattern.kind) {
                        return Err(self.error_at(first, refusal));
                    }
                    Body::Pattern(pattern)
                }
                Pigment::Solid(_) | Pigment::Image(_) => {
                    return Err(
                        self.error_at(first, "expected a pattern in function { pattern { } }")
                    );
                }
            },
            PIGMENT_KW => Body::Pigment(Box::new(self.pigment_body()?)),
            SPLINE_KW => Body::Spline(Arc::new(self.spline_body()?)),
            TRANSFORM_KW => {
                let t = self.transformation(first)?;
                Body::Transform(t)
            }
            IDENT => match first.slot.as_ref().map(|s| s.borrow().clone()) {
                Some(Value::Spline(spline)) if self.peek_kind()? == R_BRACE => {
                    Body::Spline(Arc::new(Spline::clone(&spline)))
                }
                Some(Value::Transform(t)) if self.peek_kind()? == R_BRACE => Body::Transform(*t),
                Some(Value::Pigment(p)) if self.peek_kind()? == R_BRACE => {
                    Body::Pigment(Box::new(Pigment::clone(&p)))
                }
                _ => {
                    self.unget(first.clone());
                    return Ok(None);
                }
            },
            _ => {
                self.unget(first.clone());
                return Ok(None);
            }
        };
        Ok(Some(body))
    }

    fn fn_or(&mut self, params: &[String], code: &mut Vec<Op>) -> Result<()> {
        self.fn_and(params, code)?;
        while self.eat(PIPE)? {
            self.fn_and(params, code)?;
            emit(code, Op::Or);
        }
        Ok(())
    }

    fn fn_and(&mut self, params: &[String], code: &mut Vec<Op>) -> Result<()> {
        self.fn_relational(params, code)?;
        while self.eat(AMP)? {
            self.fn_relational(params, code)?;
            emit(code, Op::And);
        }
        Ok(())
    }

    fn fn_relational(&mut self, params: &[String], code: &mut Vec<Op>) -> Result<()> {
        self.fn_additive(params, code)?;
        loop {
            let token = self.next()?;
            let op = match token.kind {
                LT => Op::Lt,
                LT_EQ => Op::Le,
                EQ => Op::Eq,
                NEQ => Op::Ne,
                GT_EQ => Op::Ge,
                GT => Op::Gt,
                _ => {
                    self.unget(token);
                    return Ok(());
                }
            };
            self.fn_additive(params, code)?;
            emit(code, op);
        }
    }

    fn fn_additive(&mut self, params: &[String], code: &mut Vec<Op>) -> Result<()> {
        self.fn_multiplicative(params, code)?;
        loop {
            let token = self.next()?;
            let op = match token.kind {
                PLUS => Op::Add,
                MINUS => Op::Sub,
                _ => {
                    self.unget(token);
                    return Ok(());
                }
            };
            self.fn_multiplicative(params, code)?;
            emit(code, op);
        }
    }

    fn fn_multiplicative(&mut self, params: &[String], code: &mut Vec<Op>) -> Result<()> {
        self.fn_unary(params, code)?;
        loop {
            let token = self.next()?;
            let op = match token.kind {
                STAR => Op::Mul,
                SLASH => Op::Div,
                _ => {
                    self.unget(token);
                    return Ok(());
                }
            };
            self.fn_unary(params, code)?;
            emit(code, op);
        }
    }

    fn fn_unary(&mut self, params: &[String], code: &mut Vec<Op>) -> Result<()> {
        let token = self.next()?;
        match token.kind {
            MINUS => {
                self.fn_unary(params, code)?;
                emit(code, Op::Neg);
            }
            PLUS => self.fn_unary(params, code)?,
            BANG => {
                return Err(self.error_at(
                    &token,
                    "'!' is not allowed in a function; compare with 0 instead",
                ));
            }
            _ => {
                self.unget(token);
                self.fn_primary(params, code)?;
            }
        }
        Ok(())
    }

    fn fn_primary(&mut self, params: &[String], code: &mut Vec<Op>) -> Result<()> {
        let token = self.next()?;
        let text = self.text(&token).to_owned();
        if let Some(index) = params.iter().position(|p| *p == text) {
            code.push(Op::Param(index as u8));
            return Ok(());
        }
        if matches!(token.kind, X_KW | Y_KW | Z_KW | U_KW | V_KW) {
            // POV-Ray's x and u name the same first parameter, as do y and v; an axis the
            // parameter list does not name is 0 (measured against POV-Ray 3.7).
            let alias = match token.kind {
                X_KW => "u",
                U_KW => "x",
                Y_KW => "v",
                V_KW => "y",
                _ => "",
            };
            match params.iter().position(|p| p == alias) {
                Some(index) => code.push(Op::Param(index as u8)),
                None => code.push(Op::Const(0.0)),
            }
            return Ok(());
        }
        match token.kind {
            NUMBER => {
                let value = text
                    .parse::<f64>()
                    .map_err(|_| self.error_at(&token, format!("malformed number '{text}'")))?;
                code.push(Op::Const(value));
            }
            L_PAREN => {
                self.fn_or(params, code)?;
                self.expect(R_PAREN, "')'")?;
            }
            IDENT => {
                let Some(slot) = token.slot.clone() else {
                    return Err(self.undeclared(&token));
                };
                let value = slot.borrow().clone();
                match value {
                    Value::Float(v) => code.push(Op::Const(v)),
                    Value::Function(function) => {
                        let argc = self.fn_args(params, code)?;
                        if argc != function.params.len() {
                            return Err(self.error_at(
                                &token,
                                format!(
                                    "function '{text}' takes {} arguments, not {argc}",
                                    function.params.len()
                                ),
                            ));
                        }
                        let part = self.fn_dot_item()?;
                        match part {
                            Some(part) => {
                                code.push(Op::CallPart(Arc::clone(&function), argc as u8, part))
                            }
                            None => code.push(Op::Call(Arc::clone(&function), argc as u8)),
                        }
                    }
                    other => {
                        return Err(self.error_at(
                            &token,
                            format!("a {} cannot be used inside a function", other.type_name()),
                        ));
                    }
                }
            }
            _ => self.fn_builtin(&token, params, code)?,
        }
        Ok(())
    }

    /// `sum(i, from, to, expr)` or `prod(...)`: `expr` for i = from, from + 1, ... up to `to`.
    fn fn_sum(&mut self, token: &Token, params: &[String], code: &mut Vec<Op>) -> Result<()> {
        self.expect(L_PAREN, "'('")?;
        let var = self.next_raw()?;
        if var.kind != IDENT {
            return Err(self.error_at(
                &var,
                format!("expected the loop variable, found {}", self.describe(&var)),
            ));
        }
        let mut inner: Vec<String> = params.to_vec();
        inner.push(self.text(&var).to_owned());
        self.expect(COMMA, "','")?;
        self.fn_or(params, code)?;
        self.expect(COMMA, "','")?;
        self.fn_or(params, code)?;
        self.expect(COMMA, "','")?;
        let mut body = Vec::new();
        self.fn_or(&inner, &mut body)?;
        self.expect(R_PAREN, "')'")?;
        match Function::stack_depth(&body) {
            Some(depth) if depth <= MAX_STACK => {}
            _ => {
                return Err(self.error_at(
                    token,
                    format!("this sum nests deeper than {MAX_STACK} levels"),
                ));
            }
        }
        code.push(Op::Sum {
            body: body.into(),
            product: token.kind == PROD_KW,
        });
        Ok(())
    }

    /// A `.x`, `.red`, ... after a call of a vector-valued function: the component index.
    fn fn_dot_item(&mut self) -> Result<Option<u8>> {
        if !self.eat(DOT)? {
            return Ok(None);
        }
        let item = self.next()?;
        let part = match item.kind {
            X_KW | U_KW | RED_KW => 0,
            Y_KW | V_KW | GREEN_KW => 1,
            Z_KW | BLUE_KW => 2,
            T_KW | FILTER_KW => 3,
            TRANSMIT_KW => 4,
            GRAY_KW => 5,
            _ => {
                return Err(
                    self.error_at(&item, format!("unknown dot item '.{}'", self.text(&item)))
                );
            }
        };
        Ok(Some(part))
    }

    /// The arguments of a call inside a function body, compiled; returns their count.
    fn fn_args(&mut self, params: &[String], code: &mut Vec<Op>) -> Result<usize> {
        self.expect(L_PAREN, "'('")?;
        if self.eat(R_PAREN)? {
            return Ok(0);
        }
        let mut count = 0;
        loop {
            self.fn_or(params, code)?;
            count += 1;
            let token = self.next()?;
            match token.kind {
                COMMA => continue,
                R_PAREN => return Ok(count),
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!("expected ',' or ')', found {}", self.describe(&token)),
                    ));
                }
            }
        }
    }

    fn fn_builtin(&mut self, token: &Token, params: &[String], code: &mut Vec<Op>) -> Result<()> {
        let constant = match token.kind {
            PI_KW => Some(std::f64::consts::PI),
            TAU_KW => Some(std::f64::consts::TAU),
            CLOCK_KW => Some(self.options.clock),
            IMAGE_WIDTH_KW => Some(f64::from(self.options.image_width)),
            IMAGE_HEIGHT_KW => Some(f64::from(self.options.image_height)),
            _ => None,
        };
        if let Some(value) = constant {
            code.push(Op::Const(value));
            return Ok(());
        }
        let unary = match token.kind {
            ABS_KW => Some(Unary::Abs),
            ACOS_KW => Some(Unary::Acos),
            ACOSH_KW => Some(Unary::Acosh),
            ASIN_KW => Some(Unary::Asin),
            ASINH_KW => Some(Unary::Asinh),
            ATAN_KW => Some(Unary::Atan),
            ATANH_KW => Some(Unary::Atanh),
            CEIL_KW => Some(Unary::Ceil),
            COS_KW => Some(Unary::Cos),
            COSH_KW => Some(Unary::Cosh),
            DEGREES_KW => Some(Unary::Degrees),
            EXP_KW => Some(Unary::Exp),
            FLOOR_KW => Some(Unary::Floor),
            INT_KW => Some(Unary::Int),
            LN_KW => Some(Unary::Ln),
            LOG_KW => Some(Unary::Log),
            RADIANS_KW => Some(Unary::Radians),
            SIN_KW => Some(Unary::Sin),
            SINH_KW => Some(Unary::Sinh),
            SQR_KW => Some(Unary::Sqr),
            SQRT_KW => Some(Unary::Sqrt),
            TAN_KW => Some(Unary::Tan),
            TANH_KW => Some(Unary::Tanh),
            _ => None,
        };
        if matches!(token.kind, SUM_KW | PROD_KW) {
            return self.fn_sum(token, params, code);
        }
        let name = self.text(token).to_owned();
        let (op, arity): (Op, std::ops::RangeInclusive<usize>) = match (unary, token.kind) {
            (Some(f), _) => (Op::Unary(f), 1..=1),
            (None, POW_KW) => (Op::Pow, 2..=2),
            (None, ATAN2_KW) => (Op::Atan2, 2..=2),
            (None, MOD_KW) => (Op::Mod, 2..=2),
            (None, DIV_KW) => (Op::Div2, 2..=2),
            (None, SELECT_KW) => (Op::Select3, 3..=4),
            (None, MIN_KW) => (Op::Min(0), 2..=255),
            (None, MAX_KW) => (Op::Max(0), 2..=255),
            _ => {
                return Err(self.error_at(
                    token,
                    format!("expected a number, parameter, function or float function in a function body, found {}", self.describe(token)),
                ));
            }
        };
        let argc = self.fn_args(params, code)?;
        if !arity.contains(&argc) {
            return Err(self.error_at(token, format!("{name}() cannot take {argc} arguments here")));
        }
        let op = match op {
            Op::Select3 if argc == 4 => Op::Select4,
            Op::Min(_) => Op::Min(argc as u8),
            Op::Max(_) => Op::Max(argc as u8),
            other => other,
        };
        emit(code, op);
        Ok(())
    }
}

/// Appends `op`, folding it into a constant when its operands are constants.
fn emit(code: &mut Vec<Op>, op: Op) {
    let n = code.len();
    let folded = matches!(
        (&op, code.as_slice()),
        (Op::Neg | Op::Not | Op::Unary(_), [.., Op::Const(_)])
            | (
                Op::Add
                    | Op::Sub
                    | Op::Mul
                    | Op::Div
                    | Op::Lt
                    | Op::Le
                    | Op::Eq
                    | Op::Ne
                    | Op::Ge
                    | Op::Gt
                    | Op::And
                    | Op::Or
                    | Op::Pow
                    | Op::Atan2
                    | Op::Mod
                    | Op::Div2,
                [.., Op::Const(_), Op::Const(_)],
            )
    );
    code.push(op);
    if folded {
        let arity = if matches!(code[n], Op::Neg | Op::Not | Op::Unary(_)) {
            1
        } else {
            2
        };
        let piece = Function::code(Vec::new(), code[n - arity..].to_vec());
        let value = piece.eval(&[]);
        code.truncate(n - arity);
        code.push(Op::Const(value));
    }
}

/// Why POV-Ray 3.7 refuses a pattern in `function { pattern { } }`, though a pigment
/// function takes it: slope and aoi need a surface; the others are not among the patterns
/// its function parser knows ("No matching } in 'pattern'").
fn refused_in_functions(kind: &PatternKind) -> Option<String> {
    let name = match kind {
        PatternKind::Slope(_) | PatternKind::Aoi => {
            return Some(
                "slope and aoi need a surface: they cannot be used in function { pattern { } }"
                    .into(),
            );
        }
        PatternKind::Average => "average",
        PatternKind::Square => "square",
        PatternKind::Triangular => "triangular",
        PatternKind::Tiling(_) => "tiling",
        PatternKind::Pavement(_) => "pavement",
        _ => return None,
    };
    Some(format!(
        "the {name} pattern cannot be used in function {{ pattern {{ }} }}, as in POV-Ray 3.7"
    ))
}
