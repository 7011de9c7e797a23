//! The request Typst sends: the package's `lib.typ` encodes
//! `(scene: str, includes: (name: str), files: (name: bytes), options: (str,), extra: (str,))`
//! with `cbor.encode`, and this module decodes it. `options` are the POV-Ray options that
//! `lib.typ` derived from its keyword arguments; `extra` are the caller's own option strings,
//! applied after them so that they win.

use minicbor::Decoder;
use minicbor::bytes::ByteSlice;

/// One render as Typst asked for it.
#[derive(Debug, Default, Clone, PartialEq)]
pub struct Request {
    /// The main scene's text.
    pub scene: String,
    /// Include files by the name the scene's `#include` uses.
    pub includes: Vec<(String, String)>,
    /// Binary assets (image maps, fonts, data files) by name.
    pub files: Vec<(String, Vec<u8>)>,
    /// POV-Ray options derived from the package's keyword arguments.
    pub options: Vec<String>,
    /// POV-Ray options the caller passed through `extra`.
    pub extra: Vec<String>,
}

impl Request {
    /// Decodes the CBOR map `lib.typ` sends. Typst's encoder writes definite lengths only.
    pub fn decode(bytes: &[u8]) -> Result<Request, String> {
        let mut d = Decoder::new(bytes);
        let entries = d
            .map()
            .map_err(|e| malformed("the request", e))?
            .ok_or("malformed request: the request must be a map of definite length")?;
        let mut request = Request::default();
        let mut have_scene = false;
        for _ in 0..entries {
            let key = d.str().map_err(|e| malformed("a request key", e))?;
            match key {
                "scene" => {
                    request.scene = d.str().map_err(|e| malformed("scene", e))?.to_owned();
                    have_scene = true;
                }
                "includes" => request.includes = text_map(&mut d, "includes")?,
                "files" => request.files = bytes_map(&mut d, "files")?,
                "options" => request.options = text_array(&mut d, "options")?,
                "extra" => request.extra = text_array(&mut d, "extra")?,
                other => return Err(format!("malformed request: unknown key `{other}`")),
            }
        }
        if d.position() != bytes.len() {
            return Err("malformed request: bytes after the request map".into());
        }
        if !have_scene {
            return Err("malformed request: no `scene`".into());
        }
        Ok(request)
    }
}

fn text_map(d: &mut Decoder<'_>, what: &str) -> Result<Vec<(String, String)>, String> {
    d.map_iter::<&str, &str>()
        .map_err(|e| malformed(what, e))?
        .map(|entry| {
            entry
                .map(|(k, v)| (k.to_owned(), v.to_owned()))
                .map_err(|e| malformed(what, e))
        })
        .collect()
}

fn bytes_map(d: &mut Decoder<'_>, what: &str) -> Result<Vec<(String, Vec<u8>)>, String> {
    d.map_iter::<&str, &ByteSlice>()
        .map_err(|e| malformed(what, e))?
        .map(|entry| {
            entry
                .map(|(k, v)| (k.to_owned(), v.to_vec()))
                .map_err(|e| malformed(what, e))
        })
        .collect()
}

fn text_array(d: &mut Decoder<'_>, what: &str) -> Result<Vec<String>, String> {
    d.array_iter::<&str>()
        .map_err(|e| malformed(what, e))?
        .map(|item| item.map(str::to_owned).map_err(|e| malformed(what, e)))
        .collect()
}

fn malformed(what: &str, error: minicbor::decode::Error) -> String {
    format!("malformed request: {what}: {error}")
}

#[cfg(test)]
mod tests {
    use super::*;
    use minicbor::Encoder;

    /// Encodes a request the way Typst's `cbor.encode` does: a definite-length map with
    /// text keys, in the order the dictionary was written.
    fn typst_like(scene: &str, extra_key: Option<&str>) -> Vec<u8> {
        let mut e = Encoder::new(Vec::new());
        let entries = 5 + u64::from(extra_key.is_some());
        e.map(entries).unwrap();
        e.str("scene").unwrap().str(scene).unwrap();
        e.str("includes").unwrap().map(1).unwrap();
        e.str("materials.inc")
            .unwrap()
            .str("#declare M = 1;")
            .unwrap();
        e.str("files").unwrap().map(1).unwrap();
        e.str("map.png").unwrap().bytes(&[137, 80, 78, 71]).unwrap();
        e.str("options").unwrap().array(2).unwrap();
        e.str("Width=32").unwrap().str("Antialias=off").unwrap();
        e.str("extra")
            .unwrap()
            .array(1)
            .unwrap()
            .str("+A0.1")
            .unwrap();
        if let Some(key) = extra_key {
            e.str(key).unwrap().null().unwrap();
        }
        e.into_writer()
    }

    #[test]
    fn decodes_every_field() {
        let request = Request::decode(&typst_like("sphere { 0, 1 }", None)).unwrap();
        assert_eq!(
            request,
            Request {
                scene: "sphere { 0, 1 }".into(),
                includes: vec![("materials.inc".into(), "#declare M = 1;".into())],
                files: vec![("map.png".into(), vec![137, 80, 78, 71])],
                options: vec!["Width=32".into(), "Antialias=off".into()],
                extra: vec!["+A0.1".into()],
            }
        );
    }

    #[test]
    fn the_scene_alone_is_enough() {
        let mut e = Encoder::new(Vec::new());
        e.map(1).unwrap().str("scene").unwrap().str("").unwrap();
        assert_eq!(Request::decode(&e.into_writer()), Ok(Request::default()));
    }

    #[test]
    fn malformed_requests_are_errors_not_panics() {
        assert_eq!(
            Request::decode(&typst_like("", Some("colour"))),
            Err("malformed request: unknown key `colour`".into())
        );
        let mut e = Encoder::new(Vec::new());
        e.map(1).unwrap().str("includes").unwrap().map(0).unwrap();
        assert_eq!(
            Request::decode(&e.into_writer()),
            Err("malformed request: no `scene`".into())
        );
        let mut e = Encoder::new(Vec::new());
        e.map(1).unwrap().str("scene").unwrap().u8(3).unwrap();
        assert!(
            Request::decode(&e.into_writer())
                .unwrap_err()
                .starts_with("malformed request: scene:")
        );
        let full = typst_like("camera {}", None);
        for cut in 0..full.len() {
            assert!(Request::decode(&full[..cut]).is_err(), "truncated at {cut}");
        }
    }
}
