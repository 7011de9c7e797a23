//! The answer the plugin hands back to Typst, as a CBOR map that `lib.typ` reads with `cbor`.
//!
//! A scene's own errors travel inside the answer (`error: str`) rather than as a plugin
//! error, so that `try-render` can show them as text; `render` raises them. Pixels are raw
//! 8-bit samples for `image(..., format: (encoding: "rgba8" | "rgb8", ..))`: encoding a PNG
//! inside the wasm interpreter cost 2.7 s against 0.16 s for raw samples on nine 600x400
//! images, so Typst gets raw samples and compresses them itself when it writes the PDF.

use minicbor::Encoder;

/// What came of a render request.
#[derive(Debug, Clone, PartialEq)]
pub struct Response {
    pub outcome: Result<Pixels, String>,
    /// `#debug` output, in the order the scene produced it.
    pub messages: Vec<Message>,
    /// Warning diagnostics (gcc-style text), empty when there are none.
    pub warnings: String,
}

/// An image as rows of 8-bit samples, top row first.
#[derive(Debug, Clone, PartialEq)]
pub struct Pixels {
    pub width: u32,
    pub height: u32,
    pub encoding: Encoding,
    pub samples: Vec<u8>,
}

/// The sample layout, named as Typst's `image` format names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Encoding {
    Rgb8,
    Rgba8,
}

impl Encoding {
    pub fn name(self) -> &'static str {
        match self {
            Encoding::Rgb8 => "rgb8",
            Encoding::Rgba8 => "rgba8",
        }
    }
}

/// Text a scene printed with `#debug`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Message {
    /// The stream's name: `"debug"`.
    pub stream: &'static str,
    pub text: String,
}

impl Response {
    /// An answer with an error and nothing else.
    pub fn error(text: String) -> Response {
        Response {
            outcome: Err(text),
            messages: Vec::new(),
            warnings: String::new(),
        }
    }

    pub fn encode(&self) -> Vec<u8> {
        let mut e = Encoder::new(Vec::new());
        self.write(&mut e)
            .expect("writing CBOR into a Vec cannot fail");
        e.into_writer()
    }

    fn write(
        &self,
        e: &mut Encoder<Vec<u8>>,
    ) -> Result<(), minicbor::encode::Error<core::convert::Infallible>> {
        let outcome_entries = match &self.outcome {
            Ok(_) => 4,
            Err(_) => 1,
        };
        e.map(outcome_entries + 2)?;
        match &self.outcome {
            Ok(pixels) => {
                e.str("width")?.u32(pixels.width)?;
                e.str("height")?.u32(pixels.height)?;
                e.str("encoding")?.str(pixels.encoding.name())?;
                e.str("pixels")?.bytes(&pixels.samples)?;
            }
            Err(text) => {
                e.str("error")?.str(text)?;
            }
        }
        e.str("messages")?.array(self.messages.len() as u64)?;
        for message in &self.messages {
            e.map(2)?;
            e.str("stream")?.str(message.stream)?;
            e.str("text")?.str(&message.text)?;
        }
        e.str("warnings")?.str(&self.warnings)?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use expect_test::expect;
    use minicbor::data::Token;

    fn tokens(bytes: &[u8]) -> String {
        minicbor::Decoder::new(bytes)
            .tokens()
            .map(|t| match t.unwrap() {
                Token::String(s) => format!("{s:?}"),
                other => other.to_string(),
            })
            .collect::<Vec<_>>()
            .join(" ")
    }

    #[test]
    fn an_image_with_its_messages() {
        let response = Response {
            outcome: Ok(Pixels {
                width: 2,
                height: 1,
                encoding: Encoding::Rgba8,
                samples: vec![255, 0, 0, 255, 0, 0, 0, 0],
            }),
            messages: vec![Message {
                stream: "debug",
                text: "n = 3\n".into(),
            }],
            warnings: String::new(),
        };
        expect![[r#"M[6] "width" 2 "height" 1 "encoding" "rgba8" "pixels" h'ff 00 00 ff 00 00 00 00' "messages" A[1] M[2] "stream" "debug" "text" "n = 3\n" "warnings" """#]]
            .assert_eq(&tokens(&response.encode()));
    }

    #[test]
    fn an_error_keeps_the_messages_before_it() {
        let response = Response {
            outcome: Err("scene.pov:1:1: error: stop\n".into()),
            messages: vec![Message {
                stream: "debug",
                text: "before the error".into(),
            }],
            warnings: "scene.pov:1:1: warning: no #version\n".into(),
        };
        expect![[r#"M[3] "error" "scene.pov:1:1: error: stop\n" "messages" A[1] M[2] "stream" "debug" "text" "before the error" "warnings" "scene.pov:1:1: warning: no #version\n""#]]
            .assert_eq(&tokens(&response.encode()));
    }
}
