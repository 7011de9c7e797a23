//! Expressions replayed from a compiled form. Loop and macro bodies evaluate the same
//! expressions over and over, and reading them token by token through the token getter is
//! most of an evaluation's time. An expression whose only effect is its value (numbers,
//! identifiers, operators, vector literals and pure built-in functions; no directive, no
//! string, no call of a macro or a declared function) is compiled the second time its
//! place is evaluated and replayed from then on.
//!
//! A replay gives the value the token-by-token reading would give, or steps aside: an
//! identifier that holds anything but a number, vector or colour, an error to report, a
//! step budget about to run out all leave the expression to the token getter, which, the
//! expression having had no effect, starts over from its first token and reports what it
//! meets at its place.

use super::Evaluator;
use super::builtins::{extreme, float_function, float_function2, refused_argument};
use super::expr::{BinOp, combined, component, is_true, logical_not};
use super::symbols::Symbol;
use super::tokens::{Cond, FileId, FrameKind, RawToken};
use super::value::{Terms, Value};
use syntax::SyntaxKind::{self, *};

/// The grammar an expression is read with: `additive` outside parentheses, `full` inside
/// them, where comparisons, logic and `? :` are allowed too.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Level {
    Additive = 0,
    Full = 1,
}

/// What is known about the expression at one place.
const UNSEEN: u32 = 0;
const SEEN_ONCE: u32 = 1;
const NOT_PURE: u32 = 2;
/// Entries from here on are indices into the compiled expressions, offset by this.
const FIRST_COMPILED: u32 = 3;

/// The compiled expressions of one evaluation, by file, token index and level.
#[derive(Debug, Default)]
pub struct ExprCache {
    /// Per file, two entries per token (one per level), allocated when first needed.
    states: Vec<Vec<u32>>,
    compiled: Vec<Compiled>,
}

/// An expression ready to replay, and the index of the token after it.
#[derive(Debug)]
struct Compiled {
    node: Node,
    end: usize,
}

/// A float, vector or colour as a replay works it out: copied freely, with nothing to drop.
#[derive(Debug, Clone, Copy)]
enum Number {
    Float(f64),
    Vector(Terms),
    Colour(Terms),
}

impl Number {
    fn of(value: &Value) -> Option<Number> {
        match value {
            Value::Float(v) => Some(Number::Float(*v)),
            Value::Vector(t) => Some(Number::Vector(*t)),
            Value::Colour(t) => Some(Number::Colour(*t)),
            _ => None,
        }
    }

    fn value(self) -> Value {
        match self {
            Number::Float(v) => Value::Float(v),
            Number::Vector(t) => Value::Vector(t),
            Number::Colour(t) => Value::Colour(t),
        }
    }
}

#[derive(Debug)]
enum Node {
    Value(Number),
    Identifier(Symbol),
    Negate(Box<Node>),
    Not(Box<Node>),
    Binary(BinOp, Box<[Node; 2]>),
    Component(Box<Node>, SyntaxKind),
    Vector(Vec<Node>),
    Choice(Box<[Node; 3]>),
    Function(fn(f64) -> f64, SyntaxKind, Box<Node>),
    Function2(SyntaxKind, Box<[Node; 2]>),
    Extreme(SyntaxKind, Vec<Node>),
}

impl ExprCache {
    fn state(&mut self, file: FileId, pos: usize, level: Level, tokens: usize) -> &mut u32 {
        let file = file as usize;
        if self.states.len() <= file {
            self.states.resize_with(file + 1, Vec::new);
        }
        let states = &mut self.states[file];
        if states.is_empty() {
            states.resize(2 * tokens, UNSEEN);
        }
        &mut states[2 * pos + level as usize]
    }
}

