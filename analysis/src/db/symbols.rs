//! The symbol table of one file: what its `#declare`, `#local`, `#macro`, macro parameters
//! and `#for` variables define. Symbols carry no positions, only the number of their
//! defining name among the file's names, so an edit that moves text without changing what
//! is defined leaves the table equal and everything built on it is reused.

use super::{Db, File};
use syntax::SyntaxKind::{self, *};
use syntax::ast::{self, AstNode};
use syntax::{SyntaxNode, SyntaxToken, TextRange};

/// Something a file defines.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Symbol {
    pub name: String,
    pub kind: SymbolKind,
    /// The number of the defining name among the file's `NAME` nodes in tree order; see
    /// [`name_ranges`].
    pub name_index: u32,
    /// The index in the table of the macro whose parameter list or body holds the symbol.
    pub container: Option<u32>,
    /// `#local`: visible in its own file or macro only.
    pub local: bool,
    /// The comment right above the definition, without its markers.
    pub doc: Option<String>,
}

/// What kind of thing a symbol is.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum SymbolKind {
    /// A declared value, with its kind and, when it is a constant, its value.
    Variable {
        value: ValueKind,
        constant: Option<String>,
    },
    Macro {
        params: Vec<MacroParam>,
    },
    Parameter,
    /// The counter of a `#for` loop.
    LoopVariable,
}

/// One parameter of a macro.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct MacroParam {
    pub name: String,
    pub optional: bool,
}

impl MacroParam {
    /// How hover and signature help show the parameter: `optional R` or `R`.
    pub fn label(&self) -> String {
        if self.optional {
            format!("optional {}", self.name)
        } else {
            self.name.clone()
        }
    }
}

/// The kind of a declared value, as far as the text tells it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ValueKind {
    Float,
    Vector,
    Color,
    String,
    Object,
    Camera,
    LightSource,
    Texture,
    Pigment,
    Normal,
    Finish,
    Interior,
    Media,
    Density,
    Transform,
    Function,
    Spline,
    Array,
    Dictionary,
    /// Another keyword block (`color_map`, `fog`, ...), named by its keyword.
    Block(SyntaxKind),
    /// A value the text alone does not tell, such as a macro's result.
    Unknown,
}

impl ValueKind {
    /// How hovers and completions name the kind.
    pub fn describe(self) -> &'static str {
        match self {
            ValueKind::Float => "float",
            ValueKind::Vector => "vector",
            ValueKind::Color => "color",
            ValueKind::String => "string",
            ValueKind::Object => "object",
            ValueKind::Camera => "camera",
            ValueKind::LightSource => "light_source",
            ValueKind::Texture => "texture",
            ValueKind::Pigment => "pigment",
            ValueKind::Normal => "normal",
            ValueKind::Finish => "finish",
            ValueKind::Interior => "interior",
            ValueKind::Media => "media",
            ValueKind::Density => "density",
            ValueKind::Transform => "transform",
            ValueKind::Function => "function",
            ValueKind::Spline => "spline",
            ValueKind::Array => "array",
            ValueKind::Dictionary => "dictionary",
            ValueKind::Block(kind) => kind.keyword_text().unwrap_or("block"),
            ValueKind::Unknown => "value",
        }
    }
}

/// The symbols `file` defines, in text order.
///
/// Holds names, kinds and constant values but no positions: typing inside an expression
/// that is not a constant, or in whitespace and comments away from definitions, leaves it
/// equal.
#[salsa::tracked(returns(ref))]
pub fn file_symbols(db: &dyn Db, file: File) -> Vec<Symbol> {
    let root = super::parse(db, file).syntax_node();
    let mut symbols: Vec<Symbol> = Vec::new();
    // Macros in the table, by their node, to give parameters and body symbols a container.
    let mut macros: Vec<(SyntaxNode, u32)> = Vec::new();
    for (name_index, name) in names(&root).enumerate() {
        let Some(text) = ast::Name::cast(name.clone()).and_then(|n| n.text()) else {
            continue;
        };
        let Some(parent) = name.parent() else {
            continue;
        };
        let container = name
            .ancestors()
            .skip(1)
            .filter(|node| node.kind() == MACRO && *node != parent)
            .find_map(|node| macros.iter().find(|(m, _)| *m == node).map(|(_, i)| *i));
        let (kind, local, doc) = match parent.kind() {
            DECLARE => {
                let declare = ast::Declare::cast(parent.clone());
                let value = declare.as_ref().and_then(|d| d.value());
                let (value, constant) = value
                    .as_ref()
                    .map_or((ValueKind::Unknown, None), value_kind);
                let local = declare.is_some_and(|d| d.is_local());
                let kind = SymbolKind::Variable { value, constant };
                (kind, local, doc_comment(&parent))
            }
            MACRO => {
                let params = ast::Macro::cast(parent.clone())
                    .map(|m| {
                        m.params()
                            .filter_map(|p| {
                                Some(MacroParam {
                                    name: p.name()?.text()?,
                                    optional: p.is_optional(),
                                })
                            })
                            .collect()
                    })
                    .unwrap_or_default();
                macros.push((parent.clone(), symbols.len() as u32));
                (SymbolKind::Macro { params }, false, doc_comment(&parent))
            }
            PARAM if in_macro_params(&parent) => (SymbolKind::Parameter, true, None),
            _ if name.ancestors().any(|a| a.kind() == FOR) => {
                (SymbolKind::LoopVariable, false, None)
            }
            _ => continue,
        };
        symbols.push(Symbol {
            name: text,
            kind,
            name_index: name_index as u32,
            container,
            local,
            doc,
        });
    }
    symbols
}

