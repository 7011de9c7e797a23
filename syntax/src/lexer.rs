//! Splits SDL source text into tokens, losing nothing: the token texts concatenate to
//! the input. Malformed input becomes `ERROR` tokens plus a [`LexError`]; lexing never fails.

use crate::SyntaxKind::{self, *};
use rowan::{TextRange, TextSize};

/// One token: its kind and where it stands in the source.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Token {
    pub kind: SyntaxKind,
    pub range: TextRange,
}

/// A problem found while lexing, such as an unterminated string.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LexError {
    pub range: TextRange,
    pub message: String,
}

/// The tokens of one source text and the errors found on the way.
#[derive(Debug, Clone, Default)]
pub struct Lexed {
    pub tokens: Vec<Token>,
    pub errors: Vec<LexError>,
}

/// Lexes a whole source text.
pub fn lex(text: &str) -> Lexed {
    let mut lexer = Lexer {
        bytes: text.as_bytes(),
        text,
        pos: 0,
        out: Lexed {
            tokens: Vec::with_capacity(text.len() / 3),
            errors: Vec::new(),
        },
    };
    lexer.run();
    lexer.out
}

struct Lexer<'a> {
    bytes: &'a [u8],
    text: &'a str,
    pos: usize,
    out: Lexed,
}

impl Lexer<'_> {
    fn run(&mut self) {
        if self.text.starts_with('\u{feff}') {
            self.pos = 3;
            self.push(BYTE_ORDER_MARK, 0);
        }
        while self.pos < self.bytes.len() {
            let start = self.pos;
            let kind = self.next_kind();
            self.push(kind, start);
        }
    }

    fn push(&mut self, kind: SyntaxKind, start: usize) {
        let range = TextRange::new(offset(start), offset(self.pos));
        self.out.tokens.push(Token { kind, range });
    }

    fn error(&mut self, start: usize, end: usize, message: impl Into<String>) {
        self.out.errors.push(LexError {
            range: TextRange::new(offset(start), offset(end)),
            message: message.into(),
        });
    }

    fn peek(&self, ahead: usize) -> u8 {
        self.bytes.get(self.pos + ahead).copied().unwrap_or(0)
    }

    fn eat_while(&mut self, pred: impl Fn(u8) -> bool) {
        while self.pos < self.bytes.len() && pred(self.bytes[self.pos]) {
            self.pos += 1;
        }
    }

    fn next_kind(&mut self) -> SyntaxKind {
        let start = self.pos;
        let b = self.bytes[self.pos];
        self.pos += 1;
        match b {
            b' ' | b'\t' | b'\r' | b'\n' | b'\x0b' | b'\x0c' => {
                self.eat_while(|b| matches!(b, b' ' | b'\t' | b'\r' | b'\n' | b'\x0b' | b'\x0c'));
                WHITESPACE
            }
            b'/' if self.peek(0) == b'/' => {
                self.eat_while(|b| b != b'\n' && b != b'\r');
                LINE_COMMENT
            }
            b'/' if self.peek(0) == b'*' => self.block_comment(start),
            b'"' => self.string(start),
            b'0'..=b'9' => {
                self.number_rest();
                NUMBER
            }
            b'.' if self.peek(0).is_ascii_digit() => {
                self.eat_while(|b| b.is_ascii_digit());
                self.exponent();
                NUMBER
            }
            b'a'..=b'z' | b'A'..=b'Z' | b'_' => {
                self.eat_while(|b| b.is_ascii_alphanumeric() || b == b'_');
                SyntaxKind::from_keyword(&self.text[start..self.pos]).unwrap_or(IDENT)
            }
            b'{' => L_BRACE,
            b'}' => R_BRACE,
            b'(' => L_PAREN,
            b')' => R_PAREN,
            b'[' => L_BRACK,
            b']' => R_BRACK,
            b'<' if self.peek(0) == b'=' => {
                self.pos += 1;
                LT_EQ
            }
            b'>' if self.peek(0) == b'=' => {
                self.pos += 1;
                GT_EQ
            }
            b'!' if self.peek(0) == b'=' => {
                self.pos += 1;
                NEQ
            }
            b'<' => LT,
            b'>' => GT,
            b'=' => EQ,
            b'+' => PLUS,
            b'-' => MINUS,
            b'*' => STAR,
            b'/' => SLASH,
            b',' => COMMA,
            b';' => SEMICOLON,
            b':' => COLON,
            b'?' => QUESTION,
            b'.' => DOT,
            b'&' => AMP,
            b'|' => PIPE,
            b'!' => BANG,
            b'#' => HASH,
            _ => {
                // Step over the whole character so that ranges stay on char boundaries.
                let width = self.text[start..].chars().next().map_or(1, char::len_utf8);
                self.pos = start + width;
                let ch = &self.text[start..self.pos];
                self.error(
                    start,
                    self.pos,
                    format!("unexpected character '{}'", ch.escape_debug()),
                );
                ERROR
            }
        }
    }

    fn number_rest(&mut self) {
        self.eat_while(|b| b.is_ascii_digit());
        if self.peek(0) == b'.' && self.peek(1).is_ascii_digit() {
            self.pos += 1;
            self.eat_while(|b| b.is_ascii_digit());
        } else if self.peek(0) == b'.'
            && !self.peek(1).is_ascii_alphabetic()
            && self.peek(1) != b'_'
        {
            // `1.` is a number, but `1.x` is not `1.` followed by `x`.
            self.pos += 1;
        }
        self.exponent();
    }

    fn exponent(&mut self) {
        if matches!(self.peek(0), b'e' | b'E') {
            let digits_at = if matches!(self.peek(1), b'+' | b'-') {
                2
            } else {
                1
            };
            if self.peek(digits_at).is_ascii_digit() {
                self.pos += digits_at;
                self.eat_while(|b| b.is_ascii_digit());
            }
        }
    }

    fn block_comment(&mut self, start: usize) -> SyntaxKind {
        self.pos += 1;
        let mut depth = 1usize;
        while self.pos < self.bytes.len() {
            match (self.bytes[self.pos], self.peek(1)) {
                (b'/', b'*') => {
                    depth += 1;
                    self.pos += 2;
                }
                (b'*', b'/') => {
                    depth -= 1;
                    self.pos += 2;
                    if depth == 0 {
                        return BLOCK_COMMENT;
                    }
                }
                _ => self.pos += 1,
            }
        }
        self.error(start, start + 2, "unterminated block comment");
        BLOCK_COMMENT
    }

    /// A string runs to its closing quote, across line breaks as in POV-Ray. One that
    /// is never closed ends at its first line break, so that a missing quote at the end
    /// does not swallow the rest of the file.
    fn string(&mut self, start: usize) -> SyntaxKind {
        let mut first_line_break = None;
        while self.pos < self.bytes.len() {
            match self.bytes[self.pos] {
                b'"' => {
                    self.pos += 1;
                    return STRING;
                }
                b'\\'
                    if self.pos + 1 < self.bytes.len()
                        && !matches!(self.peek(1), b'\n' | b'\r') =>
                {
                    self.pos += 1;
                    let width = self.text[self.pos..]
                        .chars()
                        .next()
                        .map_or(1, char::len_utf8);
                    self.pos += width;
                }
                b'\n' | b'\r' => {
                    first_line_break.get_or_insert(self.pos);
                    self.pos += 1;
                }
                _ => self.pos += 1,
            }
        }
        if let Some(line_break) = first_line_break {
            self.pos = line_break;
        }
        self.error(start, self.pos, "unterminated string");
        STRING
    }
}