impl Evaluator<'_> {
    /// The value of the expression of grammar `level` that starts where the token getter
    /// stands, replayed, with the reading position moved past it; `None` when it has to be
    /// read token by token.
    pub(super) fn replayed(&mut self, level: Level) -> Option<Value> {
        let frame = self.frames.last()?;
        // Only macro and loop bodies run their expressions more than once.
        let repeats = matches!(frame.kind, FrameKind::Macro { .. })
            || frame
                .conds
                .iter()
                .any(|cond| matches!(cond, Cond::While { .. } | Cond::For { .. }));
        if !repeats {
            return None;
        }
        let tokens = &self.files[frame.file as usize].tokens;
        // The callers often look at an expression's first token and give it back.
        let given_back = match self.pushed.as_slice() {
            [] => false,
            [first]
                if first.kind != HASH
                    && first.file == frame.file
                    && frame.pos > 0
                    && tokens[frame.pos - 1].start == first.start =>
            {
                true
            }
            _ => return None,
        };
        let start = frame.pos - usize::from(given_back);
        let (file, frame_end, token_count) = (frame.file, frame.end, tokens.len());
        let state = self.expr_cache.state(file, start, level, token_count);
        let index = match *state {
            UNSEEN => {
                *state = SEEN_ONCE;
                return None;
            }
            NOT_PURE => return None,
            SEEN_ONCE => match self.compile(file, start, level) {
                Some(compiled) => {
                    let index = self.expr_cache.compiled.len() as u32;
                    self.expr_cache.compiled.push(compiled);
                    *self.expr_cache.state(file, start, level, token_count) =
                        index + FIRST_COMPILED;
                    index as usize
                }
                None => {
                    *self.expr_cache.state(file, start, level, token_count) = NOT_PURE;
                    return None;
                }
            },
            compiled => (compiled - FIRST_COMPILED) as usize,
        };
        let compiled = &self.expr_cache.compiled[index];
        // The token after the expression, which the token-by-token reading looks at, must
        // be in the same frame: reading past a frame's end leaves the macro or file.
        let end = compiled.end;
        if end >= frame_end {
            return None;
        }
        // The tokens count against the step budget as if read; near its end the token
        // getter reads them, to stop at the right one.
        let steps = (end - start - usize::from(given_back)) as u64;
        if self.steps + steps >= self.options.budgets.steps {
            return None;
        }
        let value = self.replay(&compiled.node)?.value();
        self.steps += steps;
        if given_back {
            self.pushed.clear();
        }
        self.frames.last_mut()?.pos = end;
        Some(value)
    }

    /// The value of the expression of grammar `level` that starts where the token getter
    /// stands (nothing given back), when an earlier evaluation of its place compiled it,
    /// the token after it is one of `closing` and `accept` takes the value: replayed, with
    /// the reading position moved to that token and the steps of the expression's tokens
    /// and of `extra` more counted, as if all were read. `None`, with nothing done,
    /// otherwise. Unlike [`Self::replayed`] this never compiles: a statement that uses it
    /// reads its first run token by token.
    pub(super) fn replayed_before<T>(
        &mut self,
        level: Level,
        closing: &[SyntaxKind],
        extra: u64,
        accept: impl FnOnce(Value) -> Option<T>,
    ) -> Option<T> {
        if !self.pushed.is_empty() {
            return None;
        }
        let frame = self.frames.last()?;
        let start = frame.pos;
        let states = self.expr_cache.states.get(frame.file as usize)?;
        let state = *states.get(2 * start + level as usize)?;
        if state < FIRST_COMPILED {
            return None;
        }
        let compiled = &self.expr_cache.compiled[(state - FIRST_COMPILED) as usize];
        let end = compiled.end;
        let tokens = &self.files[frame.file as usize].tokens;
        if end >= frame.end || !closing.contains(&tokens[end].kind) {
            return None;
        }
        let steps = (end - start) as u64 + extra;
        if self.steps + steps >= self.options.budgets.steps {
            return None;
        }
        let value = accept(self.replay(&compiled.node)?.value())?;
        self.steps += steps;
        self.frames.last_mut()?.pos = end;
        Some(value)
    }

    fn compile(&self, file: FileId, start: usize, level: Level) -> Option<Compiled> {
        let source = &self.files[file as usize];
        let mut compiler = Compiler {
            evaluator: self,
            tokens: &source.tokens,
            text: &source.text,
            pos: start,
        };
        let node = match level {
            Level::Additive => compiler.additive()?,
            Level::Full => compiler.full()?,
        };
        // The token-by-token reading looks at the token after the expression through the
        // token getter, which would run a directive or look up an identifier there (and
        // call the macro it names): such an expression stays with the token getter.
        let after = compiler.tokens.get(compiler.pos)?;
        if matches!(after.kind, HASH | IDENT) {
            return None;
        }
        Some(Compiled {
            node,
            end: compiler.pos,
        })
    }

    fn replay(&self, node: &Node) -> Option<Number> {
        Some(match node {
            Node::Value(number) => *number,
            Node::Identifier(symbol) => self.numeric_identifier(*symbol)?,
            // As `negated` does.
            Node::Negate(operand) => match self.replay(operand)? {
                Number::Float(v) => Number::Float(-v),
                Number::Vector(mut t) => {
                    t.c.iter_mut().for_each(|c| *c = -*c);
                    Number::Vector(t)
                }
                Number::Colour(mut t) => {
                    t.c.iter_mut().for_each(|c| *c = -*c);
                    Number::Colour(t)
                }
            },
            Node::Not(operand) => Number::of(&logical_not(self.replay(operand)?.value()).ok()?)?,
            Node::Binary(op, operands) => {
                let [left, right] = &**operands;
                match (self.replay(left)?, self.replay(right)?) {
                    (Number::Float(a), Number::Float(b)) => Number::Float(op.apply(a, b)),
                    (a, b) => Number::of(&combined(*op, a.value(), b.value()).ok()?)?,
                }
            }
            Node::Component(operand, item) => {
                let value = self.replay(operand)?.value();
                let terms = value.terms()?;
                Number::Float(component(&value, terms, *item)?.ok()?)
            }
            Node::Vector(components) => {
                let mut c = [0.0; 5];
                for (slot, component) in c.iter_mut().zip(components) {
                    *slot = self.replay_float(component)?;
                }
                Number::Vector(Terms::new(&c[..components.len()]))
            }
            Node::Choice(parts) => {
                let [condition, a, b] = &**parts;
                let truth = is_true(self.replay_float(condition)?);
                let a = self.replay(a)?;
                let b = self.replay(b)?;
                if truth { a } else { b }
            }
            Node::Function(f, kind, argument) => {
                let v = self.replay_float(argument)?;
                if refused_argument(*kind, v).is_some() {
                    return None;
                }
                Number::Float(f(v))
            }
            Node::Function2(kind, arguments) => {
                let [a, b] = &**arguments;
                let a = self.replay_float(a)?;
                let b = self.replay_float(b)?;
                Number::Float(float_function2(*kind, a, b).ok()?)
            }
            Node::Extreme(kind, arguments) => {
                let mut values = Vec::with_capacity(arguments.len());
                for argument in arguments {
                    values.push(self.replay_float(argument)?);
                }
                Number::Float(extreme(*kind, &values))
            }
        })
    }

    fn replay_float(&self, node: &Node) -> Option<f64> {
        match self.replay(node)? {
            Number::Float(v) => Some(v),
            _ => None,
        }
    }

    /// The value of the identifier `symbol` when it holds a float, vector or colour.
    fn numeric_identifier(&self, symbol: Symbol) -> Option<Number> {
        let slot = self
            .scopes
            .iter()
            .rev()
            .find_map(|scope| scope.get(&symbol))?;
        Number::of(&slot.borrow())
    }
}

