//! Test fixtures as strings, as rust-analyzer writes them: one file, or several behind
//! `//- /name.pov` headers, with `$0` marking the cursor (twice for a range). A `.typ`
//! file stands for a Typst document: its povray blocks become files of their own, and the
//! cursor and results are mapped between the two texts as the server maps them.

use super::FilePosition;
use super::embedded::{Block, povray_blocks};
use crate::EvalOptions;
use crate::db::{File, FilePath, Project, RootDatabase};
use salsa::Setter;
use std::collections::BTreeMap;
use std::path::PathBuf;
use std::sync::Arc;
use syntax::{TextRange, TextSize};

pub const CURSOR: &str = "$0";

/// A Typst document of a fixture: its name, its text, and its blocks with their files.
pub type Document = (String, String, Vec<(Block, File)>);

pub struct Fixture {
    pub db: RootDatabase,
    /// Every file by its fixture name (`/scene.pov`, `/doc.typ#0` for blocks).
    pub files: Vec<(String, File)>,
    /// Typst documents: their text and blocks, by fixture name.
    pub documents: Vec<Document>,
    cursor: Option<(File, TextRange)>,
}

impl Fixture {
    pub fn parse(fixture: &str) -> Fixture {
        let fixture = trim_indent(fixture);
        let mut sources: Vec<(String, String)> = Vec::new();
        if !fixture.trim_start().starts_with("//-") {
            sources.push(("/main.pov".to_owned(), fixture.clone()));
        } else {
            for line in fixture.split_inclusive('\n') {
                if let Some(path) = line.strip_prefix("//-") {
                    sources.push((path.trim().to_owned(), String::new()));
                } else if let Some((_, text)) = sources.last_mut() {
                    text.push_str(line);
                }
            }
        }

        let mut db = RootDatabase::default();
        let project = Project::new(&db, Vec::new(), BTreeMap::new(), EvalOptions::default(), 0);
        let mut map = BTreeMap::new();
        for name in crate::stdinc::names() {
            let path = FilePath::Bundled(name);
            let text = crate::stdinc::get(name).unwrap_or_default();
            map.insert(path.clone(), File::new(&db, path, Arc::from(text), project));
        }
        let mut files = Vec::new();
        let mut documents = Vec::new();
        let mut cursor = None;
        for (name, text) in sources {
            let (text, marks) = take_cursor(&text);
            let disk = PathBuf::from("/fixture").join(name.trim_start_matches('/'));
            if name.ends_with(".typ") {
                let mut blocks = Vec::new();
                for (index, block) in povray_blocks(&text).into_iter().enumerate() {
                    let path = FilePath::Embedded {
                        document: disk.clone(),
                        index: index as u32,
                    };
                    let file =
                        File::new(&db, path.clone(), Arc::from(block.text.as_str()), project);
                    map.insert(path, file);
                    if let Some(range) = marks
                        && let (Some(start), Some(end)) =
                            (block.from_host(range.start()), block.from_host(range.end()))
                    {
                        cursor = Some((file, TextRange::new(start, end)));
                    }
                    files.push((format!("{name}#{index}"), file));
                    blocks.push((block, file));
                }
                documents.push((name, text, blocks));
            } else {
                let path = FilePath::Disk(disk);
                let file = File::new(&db, path.clone(), Arc::from(text.as_str()), project);
                map.insert(path, file);
                if let Some(range) = marks {
                    cursor = Some((file, range));
                }
                files.push((name, file));
            }
        }
        project.set_files(&mut db).to(map);
        Fixture {
            db,
            files,
            documents,
            cursor,
        }
    }

    #[track_caller]
    pub fn position(&self) -> FilePosition {
        let (file, range) = self.cursor.expect("the fixture has a $0 cursor");
        FilePosition {
            file,
            offset: range.start(),
        }
    }

    #[track_caller]
    pub fn file(&self, name: &str) -> File {
        self.files
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, f)| *f)
            .unwrap_or_else(|| panic!("no file {name} in the fixture"))
    }

    /// How tests show a range: the fixture name, line and column (one-based, in the
    /// Typst document for blocks), and the text.
    pub fn show(&self, file: File, range: TextRange) -> String {
        for (name, text, blocks) in &self.documents {
            if let Some((block, _)) = blocks.iter().find(|(_, f)| *f == file) {
                let host = block.to_host_range(range);
                return format!(
                    "{name} {} {:?}",
                    line_col(text, host.start()),
                    first_line(&text[host])
                );
            }
        }
        let name = self
            .files
            .iter()
            .find(|(_, f)| *f == file)
            .map_or_else(|| self.name_of(file), |(n, _)| n.clone());
        let text = file.text(&self.db);
        let start = line_col(text, range.start());
        let excerpt = text
            .get(std::ops::Range::<usize>::from(range))
            .unwrap_or("?");
        format!("{name} {start} {:?}", first_line(excerpt))
    }
}

impl Fixture {
    /// A file's fixture name; bundled includes as `bundled:colors.inc`.
    pub fn name_of(&self, file: File) -> String {
        if let Some((name, _)) = self.files.iter().find(|(_, f)| *f == file) {
            return name.clone();
        }
        match file.path(&self.db) {
            FilePath::Bundled(name) => format!("bundled:{name}"),
            other => format!("{other:?}"),
        }
    }
}

/// The first line of an excerpt, with `…` when there is more.
fn first_line(text: &str) -> String {
    match text.split_once('\n') {
        Some((first, _)) => format!("{first}…"),
        None => text.to_owned(),
    }
}

fn line_col(text: &str, offset: TextSize) -> String {
    let before = &text[..usize::from(offset).min(text.len())];
    let line = before.matches('\n').count() + 1;
    let col = before.len() - before.rfind('\n').map_or(0, |i| i + 1) + 1;
    format!("{line}:{col}")
}

/// Removes the `$0` markers; one marks a position, two a range.
fn take_cursor(text: &str) -> (String, Option<TextRange>) {
    let Some(first) = text.find(CURSOR) else {
        return (text.to_owned(), None);
    };
    let mut out = text[..first].to_owned();
    let rest = &text[first + CURSOR.len()..];
    let start = TextSize::new(first as u32);
    match rest.find(CURSOR) {
        Some(second) => {
            out.push_str(&rest[..second]);
            let end = TextSize::new(out.len() as u32);
            out.push_str(&rest[second + CURSOR.len()..]);
            (out, Some(TextRange::new(start, end)))
        }
        None => {
            out.push_str(rest);
            (out, Some(TextRange::empty(start)))
        }
    }
}

/// Removes the indentation common to all non-blank lines, and a first empty line, so
/// fixtures can be indented with the test.
pub fn trim_indent(text: &str) -> String {
    let text = text.strip_prefix('\n').unwrap_or(text);
    let indent = text
        .lines()
        .filter(|line| !line.trim().is_empty())
        .map(|line| line.len() - line.trim_start().len())
        .min()
        .unwrap_or(0);
    text.split_inclusive('\n')
        .map(|line| {
            if line.trim().is_empty() {
                &line[line.trim_end_matches(['\n', '\r']).len()..]
            } else {
                &line[indent..]
            }
        })
        .collect()
}
