//! Built-in constants and functions usable in expressions: the float, vector and string
//! functions of POV-Ray's reference, and the colour keywords.

use super::tokens::Token;
use super::value::{Terms, Value};
use super::{Evaluator, Result};
use glam::DVec3;
use syntax::SyntaxKind::{self, *};

impl Evaluator<'_> {
    /// The value of a built-in constant or function call starting at `token`, or `None`
    /// when `token` does not start one.
    pub fn builtin(&mut self, token: &Token) -> Result<Option<Value>> {
        if let Some(value) = self.builtin_constant(token.kind) {
            return Ok(Some(value));
        }
        match token.kind {
            kind if super::expr::is_colour_keyword(kind) => Err(self.error_at(
                token,
                format!(
                    "expected a numeric expression, found the color keyword '{}'; color keywords may only start an expression",
                    self.text(token)
                ),
            )),
            _ => self.builtin_function(token),
        }
    }

    /// The value of a built-in constant (`pi`, `x`, `clock`, `version`, ...).
    pub(super) fn builtin_constant(&self, kind: SyntaxKind) -> Option<Value> {
        let vector = |v: DVec3| Value::Vector(Terms::new(&[v.x, v.y, v.z]));
        let float = |v: f64| Some(Value::Float(v));
        match kind {
            PI_KW => float(std::f64::consts::PI),
            TAU_KW => float(std::f64::consts::TAU),
            TRUE_KW | YES_KW | ON_KW => float(1.0),
            FALSE_KW | NO_KW | OFF_KW => float(0.0),
            X_KW => Some(vector(DVec3::X)),
            Y_KW => Some(vector(DVec3::Y)),
            Z_KW => Some(vector(DVec3::Z)),
            T_KW => Some(Value::Vector(Terms::new(&[0.0, 0.0, 0.0, 1.0]))),
            U_KW => Some(Value::Vector(Terms::new(&[1.0, 0.0]))),
            V_KW => Some(Value::Vector(Terms::new(&[0.0, 1.0]))),
            CLOCK_KW => float(self.options.clock),
            CLOCK_DELTA_KW => float(0.0),
            CLOCK_ON_KW => float(f64::from(u8::from(self.options.clock_on))),
            INITIAL_CLOCK_KW => float(self.options.initial_clock),
            FINAL_CLOCK_KW => float(self.options.final_clock),
            INITIAL_FRAME_KW => float(f64::from(self.options.initial_frame)),
            FINAL_FRAME_KW => float(f64::from(self.options.final_frame)),
            FRAME_NUMBER_KW => float(f64::from(self.options.frame_number)),
            IMAGE_WIDTH_KW => float(f64::from(self.options.image_width)),
            IMAGE_HEIGHT_KW => float(f64::from(self.options.image_height)),
            VERSION_KW => float(self.version),
            _ => None,
        }
    }

    fn builtin_function(&mut self, token: &Token) -> Result<Option<Value>> {
        let float = |v: f64| Ok(Some(Value::Float(v)));
        let kind = token.kind;
        if let Some(f) = float_function(kind) {
            let args = self.float_args_exactly(token, 1)?;
            let v = args[0];
            if let Some(name) = refused_argument(kind, v) {
                return Err(self.error_at(token, format!("{name} of negative number {v:.6}")));
            }
            return float(f(v));
        }
        match kind {
            ATAN2_KW | POW_KW | MOD_KW | DIV_KW => {
                let a = self.float_args_exactly(token, 2)?;
                match float_function2(kind, a[0], a[1]) {
                    Ok(v) => float(v),
                    Err(message) => Err(self.error_at(token, message)),
                }
            }
            MIN_KW | MAX_KW => {
                let a = self.float_args()?;
                if a.is_empty() {
                    return Err(self.error_at(
                        token,
                        format!("{}() takes at least 1 argument", self.text(token)),
                    ));
                }
                float(extreme(kind, &a))
            }
            SELECT_KW => {
                let a = self.float_args()?;
                match a.as_slice() {
                    [c, neg, rest] => float(if *c < 0.0 { *neg } else { *rest }),
                    [c, neg, zero, pos] => float(if *c < 0.0 {
                        *neg
                    } else if *c == 0.0 {
                        *zero
                    } else {
                        *pos
                    }),
                    _ => Err(self.error_at(token, "select() takes 3 or 4 arguments")),
                }
            }
            BITWISE_AND_KW | BITWISE_OR_KW | BITWISE_XOR_KW => {
                let a = self.float_args()?;
                if a.len() < 2 {
                    return Err(self.error_at(
                        token,
                        format!("{}() takes at least 2 arguments", self.text(token)),
                    ));
                }
                let ints = a.iter().map(|v| v.trunc() as i64 as i32);
                let result = match kind {
                    BITWISE_AND_KW => ints.reduce(|x, y| x & y),
                    BITWISE_OR_KW => ints.reduce(|x, y| x | y),
                    _ => ints.reduce(|x, y| x ^ y),
                };
                float(f64::from(result.unwrap_or(0)))
            }
            SEED_KW => {
                let a = self.float_args_exactly(token, 1)?;
                float(self.rng.seed(c_int(a[0])) as f64)
            }
            RAND_KW => {
                let a = self.float_args_exactly(token, 1)?;
                match self.rng.rand(a[0]) {
                    Some(v) => float(v),
                    None => {
                        Err(self.error_at(token, "rand() of a stream that seed() did not create"))
                    }
                }
            }
            VDOT_KW => {
                let (a, b) = self.two_vectors()?;
                float(a.dot(b))
            }
            VLENGTH_KW => {
                self.expect(L_PAREN, "'('")?;
                let first = self.next()?;
                self.unget(first.clone());
                let value = self.value_in_parens()?;
                self.expect(R_PAREN, "')'")?;
                match value.terms() {
                    Some(t) => float(t.as_slice().iter().map(|c| c * c).sum::<f64>().sqrt()),
                    None => Err(self.error_at(
                        &first,
                        format!("expected a vector, found {}", value.type_name()),
                    )),
                }
            }
            VCROSS_KW => {
                let (a, b) = self.two_vectors()?;
                Ok(Some(vec3(a.cross(b))))
            }
            VNORMALIZE_KW => {
                self.expect(L_PAREN, "'('")?;
                let v = self.vector_in_parens()?;
                self.expect(R_PAREN, "')'")?;
                let length = v.length();
                if length == 0.0 {
                    self.warn_at(token, "vnormalize() of a zero-length vector");
                    return Ok(Some(vec3(DVec3::ZERO)));
                }
                Ok(Some(vec3(v / length)))
            }
            VROTATE_KW => {
                let (v, r) = self.two_vectors()?;
                let t = crate::scene::Transform::rotate_degrees(r);
                Ok(Some(vec3(t.vector(v))))
            }
            VAXIS_ROTATE_KW => {
                self.expect(L_PAREN, "'('")?;
                let v = self.vector_in_parens()?;
                self.expect(COMMA, "','")?;
                let axis = self.vector_in_parens()?;
                self.expect(COMMA, "','")?;
                let degrees = self.float_in_parens()?;
                self.expect(R_PAREN, "')'")?;
                if axis.length() == 0.0 {
                    return Err(self.error_at(token, "vaxis_rotate() about a zero-length axis"));
                }
                let rotation = glam::DQuat::from_axis_angle(axis.normalize(), degrees.to_radians());
                Ok(Some(vec3(rotation * v)))
            }
            ASC_KW => {
                let s = self.string_args_exactly(token, 1)?;
                float(s[0].chars().next().map_or(0.0, |c| f64::from(u32::from(c))))
            }
            STRLEN_KW => {
                let s = self.string_args_exactly(token, 1)?;
                float(s[0].chars().count() as f64)
            }
            STRCMP_KW => {
                let s = self.string_args_exactly(token, 2)?;
                float(f64::from(strcmp(&s[0], &s[1])))
            }
            VAL_KW => {
                let s = self.string_args_exactly(token, 1)?;
                float(parse_leading_float(&s[0]))
            }
            FILE_EXISTS_KW => {
                let s = self.string_args_exactly(token, 1)?;
                float(f64::from(u8::from(
                    self.source.read(&s[0]).is_some() || crate::stdinc::get(&s[0]).is_some(),
                )))
            }
            DEFINED_KW => {
                self.expect(L_PAREN, "'('")?;
                let name = self.next_raw()?;
                let defined = self.defined_item(&name)?;
                self.expect(R_PAREN, "')'")?;
                float(f64::from(u8::from(defined)))
            }
            DIMENSIONS_KW | DIMENSION_SIZE_KW => self.array_dimensions(token),
            CONCAT_KW => {
                let parts = self.string_args()?;
                self.checked_string(parts.concat())
            }
            CHR_KW => {
                let a = self.float_args_exactly(token, 1)?;
                let code = a[0].trunc() as i64;
                let c = u32::try_from(code)
                    .ok()
                    .and_then(char::from_u32)
                    .ok_or_else(|| {
                        self.error_at(token, format!("chr({code}) is not a character"))
                    })?;
                self.checked_string(c.to_string())
            }
            STR_KW => {
                self.expect(L_PAREN, "'('")?;
                let v = self.float_in_parens()?;
                self.expect(COMMA, "','")?;
                let width = self.float_in_parens()?.trunc() as i64;
                self.expect(COMMA, "','")?;
                let precision = self.float_in_parens()?.trunc() as i64;
                self.expect(R_PAREN, "')'")?;
                self.checked_string(format_float(v, width, precision))
            }
            VSTR_KW => {
                self.expect(L_PAREN, "'('")?;
                let n = (self.float_in_parens()?.trunc() as i64).clamp(2, 5) as usize;
                self.expect(COMMA, "','")?;
                let at = self.next()?;
                self.unget(at.clone());
                let value = self.value_in_parens()?;
                self.expect(COMMA, "','")?;
                let separator = self.string_in_parens()?;
                self.expect(COMMA, "','")?;
                let width = self.float_in_parens()?.trunc() as i64;
                self.expect(COMMA, "','")?;
                let precision = self.float_in_parens()?.trunc() as i64;
                self.expect(R_PAREN, "')'")?;
                // A float counts as <v, 0, ...>; extra components are dropped and missing
                // ones are zero (measured against POV-Ray 3.7).
                let terms = match value.terms() {
                    Some(t) => Terms {
                        len: n as u8,
                        ..t.promoted(5)
                    },
                    None => {
                        return Err(self.error_at(
                            &at,
                            format!("expected a vector, found {}", value.type_name()),
                        ));
                    }
                };
                let parts: Vec<String> = terms.c[..n]
                    .iter()
                    .map(|&c| format_float(c, width, precision))
                    .collect();
                self.checked_string(parts.join(&separator))
            }
            SUBSTR_KW => {
                self.expect(L_PAREN, "'('")?;
                let s = self.string_in_parens()?;
                self.expect(COMMA, "','")?;
                let start = self.float_in_parens()?.trunc() as i64;
                self.expect(COMMA, "','")?;
                let len = self.float_in_parens()?.trunc() as i64;
                self.expect(R_PAREN, "')'")?;
                let chars: Vec<char> = s.chars().collect();
                if start + len - 1 > chars.len() as i64 {
                    return Err(self.error_at(
                        token,
                        format!(
                            "substr() of {len} characters from {start} runs past a string of {}",
                            chars.len()
                        ),
                    ));
                }
                // Measured against POV-Ray 3.7: a start before 1 or a length below 1 gives "".
                let piece: String = if start < 1 || len < 1 {
                    String::new()
                } else {
                    chars[(start - 1) as usize..(start - 1 + len) as usize]
                        .iter()
                        .collect()
                };
                Ok(Some(Value::String(piece.into())))
            }
            STRUPR_KW | STRLWR_KW => {
                let s = self.string_args_exactly(token, 1)?;
                let out = if kind == STRUPR_KW {
                    s[0].to_ascii_uppercase()
                } else {
                    s[0].to_ascii_lowercase()
                };
                Ok(Some(Value::String(out.into())))
            }
            TRACE_KW => self.trace_call(token),
            INSIDE_KW => {
                self.expect(L_PAREN, "'('")?;
                let object = self.shared_object_or_identifier()?;
                self.expect(COMMA, "','")?;
                let point = self.vector_in_parens()?;
                self.expect(R_PAREN, "')'")?;
                let inside = self
                    .inside_test_of(&object)
                    .map_err(|m| self.error_at(token, m))?
                    .contains(point);
                float(f64::from(u8::from(inside)))
            }
            MIN_EXTENT_KW | MAX_EXTENT_KW => {
                self.expect(L_PAREN, "'('")?;
                let object = self.object_or_identifier()?;
                self.expect(R_PAREN, "')'")?;
                let (min, max) = self
                    .geometry
                    .extent(&object)
                    .map_err(|m| self.error_at(token, m))?;
                Ok(Some(vec3(if kind == MIN_EXTENT_KW { min } else { max })))
            }
            VTURBULENCE_KW => {
                self.expect(L_PAREN, "'('")?;
                let lambda = self.float_in_parens()?;
                self.expect(COMMA, "','")?;
                let omega = self.float_in_parens()?;
                self.expect(COMMA, "','")?;
                let octaves = self.float_in_parens()?.trunc().clamp(1.0, 10.0) as u32;
                self.expect(COMMA, "','")?;
                let point = self.vector_in_parens()?;
                self.expect(R_PAREN, "')'")?;
                Ok(Some(vec3(crate::noise::turbulence(
                    point, octaves, omega, lambda,
                ))))
            }
            NOW_KW => float(super::datetime::now()),
            DATETIME_KW => {
                self.expect(L_PAREN, "'('")?;
                let days = self.float_in_parens()?;
                let format = if self.eat(COMMA)? {
                    self.string_in_parens()?
                } else {
                    "%Y-%m-%d %H:%M:%SZ".to_owned()
                };
                self.expect(R_PAREN, "')'")?;
                self.checked_string(super::datetime::format(days, &format))
            }
            INPUT_FILE_NAME_KW => Ok(Some(Value::String(self.files[0].name.as_str().into()))),
            _ => Ok(None),
        }
    }

    /// `trace(Object, Start, Direction [, NormalIdent])`, after `trace`.
    fn trace_call(&mut self, token: &Token) -> Result<Option<Value>> {
        self.expect(L_PAREN, "'('")?;
        let object = self.shared_object_or_identifier()?;
        self.expect(COMMA, "','")?;
        let origin = self.vector_in_parens()?;
        self.expect(COMMA, "','")?;
        let direction = self.vector_in_parens()?;
        let normal_slot = if self.eat(COMMA)? {
            let name = self.next_raw()?;
            let text = self.text(&name).to_owned();
            if self.lookup(&text).is_none() {
                self.declare(&text, Value::Vector(Terms::new(&[0.0, 0.0, 0.0])));
            }
            self.lookup(&text)
        } else {
            None
        };
        self.expect(R_PAREN, "')'")?;
        let hit = self
            .tracer_of(&object)
            .and_then(|tracer| tracer.trace(origin, direction))
            .map_err(|m| self.error_at(token, m))?;
        let (point, normal) = hit.unwrap_or((DVec3::ZERO, DVec3::ZERO));
        if let Some(slot) = normal_slot {
            *slot.borrow_mut() = vec3(normal);
        }
        Ok(Some(vec3(point)))
    }

    fn checked_string(&self, s: String) -> Result<Option<Value>> {
        if s.len() > self.options.budgets.string_bytes {
            return Err(self.budget_error(
                format!(
                    "string of {} bytes exceeds the budget of {} bytes",
                    s.len(),
                    self.options.budgets.string_bytes
                ),
                "max-string-bytes",
            ));
        }
        Ok(Some(Value::String(s.into())))
    }

    fn float_args_exactly(&mut self, token: &Token, n: usize) -> Result<Vec<f64>> {
        let args = self.float_args()?;
        if args.len() != n {
            let plural = if n == 1 { "" } else { "s" };
            return Err(self.error_at(
                token,
                format!(
                    "{}() takes {n} argument{plural}, not {}",
                    self.text(token),
                    args.len()
                ),
            ));
        }
        Ok(args)
    }

    fn string_args(&mut self) -> Result<Vec<String>> {
        self.expect(L_PAREN, "'('")?;
        let mut args = Vec::new();
        loop {
            args.push(self.string_in_parens()?);
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

    fn string_args_exactly(&mut self, token: &Token, n: usize) -> Result<Vec<String>> {
        let args = self.string_args()?;
        if args.len() != n {
            let plural = if n == 1 { "" } else { "s" };
            return Err(self.error_at(
                token,
                format!(
                    "{}() takes {n} argument{plural}, not {}",
                    self.text(token),
                    args.len()
                ),
            ));
        }
        Ok(args)
    }

    fn two_vectors(&mut self) -> Result<(DVec3, DVec3)> {
        self.expect(L_PAREN, "'('")?;
        let a = self.vector_in_parens()?;
        self.expect(COMMA, "','")?;
        let b = self.vector_in_parens()?;
        self.expect(R_PAREN, "')'")?;
        Ok((a, b))
    }

    fn array_dimensions(&mut self, token: &Token) -> Result<Option<Value>> {
        self.expect(L_PAREN, "'('")?;
        let at = self.next()?;
        self.unget(at.clone());
        let value = self.value_in_parens()?;
        let Value::Array(array) = value else {
            return Err(self.error_at(
                &at,
                format!("expected an array, found {}", value.type_name()),
            ));
        };
        let result = if token.kind == DIMENSIONS_KW {
            array.dims.len() as f64
        } else {
            self.expect(COMMA, "','")?;
            let dim = self.float_in_parens()?.trunc() as i64;
            // POV-Ray answers 0 for a dimension the array does not have.
            if dim < 1 || dim as usize > array.dims.len() {
                0.0
            } else {
                array.dims[dim as usize - 1] as f64
            }
        };
        self.expect(R_PAREN, "')'")?;
        Ok(Some(Value::Float(result)))
    }

    /// Whether `defined(...)`/`#ifdef (...)` names something: an identifier, an array
    /// element or a dictionary key.
    pub fn defined_item(&mut self, name: &Token) -> Result<bool> {
        if name.kind != IDENT {
            // Built-in constants such as pi are not identifiers.
            return Ok(false);
        }
        let text = self.text(name).to_owned();
        let Some(slot) = self.lookup(&text) else {
            return Ok(false);
        };
        let value = slot.borrow().clone();
        match value {
            Value::Array(array) if self.peek_kind()? == L_BRACK => {
                let mut indices = Vec::new();
                while self.eat(L_BRACK)? {
                    let open = name.clone();
                    indices.push(self.array_index(&open)?);
                    self.expect(R_BRACK, "']'")?;
                }
                let flat = self.flat_index(name, &array.dims, &indices)?;
                Ok(array.items[flat].is_some())
            }
            Value::Dictionary(dict) if matches!(self.peek_kind()?, L_BRACK | DOT) => {
                let key = if self.eat(DOT)? {
                    let key = self.next_raw()?;
                    self.text(&key).to_owned()
                } else {
                    self.expect(L_BRACK, "'['")?;
                    let key = self.string()?;
                    self.expect(R_BRACK, "']'")?;
                    key
                };
                Ok(dict.contains_key(&key))
            }
            _ => Ok(true),
        }
    }
}

/// C's `strcmp`: the difference of the first differing bytes, a terminating NUL counting
/// as zero.
pub fn strcmp(a: &str, b: &str) -> i32 {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    for i in 0..a.len().max(b.len()) {
        let (x, y) = (
            a.get(i).copied().unwrap_or(0),
            b.get(i).copied().unwrap_or(0),
        );
        if x != y {
            return i32::from(x) - i32::from(y);
        }
    }
    0
}

/// C's `(double)(int)v` on x86: truncation, and INT_MIN for anything out of range or NaN.
fn c_int(v: f64) -> f64 {
    if v.is_nan() || v >= 2_147_483_648.0 || v <= -2_147_483_649.0 {
        return f64::from(i32::MIN);
    }
    f64::from(v.trunc() as i32)
}

fn vec3(v: DVec3) -> Value {
    Value::Vector(Terms::new(&[v.x, v.y, v.z]))
}

/// C's `strtod` on the start of a string, as POV-Ray's `val()`: "12abc" is 12, "abc" is 0.
fn parse_leading_float(s: &str) -> f64 {
    let s = s.trim_start();
    let mut end = 0;
    let bytes = s.as_bytes();
    let mut seen_digit = false;
    let mut seen_dot = false;
    let mut seen_exp = false;
    while end < bytes.len() {
        let b = bytes[end];
        let ok = match b {
            b'0'..=b'9' => {
                seen_digit = true;
                true
            }
            b'+' | b'-' => end == 0 || matches!(bytes[end - 1], b'e' | b'E'),
            b'.' if !seen_dot && !seen_exp => {
                seen_dot = true;
                true
            }
            b'e' | b'E' if seen_digit && !seen_exp => {
                seen_exp = true;
                true
            }
            _ => false,
        };
        if !ok {
            break;
        }
        end += 1;
    }
    let mut candidate = &s[..end];
    while !candidate.is_empty() {
        if let Ok(v) = candidate.parse::<f64>() {
            return v;
        }
        candidate = &candidate[..candidate.len() - 1];
    }
    0.0
}

/// `str(A, L, P)`: C's `%*.*f` with POV-Ray's twists: a negative width pads with zeros, a
/// negative precision means C's default of six digits.
pub fn format_float(v: f64, width: i64, precision: i64) -> String {
    let precision = if precision < 0 {
        6
    } else {
        precision.min(64) as usize
    };
    let width_abs = width.unsigned_abs().min(256) as usize;
    let text = if width < 0 {
        format!("{v:0width_abs$.precision$}")
    } else {
        format!("{v:width_abs$.precision$}")
    };
    // POV-Ray on x86 prints C's NaN, which carries the sign bit: "-nan".
    if v.is_nan() {
        return format!("{:>width_abs$}", "-nan");
    }
    text
}

/// The built-in function of one float named by `kind` (`sin`, `sqrt`, `int`, ...).
pub(super) fn float_function(kind: SyntaxKind) -> Option<fn(f64) -> f64> {
    match kind {
        ABS_KW => Some(f64::abs),
        ACOS_KW => Some(|v: f64| v.clamp(-1.0, 1.0).acos()),
        ACOSH_KW => Some(f64::acosh),
        ASIN_KW => Some(|v: f64| v.clamp(-1.0, 1.0).asin()),
        ASINH_KW => Some(f64::asinh),
        ATAN_KW => Some(f64::atan),
        ATANH_KW => Some(f64::atanh),
        CEIL_KW => Some(f64::ceil),
        COS_KW => Some(f64::cos),
        COSH_KW => Some(f64::cosh),
        DEGREES_KW => Some(f64::to_degrees),
        EXP_KW => Some(f64::exp),
        FLOOR_KW => Some(f64::floor),
        INT_KW => Some(c_int),
        LN_KW => Some(f64::ln),
        LOG_KW => Some(f64::log10),
        RADIANS_KW => Some(f64::to_radians),
        SIN_KW => Some(f64::sin),
        SINH_KW => Some(f64::sinh),
        SQRT_KW => Some(f64::sqrt),
        TAN_KW => Some(f64::tan),
        TANH_KW => Some(f64::tanh),
        _ => None,
    }
}

/// The name of a one-float function for an argument POV-Ray stops at (the others give NaN
/// or infinity).
pub(super) fn refused_argument(kind: SyntaxKind, v: f64) -> Option<&'static str> {
    match kind {
        LN_KW if v <= 0.0 => Some("ln"),
        LOG_KW if v <= 0.0 => Some("log"),
        SQRT_KW if v < 0.0 => Some("sqrt"),
        _ => None,
    }
}