/// Reads an expression from a file's tokens as the expression parsers in `expr.rs` do, for
/// the forms a replay can evaluate; `None` for anything else.
struct Compiler<'e, 'a> {
    evaluator: &'e Evaluator<'a>,
    tokens: &'e [RawToken],
    text: &'e str,
    pos: usize,
}

impl Compiler<'_, '_> {
    fn peek(&self) -> Option<SyntaxKind> {
        self.tokens.get(self.pos).map(|t| t.kind)
    }

    fn bump(&mut self) -> Option<RawToken> {
        let token = *self.tokens.get(self.pos)?;
        self.pos += 1;
        Some(token)
    }

    fn eat(&mut self, kind: SyntaxKind) -> bool {
        let found = self.peek() == Some(kind);
        self.pos += usize::from(found);
        found
    }

    fn text(&self, token: RawToken) -> &str {
        &self.text[token.start as usize..token.end as usize]
    }

    /// `C ? A : B` and the logical and relational levels, as inside parentheses.
    fn full(&mut self) -> Option<Node> {
        let condition =
            self.binary_level(Self::relational, &[(AMP, BinOp::And), (PIPE, BinOp::Or)])?;
        if !self.eat(QUESTION) {
            return Some(condition);
        }
        let a = self.full()?;
        if !self.eat(COLON) {
            return None;
        }
        let b = self.full()?;
        Some(Node::Choice(Box::new([condition, a, b])))
    }

