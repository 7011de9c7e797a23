//! Expressions: POV-Ray's float, vector, colour and string expressions, with its
//! precedence and its rule that relational, logical and conditional operators only appear
//! inside parentheses (which is what lets `>` close a vector literal).

use super::expr_cache::Level;
use super::tokens::Token;
use super::value::{Terms, Value};
use super::{Evaluator, Result};
use syntax::SyntaxKind::{self, *};

/// Comparison tolerance of `=` and `!=`, as POV-Ray's EPSILON.
pub const EPSILON: f64 = 1.0e-10;

#[derive(Debug, Clone, Copy)]
pub(super) enum BinOp {
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
}

impl BinOp {
    /// POV-Ray's operators, applied to one component. `=` and `!=` allow EPSILON, and so
    /// do `<=` and `>=` (as "less or equal"); `<` and `>` are exact; logic treats anything
    /// within EPSILON of zero as false.
    pub(super) fn apply(self, a: f64, b: f64) -> f64 {
        let equal = (a - b).abs() <= EPSILON;
        let truth = |t: bool| f64::from(u8::from(t));
        match self {
            BinOp::Add => a + b,
            BinOp::Sub => a - b,
            BinOp::Mul => a * b,
            // POV-Ray answers +inf for any division by zero, 0/0 and -1/0 included.
            BinOp::Div if b == 0.0 => f64::INFINITY,
            BinOp::Div => a / b,
            BinOp::Lt => truth(a < b),
            BinOp::Le => truth(a < b || equal),
            BinOp::Eq => truth(equal),
            BinOp::Ne => truth(!equal),
            BinOp::Ge => truth(a > b || equal),
            BinOp::Gt => truth(a > b),
            BinOp::And => truth(is_true(a) && is_true(b)),
            BinOp::Or => truth(is_true(a) || is_true(b)),
        }
    }
}

/// POV-Ray's truth: anything within EPSILON of zero is false.
pub fn is_true(v: f64) -> bool {
    v.abs() > EPSILON
}