fn offset(pos: usize) -> TextSize {
    TextSize::try_from(pos).unwrap_or(TextSize::new(u32::MAX))
}

/// The value of a string literal's text (quotes included), with escapes resolved.
/// Unknown escapes keep their character, as POV-Ray does, and are reported.
pub fn unescape_string(literal: &str) -> (String, Vec<(TextRange, String)>) {
    let inner_end = if literal.len() >= 2 && literal.ends_with('"') {
        literal.len() - 1
    } else {
        literal.len()
    };
    let inner = literal.get(1..inner_end).unwrap_or("");
    let mut value = String::with_capacity(inner.len());
    let mut problems = Vec::new();
    let mut chars = inner.char_indices();
    while let Some((i, c)) = chars.next() {
        if c != '\\' {
            value.push(c);
            continue;
        }
        let Some((_, e)) = chars.next() else {
            value.push('\\');
            break;
        };
        match e {
            'a' => value.push('\u{7}'),
            'b' => value.push('\u{8}'),
            'f' => value.push('\u{c}'),
            'n' => value.push('\n'),
            'r' => value.push('\r'),
            't' => value.push('\t'),
            'v' => value.push('\u{b}'),
            '0' => value.push('\0'),
            '\\' | '"' | '\'' => value.push(e),
            'u' => {
                // \uXXXX: a Unicode code point in four hex digits.
                let hex: String = chars.clone().take(4).map(|(_, c)| c).collect();
                match u32::from_str_radix(&hex, 16)
                    .ok()
                    .filter(|_| hex.len() == 4)
                    .and_then(char::from_u32)
                {
                    Some(c) => {
                        value.push(c);
                        for _ in 0..4 {
                            chars.next();
                        }
                    }
                    None => {
                        problems.push((
                            TextRange::at(offset(i + 1), TextSize::of("\\u")),
                            "expected four hex digits after \\u".to_owned(),
                        ));
                        value.push_str("\\u");
                    }
                }
            }
            other => {
                let at = offset(i + 1);
                problems.push((
                    TextRange::at(at, TextSize::of("\\") + TextSize::of(other)),
                    format!("unknown escape sequence '\\{other}'"),
                ));
                value.push('\\');
                value.push(other);
            }
        }
    }
    (value, problems)
}