    fn relational(&mut self) -> Option<Node> {
        self.binary_level(
            Self::additive,
            &[
                (LT, BinOp::Lt),
                (LT_EQ, BinOp::Le),
                (EQ, BinOp::Eq),
                (NEQ, BinOp::Ne),
                (GT_EQ, BinOp::Ge),
                (GT, BinOp::Gt),
            ],
        )
    }

    fn additive(&mut self) -> Option<Node> {
        self.binary_level(
            Self::multiplicative,
            &[(PLUS, BinOp::Add), (MINUS, BinOp::Sub)],
        )
    }

    fn multiplicative(&mut self) -> Option<Node> {
        self.binary_level(Self::unary, &[(STAR, BinOp::Mul), (SLASH, BinOp::Div)])
    }

    /// Operands of `operand` joined left to right by the `operators`.
    fn binary_level(
        &mut self,
        operand: fn(&mut Self) -> Option<Node>,
        operators: &[(SyntaxKind, BinOp)],
    ) -> Option<Node> {
        let mut left = operand(self)?;
        loop {
            let kind = self.peek()?;
            let Some(&(_, op)) = operators.iter().find(|(k, _)| *k == kind) else {
                return Some(left);
            };
            self.pos += 1;
            let right = operand(self)?;
            left = Node::Binary(op, Box::new([left, right]));
        }
    }

    fn unary(&mut self) -> Option<Node> {
        match self.peek()? {
            MINUS => {
                self.pos += 1;
                Some(Node::Negate(Box::new(self.unary()?)))
            }
            PLUS => {
                self.pos += 1;
                self.unary()
            }
            BANG => {
                self.pos += 1;
                Some(Node::Not(Box::new(self.unary()?)))
            }
            _ => self.postfix(),
        }
    }

    fn postfix(&mut self) -> Option<Node> {
        let mut node = self.primary()?;
        loop {
            match self.peek()? {
                DOT => {
                    self.pos += 1;
                    let item = self.bump()?.kind;
                    let is_item = matches!(
                        item,
                        X_KW | Y_KW
                            | Z_KW
                            | U_KW
                            | V_KW
                            | T_KW
                            | RED_KW
                            | GREEN_KW
                            | BLUE_KW
                            | FILTER_KW
                            | TRANSMIT_KW
                            | GRAY_KW
                    );
                    if !is_item {
                        return None;
                    }
                    node = Node::Component(Box::new(node), item);
                }
                // Whether a subscript follows depends on the value.
                L_BRACK => return None,
                _ => return Some(node),
            }
        }
    }