/// The ranges of the identifiers of `file`'s `NAME` nodes, in tree order, so that a
/// [`Symbol::name_index`] can be located. Changes with every edit that moves a name.
#[salsa::tracked(returns(ref))]
pub fn name_ranges(db: &dyn Db, file: File) -> Vec<TextRange> {
    let root = super::parse(db, file).syntax_node();
    names(&root)
        .map(|name| {
            ast::Name::cast(name.clone())
                .and_then(|n| n.token())
                .map_or(name.text_range(), |t| t.text_range())
        })
        .collect()
}

fn names(root: &SyntaxNode) -> impl Iterator<Item = SyntaxNode> + use<> {
    root.descendants().filter(|node| node.kind() == NAME)
}

/// Whether a parameter belongs to a macro (not to a `function (x, y) { }`).
fn in_macro_params(param: &SyntaxNode) -> bool {
    param
        .parent()
        .and_then(|list| list.parent())
        .is_some_and(|owner| owner.kind() == MACRO)
}

/// The comments right above a definition, joined: line comments on consecutive lines or
/// one block comment, separated from the definition by at most one line break.
pub fn doc_comment(node: &SyntaxNode) -> Option<String> {
    let mut lines: Vec<String> = Vec::new();
    let mut element = first_token(node)?.prev_token();
    while let Some(token) = element {
        match token.kind() {
            WHITESPACE if line_breaks(token.text()) <= 1 => {}
            LINE_COMMENT => lines.push(ast_comment_text(&token)),
            BLOCK_COMMENT => {
                lines.push(ast_comment_text(&token));
                break;
            }
            _ => break,
        }
        element = token.prev_token();
    }
    if lines.is_empty() {
        return None;
    }
    lines.reverse();
    let text = lines.join("\n").trim().to_owned();
    (!text.is_empty()).then_some(text)
}

fn first_token(node: &SyntaxNode) -> Option<SyntaxToken> {
    node.first_token()
}

fn line_breaks(text: &str) -> usize {
    text.matches('\n').count()
}

fn ast_comment_text(token: &SyntaxToken) -> String {
    let comment = ast::Comment::cast(token.clone());
    let content = comment.as_ref().map_or(token.text(), |c| c.content());
    content
        .lines()
        .map(|line| line.trim().trim_start_matches('*').trim())
        .collect::<Vec<_>>()
        .join("\n")
        .trim()
        .to_owned()
}

/// The kind of a declared value, and its text when it is a constant.
fn value_kind(value: &SyntaxNode) -> (ValueKind, Option<String>) {
    let kind = match value.kind() {
        LITERAL => match value.first_token().map(|t| t.kind()) {
            Some(STRING) => ValueKind::String,
            _ => ValueKind::Float,
        },
        VECTOR => ValueKind::Vector,
        COLOR => ValueKind::Color,
        OBJECT => ValueKind::Object,
        CAMERA => ValueKind::Camera,
        LIGHT_SOURCE => ValueKind::LightSource,
        TEXTURE => ValueKind::Texture,
        PIGMENT => ValueKind::Pigment,
        NORMAL => ValueKind::Normal,
        FINISH => ValueKind::Finish,
        INTERIOR => ValueKind::Interior,
        MEDIA => ValueKind::Media,
        DENSITY => ValueKind::Density,
        TRANSFORM => ValueKind::Transform,
        FUNCTION => ValueKind::Function,
        SPLINE => ValueKind::Spline,
        ARRAY => ValueKind::Array,
        DICTIONARY => ValueKind::Dictionary,
        BLOCK | ATMOSPHERIC => value
            .children_with_tokens()
            .filter_map(|e| e.into_token())
            .find(|t| t.kind().is_keyword())
            .map_or(ValueKind::Unknown, |t| ValueKind::Block(t.kind())),
        CALL => call_kind(value),
        _ => match fold(value) {
            Some(Constant::Float(_)) => ValueKind::Float,
            Some(Constant::Vector(_)) => ValueKind::Vector,
            None => ValueKind::Unknown,
        },
    };
    let constant = match kind {
        ValueKind::String => value.first_token().map(|t| t.text().to_owned()),
        _ => fold(value).map(|c| c.to_string()),
    };
    (kind, constant)
}

