//! `#fopen`, `#read`, `#write` and `#fclose` over a virtual file system: files are read
//! through the evaluation's [`FileSource`](crate::files::FileSource) and written into the
//! evaluation's output map, so a scene can write a file and read it back. The CLI decides
//! whether written files reach the disk.

use super::tokens::Token;
use super::value::{Terms, Value};
use super::{Evaluator, Result};
use std::cell::RefCell;
use std::rc::Rc;
use syntax::SyntaxKind::*;

/// An open file: its name, and for reading, its text and how far it has been read.
#[derive(Debug, Clone, PartialEq)]
pub struct OpenFile {
    pub name: String,
    pub reading: Option<(std::sync::Arc<str>, usize)>,
}

impl Evaluator<'_> {
    /// `#fopen Handle "name" read|write|append`, after `fopen`.
    pub fn fopen(&mut self) -> Result<()> {
        let handle = self.next_raw()?;
        if handle.kind != IDENT {
            return Err(self.error_at(
                &handle,
                format!(
                    "expected a file handle identifier, found {}",
                    self.describe(&handle)
                ),
            ));
        }
        let name = self.string()?;
        let mode = self.next()?;
        let reading = match mode.kind {
            READ_KW => {
                // What this scene wrote earlier wins over what the file source holds.
                let written = self
                    .written
                    .get(&name)
                    .map(|t| std::sync::Arc::from(t.as_str()));
                let text = written.or_else(|| self.source.read(&name));
                let Some(text) = text else {
                    return Err(self.error_at(
                        &mode,
                        format!("cannot open '{name}' for reading: no such file"),
                    ));
                };
                Some((text, 0))
            }
            WRITE_KW => {
                self.written.insert(name.clone(), String::new());
                None
            }
            APPEND_KW => {
                self.written.entry(name.clone()).or_default();
                None
            }
            _ => {
                return Err(self.error_at(
                    &mode,
                    format!(
                        "expected read, write or append, found {}",
                        self.describe(&mode)
                    ),
                ));
            }
        };
        let handle_name = self.text(&handle).to_owned();
        let file = Value::File(Rc::new(RefCell::new(OpenFile { name, reading })));
        self.define_global(&handle_name, file);
        Ok(())
    }

    /// `#fclose Handle`, after `fclose`.
    pub fn fclose(&mut self) -> Result<()> {
        let handle = self.next_raw()?;
        let name = self.text(&handle).to_owned();
        match self.lookup(&name).map(|slot| slot.borrow().clone()) {
            Some(Value::File(_)) => {
                self.undef(&name);
                Ok(())
            }
            Some(other) => Err(self.error_at(
                &handle,
                format!("'{name}' is a {}, not a file", other.type_name()),
            )),
            // A file read to its end is already closed; closing it again is harmless.
            None => Ok(()),
        }
    }

    /// `#write (Handle, item, ...)`, after `write`.
    pub fn write_directive(&mut self) -> Result<()> {
        self.expect(L_PAREN, "'('")?;
        let (handle, file) = self.file_handle()?;
        let mut text = String::new();
        // Commas between the items are optional, as everywhere in POV-Ray's argument lists.
        while !self.eat(R_PAREN)? {
            self.eat(COMMA)?;
            let at = self.next()?;
            if matches!(
                at.kind,
                UINT8_KW
                    | SINT8_KW
                    | UINT16BE_KW
                    | UINT16LE_KW
                    | SINT16BE_KW
                    | SINT16LE_KW
                    | SINT32BE_KW
                    | SINT32LE_KW
            ) {
                return Err(self.unsupported(&at, "binary #write"));
            }
            self.unget(at.clone());
            match self.value_in_parens()? {
                Value::String(s) => text.push_str(&s),
                Value::Float(v) => text.push_str(&format_g(v)),
                Value::Vector(t) | Value::Colour(t) => {
                    let parts: Vec<String> = t.as_slice().iter().map(|&c| format_g(c)).collect();
                    text.push_str(&format!("<{}> ", parts.join(",")));
                }
                other => {
                    return Err(
                        self.error_at(&at, format!("cannot #write a {}", other.type_name()))
                    );
                }
            }
        }
        let name = file.borrow().name.clone();
        if file.borrow().reading.is_some() {
            return Err(self.error_at(
                &handle,
                format!("'{name}' is open for reading, not writing"),
            ));
        }
        self.written.entry(name).or_default().push_str(&text);
        Ok(())
    }

    /// `#read (Handle, Var, ...)`, after `read`. At the end of the file the handle is
    /// undefined, which is how scenes detect it.
    pub fn read_directive(&mut self) -> Result<()> {
        self.expect(L_PAREN, "'('")?;
        let (handle, file) = self.file_handle()?;
        let handle_name = self.text(&handle).to_owned();
        while !self.eat(R_PAREN)? {
            self.eat(COMMA)?;
            let target = self.next_raw()?;
            if target.kind != IDENT {
                return Err(self.error_at(
                    &target,
                    format!(
                        "expected an identifier to read into, found {}",
                        self.describe(&target)
                    ),
                ));
            }
            let item = {
                let mut open = file.borrow_mut();
                let Some((text, pos)) = &mut open.reading else {
                    return Err(
                        self.error_at(&handle, "this file is open for writing, not reading")
                    );
                };
                read_item(text, pos)
            };
            match item {
                Ok(Some(value)) => {
                    let name = self.text(&target).to_owned();
                    match self.lookup(&name) {
                        Some(slot) => *slot.borrow_mut() = value,
                        None => self.declare(&name, value),
                    }
                    // Reading the last item closes the file at once (measured against
                    // POV-Ray 3.7), so `defined(Handle)` is false right after it.
                    let at_end = match &file.borrow().reading {
                        Some((text, pos)) => text[*pos..]
                            .trim_start_matches(|c: char| c.is_whitespace() || c == ',')
                            .is_empty(),
                        None => false,
                    };
                    if at_end {
                        self.undef(&handle_name);
                    }
                }
                Ok(None) => {
                    self.undef(&handle_name);
                    while !self.eat(R_PAREN)? {
                        self.next_raw()?;
                    }
                    return Ok(());
                }
                Err(message) => return Err(self.error_at(&target, format!("#read: {message}"))),
            }
        }
        Ok(())
    }

    fn file_handle(&mut self) -> Result<(Token, Rc<RefCell<OpenFile>>)> {
        let handle = self.next()?;
        match handle.slot.as_ref().map(|s| s.borrow().clone()) {
            Some(Value::File(file)) => Ok((handle, file)),
            _ => Err(self.error_at(
                &handle,
                format!(
                    "expected an open file handle, found {}",
                    self.describe(&handle)
                ),
            )),
        }
    }
}

