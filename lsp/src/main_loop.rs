//! The one thread that writes to the database. Document notifications reach it through a
//! channel in the order the client sent them, so edits apply strictly in order whatever
//! tower-lsp-server does with handlers concurrently. A write cancels the queries running
//! on snapshots and waits for them to let go; after each batch of events the loop starts
//! a diagnostics job on a fresh snapshot.

use crate::bundled::BundledFiles;
use crate::convert;
use crate::documents::{DocumentKind, DocumentView, OpenDocument, Part, apply_change, path_of};
use crate::publisher::{Publication, Publisher};
use crate::snapshot::{Snapshot, World};
use analysis::EvalOptions;
use analysis::db::{self, File, FilePath, Project, ProjectFiles, RootDatabase};
use analysis::files::read_sdl_file;
use analysis::ide::embedded;
use salsa::Setter;
use std::collections::{BTreeMap, HashMap};
use std::panic::AssertUnwindSafe;
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::mpsc::{Receiver, Sender};
use syntax::line_index::LineIndex;
use tokio::sync::oneshot;
use tower_lsp_server::ls_types::{FileChangeType, FileEvent, TextDocumentContentChangeEvent, Uri};

/// What the main loop is asked to do.
pub enum Event {
    Open {
        uri: Uri,
        language_id: String,
        version: i32,
        text: String,
    },
    Change {
        uri: Uri,
        version: i32,
        changes: Vec<TextDocumentContentChangeEvent>,
    },
    Close {
        uri: Uri,
    },
    /// The client saw files change on disk.
    DiskChanged(Vec<FileEvent>),
    /// Files a check read from disk that the database should hold from now on.
    Load(Vec<PathBuf>),
    /// New include search directories (POV-Ray's library paths).
    Configure {
        library_paths: Vec<PathBuf>,
    },
    /// A snapshot for a request, taken after every earlier event.
    Snapshot(oneshot::Sender<Snapshot>),
}

/// How handlers reach the main loop.
#[derive(Debug, Clone)]
pub struct MainLoopHandle {
    sender: Sender<Event>,
}

impl MainLoopHandle {
    /// Starts the main loop on a thread of its own.
    pub fn spawn(publisher: Publisher) -> MainLoopHandle {
        let (sender, receiver) = std::sync::mpsc::channel();
        let handle = MainLoopHandle { sender };
        let jobs = handle.clone();
        std::thread::Builder::new()
            .name("povrayst main loop".to_owned())
            .spawn(move || MainLoop::new(publisher, jobs).run(receiver))
            .expect("the main loop thread starts");
        handle
    }

    pub fn send(&self, event: Event) {
        // The loop only stops when every handle is gone.
        let _ = self.sender.send(event);
    }

    /// A snapshot that reflects every event sent before; `None` once the loop is gone.
    pub async fn snapshot(&self) -> Option<Snapshot> {
        let (sender, receiver) = oneshot::channel();
        self.send(Event::Snapshot(sender));
        receiver.await.ok()
    }
}

struct MainLoop {
    db: RootDatabase,
    project: Project,
    files: BTreeMap<FilePath, File>,
    documents: HashMap<Uri, OpenDocument>,
    /// The database's parts of each open document.
    parts: HashMap<Uri, Vec<Part>>,
    bundled: BundledFiles,
    world: Arc<World>,
    /// Whether documents or files changed since the world was last rebuilt.
    dirty: bool,
    /// Whether documents changed since their includes were last loaded.
    includes_stale: bool,
    /// Whether the files map changed since it was last given to the project.
    files_changed: bool,
    generation: u64,
    publisher: Publisher,
    jobs: MainLoopHandle,
}