#[cfg(test)]
mod tests {
    use super::*;
    use expect_test::{Expect, expect};
    use std::fmt::Write;

    fn check(input: &str, expect: Expect) {
        let lexed = lex(input);
        let mut out = String::new();
        for t in &lexed.tokens {
            writeln!(out, "{:?} {:?}", t.kind, &input[t.range]).unwrap();
        }
        for e in &lexed.errors {
            writeln!(out, "error {:?}: {}", e.range, e.message).unwrap();
        }
        expect.assert_eq(&out);
        let joined: String = lexed.tokens.iter().map(|t| &input[t.range]).collect();
        assert_eq!(joined, input, "lexing must be lossless");
    }

    #[test]
    fn numbers() {
        check(
            "1 .5 1e-3 2.5E+2 3. 1.x 7e",
            expect![[r#"
                NUMBER "1"
                WHITESPACE " "
                NUMBER ".5"
                WHITESPACE " "
                NUMBER "1e-3"
                WHITESPACE " "
                NUMBER "2.5E+2"
                WHITESPACE " "
                NUMBER "3."
                WHITESPACE " "
                NUMBER "1"
                DOT "."
                X_KW "x"
                WHITESPACE " "
                NUMBER "7"
                IDENT "e"
            "#]],
        );
    }

    #[test]
    fn comments_nest_and_directives_split() {
        check(
            "/* a /* b */ c */#declare // end\nR=<1,2>;",
            expect![[r##"
                BLOCK_COMMENT "/* a /* b */ c */"
                HASH "#"
                DECLARE_KW "declare"
                WHITESPACE " "
                LINE_COMMENT "// end"
                WHITESPACE "\n"
                IDENT "R"
                EQ "="
                LT "<"
                NUMBER "1"
                COMMA ","
                NUMBER "2"
                GT ">"
                SEMICOLON ";"
            "##]],
        );
    }

    #[test]
    fn malformed_input_becomes_error_tokens() {
        check(
            "\u{feff}a @ \"open\nb /* never",
            expect![[r#"
                BYTE_ORDER_MARK "\u{feff}"
                IDENT "a"
                WHITESPACE " "
                ERROR "@"
                WHITESPACE " "
                STRING "\"open"
                WHITESPACE "\n"
                IDENT "b"
                WHITESPACE " "
                BLOCK_COMMENT "/* never"
                error 5..6: unexpected character '@'
                error 7..12: unterminated string
                error 15..17: unterminated block comment
            "#]],
        );
    }

    #[test]
    fn operators() {
        check(
            "a<=b>=c!=d&e|!f?g:h",
            expect![[r#"
                IDENT "a"
                LT_EQ "<="
                IDENT "b"
                GT_EQ ">="
                IDENT "c"
                NEQ "!="
                IDENT "d"
                AMP "&"
                IDENT "e"
                PIPE "|"
                BANG "!"
                IDENT "f"
                QUESTION "?"
                IDENT "g"
                COLON ":"
                IDENT "h"
            "#]],
        );
    }

    #[test]
    fn string_escapes() {
        let (value, problems) = unescape_string(r#""a\"b\\c\nd\q""#);
        assert_eq!(value, "a\"b\\c\nd\\q");
        assert_eq!(problems.len(), 1);
        assert_eq!(problems[0].1, "unknown escape sequence '\\q'");
    }

    #[test]
    fn strings_span_lines() {
        check(
            "\"a\nb\" \"open\nc",
            expect![[r#"
                STRING "\"a\nb\""
                WHITESPACE " "
                STRING "\"open"
                WHITESPACE "\n"
                IDENT "c"
                error 6..11: unterminated string
            "#]],
        );
    }

    #[test]
    fn unicode_in_strings_and_comments() {
        let lexed = lex("// é\n\"ü\" ä");
        let kinds: Vec<_> = lexed.tokens.iter().map(|t| t.kind).collect();
        assert_eq!(kinds, [LINE_COMMENT, WHITESPACE, STRING, WHITESPACE, ERROR]);
    }
}