/// Reads the next comma-separated literal (string, float or vector) of a data file.
fn read_item(text: &str, pos: &mut usize) -> std::result::Result<Option<Value>, String> {
    let rest = &text[*pos..];
    let skipped = rest.len()
        - rest
            .trim_start_matches(|c: char| c.is_whitespace() || c == ',')
            .len();
    *pos += skipped;
    let rest = &text[*pos..];
    let Some(first) = rest.chars().next() else {
        return Ok(None);
    };
    let value = if first == '"' {
        let end = rest[1..]
            .find('"')
            .ok_or("unterminated string in the data file")?
            + 2;
        let (value, _) = syntax::lexer::unescape_string(&rest[..end]);
        *pos += end;
        Value::String(value.into())
    } else if first == '<' {
        let end = rest
            .find('>')
            .ok_or("unterminated vector in the data file")?;
        let parts: std::result::Result<Vec<f64>, _> = rest[1..end]
            .split(',')
            .map(|p| p.trim().parse::<f64>())
            .collect();
        let parts = parts.map_err(|_| format!("malformed vector '{}'", &rest[..=end]))?;
        if !(2..=5).contains(&parts.len()) {
            return Err(format!(
                "a vector has 2 to 5 components, not {}",
                parts.len()
            ));
        }
        *pos += end + 1;
        Value::Vector(Terms::new(&parts))
    } else {
        let end = rest
            .find(|c: char| c == ',' || c.is_whitespace())
            .unwrap_or(rest.len());
        let number = rest[..end]
            .parse::<f64>()
            .map_err(|_| format!("expected a number, found '{}'", &rest[..end]))?;
        *pos += end;
        Value::Float(number)
    };
    Ok(Some(value))
}

/// C's `%g`: six significant digits, exponent notation for very large or small values.
pub fn format_g(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return if v.is_nan() {
            "nan".into()
        } else if v.is_infinite() {
            if v > 0.0 { "inf".into() } else { "-inf".into() }
        } else {
            "0".into()
        };
    }
    let exponent = v.abs().log10().floor() as i32;
    let trim = |s: String| -> String {
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_owned()
        } else {
            s
        }
    };
    let rounded_exponent = {
        let scientific = format!("{v:.5e}");
        scientific
            .split('e')
            .nth(1)
            .and_then(|e| e.parse::<i32>().ok())
            .unwrap_or(exponent)
    };
    if !(-4..6).contains(&rounded_exponent) {
        let scientific = format!("{v:.5e}");
        let (mantissa, exp) = scientific.split_once('e').unwrap_or((&scientific, "0"));
        let exp: i32 = exp.parse().unwrap_or(0);
        let sign = if exp < 0 { '-' } else { '+' };
        format!("{}e{sign}{:02}", trim(mantissa.to_owned()), exp.abs())
    } else {
        let decimals = (5 - rounded_exponent).max(0) as usize;
        trim(format!("{v:.decimals$}"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn g_format_matches_c() {
        assert_eq!(format_g(-123.45), "-123.45");
        assert_eq!(format_g(1.0 / 3.0), "0.333333");
        assert_eq!(format_g(1e20), "1e+20");
        assert_eq!(format_g(0.000001), "1e-06");
        assert_eq!(format_g(42.0), "42");
        assert_eq!(format_g(999999.5), "1e+06");
        assert_eq!(format_g(0.0001), "0.0001");
    }

    #[test]
    fn data_items_are_read_in_turn() {
        let text = "\"A quote\", -123.45, <1,2,-3>\n";
        let mut pos = 0;
        assert_eq!(
            read_item(text, &mut pos),
            Ok(Some(Value::String("A quote".into())))
        );
        assert_eq!(read_item(text, &mut pos), Ok(Some(Value::Float(-123.45))));
        assert_eq!(
            read_item(text, &mut pos),
            Ok(Some(Value::Vector(Terms::new(&[1.0, 2.0, -3.0]))))
        );
        assert_eq!(read_item(text, &mut pos), Ok(None));
    }
}