impl MainLoop {
    fn new(publisher: Publisher, jobs: MainLoopHandle) -> MainLoop {
        let mut db = RootDatabase::default().with_geometry(Arc::new(renderer::SceneGeometry));
        let project = Project::new(&db, Vec::new(), BTreeMap::new(), EvalOptions::default(), 0);
        let mut files = BTreeMap::new();
        for name in analysis::stdinc::names() {
            let text = analysis::stdinc::get(name).unwrap_or_default();
            let path = FilePath::Bundled(name);
            files.insert(path.clone(), File::new(&db, path, Arc::from(text), project));
        }
        project.set_files(&mut db).to(files.clone());
        let bundled = BundledFiles::new();
        let world = Arc::new(World {
            documents: HashMap::new(),
            project,
            bundled: bundled.clone(),
        });
        MainLoop {
            db,
            project,
            files,
            documents: HashMap::new(),
            parts: HashMap::new(),
            bundled,
            world,
            dirty: false,
            includes_stale: false,
            files_changed: false,
            generation: 0,
            publisher,
            jobs,
        }
    }

    fn run(mut self, receiver: Receiver<Event>) {
        while let Ok(event) = receiver.recv() {
            let mut changed = self.handle_guarded(event);
            // Take every event already waiting before checking again: a burst of edits
            // costs one diagnostics run.
            while let Ok(event) = receiver.try_recv() {
                changed |= self.handle_guarded(event);
            }
            if changed {
                // Diagnostics first: the job checks on one core while this thread looks
                // for includes to load on the other. Loading one is a write, which
                // cancels the job and starts a new one.
                self.flush_world();
                self.schedule_diagnostics();
                if self.load_includes() {
                    self.flush_world();
                    self.schedule_diagnostics();
                }
            }
        }
    }

    /// [`MainLoop::handle`], surviving a bug in it: the event is lost (the panic hook has
    /// said why), the loop goes on.
    fn handle_guarded(&mut self, event: Event) -> bool {
        std::panic::catch_unwind(AssertUnwindSafe(|| self.handle(event))).unwrap_or(true)
    }

    /// Applies one event; says whether diagnostics may have changed.
    fn handle(&mut self, event: Event) -> bool {
        match event {
            Event::Open {
                uri,
                language_id,
                version,
                text,
            } => {
                let Some(kind) = DocumentKind::of(&uri, &language_id) else {
                    return false;
                };
                self.documents.insert(
                    uri.clone(),
                    OpenDocument {
                        kind,
                        version,
                        text,
                    },
                );
                self.sync_document(&uri);
            }
            Event::Change {
                uri,
                version,
                changes,
            } => {
                let Some(document) = self.documents.get_mut(&uri) else {
                    return false;
                };
                for change in &changes {
                    apply_change(&mut document.text, change);
                }
                document.version = version;
                self.sync_document(&uri);
            }
            Event::Close { uri } => {
                if self.documents.remove(&uri).is_none() {
                    return false;
                }
                for part in self.parts.remove(&uri).unwrap_or_default() {
                    self.release(&part.path);
                }
                self.generation += 1;
                self.publisher.publish(Publication {
                    uri,
                    version: None,
                    generation: self.generation,
                    diagnostics: Vec::new(),
                });
            }
            Event::DiskChanged(events) => self.disk_changed(&events),
            Event::Load(paths) => {
                let mut loaded = false;
                for path in paths {
                    let key = FilePath::Disk(db::normalize(&path));
                    if self.files.contains_key(&key) {
                        continue;
                    }
                    if let Ok(text) = read_sdl_file(&path) {
                        self.set_file(key, &text);
                        loaded = true;
                    }
                }
                if !loaded {
                    return false;
                }
            }
            Event::Configure { library_paths } => {
                self.project
                    .set_library_paths(&mut self.db)
                    .to(library_paths);
            }
            Event::Snapshot(reply) => {
                self.flush();
                let _ = reply.send(self.snapshot());
                return false;
            }
        }
        self.dirty = true;
        self.includes_stale = true;
        true
    }