    fn primary(&mut self) -> Option<Node> {
        let token = self.bump()?;
        match token.kind {
            NUMBER => Some(Node::Value(Number::Float(self.text(token).parse().ok()?))),
            L_PAREN => {
                let node = self.full()?;
                self.eat(R_PAREN).then_some(node)
            }
            LT => self.vector_literal(),
            // An identifier followed by '(' calls a function, spline or macro; one followed
            // by '[' is an array element.
            IDENT if matches!(self.peek()?, L_PAREN | L_BRACK) => None,
            // A name never met is declared nowhere; the token getter reports it.
            IDENT => Some(Node::Identifier(
                self.evaluator.interner.get(self.text(token))?,
            )),
            // `version` changes with `#version`; the other constants are fixed for an
            // evaluation.
            VERSION_KW => None,
            kind => {
                if let Some(value) = self.evaluator.builtin_constant(kind) {
                    return Some(Node::Value(Number::of(&value)?));
                }
                self.function_call(kind)
            }
        }
    }

    /// `<a, b, c>` after the `<`: two to five float components, commas optional.
    fn vector_literal(&mut self) -> Option<Node> {
        let mut components = Vec::with_capacity(5);
        loop {
            if self.peek()? == GT && !components.is_empty() {
                self.pos += 1;
                break;
            }
            components.push(self.additive()?);
            self.eat(COMMA);
            if components.len() > 5 {
                return None;
            }
        }
        (components.len() >= 2).then_some(Node::Vector(components))
    }