impl Evaluator<'_> {
    /// An expression outside parentheses: arithmetic only. Colour keywords may only start
    /// one (`rgb <1, 0, 0> * 0.5`), where they take the whole expression after them.
    pub fn expression(&mut self) -> Result<Value> {
        let first = self.next()?;
        self.unget(first.clone());
        if is_colour_keyword(first.kind) {
            return Ok(Value::colour(self.colour()?));
        }
        let value = self.additive()?;
        Ok(self.colour_guess(&first, value))
    }

    /// A float expression.
    pub fn float(&mut self) -> Result<f64> {
        let first = self.next()?;
        self.unget(first.clone());
        let value = self.additive()?;
        self.to_float(&first, value)
    }

    /// A float expression truncated to an integer, as POV-Ray's "I" parameters are.
    pub fn int(&mut self) -> Result<i64> {
        Ok(self.float()?.trunc() as i64)
    }

    /// A 3-component vector; a float is promoted to all three.
    pub fn vector(&mut self) -> Result<glam::DVec3> {
        Ok(self.vector_of(3)?.vec3())
    }

    /// A vector of exactly `len` components: shorter vectors are padded with zeros, a float
    /// fills every component, longer vectors are an error.
    pub fn vector_of(&mut self, len: u8) -> Result<Terms> {
        let first = self.next()?;
        self.unget(first.clone());
        let value = self.additive()?;
        match value {
            Value::Float(v) => Ok(Terms::splat(v, len)),
            Value::Vector(t) | Value::Colour(t) if t.len <= len || len >= 3 => Ok(Terms {
                len,
                ..t.promoted(len)
            }),
            other => Err(self.error_at(
                &first,
                format!(
                    "expected a vector of {len} components, found {}",
                    other.type_name()
                ),
            )),
        }
    }

    /// A string expression: a literal, a string function call or a string identifier. It
    /// reads no token past its end (there are no string operators), so that a directive
    /// right after `#debug "..."` runs after the message, not before.
    pub fn string(&mut self) -> Result<String> {
        let first = self.next()?;
        let value = match first.kind {
            // The token getter has already resolved `Array[i]`; nothing past the
            // identifier is read, so `#debug S` inside a loop prints before its #end runs.
            IDENT => match &first.slot {
                Some(slot) => slot.borrow().clone(),
                None => return Err(self.undeclared(&first)),
            },
            L_PAREN => {
                self.unget(first.clone());
                self.postfix()?
            }
            _ => {
                self.unget(first.clone());
                self.primary()?
            }
        };
        match value {
            Value::String(s) => Ok(s.to_string()),
            other => Err(self.error_at(
                &first,
                format!("expected a string, found {}", other.type_name()),
            )),
        }
    }

    /// A parenthesised condition, as `#if (...)` and `#while (...)` take.
    pub fn condition(&mut self) -> Result<bool> {
        self.expect(L_PAREN, "'('")?;
        if let Some(v) = self.replayed_float(&[R_PAREN]) {
            self.expect(R_PAREN, "')'")?;
            return Ok(is_true(v));
        }
        let first = self.next()?;
        self.unget(first.clone());
        let value = self.full_expression()?;
        self.expect(R_PAREN, "')'")?;
        Ok(is_true(self.to_float(&first, value)?))
    }

    pub fn to_float(&self, at: &Token, value: Value) -> Result<f64> {
        match value {
            Value::Float(v) => Ok(v),
            other => {
                Err(self.error_at(at, format!("expected a float, found {}", other.type_name())))
            }
        }
    }

    /// POV-Ray decides an expression is a colour from its first token: a colour
    /// identifier or colour keyword makes the whole value a colour.
    fn colour_guess(&self, first: &Token, value: Value) -> Value {
        let starts_colour = first.kind == IDENT
            && first
                .slot
                .as_ref()
                .is_some_and(|slot| matches!(&*slot.borrow(), Value::Colour(_)));
        match value {
            // `C.red` stays a float (POV-Ray 3.7 prints `#declare F = C.red;` with str() and
            // adds it to a vector component by component); a vector made from a colour
            // identifier stays a colour.
            Value::Vector(t) if starts_colour => Value::colour(t),
            other => other,
        }
    }

    /// Whether the token after an operand was given back and is none of `operators`: then
    /// a precedence level's operator loop ends without taking the token out and putting it
    /// back, as each level would otherwise do after every operand.
    fn ends_before(&self, operators: &[SyntaxKind]) -> bool {
        self.given_back_kind()
            .is_some_and(|kind| !operators.contains(&kind))
    }

    /// Inside parentheses: `C ? A : B`, logical and relational operators too.
    pub fn full_expression(&mut self) -> Result<Value> {
        if let Some(value) = self.replayed(Level::Full) {
            return Ok(value);
        }
        let first = self.next()?;
        self.unget(first.clone());
        let condition = self.logical()?;
        if !self.ends_before(&[QUESTION]) && self.eat(QUESTION)? {
            let truth = is_true(self.to_float(&first, condition)?);
            let a = self.full_expression()?;
            self.expect(COLON, "':'")?;
            let b = self.full_expression()?;
            return Ok(if truth { a } else { b });
        }
        Ok(condition)
    }

    fn logical(&mut self) -> Result<Value> {
        let mut left = self.relational()?;
        loop {
            if self.ends_before(&[AMP, PIPE]) {
                return Ok(left);
            }
            let op = self.next()?;
            let bin = match op.kind {
                AMP => BinOp::And,
                PIPE => BinOp::Or,
                _ => {
                    self.unget(op);
                    return Ok(left);
                }
            };
            let right = self.relational()?;
            left = self.binary(&op, bin, left, right)?;
        }
    }

    fn relational(&mut self) -> Result<Value> {
        let mut left = self.additive()?;
        loop {
            if self.ends_before(&[LT, LT_EQ, EQ, NEQ, GT_EQ, GT]) {
                return Ok(left);
            }
            let op = self.next()?;
            let bin = match op.kind {
                LT => BinOp::Lt,
                LT_EQ => BinOp::Le,
                EQ => BinOp::Eq,
                NEQ => BinOp::Ne,
                GT_EQ => BinOp::Ge,
                GT => BinOp::Gt,
                _ => {
                    self.unget(op);
                    return Ok(left);
                }
            };
            let right = self.additive()?;
            left = match (&left, &right) {
                // Strings compare as strcmp() does.
                (Value::String(a), Value::String(b)) => {
                    Value::Float(bin.apply(f64::from(super::builtins::strcmp(a, b)), 0.0))
                }
                _ => self.binary(&op, bin, left, right)?,
            };
        }
    }

    /// `A + B`, `A - B`: the level that vector components and statement arguments use.
    pub fn additive(&mut self) -> Result<Value> {
        if let Some(value) = self.replayed(Level::Additive) {
            return Ok(value);
        }
        let mut left = self.multiplicative()?;
        loop {
            if self.ends_before(&[PLUS, MINUS]) {
                return Ok(left);
            }
            let op = self.next()?;
            let bin = match op.kind {
                PLUS => BinOp::Add,
                MINUS => BinOp::Sub,
                _ => {
                    self.unget(op);
                    return Ok(left);
                }
            };
            let right = self.multiplicative()?;
            left = self.binary(&op, bin, left, right)?;
        }
    }

    fn multiplicative(&mut self) -> Result<Value> {
        let mut left = self.unary()?;
        loop {
            if self.ends_before(&[STAR, SLASH]) {
                return Ok(left);
            }
            let op = self.next()?;
            let bin = match op.kind {
                STAR => BinOp::Mul,
                SLASH => BinOp::Div,
                _ => {
                    self.unget(op);
                    return Ok(left);
                }
            };
            let right = self.unary()?;
            left = self.binary(&op, bin, left, right)?;
        }
    }

    fn unary(&mut self) -> Result<Value> {
        let token = self.next()?;
        match token.kind {
            MINUS => {
                let value = self.unary()?;
                self.negate(&token, value)
            }
            PLUS => self.unary(),
            BANG => {
                let value = self.unary()?;
                logical_not(value).map_err(|message| self.error_at(&token, message))
            }
            _ => {
                self.unget(token);
                self.postfix()
            }
        }
    }

    fn negate(&self, at: &Token, value: Value) -> Result<Value> {
        negated(value).map_err(|message| self.error_at(at, message))
    }

    fn binary(&self, op: &Token, bin: BinOp, left: Value, right: Value) -> Result<Value> {
        combined(bin, left, right).map_err(|message| self.error_at(op, message))
    }
    /// A primary followed by dot items (`.x`, `.red`, `.hf`) and subscripts.
    fn postfix(&mut self) -> Result<Value> {
        let first = self.next()?;
        self.unget(first.clone());
        let mut value = self.primary()?;
        loop {
            if self.ends_before(&[DOT, L_BRACK]) {
                return Ok(value);
            }
            let token = self.next()?;
            match token.kind {
                DOT => {
                    let item = self.next()?;
                    value = self.dot_item(&item, value)?;
                }
                L_BRACK if matches!(value, Value::Array(_) | Value::Dictionary(_)) => {
                    value = self.subscript(&token, value)?;
                }
                _ => {
                    self.unget(token);
                    return Ok(value);
                }
            }
        }
    }

    pub fn dot_item(&mut self, item: &Token, value: Value) -> Result<Value> {
        if let Value::Dictionary(dict) = &value {
            let key = self.text(item).to_owned();
            return dict.get(&key).cloned().ok_or_else(|| {
                self.error_at(item, format!("the dictionary has no key \"{key}\""))
            });
        }
        let Some(terms) = value.terms() else {
            return Err(self.error_at(
                item,
                format!("a {} has no '.{}'", value.type_name(), self.text(item)),
            ));
        };
        if item.kind == IDENT && self.text(item) == "hf" {
            let [r, g, ..] = terms.promoted(3).c;
            return Ok(Value::Float(r + g / 256.0));
        }
        match component(&value, terms, item.kind) {
            Some(Ok(v)) => Ok(Value::Float(v)),
            Some(Err(needed)) => Err(self.error_at(
                item,
                format!(
                    "'.{}' needs a vector of at least {needed} components",
                    self.text(item)
                ),
            )),
            None => Err(self.error_at(item, format!("unknown dot item '.{}'", self.text(item)))),
        }
    }

    /// `Array[i]...` or `Dict["key"]`, after the `[`.
    pub fn subscript(&mut self, open: &Token, value: Value) -> Result<Value> {
        match value {
            Value::Dictionary(dict) => {
                let key = self.string()?;
                self.expect(R_BRACK, "']'")?;
                dict.get(&key).cloned().ok_or_else(|| {
                    self.error_at(open, format!("the dictionary has no key \"{key}\""))
                })
            }
            Value::Array(array) => {
                let mut indices = vec![self.array_index(open)?];
                self.expect(R_BRACK, "']'")?;
                while indices.len() < array.dims.len() {
                    let open = self.expect(L_BRACK, "'[' for the next array dimension")?;
                    indices.push(self.array_index(&open)?);
                    self.expect(R_BRACK, "']'")?;
                }
                let flat = self.flat_index(open, &array.dims, &indices)?;
                array.items[flat].clone().ok_or_else(|| {
                    self.error_at(
                        open,
                        format!("array element {indices:?} is used before it was set"),
                    )
                })
            }
            other => Err(self.error_at(
                open,
                format!("a {} cannot be subscripted", other.type_name()),
            )),
        }
    }

    pub fn array_index(&mut self, at: &Token) -> Result<i64> {
        let v = self.float()?;
        if !v.is_finite() {
            return Err(self.error_at(at, "array index is not a finite number"));
        }
        Ok(v.trunc() as i64)
    }

    /// The position of an element in an array's flat storage, with POV-Ray's bounds check.
    pub fn flat_index(&self, at: &Token, dims: &[usize], indices: &[i64]) -> Result<usize> {
        let mut flat = 0usize;
        for (&index, &size) in indices.iter().zip(dims) {
            if index < 0 || index as usize >= size {
                return Err(self.error_at(
                    at,
                    format!("array index {index} out of range: this dimension has {size} elements (0 to {})", size as i64 - 1),
                ));
            }
            flat = flat * size + index as usize;
        }
        Ok(flat)
    }

    /// Literals, parentheses, vectors, identifiers, built-in constants and functions.
    fn primary(&mut self) -> Result<Value> {
        let token = self.next()?;
        match token.kind {
            NUMBER => {
                let text = self.text(&token);
                text.parse::<f64>()
                    .map(Value::Float)
                    .map_err(|_| self.error_at(&token, format!("malformed number '{text}'")))
            }
            STRING => {
                let (value, problems) = syntax::lexer::unescape_string(self.text(&token));
                if let Some((range, message)) = problems.into_iter().next() {
                    let shifted = range + syntax::TextSize::new(token.start);
                    self.warnings.push(syntax::Diagnostic::warning(
                        self.files[token.file as usize].name.clone(),
                        shifted,
                        message,
                    ));
                }
                Ok(Value::String(value.into()))
            }
            L_PAREN => {
                let value = self.full_expression()?;
                self.expect(R_PAREN, "')'")?;
                Ok(value)
            }
            LT => self.vector_literal(&token),
            IDENT => self.identifier_value(token),
            _ => {
                if let Some(value) = self.builtin(&token)? {
                    return Ok(value);
                }
                Err(self.error_at(
                    &token,
                    format!("expected an expression, found {}", self.describe(&token)),
                ))
            }
        }
    }

    fn vector_literal(&mut self, open: &Token) -> Result<Value> {
        let mut components = Vec::with_capacity(5);
        loop {
            let at = self.next()?;
            if at.kind == GT && !components.is_empty() {
                break;
            }
            self.unget(at.clone());
            let value = self.additive()?;
            components.push(self.to_float(&at, value)?);
            // Commas are optional (`<1 0 -1>` is three components to POV-Ray, and `<1,2,>`
            // two); a component runs as far as an expression can.
            self.eat(COMMA)?;
            if components.len() > 5 {
                break;
            }
        }
        if !(2..=5).contains(&components.len()) {
            return Err(self.error_at(
                open,
                format!("a vector has 2 to 5 components, not {}", components.len()),
            ));
        }
        Ok(Value::Vector(Terms::new(&components)))
    }

    /// The value of an identifier, calling functions and splines that follow with `(`.
    fn identifier_value(&mut self, token: Token) -> Result<Value> {
        let Some(slot) = token.slot.clone() else {
            return Err(self.undeclared(&token));
        };
        let value = slot.borrow().clone();
        match value {
            Value::Uninitialized => Err(self.error_at(
                &token,
                format!(
                    "'{}' has no value yet: a #local is created before its value is read",
                    self.text(&token)
                ),
            )),
            Value::Function(function) if self.peek_kind()? == L_PAREN => {
                self.call_function(&token, &function)
            }
            Value::Spline(spline) if self.peek_kind()? == L_PAREN => {
                self.call_spline(&token, &spline)
            }
            other => Ok(other),
        }
    }

    /// "undeclared identifier 'Foo'", with the closest declared name or keyword.
    pub fn undeclared(&self, token: &Token) -> Box<syntax::Diagnostic> {
        let name = self.text(token);
        let mut error = self.error_at(token, format!("undeclared identifier '{name}'"));
        if let Some(suggestion) = self.suggest(name) {
            error.notes.push(format!("did you mean '{suggestion}'?"));
        }
        error
    }

    /// The parenthesised, comma-separated arguments of a call, as floats.
    pub fn float_args(&mut self) -> Result<Vec<f64>> {
        self.expect(L_PAREN, "'('")?;
        let mut args = Vec::new();
        if self.eat(R_PAREN)? {
            return Ok(args);
        }
        loop {
            args.push(self.float_in_parens()?);
            let token = self.next()?;
            match token.kind {
                COMMA => continue,
                R_PAREN => return Ok(args),
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected ',' or ')' in argument list, found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
    }

    /// A float argument inside a call's parentheses, where the full grammar applies.
    pub fn float_in_parens(&mut self) -> Result<f64> {
        if let Some(v) = self.replayed_float(&[COMMA, R_PAREN]) {
            return Ok(v);
        }
        let first = self.next()?;
        self.unget(first.clone());
        let value = self.full_expression()?;
        self.to_float(&first, value)
    }

    /// A float inside parentheses (the full grammar) followed by one of `closing`, when an
    /// earlier run of its place compiled it: replayed, up to that token.
    fn replayed_float(&mut self, closing: &[SyntaxKind]) -> Option<f64> {
        self.replayed_before(Level::Full, closing, 0, |value| match value {
            Value::Float(v) => Some(v),
            _ => None,
        })
    }

    /// Any value inside a call's parentheses.
    pub fn value_in_parens(&mut self) -> Result<Value> {
        self.full_expression()
    }

    /// A vector argument inside parentheses, promoted to 3 components.
    pub fn vector_in_parens(&mut self) -> Result<glam::DVec3> {
        let replayed =
            self.replayed_before(Level::Full, &[COMMA, R_PAREN], 0, |value| match value {
                Value::Float(v) => Some(glam::DVec3::splat(v)),
                Value::Vector(t) | Value::Colour(t) => Some(t.promoted(3).vec3()),
                _ => None,
            });
        if let Some(v) = replayed {
            return Ok(v);
        }
        let first = self.next()?;
        self.unget(first.clone());
        match self.full_expression()? {
            Value::Float(v) => Ok(glam::DVec3::splat(v)),
            Value::Vector(t) | Value::Colour(t) => Ok(t.promoted(3).vec3()),
            other => Err(self.error_at(
                &first,
                format!("expected a vector, found {}", other.type_name()),
            )),
        }
    }

    pub fn string_in_parens(&mut self) -> Result<String> {
        let first = self.next()?;
        self.unget(first.clone());
        match self.full_expression()? {
            Value::String(s) => Ok(s.to_string()),
            other => Err(self.error_at(
                &first,
                format!("expected a string, found {}", other.type_name()),
            )),
        }
    }
}

/// The keywords that start a colour: `color`, `rgb` and its kin, and the component names.
pub fn is_colour_keyword(kind: syntax::SyntaxKind) -> bool {
    matches!(
        kind,
        COLOR_KW
            | COLOUR_KW
            | RGB_KW
            | RGBF_KW
            | RGBT_KW
            | RGBFT_KW
            | SRGB_KW
            | SRGBF_KW
            | SRGBT_KW
            | SRGBFT_KW
            | RED_KW
            | GREEN_KW
            | BLUE_KW
            | FILTER_KW
            | TRANSMIT_KW
    )
}

/// `left bin right` with POV-Ray's promotion: a float spreads over every component, a
/// shorter vector gains zero components, and a colour operand makes the result a colour.
/// The error is the message for the operator's place.
pub(super) fn combined(
    bin: BinOp,
    left: Value,
    right: Value,
) -> std::result::Result<Value, String> {
    // Two floats, the commonest case, give what the general rule below gives for them.
    if let (Value::Float(a), Value::Float(b)) = (&left, &right) {
        return Ok(Value::Float(bin.apply(*a, *b)));
    }
    if let (BinOp::Add, Value::String(_), Value::String(_)) = (bin, &left, &right) {
        return Err("strings are joined with concat(), not '+'".into());
    }
    let (Some(a), Some(b)) = (left.terms(), right.terms()) else {
        let culprit = if left.is_numeric() { &right } else { &left };
        return Err(format!(
            "expected a float, vector or color operand, found {}",
            culprit.type_name()
        ));
    };
    let colour = matches!(left, Value::Colour(_)) || matches!(right, Value::Colour(_));
    let len = a.len.max(b.len).max(if colour { 5 } else { 1 });
    let a = if a.len == 1 {
        Terms::splat(a.c[0], len)
    } else {
        a.promoted(len)
    };
    let b = if b.len == 1 {
        Terms::splat(b.c[0], len)
    } else {
        b.promoted(len)
    };
    let mut out = Terms { len, c: [0.0; 5] };
    for i in 0..len as usize {
        out.c[i] = bin.apply(a.c[i], b.c[i]);
    }
    Ok(match (colour, len) {
        (true, _) => Value::colour(out),
        (false, 1) => Value::Float(out.c[0]),
        (false, _) => Value::Vector(out),
    })
}

/// `-value`; the error is the message for the operator's place.
pub(super) fn negated(value: Value) -> std::result::Result<Value, String> {
    match value {
        Value::Float(v) => Ok(Value::Float(-v)),
        Value::Vector(mut t) => {
            t.c.iter_mut().for_each(|c| *c = -*c);
            Ok(Value::Vector(t))
        }
        Value::Colour(mut t) => {
            t.c.iter_mut().for_each(|c| *c = -*c);
            Ok(Value::Colour(t))
        }
        other => Err(format!("cannot negate a {}", other.type_name())),
    }
}

/// `!value`, component by component; the error is the message for the operator's place.
pub(super) fn logical_not(value: Value) -> std::result::Result<Value, String> {
    let not = |v: f64| f64::from(u8::from(!is_true(v)));
    match value {
        Value::Float(v) => Ok(Value::Float(not(v))),
        Value::Vector(mut t) => {
            t.c.iter_mut().for_each(|c| *c = not(*c));
            Ok(Value::Vector(t))
        }
        other => Err(format!("cannot apply '!' to a {}", other.type_name())),
    }
}

/// The dot item `.item` (`.x`, `.red`, `.gray`, ...) of a float, vector or colour whose
/// terms are `terms`: `None` for a word that is no such item, `Some(Err(n))` when the
/// value has fewer than the `n` components the item needs. A float answers every item
/// with itself.
pub(super) fn component(
    value: &Value,
    terms: Terms,
    item: SyntaxKind,
) -> Option<std::result::Result<f64, usize>> {
    let index = match item {
        X_KW | U_KW | RED_KW => 0,
        Y_KW | V_KW | GREEN_KW => 1,
        Z_KW | BLUE_KW => 2,
        T_KW => 3,
        FILTER_KW => 3,
        TRANSMIT_KW => 4,
        GRAY_KW => {
            let [r, g, b, ..] = terms.promoted(3).c;
            return Some(Ok(r * 0.297 + g * 0.589 + b * 0.114));
        }
        _ => return None,
    };
    if matches!(value, Value::Float(_)) {
        return Some(Ok(terms.c[0]));
    }
    if index >= terms.len as usize {
        return Some(Err(index + 1));
    }
    Some(Ok(terms.c[index]))
}
