//! A consistent view for one request or diagnostics job: a clone of the database taken
//! after every earlier edit, and the open documents as they were then. Holding a snapshot
//! delays the next edit, so snapshots live only as long as their request.

use crate::bundled::BundledFiles;
use crate::convert;
use crate::documents::{DocumentKind, DocumentView, Part};
use analysis::db::{self, File, FilePath, Project, RootDatabase};
use analysis::files::read_sdl_file;
use analysis::ide::FilePosition;
use std::collections::HashMap;
use std::sync::Arc;
use syntax::line_index::LineIndex;
use syntax::{TextRange, TextSize};
use tower_lsp_server::ls_types::{Location, Position, Range, Uri};

/// What the main loop shares with requests, rebuilt on every edit.
#[derive(Debug, Clone)]
pub struct World {
    pub documents: HashMap<Uri, DocumentView>,
    pub project: Project,
    pub bundled: BundledFiles,
}

impl World {
    /// The open document at `path`.
    pub fn document_at(&self, path: &std::path::Path) -> Option<(&Uri, &DocumentView)> {
        self.documents.iter().find(|(_, view)| view.path == path)
    }
}

pub struct Snapshot {
    pub db: RootDatabase,
    pub world: Arc<World>,
}

impl Snapshot {
    pub fn document(&self, uri: &Uri) -> Option<&DocumentView> {
        self.world.documents.get(uri)
    }

    /// The part of an open document at a protocol position, and the offset in its file.
    /// Positions of a Typst document outside its povray blocks have none.
    pub fn file_position(&self, uri: &Uri, position: Position) -> Option<(&Part, TextSize)> {
        let view = self.document(uri)?;
        let offset = convert::offset(&view.line_index, &view.text, position);
        match view.kind {
            DocumentKind::Scene => Some((view.parts.first()?, offset)),
            DocumentKind::Typst => view.parts.iter().find_map(|part| {
                let block = part.block.as_ref()?;
                Some((part, block.from_host(offset)?))
            }),
        }
    }

    /// The part of an open document at a protocol position, and the position in its file
    /// that the analysis answers for.
    pub fn analysis_position(
        &self,
        uri: &Uri,
        position: Position,
    ) -> Option<(&Part, FilePosition)> {
        let (part, offset) = self.file_position(uri, position)?;
        Some((
            part,
            FilePosition {
                file: part.file,
                offset,
            },
        ))
    }

    /// The part of an open document that a protocol range falls in, and the range in
    /// its file.
    pub fn file_range(&self, uri: &Uri, range: Range) -> Option<(&Part, TextRange)> {
        let (part, start) = self.file_position(uri, range.start)?;
        let view = self.document(uri)?;
        let end = convert::offset(&view.line_index, &view.text, range.end);
        let end = match &part.block {
            Some(block) => block
                .from_host(end)
                .unwrap_or(TextSize::of(block.text.as_str())),
            None => end,
        };
        Some((part, TextRange::new(start, end.max(start))))
    }

    /// A range of a part's file as a protocol range in its document.
    pub fn part_range(&self, part: &Part, range: TextRange) -> Range {
        let Some(view) = self
            .world
            .documents
            .values()
            .find(|view| view.parts.iter().any(|p| p.file == part.file))
        else {
            return Range::default();
        };
        let range = match &part.block {
            Some(block) => block.to_host_range(range),
            None => range,
        };
        convert::range(&view.line_index, &view.text, range)
    }

    /// Where a range of a database file is, for the protocol.
    pub fn file_location(&self, file: File, range: TextRange) -> Option<Location> {
        self.location(file.path(&self.db), range)
    }

    /// The URI of a file, as [`Snapshot::location`] finds it.
    pub fn uri(&self, path: &FilePath) -> Option<Uri> {
        self.location(path, TextRange::default())
            .map(|location| location.uri)
    }

    /// Where a range of a file is, for the protocol: open documents by their URI (blocks
    /// of a Typst document in it), bundled includes in the cache directory, other files
    /// on disk.
    pub fn location(&self, path: &FilePath, range: TextRange) -> Option<Location> {
        match path {
            FilePath::Embedded { document, index } => {
                let (uri, view) = self.world.document_at(document)?;
                let part = view.parts.get(*index as usize)?;
                Some(Location::new(uri.clone(), self.part_range(part, range)))
            }
            FilePath::Disk(disk) => {
                if let Some((uri, view)) = self.world.document_at(disk) {
                    let range = convert::range(&view.line_index, &view.text, range);
                    return Some(Location::new(uri.clone(), range));
                }
                let uri = Uri::from_file_path(disk)?;
                Some(Location::new(uri, self.range_in(path, range)?))
            }
            FilePath::Bundled(name) => {
                let uri = self.world.bundled.uri(name)?;
                Some(Location::new(uri, self.range_in(path, range)?))
            }
        }
    }

    /// A range of a file that is not open, converted with the text the database holds,
    /// or the text on disk.
    fn range_in(&self, path: &FilePath, range: TextRange) -> Option<Range> {
        if let Some(file) = self.world.project.files(&self.db).get(path) {
            let text = file.text(&self.db);
            return Some(convert::range(db::line_index(&self.db, *file), text, range));
        }
        let text = match path {
            FilePath::Disk(disk) => read_sdl_file(disk).ok()?,
            FilePath::Bundled(name) => analysis::stdinc::get(name)?.to_owned(),
            FilePath::Embedded { .. } => return None,
        };
        Some(convert::range(&LineIndex::new(&text), &text, range))
    }
}