    /// A pure built-in function of floats and its parenthesised arguments.
    fn function_call(&mut self, kind: SyntaxKind) -> Option<Node> {
        let pure = float_function(kind).is_some()
            || matches!(kind, ATAN2_KW | POW_KW | MOD_KW | DIV_KW | MIN_KW | MAX_KW);
        if !pure || !self.eat(L_PAREN) {
            return None;
        }
        let mut arguments = Vec::new();
        loop {
            arguments.push(self.full()?);
            match self.bump()?.kind {
                COMMA => continue,
                R_PAREN => break,
                _ => return None,
            }
        }
        if let Some(f) = float_function(kind) {
            let [argument] = <[Node; 1]>::try_from(arguments).ok()?;
            return Some(Node::Function(f, kind, Box::new(argument)));
        }
        if matches!(kind, MIN_KW | MAX_KW) {
            return Some(Node::Extreme(kind, arguments));
        }
        let pair = <[Node; 2]>::try_from(arguments).ok()?;
        Some(Node::Function2(kind, Box::new(pair)))
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::check_debug;
    use super::super::{Budgets, EvalOptions, evaluate};
    use expect_test::expect;

    #[test]
    fn replayed_expressions_give_the_values_read_token_by_token() {
        check_debug(
            r#"#declare V = <1, 2, 3>;
#declare C = rgb <0.1, 0.2, 0.3>;
#for (I, 0, 3)
  #local A = -I * 2 + V.y / 4 - (I > 1 ? 10 : 20) + max(I, 1.5) + pow(2, I) + int(I / 3);
  #local W = <I, I + 1, -I> * 2 + V - x;
  #local D = C * I + (I = 2 & !(I < 1));
  #debug concat(str(A, 0, 3), " ", vstr(3, W, ",", 0, 1), " ", vstr(5, D, ",", 0, 3), "\n")
#end
"#,
            expect![[r#"
                -17.000 0.0,4.0,3.0 0.000,0.000,0.000,0.000,0.000
                -18.000 2.0,6.0,1.0 0.100,0.200,0.300,0.000,0.000
                -7.500 4.0,8.0,-1.0 1.200,1.400,1.600,1.000,1.000
                -3.500 6.0,10.0,-3.0 0.300,0.600,0.900,0.000,0.000
            "#]],
        );
    }

    #[test]
    fn replayed_declarations_assign_as_declarations_read_token_by_token() {
        // Output of POV-Ray 3.7: `#declare` in a macro writes the global, `#local` shadows
        // it, a colour stays a colour.
        check_debug(
            r#"#version 3.7;
#declare C = rgb <0.1, 0.2, 0.3>;
#declare G = 0;
#declare N = 7;
#macro Step(I)
  #declare G = G + I;
  #local N = I * 2;
  #local L = C;
  #local L = L * N + <I, 0, 1>;
  L
#end
#for (I, 1, 4)
  #local K = Step(I);
  #debug concat(str(G, 0, 0), " ", str(N, 0, 0), " ", vstr(5, K, ",", 0, 2), "\n")
#end
"#,
            expect![[r#"
                1 7 1.20,0.40,1.60,0.00,0.00
                3 7 2.40,0.80,2.20,0.00,0.00
                6 7 3.60,1.20,2.80,0.00,0.00
                10 7 4.80,1.60,3.40,0.00,0.00
            "#]],
        );
    }

    #[test]
    fn replayed_conditions_arguments_and_cases_take_the_branches_read_token_by_token() {
        // Output of POV-Ray 3.7.
        check_debug(
            r#"#version 3.7;
#declare V = <1, 2, 3>;
#declare F = function(a, b, c) { a * 10 + b - c }
#macro M(A, B) (A + B.y) #end
#for (I, 0, 5)
  #if (I > 1 & I < 4)
    #debug "in "
  #end
  #switch (I * 2)
    #case (4)
      #debug "four "
    #break
    #range (6, 8)
      #debug "six-eight "
    #break
  #end
  #local W = vcross(V, <I, 1, 0>);
  #debug concat(str(F(I, I / 2, 1), 0, 1), " ", str(M(I * 2, V + I), 0, 0), " ", vstr(3, W, ",", 0, 0), "\n")
#end
"#,
            expect![[r#"
                -1.0 2 -3,0,1
                9.5 5 -3,3,-1
                in four 20.0 8 -3,6,-3
                in six-eight 30.5 11 -3,9,-5
                six-eight 41.0 14 -3,12,-7
                51.5 17 -3,15,-9
            "#]],
        );
    }

    #[test]
    fn an_identifier_that_changes_type_is_read_token_by_token_and_its_error_located() {
        check_debug(
            r#"#macro Twice(A) (A * 2) #end
#declare Values = array[4] {1, 2, "three", 4}
#for (I, 0, 3)
  #local X = Values[I];
  #local Y = 1 + X;
  #debug concat(str(Twice(Y), 0, 0), "\n")
#end
"#,
            expect![[r#"
                scene.pov:6:16: error: expected a float, vector or color operand, found string
                    6 |   #local Y = 1 + X;
                      |                ^
            "#]],
        );
    }

    #[test]
    fn the_step_budget_stops_a_replayed_expression_at_each_of_its_tokens() {
        let text =
            "#version 3.7;\n#declare S = 0;\n#while (S < 100)\n  #declare S = S + 1;\n#end\n";
        let files = crate::files::MemoryFiles::new().with("scene.pov", text);
        let mut stopped_at = std::collections::BTreeSet::new();
        for steps in 1..200 {
            let options = EvalOptions {
                budgets: Budgets {
                    steps,
                    ..Budgets::default()
                },
                ..EvalOptions::default()
            };
            let evaluation = evaluate("scene.pov", &files, &options);
            let error = evaluation.diagnostics.iter().find(|d| d.is_error());
            let error = error.expect("the budget runs out");
            assert!(error.message.contains("step budget"), "{}", error.message);
            stopped_at.insert(u32::from(error.span.range.start()));
        }
        // Every token of the repeated declaration is a place where some budget runs out.
        let line = text.find("  #declare S = S").expect("the declaration") as u32;
        for column in [2, 3, 11, 13, 15, 17, 19, 20] {
            assert!(
                stopped_at.contains(&(line + column)),
                "never stopped at column {column}"
            );
        }
    }
}