/// The kind a built-in function returns; macros and user functions are not known.
fn call_kind(call: &SyntaxNode) -> ValueKind {
    let Some(builtin) = ast::Call::cast(call.clone()).and_then(|c| c.builtin()) else {
        return ValueKind::Unknown;
    };
    match builtin.kind() {
        CONCAT_KW | STR_KW | CHR_KW | SUBSTR_KW | STRUPR_KW | STRLWR_KW | DATETIME_KW | VSTR_KW => {
            ValueKind::String
        }
        VNORMALIZE_KW | VCROSS_KW | VROTATE_KW | VAXIS_ROTATE_KW | MIN_EXTENT_KW
        | MAX_EXTENT_KW | TRACE_KW | VTURBULENCE_KW => ValueKind::Vector,
        _ => ValueKind::Float,
    }
}

/// A value computed from the text alone.
#[derive(Debug, Clone, PartialEq)]
pub enum Constant {
    Float(f64),
    Vector(Vec<f64>),
}

impl std::fmt::Display for Constant {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Constant::Float(x) => write!(f, "{}", number(*x)),
            Constant::Vector(v) => {
                let parts: Vec<String> = v.iter().map(|x| number(*x)).collect();
                write!(f, "<{}>", parts.join(", "))
            }
        }
    }
}

fn number(x: f64) -> String {
    if x == x.trunc() && x.abs() < 1e15 {
        format!("{}", x as i64)
    } else {
        format!("{x}")
    }
}

/// Folds an expression of numbers, vectors, `pi`, `x`/`y`/`z` and arithmetic.
pub fn fold(node: &SyntaxNode) -> Option<Constant> {
    match node.kind() {
        LITERAL => {
            let token = node.first_token()?;
            match token.kind() {
                NUMBER => token.text().parse().ok().map(Constant::Float),
                PI_KW => Some(Constant::Float(std::f64::consts::PI)),
                TAU_KW => Some(Constant::Float(std::f64::consts::TAU)),
                TRUE_KW | YES_KW | ON_KW => Some(Constant::Float(1.0)),
                FALSE_KW | NO_KW | OFF_KW => Some(Constant::Float(0.0)),
                X_KW => Some(Constant::Vector(vec![1.0, 0.0, 0.0])),
                Y_KW => Some(Constant::Vector(vec![0.0, 1.0, 0.0])),
                Z_KW => Some(Constant::Vector(vec![0.0, 0.0, 1.0])),
                _ => None,
            }
        }
        PAREN_EXPR => fold(&node.children().next()?),
        VECTOR => {
            let parts: Option<Vec<f64>> = node
                .children()
                .map(|c| match fold(&c)? {
                    Constant::Float(x) => Some(x),
                    Constant::Vector(_) => None,
                })
                .collect();
            parts
                .filter(|p| (2..=5).contains(&p.len()))
                .map(Constant::Vector)
        }
        PREFIX_EXPR => {
            let operator = significant_tokens(node).next()?.kind();
            let operand = fold(&node.children().next()?)?;
            match operator {
                MINUS => Some(map(operand, |x| -x)),
                PLUS => Some(operand),
                _ => None,
            }
        }
        BIN_EXPR => {
            let mut operands = node.children();
            let left = fold(&operands.next()?)?;
            let right = fold(&operands.next()?)?;
            let operator = significant_tokens(node)
                .find(|t| matches!(t.kind(), PLUS | MINUS | STAR | SLASH))?
                .kind();
            let apply = |a: f64, b: f64| match operator {
                PLUS => a + b,
                MINUS => a - b,
                STAR => a * b,
                _ => a / b,
            };
            if operator == SLASH && matches!(right, Constant::Float(d) if d == 0.0) {
                return None;
            }
            Some(match (left, right) {
                (Constant::Float(a), Constant::Float(b)) => Constant::Float(apply(a, b)),
                (Constant::Vector(a), Constant::Float(b)) => {
                    Constant::Vector(a.iter().map(|&x| apply(x, b)).collect())
                }
                (Constant::Float(a), Constant::Vector(b)) => {
                    Constant::Vector(b.iter().map(|&x| apply(a, x)).collect())
                }
                (Constant::Vector(a), Constant::Vector(b)) if a.len() == b.len() => {
                    Constant::Vector(a.iter().zip(&b).map(|(&x, &y)| apply(x, y)).collect())
                }
                _ => return None,
            })
        }
        _ => None,
    }
}

fn map(constant: Constant, f: impl Fn(f64) -> f64) -> Constant {
    match constant {
        Constant::Float(x) => Constant::Float(f(x)),
        Constant::Vector(v) => Constant::Vector(v.into_iter().map(f).collect()),
    }
}

fn significant_tokens(node: &SyntaxNode) -> impl Iterator<Item = SyntaxToken> + use<> {
    node.children_with_tokens()
        .filter_map(|e| e.into_token())
        .filter(|t| !t.kind().is_trivia())
}