    /// Brings the database's files of one open document up to date with its text.
    fn sync_document(&mut self, uri: &Uri) {
        let Some(document) = self.documents.get(uri) else {
            return;
        };
        let path = path_of(uri);
        let text = document.text.clone();
        let parts = match document.kind {
            DocumentKind::Scene => {
                let key = match self.bundled.name_of(&path) {
                    Some(name) => FilePath::Bundled(name),
                    None => FilePath::Disk(path),
                };
                let file = self.set_file(key.clone(), &text);
                vec![Part {
                    file,
                    path: key,
                    block: None,
                }]
            }
            DocumentKind::Typst => {
                let blocks = embedded::povray_blocks(&text);
                let old = self.parts.get(uri).map_or(0, Vec::len);
                for index in blocks.len()..old {
                    self.release(&FilePath::Embedded {
                        document: path.clone(),
                        index: index as u32,
                    });
                }
                blocks
                    .into_iter()
                    .enumerate()
                    .map(|(index, block)| {
                        let key = FilePath::Embedded {
                            document: path.clone(),
                            index: index as u32,
                        };
                        let file = self.set_file(key.clone(), &block.text);
                        Part {
                            file,
                            path: key,
                            block: Some(Arc::new(block)),
                        }
                    })
                    .collect()
            }
        };
        self.parts.insert(uri.clone(), parts);
    }

    /// Sets a file's text, making the file when the database does not hold it yet.
    fn set_file(&mut self, path: FilePath, text: &str) -> File {
        if let Some(&file) = self.files.get(&path) {
            if **file.text(&self.db) != *text {
                file.set_text(&mut self.db).to(Arc::from(text));
            }
            return file;
        }
        let file = File::new(&self.db, path.clone(), Arc::from(text), self.project);
        self.files.insert(path, file);
        self.files_changed = true;
        file
    }

    /// A document stopped holding a file: it goes back to its text on disk (or the
    /// bundled text), or leaves the database.
    fn release(&mut self, path: &FilePath) {
        let original = match path {
            FilePath::Disk(disk) => read_sdl_file(disk).ok(),
            FilePath::Bundled(name) => analysis::stdinc::get(name).map(str::to_owned),
            FilePath::Embedded { .. } => None,
        };
        match original {
            Some(text) => {
                self.set_file(path.clone(), &text);
            }
            None => {
                self.files.remove(path);
                self.files_changed = true;
            }
        }
    }

    fn disk_changed(&mut self, events: &[FileEvent]) {
        for event in events {
            let path = path_of(&event.uri);
            let key = FilePath::Disk(path.clone());
            let open = self.documents.keys().any(|uri| path_of(uri) == path);
            if open || !self.files.contains_key(&key) {
                continue;
            }
            match std::fs::read_to_string(&path) {
                Ok(text) if event.typ != FileChangeType::DELETED => {
                    self.set_file(key, &text);
                }
                _ => {
                    self.files.remove(&key);
                    self.files_changed = true;
                }
            }
        }
        let revision = self.project.disk_revision(&self.db);
        self.project
            .set_disk_revision(&mut self.db)
            .to(revision + 1);
    }

    /// Loads the includes of changed documents, gives the project its new file list and
    /// rebuilds what snapshots share: everything a request must see.
    fn flush(&mut self) {
        self.load_includes();
        self.flush_world();
    }

    /// Gives the project its new file list and rebuilds what snapshots share.
    fn flush_world(&mut self) {
        self.set_project_files();
        if !self.dirty {
            return;
        }
        self.dirty = false;
        let documents = self
            .documents
            .iter()
            .map(|(uri, document)| {
                let view = DocumentView {
                    kind: document.kind,
                    version: document.version,
                    text: Arc::from(document.text.as_str()),
                    line_index: Arc::new(LineIndex::new(&document.text)),
                    path: path_of(uri),
                    parts: self.parts.get(uri).cloned().unwrap_or_default(),
                };
                (uri.clone(), view)
            })
            .collect();
        self.world = Arc::new(World {
            documents,
            project: self.project,
            bundled: self.bundled.clone(),
        });
    }

    fn set_project_files(&mut self) {
        if self.files_changed {
            self.project.set_files(&mut self.db).to(self.files.clone());
            self.files_changed = false;
        }
    }

