//! The `#` directives: declarations, conditionals, loops, macros, includes and messages.
//! They run inside the token getter, so they may stand between any two tokens of a scene.

use super::expr::EPSILON;
use super::expr_cache::Level;
use super::stream::SkipStop;
use super::symbols::Symbol;
use super::tokens::{Cond, FileId, Frame, FrameKind, Token};
use super::value::{Array, Value};
use super::{Evaluator, Message, Result, Stream};
use std::rc::Rc;
use syntax::SyntaxKind::{self, *};

impl Evaluator<'_> {
    /// Runs the directive whose `#` was just read.
    pub fn directive(&mut self, hash: Token, keyword: Token) -> Result<()> {
        match keyword.kind {
            DECLARE_KW => self.declaration(false),
            LOCAL_KW => self.declaration(true),
            UNDEF_KW => {
                let name = self.next_raw()?;
                if name.kind != IDENT {
                    return Err(self.error_at(
                        &name,
                        format!(
                            "expected an identifier after #undef, found {}",
                            self.describe(&name)
                        ),
                    ));
                }
                let text = self.text(&name).to_owned();
                if !self.undef(&text) {
                    self.warn_at(&name, format!("#undef of '{text}', which is not declared"));
                }
                Ok(())
            }
            IF_KW => {
                let taken = self.condition()?;
                self.branch(taken, &hash)
            }
            IFDEF_KW | IFNDEF_KW => {
                self.expect(L_PAREN, "'('")?;
                let name = self.next_raw()?;
                let defined = self.defined_item(&name)?;
                self.expect(R_PAREN, "')'")?;
                self.branch(defined == (keyword.kind == IFDEF_KW), &hash)
            }
            ELSE_KW | ELSEIF_KW => self.else_directive(&hash, keyword.kind == ELSEIF_KW),
            WHILE_KW => {
                let cond_pos = self.position();
                self.loop_test(cond_pos, &hash, hash.start)
            }
            FOR_KW => self.for_directive(&hash),
            SWITCH_KW => self.switch_directive(&hash),
            CASE_KW | RANGE_KW => self.case_directive(&hash, &keyword),
            BREAK_KW => self.break_directive(&hash),
            END_KW => self.end_directive(&hash),
            MACRO_KW => self.define_macro(&hash),
            INCLUDE_KW => self.include(),
            VERSION_KW => {
                let first = self.next()?;
                self.unget(first.clone());
                let version = self.float()?;
                if !self.eat(SEMICOLON)? {
                    self.warn_at(&first, "missing ';' after #version");
                }
                self.version = version;
                self.version_set = true;
                self.version_directive = Some((hash.file, hash.range().cover(keyword.range())));
                Ok(())
            }
            DEBUG_KW | WARNING_KW | ERROR_KW | RENDER_KW | STATISTICS_KW => {
                let text = self.string()?;
                match keyword.kind {
                    WARNING_KW => {
                        self.warn_at(&hash, text);
                        Ok(())
                    }
                    ERROR_KW => Err(self.error_at(&hash, text)),
                    _ => {
                        self.messages.push(Message {
                            stream: Stream::Debug,
                            text,
                        });
                        Ok(())
                    }
                }
            }
            DEFAULT_KW => self.default_directive(),
            FOPEN_KW => self.fopen(),
            FCLOSE_KW => self.fclose(),
            READ_KW => self.read_directive(),
            WRITE_KW => self.write_directive(),
            IDENT => {
                // POV-Ray ignores a '#' before an identifier, so `#Macro()` calls the macro.
                self.warn_at(&hash, "stray '#' ignored");
                let name = self.text(&keyword).to_owned();
                let slot = self.lookup(&name);
                let definition = match slot.as_ref().map(|s| s.borrow().clone()) {
                    Some(Value::Macro(definition)) => Some(definition),
                    _ => None,
                };
                match definition {
                    Some(definition) => self.invoke_macro(definition, &keyword),
                    None => {
                        self.unget(Token { slot, ..keyword });
                        Ok(())
                    }
                }
            }
            _ if !keyword.kind.is_keyword() => {
                // POV-Ray ignores a '#' that no directive name follows.
                self.warn_at(&hash, "stray '#' ignored");
                self.unget(keyword);
                Ok(())
            }
            _ => Err(self.error_at(
                &keyword,
                format!("unknown directive '#{}'", self.text(&keyword)),
            )),
        }
    }

    /// `#declare`/`#local NAME[index]... = value [;]`.
    fn declaration(&mut self, local: bool) -> Result<()> {
        let mut name = self.next_raw()?;
        if name.kind == DEPRECATED_KW {
            name = self.next_raw()?;
            if name.kind == ONCE_KW {
                name = self.next_raw()?;
            }
            if name.kind == STRING {
                name = self.next_raw()?;
            }
        }
        if name.kind != IDENT {
            let message = if name.kind.is_keyword() {
                format!(
                    "'{}' is a reserved word and cannot be declared",
                    self.text(&name)
                )
            } else {
                format!(
                    "expected an identifier to declare, found {}",
                    self.describe(&name)
                )
            };
            return Err(self.error_at(&name, message));
        }
        // The name's symbol is looked up (and a new name numbered) where the name was
        // found, when the declaration needs it.
        let frame = self.frames.last().expect("the main frame is never popped");
        let name_at = (frame.file, frame.pos - 1);
        if self.raw_lookahead(0).is_some_and(|t| t.kind == EQ)
            && self.replayed_declaration(local, name_at).is_some()
        {
            return Ok(());
        }
        let mut indices = Vec::new();
        let mut key = None;
        loop {
            let next = self.next()?;
            match next.kind {
                L_BRACK if key.is_none() => {
                    let at = next.clone();
                    if self.peek_kind()? == STRING {
                        key = Some(self.string()?);
                    } else {
                        indices.push((self.array_index(&at)?, at));
                    }
                    self.expect(R_BRACK, "']'")?;
                }
                DOT if indices.is_empty() && key.is_none() => {
                    let member = self.next_raw()?;
                    key = Some(self.text(&member).to_owned());
                }
                EQ => break,
                _ => {
                    return Err(self.error_at(
                        &next,
                        format!(
                            "expected '=' after '{}', found {}",
                            self.text(&name),
                            self.describe(&next)
                        ),
                    ));
                }
            }
        }
        // The value may end inside a macro it calls (`#local A = M()` where M's body ends
        // in an expression), whose scope is still open when the value is assigned: the
        // scope and frame depth of the directive itself are the ones that count.
        let scope = self.scopes.len() - 1;
        let depth = self.frames.len();
        if local && indices.is_empty() && key.is_none() {
            let symbol = self.symbol_at(name_at.0, name_at.1);
            if !self.scopes[scope].contains_key(&symbol) {
                // POV-Ray creates a #local before reading its value, so the value cannot
                // use an outer identifier of the same name.
                self.declare_local_symbol_in(scope, symbol, Value::Uninitialized);
            }
        }
        let first = self.guarded_at(depth, Self::next)?;
        self.unget(first.clone());
        let value = self.rvalue_from(depth)?;
        // Looking past the value may also have left the scope of the directive (a texture
        // ending a macro body is followed by its #end); then the scope read on to counts.
        let scope = scope.min(self.scopes.len() - 1);
        let needs_semicolon = value.is_numeric();
        let symbol = self.symbol_at(name_at.0, name_at.1);
        if !indices.is_empty() {
            self.assign_element(&name, symbol, &indices, value)?;
        } else if let Some(key) = key {
            self.assign_key(&name, symbol, key, value)?;
        } else {
            let existing = if local {
                self.scopes[scope].get(&symbol).cloned()
            } else {
                self.lookup_symbol_in(scope, symbol)
            };
            if let (Some(slot), Value::Function(_)) = (existing, &value)
                && matches!(&*slot.borrow(), Value::Function(_))
            {
                return Err(self.error_at(
                    &name,
                    format!(
                        "function '{}' is already declared; #undef it before declaring it again",
                        self.text(&name)
                    ),
                ));
            }
            if local {
                self.declare_local_symbol_in(scope, symbol, value);
            } else {
                self.declare_symbol_in(scope, symbol, value);
            }
        }
        // A '#' given back here is a held-back #declare: the ';' is missing, and that
        // declaration must not run before the error is reported.
        let semicolon =
            !matches!(self.pushed.last(), Some(t) if t.kind == HASH) && self.eat(SEMICOLON)?;
        if !semicolon && needs_semicolon && self.version >= 3.5 {
            return Err(self
                .error_at(
                    &first,
                    "missing ';' after the declaration of a float, vector or color",
                )
                .with_note_boxed(
                    "POV-Ray 3.5 and later require it; strings and objects may omit it",
                ));
        }
        Ok(())
    }

    /// `NAME = VALUE;` after `#declare` or `#local`, where the value is an expression that
    /// an earlier run of this place compiled, ending at the `;`: assigned at once, with the
    /// same effects as reading it token by token (a new `#local` is created before its
    /// value is read). `None` when it must be read token by token; only that first effect,
    /// which the reading repeats harmlessly, has happened then.
    fn replayed_declaration(&mut self, local: bool, name_at: (FileId, usize)) -> Option<()> {
        let scope = self.scopes.len() - 1;
        let symbol = self.symbol_at(name_at.0, name_at.1);
        if local && !self.scopes[scope].contains_key(&symbol) {
            self.declare_local_symbol_in(scope, symbol, Value::Uninitialized);
        }
        self.frames.last_mut()?.pos += 1;
        // The '=' and the ';' count as steps too.
        let Some(value) = self.replayed_rvalue(&[SEMICOLON], 2) else {
            self.frames.last_mut()?.pos -= 1;
            return None;
        };
        self.frames.last_mut()?.pos += 1;
        if local {
            self.declare_local_symbol_in(scope, symbol, value);
        } else {
            self.declare_symbol_in(scope, symbol, value);
        }
        Some(())
    }

    /// A value as [`Self::rvalue`] reads it, when it is an expression that an earlier run
    /// of its place compiled and one of `closing` follows it: replayed, with the reading
    /// position moved to that token (see [`Self::replayed_before`] for `extra`). As when
    /// read token by token, a vector led by a colour identifier is a colour.
    pub(super) fn replayed_rvalue(&mut self, closing: &[SyntaxKind], extra: u64) -> Option<Value> {
        let frame = self.frames.last()?;
        let (file, first) = (frame.file, frame.pos);
        match self.replayed_before(Level::Additive, closing, extra, Some)? {
            Value::Vector(terms) if self.files[file as usize].tokens[first].kind == IDENT => {
                let leader = self.symbol_at(file, first);
                let colour = self
                    .lookup_symbol(leader)
                    .is_some_and(|slot| matches!(&*slot.borrow(), Value::Colour(_)));
                Some(if colour {
                    Value::colour(terms)
                } else {
                    Value::Vector(terms)
                })
            }
            other => Some(other),
        }
    }

    fn assign_element(
        &mut self,
        at: &Token,
        symbol: Symbol,
        indices: &[(i64, Token)],
        value: Value,
    ) -> Result<()> {
        let Some(slot) = self.lookup_symbol(symbol) else {
            return Err(self.undeclared(at));
        };
        let name = self.text(at);
        let mut stored = slot.borrow_mut();
        let Value::Array(array) = &mut *stored else {
            return Err(self.error_at(
                at,
                format!("'{name}' is a {}, not an array", stored.type_name()),
            ));
        };
        if indices.len() != array.dims.len() {
            return Err(self.error_at(
                at,
                format!(
                    "'{name}' has {} dimensions but {} indices were given",
                    array.dims.len(),
                    indices.len()
                ),
            ));
        }
        let plain: Vec<i64> = indices.iter().map(|(i, _)| *i).collect();
        let flat = self.flat_index(&indices[0].1, &array.dims, &plain)?;
        let array = Rc::make_mut(array);
        if !array.mixed
            && let Some(existing) = array.items.iter().flatten().next()
            && !same_kind(existing, &value)
        {
            return Err(self.error_at(
                at,
                format!(
                    "cannot store a {} in an array of {} (declare it `array mixed` to allow this)",
                    value.type_name(),
                    existing.type_name()
                ),
            ));
        }
        array.items[flat] = Some(value);
        Ok(())
    }

    fn assign_key(&mut self, at: &Token, symbol: Symbol, key: String, value: Value) -> Result<()> {
        let Some(slot) = self.lookup_symbol(symbol) else {
            return Err(self.undeclared(at));
        };
        let name = self.text(at);
        let mut stored = slot.borrow_mut();
        let Value::Dictionary(dict) = &mut *stored else {
            return Err(self.error_at(
                at,
                format!("'{name}' is a {}, not a dictionary", stored.type_name()),
            ));
        };
        Rc::make_mut(dict).insert(key, value);
        Ok(())
    }

    /// The right-hand side of a declaration or a macro argument: a value of any type.
    pub fn rvalue(&mut self) -> Result<Value> {
        self.rvalue_from(self.frames.len())
    }

    /// A value that began at frame depth `depth`: a macro its first token called may have
    /// returned since, and one called later must still run in full.
    fn rvalue_from(&mut self, depth: usize) -> Result<Value> {
        // Reading an array identifier looks at the token after it (for a subscript), which
        // must not run a following #declare early.
        let token = self.guarded_at(depth, Self::next)?;
        let kind = token.kind;
        self.unget(token.clone());
        if Self::starts_object(kind) {
            return Ok(Value::Object(Rc::new(self.object()?)));
        }
        match kind {
            LIGHT_SOURCE_KW => Ok(Value::Light(Rc::new(self.light_source()?))),
            CAMERA_KW => Ok(Value::Camera(Rc::new(self.camera_value()?))),
            TEXTURE_KW => {
                self.next()?;
                let mut texture = self.texture_body()?;
                // More texture blocks after the first make a layered texture. A macro call
                // after the last one runs after the texture is assigned, as in POV-Ray
                // (`#declare T = texture {...}` then `Screen_Plane(T, ...)`).
                loop {
                    let next = self.guarded_at(depth, Self::next_unexpanded)?;
                    if next.kind != TEXTURE_KW {
                        self.unget(next);
                        break;
                    }
                    let top = self.texture_body()?;
                    texture = super::object::layer(texture, top)
                        .map_err(|reason| self.error_at(&next, reason))?;
                }
                Ok(Value::Texture(Rc::new(texture)))
            }
            STRING | CONCAT_KW | STR_KW | CHR_KW | SUBSTR_KW | STRUPR_KW | STRLWR_KW | VSTR_KW
            | DATETIME_KW => Ok(Value::String(self.string()?.into())),
            IDENT
                if token
                    .slot
                    .as_ref()
                    .is_some_and(|s| matches!(&*s.borrow(), Value::String(_))) =>
            {
                Ok(Value::String(self.string()?.into()))
            }
            PIGMENT_KW => {
                self.next()?;
                Ok(Value::Pigment(Rc::new(self.pigment_body()?)))
            }
            NORMAL_KW => {
                self.next()?;
                Ok(Value::Normal(Rc::new(self.normal_body()?)))
            }
            FINISH_KW => {
                self.next()?;
                Ok(Value::Finish(Rc::new(self.finish_body(None)?)))
            }
            INTERIOR_KW => {
                self.next()?;
                Ok(Value::Interior(Rc::new(self.interior_body()?)))
            }
            COLOR_MAP_KW | COLOUR_MAP_KW => {
                self.next()?;
                Ok(Value::ColourMap(Rc::new(self.colour_map_body()?)))
            }
            PIGMENT_MAP_KW => {
                self.next()?;
                Ok(Value::PigmentMap(Rc::new(self.pigment_map_body()?)))
            }
            TRANSFORM_KW => {
                self.next()?;
                Ok(Value::Transform(Rc::new(self.transform_body()?)))
            }
            FUNCTION_KW => Ok(Value::Function(std::sync::Arc::new(self.function_value()?))),
            SPLINE_KW => {
                self.next()?;
                Ok(Value::Spline(Rc::new(self.spline_body()?)))
            }
            ARRAY_KW => {
                self.next()?;
                Ok(Value::Array(Rc::new(self.array_body()?)))
            }
            DICTIONARY_KW => {
                self.next()?;
                Ok(Value::Dictionary(Rc::new(self.dictionary_body()?)))
            }
            MATERIAL_KW => {
                self.next()?;
                Ok(Value::Material(Rc::new(self.material_body()?)))
            }
            MEDIA_KW => {
                self.next()?;
                Ok(Value::Media(Rc::new(self.media_body()?)))
            }
            DENSITY_KW => {
                self.next()?;
                Ok(Value::Density(Rc::new(self.density_body()?)))
            }
            DENSITY_MAP_KW => {
                self.next()?;
                Ok(Value::DensityMap(Rc::new(self.density_map_body()?)))
            }
            FOG_KW => {
                self.next()?;
                Ok(Value::Fog(Rc::new(self.fog_body()?)))
            }
            RAINBOW_KW => {
                self.next()?;
                Ok(Value::Rainbow(Rc::new(self.rainbow_body()?)))
            }
            SKY_SPHERE_KW => {
                self.next()?;
                Ok(Value::SkySphere(Rc::new(self.sky_sphere_body()?)))
            }
            NORMAL_MAP_KW | TEXTURE_MAP_KW | SLOPE_MAP_KW => {
                Err(self.unsupported(&token, &format!("declaring a {}", self.text(&token))))
            }
            _ => {
                // An expression is only known to end when the token after it is read; a
                // `#declare` there must wait until this value is assigned.
                self.guarded_at(depth, Self::expression)
            }
        }
    }

    /// Runs `read`, which may look at the token after a declaration's value, holding back
    /// any `#declare` it meets until the value is assigned.
    fn guarded<T>(&mut self, read: impl FnOnce(&mut Self) -> Result<T>) -> Result<T> {
        self.guarded_at(self.frames.len(), read)
    }

    /// `guarded` for a value that began at frame depth `depth`.
    fn guarded_at<T>(
        &mut self,
        depth: usize,
        read: impl FnOnce(&mut Self) -> Result<T>,
    ) -> Result<T> {
        self.declaring.push(depth);
        let result = read(self);
        self.declaring.pop();
        result
    }

    /// `array[N][M] [mixed] { ... }`, after `array`.
    fn array_body(&mut self) -> Result<Array> {
        let mut dims = Vec::new();
        let mut at = self.next()?;
        let mut mixed = false;
        if at.kind == MIXED_KW {
            mixed = true;
            at = self.next()?;
        }
        while at.kind == L_BRACK {
            if self.eat(R_BRACK)? {
                dims.push(None);
            } else {
                let size = self.array_index(&at)?;
                if size <= 0 {
                    return Err(
                        self.error_at(&at, format!("array dimension must be positive, not {size}"))
                    );
                }
                dims.push(Some(size as usize));
                self.expect(R_BRACK, "']'")?;
            }
            // Whether an initializer follows is only known from the next token.
            at = self.guarded(Self::next)?;
        }
        if at.kind == MIXED_KW {
            mixed = true;
            at = self.guarded(Self::next)?;
        }
        if dims.len() > 5 {
            return Err(self.error_at(&at, "too many array dimensions: POV-Ray allows 5"));
        }
        if dims.is_empty() {
            return Err(self.error_at(&at, "expected '[' with the array's size"));
        }
        let initializer = if at.kind == L_BRACE {
            Some(self.array_initializer(&at, dims.len())?)
        } else {
            self.unget(at.clone());
            None
        };
        let sizes: Vec<usize> = match (&initializer, dims.iter().all(Option::is_some)) {
            (_, true) => dims.iter().map(|d| d.unwrap_or(0)).collect(),
            (Some(init), false) => init.shape.clone(),
            (None, false) => {
                return Err(self.error_at(&at, "an array without sizes needs an initializer"));
            }
        };
        let total = sizes.iter().try_fold(1usize, |acc, &d| acc.checked_mul(d));
        let total = match total {
            Some(t) if t <= self.options.budgets.array_elements => t,
            _ => {
                return Err(self.budget_error(
                    format!(
                        "array of {sizes:?} elements exceeds the budget of {} elements",
                        self.options.budgets.array_elements
                    ),
                    "max-array-elements",
                ));
            }
        };
        let mut items = vec![None; total];
        if let Some(init) = initializer {
            if init.shape != sizes {
                return Err(self.error_at(
                    &at,
                    format!(
                        "the initializer has shape {:?} but the array is declared {:?}",
                        init.shape, sizes
                    ),
                ));
            }
            for (slot, value) in items.iter_mut().zip(init.values) {
                *slot = Some(value);
            }
        }
        Ok(Array {
            dims: sizes,
            items,
            mixed,
        })
    }

    fn array_initializer(&mut self, open: &Token, depth: usize) -> Result<Initializer> {
        let mut values = Vec::new();
        let mut shape: Option<Vec<usize>> = None;
        let mut count = 0;
        loop {
            if self.eat(R_BRACE)? {
                break;
            }
            if depth > 1 {
                let inner_open = self.expect(L_BRACE, "'{' for the next array dimension")?;
                let inner = self.array_initializer(&inner_open, depth - 1)?;
                if shape.as_ref().is_some_and(|s| *s != inner.shape) {
                    return Err(
                        self.error_at(&inner_open, "rows of an array initializer differ in size")
                    );
                }
                shape = Some(inner.shape);
                values.extend(inner.values);
            } else {
                values.push(self.rvalue()?);
            }
            count += 1;
            // Commas between the items are optional, as in all of POV-Ray's lists.
            self.eat(COMMA)?;
        }
        if count == 0 {
            return Err(self.error_at(open, "empty array initializer"));
        }
        let mut full = vec![count];
        full.extend(shape.unwrap_or_default());
        Ok(Initializer {
            shape: full,
            values,
        })
    }

    /// `dictionary { ["key"]: value, ... }`, after `dictionary`.
    fn dictionary_body(&mut self) -> Result<super::value::Dictionary> {
        self.expect(L_BRACE, "'{'")?;
        let mut dict = super::value::Dictionary::new();
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => return Ok(dict),
                L_BRACK => {
                    let key = self.string()?;
                    self.expect(R_BRACK, "']'")?;
                    self.expect(COLON, "':'")?;
                    let value = self.rvalue()?;
                    dict.insert(key, value);
                    self.eat(COMMA)?;
                }
                IDENT => {
                    let key = self.text(&token).to_owned();
                    self.expect(COLON, "':'")?;
                    let value = self.rvalue()?;
                    dict.insert(key, value);
                    self.eat(COMMA)?;
                }
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected '[\"key\"]: value' or '}}', found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
    }

    fn branch(&mut self, taken: bool, hash: &Token) -> Result<()> {
        if taken {
            self.conds().push(Cond::If {
                opened_at: hash.start,
            });
            return Ok(());
        }
        loop {
            match self.skip_block(true, hash)? {
                SkipStop::End => return Ok(()),
                SkipStop::Else => {
                    self.conds().push(Cond::If {
                        opened_at: hash.start,
                    });
                    return Ok(());
                }
                SkipStop::ElseIf => {
                    if self.condition()? {
                        self.conds().push(Cond::If {
                            opened_at: hash.start,
                        });
                        return Ok(());
                    }
                }
                // These belong to an enclosing #switch or loop; skipping passes them by.
                SkipStop::Case | SkipStop::Range | SkipStop::Break => {}
            }
        }
    }

    fn else_directive(&mut self, hash: &Token, elseif: bool) -> Result<()> {
        match self.conds().last().cloned() {
            Some(Cond::If { .. }) => {
                self.conds().pop();
                self.skip_block(false, hash)?;
                Ok(())
            }
            // Running a taken clause, execution falls through an #else as through a #case.
            Some(Cond::Switch { taken: true, .. }) if !elseif => Ok(()),
            Some(Cond::Switch { taken: false, .. }) if !elseif => {
                Err(self.error_at(hash, "#else in a #switch before any #case or #range"))
            }
            _ => Err(self.error_at(
                hash,
                format!(
                    "#{} without a matching #if",
                    if elseif { "elseif" } else { "else" }
                ),
            )),
        }
    }

    /// Evaluates a `#while` condition at `cond_pos`; enters the body or skips past `#end`.
    fn loop_test(&mut self, cond_pos: usize, hash: &Token, opened_at: u32) -> Result<()> {
        if self.condition()? {
            self.conds().push(Cond::While {
                cond_pos,
                opened_at,
            });
        } else {
            self.skip_block(false, hash)?;
        }
        Ok(())
    }

    /// Counts one loop iteration; the error points at the loop's `#while` or `#for`.
    fn count_iteration(&mut self, hash: &Token, opened_at: u32) -> Result<()> {
        self.loop_iterations += 1;
        if self.loop_iterations > self.options.budgets.loop_iterations {
            let range = syntax::TextRange::at(opened_at.into(), 1.into());
            let mut error = self.error_in(
                hash.file,
                range,
                format!(
                    "loop iteration budget of {} exceeded (endless loop?)",
                    self.options.budgets.loop_iterations
                ),
            );
            error.notes.push("raise the limit with the `max-loop-iterations` option if the scene really needs more".into());
            return Err(error);
        }
        Ok(())
    }

    fn for_directive(&mut self, hash: &Token) -> Result<()> {
        self.expect(L_PAREN, "'('")?;
        let name = self.next_raw()?;
        if name.kind != IDENT {
            return Err(self.error_at(
                &name,
                format!("expected the loop variable, found {}", self.describe(&name)),
            ));
        }
        let name = self.text(&name).to_owned();
        self.expect(COMMA, "','")?;
        let start = self.float_in_parens()?;
        self.expect(COMMA, "','")?;
        let end = self.float_in_parens()?;
        let step = if self.eat(COMMA)? {
            self.float_in_parens()?
        } else {
            1.0
        };
        self.expect(R_PAREN, "')'")?;
        if step == 0.0 {
            return Err(self.error_at(hash, "#for with a step of 0 never ends"));
        }
        let variable = self.interner.intern(&name);
        self.declare_local_symbol(variable, Value::Float(start));
        if for_continues(start, end, step) {
            let body_pos = self.position();
            self.conds().push(Cond::For {
                variable,
                end,
                step,
                body_pos,
                opened_at: hash.start,
            });
        } else {
            self.skip_block(false, hash)?;
        }
        Ok(())
    }

    fn switch_directive(&mut self, hash: &Token) -> Result<()> {
        self.expect(L_PAREN, "'('")?;
        let value = self.float_in_parens()?;
        self.expect(R_PAREN, "')'")?;
        // Measured against POV-Ray 3.7: tokens before the first #case run.
        self.conds().push(Cond::Switch {
            value,
            opened_at: hash.start,
            taken: false,
        });
        Ok(())
    }

    /// Skips to the next `#case`/`#range` that matches `value`, an `#else`, or the `#end`,
    /// and marks the switch taken when a clause is entered.
    fn next_clause(&mut self, value: f64, hash: &Token) -> Result<()> {
        loop {
            let entered = match self.skip_block(true, hash)? {
                SkipStop::End => {
                    self.conds().pop();
                    return Ok(());
                }
                SkipStop::Else => true,
                SkipStop::Case => self.case_matches(value, false)?,
                SkipStop::Range => self.case_matches(value, true)?,
                SkipStop::Break | SkipStop::ElseIf => false,
            };
            if entered {
                if let Some(Cond::Switch { taken, .. }) = self.conds().last_mut() {
                    *taken = true;
                }
                return Ok(());
            }
        }
    }

    fn case_matches(&mut self, value: f64, range: bool) -> Result<bool> {
        self.expect(L_PAREN, "'('")?;
        let low = self.float_in_parens()?;
        let matched = if range {
            self.expect(COMMA, "','")?;
            let high = self.float_in_parens()?;
            low <= value && value <= high
        } else {
            (value - low).abs() <= EPSILON
        };
        self.expect(R_PAREN, "')'")?;
        Ok(matched)
    }

    /// A `#case` or `#range` met while running a clause: its condition decides whether the
    /// clause falls through into it.
    fn case_directive(&mut self, hash: &Token, keyword: &Token) -> Result<()> {
        let Some(Cond::Switch { value, taken, .. }) = self.conds().last().cloned() else {
            return Err(self.error_at(keyword, format!("#{} outside #switch", self.text(keyword))));
        };
        // A taken clause without #break falls through into the next one, whatever its
        // condition, as in C (measured against POV-Ray 3.7).
        let matched = self.case_matches(value, keyword.kind == RANGE_KW)?;
        if taken || matched {
            if let Some(Cond::Switch { taken, .. }) = self.conds().last_mut() {
                *taken = true;
            }
            return Ok(());
        }
        let opened = hash.clone();
        self.next_clause(value, &opened)
    }

    /// `#break`: leaves the innermost `#switch`, loop or macro.
    fn break_directive(&mut self, hash: &Token) -> Result<()> {
        let conds = self.conds().clone();
        let target = conds.iter().rposition(|c| {
            matches!(
                c,
                Cond::Switch { .. } | Cond::While { .. } | Cond::For { .. }
            )
        });
        match target {
            Some(index) => {
                let levels = conds.len() - index;
                self.conds().truncate(index);
                for _ in 0..levels {
                    self.skip_block(false, hash)?;
                }
                Ok(())
            }
            None if matches!(
                self.frames.last().map(|f| &f.kind),
                Some(FrameKind::Macro { .. })
            ) =>
            {
                if !conds.is_empty() {
                    self.conds().clear();
                }
                self.pop_frame()
            }
            None => Err(self.error_at(hash, "#break outside #switch, #while, #for or #macro")),
        }
    }

    fn end_directive(&mut self, hash: &Token) -> Result<()> {
        match self.conds().pop() {
            Some(Cond::If { .. }) | Some(Cond::Switch { .. }) => Ok(()),
            Some(Cond::While {
                cond_pos,
                opened_at,
            }) => {
                self.count_iteration(hash, opened_at)?;
                self.seek(cond_pos);
                self.loop_test(cond_pos, hash, opened_at)
            }
            Some(Cond::For {
                variable,
                end,
                step,
                body_pos,
                opened_at,
            }) => {
                self.count_iteration(hash, opened_at)?;
                let current = match self
                    .lookup_symbol(variable)
                    .map(|slot| slot.borrow().clone())
                {
                    Some(Value::Float(v)) => v,
                    _ => {
                        let name = self.interner.name(variable);
                        return Err(self.error_at(
                            hash,
                            format!("the #for variable '{name}' is no longer a float"),
                        ));
                    }
                };
                let next = current + step;
                self.declare_local_symbol(variable, Value::Float(next));
                if for_continues(next, end, step) {
                    self.seek(body_pos);
                    self.conds().push(Cond::For {
                        variable,
                        end,
                        step,
                        body_pos,
                        opened_at,
                    });
                }
                Ok(())
            }
            None => Err(self.error_at(
                hash,
                "#end without a matching #if, #while, #for, #switch or #macro",
            )),
        }
    }

    fn include(&mut self) -> Result<()> {
        let at = self.next()?;
        self.unget(at.clone());
        let name = self.string()?;
        let Some(file) = self.load(&name) else {
            let mut error = self.missing_file(&at, &name, "include");
            error.notes.push(format!(
                "standard includes: {}",
                crate::stdinc::names().collect::<Vec<_>>().join(", ")
            ));
            return Err(error);
        };
        if let Some(position) = self.include_stack.iter().position(|&f| f == file) {
            let chain: Vec<&str> = self.include_stack[position..]
                .iter()
                .map(|&f| self.files[f as usize].name.as_str())
                .chain(std::iter::once(name.as_str()))
                .collect();
            return Err(self.error_at(&at, format!("include cycle: {}", chain.join(" -> "))));
        }
        if self.include_stack.len() > self.options.budgets.include_depth {
            return Err(self.budget_error(
                format!(
                    "includes nested more than {} deep",
                    self.options.budgets.include_depth
                ),
                "max-include-depth",
            ));
        }
        self.syntax_check(file)?;
        let end = self.files[file as usize].tokens.len();
        self.include_stack.push(file);
        self.push_scope();
        self.push_frame(Frame {
            file,
            pos: 0,
            end,
            kind: FrameKind::Include,
            conds: Vec::new(),
            entered_at: Some((at.file, at.range())),
        });
        Ok(())
    }
}

/// The shape of an array initializer and its values in row-major order.
struct Initializer {
    shape: Vec<usize>,
    values: Vec<Value>,
}

fn for_continues(value: f64, end: f64, step: f64) -> bool {
    if step > 0.0 {
        value <= end + EPSILON
    } else {
        value >= end - EPSILON
    }
}

fn same_kind(a: &Value, b: &Value) -> bool {
    let numeric = |v: &Value| v.is_numeric();
    (numeric(a) && numeric(b)) || std::mem::discriminant(a) == std::mem::discriminant(b)
}

trait WithNote {
    fn with_note_boxed(self, note: &str) -> Self;
}

impl WithNote for Box<syntax::Diagnostic> {
    fn with_note_boxed(mut self, note: &str) -> Self {
        self.notes.push(note.to_owned());
        self
    }
}