/// `atan2`, `pow`, `mod` or `div` of `a` and `b`; the error is a domain error's message.
pub(super) fn float_function2(
    kind: SyntaxKind,
    a: f64,
    b: f64,
) -> std::result::Result<f64, &'static str> {
    match kind {
        ATAN2_KW if a == 0.0 && b == 0.0 => Err("domain error: atan2(0, 0)"),
        ATAN2_KW => Ok(a.atan2(b)),
        POW_KW if a == 0.0 && b == 0.0 => Err("domain error: pow(0, 0)"),
        POW_KW => Ok(a.powf(b)),
        MOD_KW => Ok(a % b),
        _ => Ok(c_int(a / b)),
    }
}

/// `min(...)` or `max(...)` of at least one argument.
pub(super) fn extreme(kind: SyntaxKind, args: &[f64]) -> f64 {
    let pick = if kind == MIN_KW { f64::min } else { f64::max };
    args.iter().copied().reduce(pick).unwrap_or(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn str_formats_like_the_reference_examples() {
        assert_eq!(format_float(123.456, 0, 3), "123.456");
        assert_eq!(format_float(123.456, 9, 3), "  123.456");
        assert_eq!(format_float(123.456, 0, 2), "123.46");
        assert_eq!(format_float(123.456, 0, 0), "123");
        assert_eq!(format_float(123.456, 5, 0), "  123");
        assert_eq!(format_float(123.0, 7, 2), " 123.00");
        assert_eq!(format_float(123.456, 0, -1), "123.456000");
        assert_eq!(format_float(123.456, -9, 3), "00123.456");
        assert_eq!(format_float(-1.5, -6, 1), "-001.5");
    }

    #[test]
    fn val_reads_a_leading_number() {
        assert_eq!(parse_leading_float("123.45"), 123.45);
        assert_eq!(parse_leading_float(" -2e3x"), -2000.0);
        assert_eq!(parse_leading_float("abc"), 0.0);
    }
}