    /// Loads the disk files that open documents include, directly or through other
    /// includes, before any request can ask about them. Each round loads the includes the
    /// previous round made reachable. Says whether it loaded any.
    fn load_includes(&mut self) -> bool {
        if !self.includes_stale {
            return false;
        }
        self.includes_stale = false;
        let mut any = false;
        let parts: Vec<File> = self
            .parts
            .values()
            .flatten()
            .map(|part| part.file)
            .collect();
        loop {
            self.set_project_files();
            // A bug in a query must not take the main loop down with it: the document
            // then just lacks its includes, and the diagnostics job reports the failure.
            let db = &self.db;
            let found = std::panic::catch_unwind(AssertUnwindSafe(|| {
                parts
                    .iter()
                    .flat_map(|&file| db::unloaded_includes(db, file))
                    .collect::<Vec<PathBuf>>()
            }));
            let Ok(mut unloaded) = found else {
                return any;
            };
            unloaded.sort();
            unloaded.dedup();
            let mut loaded = false;
            for path in unloaded {
                if let Ok(text) = read_sdl_file(&path) {
                    self.set_file(FilePath::Disk(path), &text);
                    loaded = true;
                }
            }
            if !loaded {
                return any;
            }
            any = true;
            self.dirty = true;
        }
    }

    fn snapshot(&self) -> Snapshot {
        Snapshot {
            db: self.db.clone(),
            world: self.world.clone(),
        }
    }

    /// Checks every open document on a thread of its own; the results go to the
    /// publisher, files the checks found on disk come back as a [`Event::Load`].
    fn schedule_diagnostics(&mut self) {
        self.generation += 1;
        let generation = self.generation;
        let snapshot = self.snapshot();
        let publisher = self.publisher.clone();
        let jobs = self.jobs.clone();
        let spawned = std::thread::Builder::new()
            .name("povrayst diagnostics".to_owned())
            .spawn(move || {
                let unloaded = publish_diagnostics(snapshot, generation, &publisher);
                if !unloaded.is_empty() {
                    jobs.send(Event::Load(unloaded));
                }
            });
        if let Err(error) = spawned {
            eprintln!("povrayst lsp: cannot start a diagnostics job: {error}");
        }
    }
}

/// Publishes the diagnostics of every open document; returns the disk files the checks
/// read that the database does not hold. Stops quietly when a newer edit cancels it.
fn publish_diagnostics(snapshot: Snapshot, generation: u64, publisher: &Publisher) -> Vec<PathBuf> {
    let mut unloaded = Vec::new();
    for (uri, view) in &snapshot.world.documents {
        let checked = std::panic::catch_unwind(AssertUnwindSafe(|| {
            let mut diagnostics = Vec::new();
            let mut unloaded = Vec::new();
            for part in &view.parts {
                // The lints need the tree and the names; the check runs the evaluator.
                // Neither needs the other, so they run side by side.
                let lint_db = snapshot.db.clone();
                let (checked, lints) = std::thread::scope(|scope| {
                    let lints = scope.spawn(move || {
                        let files = ProjectFiles::new(&lint_db, part.file);
                        let linted = analysis::lint::lint(files.main_name(), &files);
                        (files.main_name().to_owned(), linted.warnings)
                    });
                    let checked = db::check_file(&snapshot.db, part.file);
                    let lints = lints
                        .join()
                        .unwrap_or_else(|payload| std::panic::resume_unwind(payload));
                    (checked, lints)
                });
                diagnostics.extend(convert::diagnostics(&snapshot, part, checked));
                let (main_name, lints) = lints;
                diagnostics.extend(convert::lints(&snapshot, part, &main_name, &lints));
                unloaded.extend(checked.unloaded.iter().cloned());
            }
            (diagnostics, unloaded)
        }));
        match checked {
            Ok((diagnostics, paths)) => {
                unloaded.extend(paths);
                publisher.publish(Publication {
                    uri: uri.clone(),
                    version: Some(view.version),
                    generation,
                    diagnostics,
                });
            }
            Err(payload) if payload.is::<salsa::Cancelled>() => return Vec::new(),
            // A bug of ours: say so in the document rather than leave stale diagnostics.
            // The panic hook has printed the details on stderr.
            Err(payload) => publisher.publish(Publication {
                uri: uri.clone(),
                version: Some(view.version),
                generation,
                diagnostics: vec![convert::internal_error(&crate::server::panic_message(
                    payload.as_ref(),
                ))],
            }),
        }
    }
    unloaded.sort();
    unloaded.dedup();
    unloaded
}
