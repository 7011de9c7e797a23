//! Where scene and include texts, and the binary files a scene reads (images, fonts), come
//! from. The evaluator never touches the file system itself: the CLI supplies files from its
//! search paths, the Typst plugin from the document's `includes` and `files`, tests from
//! memory. The standard includes are found last.

use std::collections::BTreeMap;
use std::sync::Arc;
use syntax::SourceResolver;

/// Supplies file texts by the name a scene uses for them.
pub trait FileSource {
    /// The text of `name`, or `None` when this source does not have it.
    fn read(&self, name: &str) -> Option<Arc<str>>;
    /// The bytes of `name` (an image, a height field, a font), found by the same rules as
    /// `read`, or `None` when this source does not have it.
    fn read_bytes(&self, name: &str) -> Option<Arc<[u8]>>;
    /// Every name this source can supply: "cannot find" errors list those of the missing
    /// file's kind.
    fn names(&self) -> Vec<String>;
    /// The syntax tree of `name`'s text when this source already holds one (the language
    /// server's database does), so that checking and linting need not parse it again.
    /// `None` lets the caller parse the text [`FileSource::read`] gives.
    fn parse(&self, _name: &str) -> Option<syntax::Parse> {
        None
    }
}

/// The text of an SDL file's bytes, and whether they were read as Latin-1. POV-Ray reads
/// bytes, and scenes and includes written for it are often Latin-1: text that is not UTF-8
/// is read as Latin-1 rather than refused.
pub fn decode_sdl(bytes: Vec<u8>) -> (String, bool) {
    match String::from_utf8(bytes) {
        Ok(text) => (text, false),
        Err(error) => (
            error.into_bytes().iter().map(|&b| char::from(b)).collect(),
            true,
        ),
    }
}

/// An SDL file's text, read from disk as [`decode_sdl`] reads bytes.
pub fn read_sdl_file(path: &std::path::Path) -> std::io::Result<String> {
    std::fs::read(path).map(|bytes| decode_sdl(bytes).0)
}

/// Files held in memory, such as the Typst package's `includes` and `files` dictionaries.
#[derive(Debug, Clone, Default)]
pub struct MemoryFiles {
    files: BTreeMap<String, Arc<str>>,
    binary: BTreeMap<String, Arc<[u8]>>,
}

impl MemoryFiles {
    pub fn new() -> Self {
        Self::default()
    }

    pub fn insert(&mut self, name: impl Into<String>, text: impl Into<Arc<str>>) -> &mut Self {
        self.files.insert(name.into(), text.into());
        self
    }

    pub fn with(mut self, name: impl Into<String>, text: impl Into<Arc<str>>) -> Self {
        self.insert(name, text);
        self
    }

    /// Adds a file as bytes; if they are UTF-8 text, `#include` and `#fopen` can read it too.
    pub fn insert_bytes(
        &mut self,
        name: impl Into<String>,
        bytes: impl Into<Arc<[u8]>>,
    ) -> &mut Self {
        let name = name.into();
        let bytes = bytes.into();
        if let Ok(text) = std::str::from_utf8(&bytes) {
            self.files.insert(name.clone(), Arc::from(text));
        }
        self.binary.insert(name, bytes);
        self
    }
}

impl FileSource for MemoryFiles {
    fn read(&self, name: &str) -> Option<Arc<str>> {
        self.files.get(name).cloned()
    }

    fn read_bytes(&self, name: &str) -> Option<Arc<[u8]>> {
        match self.binary.get(name) {
            Some(bytes) => Some(bytes.clone()),
            None => self.files.get(name).map(|text| Arc::from(text.as_bytes())),
        }
    }

    fn names(&self) -> Vec<String> {
        let mut names: Vec<String> = self
            .files
            .keys()
            .chain(self.binary.keys())
            .cloned()
            .collect();
        names.sort();
        names.dedup();
        names
    }
}

/// The texts of every file an evaluation read, so that diagnostics can quote them.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Sources {
    files: BTreeMap<String, Arc<str>>,
}

impl Sources {
    pub fn insert(&mut self, name: &str, text: Arc<str>) {
        self.files.entry(name.to_owned()).or_insert(text);
    }

    pub fn get(&self, name: &str) -> Option<&Arc<str>> {
        self.files.get(name)
    }

    pub fn iter(&self) -> impl Iterator<Item = (&str, &Arc<str>)> {
        self.files.iter().map(|(name, text)| (name.as_str(), text))
    }
}

impl SourceResolver for Sources {
    fn source(&self, file: &str) -> Option<&str> {
        self.files.get(file).map(|text| &**text)
    }
}

/// Files read from directories on disk, searched in order, as POV-Ray's library paths.
/// Only the CLI and tests use it; the Typst plugin has no file system.
#[derive(Debug, Clone, Default)]
pub struct DirectoryFiles {
    paths: Vec<std::path::PathBuf>,
}

impl DirectoryFiles {
    pub fn new(paths: impl IntoIterator<Item = std::path::PathBuf>) -> Self {
        DirectoryFiles {
            paths: paths.into_iter().collect(),
        }
    }
}

impl DirectoryFiles {
    fn candidates(&self, name: &str) -> Vec<std::path::PathBuf> {
        let relative = std::path::Path::new(name);
        if relative.is_absolute() {
            vec![relative.to_path_buf()]
        } else {
            self.paths.iter().map(|dir| dir.join(relative)).collect()
        }
    }
}

impl FileSource for DirectoryFiles {
    fn read(&self, name: &str) -> Option<Arc<str>> {
        self.candidates(name)
            .into_iter()
            .find_map(|path| read_sdl_file(&path).ok().map(Arc::from))
    }

    fn read_bytes(&self, name: &str) -> Option<Arc<[u8]>> {
        self.candidates(name)
            .into_iter()
            .find_map(|path| std::fs::read(path).ok())
            .map(Arc::from)
    }

    fn names(&self) -> Vec<String> {
        files_in(self.paths.iter().map(std::path::PathBuf::as_path))
    }
}

/// The files directly in `dirs`, sorted and without repeats: what a "cannot find" error
/// lists as available (those of the missing file's kind).
pub fn files_in<'a>(dirs: impl IntoIterator<Item = &'a std::path::Path>) -> Vec<String> {
    let mut names: Vec<String> = dirs
        .into_iter()
        .filter_map(|dir| std::fs::read_dir(dir).ok())
        .flatten()
        .filter_map(|entry| entry.ok())
        .filter(|entry| entry.file_type().is_ok_and(|t| t.is_file()))
        .filter_map(|entry| entry.file_name().into_string().ok())
        .collect();
    names.sort();
    names.dedup();
    names
}
