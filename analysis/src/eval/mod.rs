//! The evaluator: runs a scene's directives, macros and expressions over its token stream,
//! the way POV-Ray's parser does, and builds the [`Scene`] it describes.
//!
//! POV-Ray stops at the first error, and so do we: an [`Evaluation`] carries at most one
//! error, located in the file where it happened, plus the warnings and `#debug` text met
//! before it.

mod atmosphere;
mod bicubic_patch;
mod bitmap;
mod builtins;
mod camera;
mod colour;
mod datetime;
mod directives;
mod expr;
mod expr_cache;
mod file_io;
mod function_body;
mod height_field;
mod light;
mod light_group;
mod macros;
mod math_shapes;
mod media;
mod mesh;
mod normal_map;
mod object;
mod object_queries;
mod pattern_head;
mod photons;
mod polygon;
mod radiosity;
mod rng;
mod scene_items;
mod spline;
mod stream;
mod symbols;
mod text;
mod texture;
mod tokens;
mod transform;
pub mod value;
mod warp;

use crate::files::{FileSource, Sources};
use crate::scene::{Camera, GlobalSettings, Light, Object, Scene, Texture};
use crate::stdinc;
use std::collections::HashMap;
use std::sync::Arc;
use symbols::Scope;
use syntax::{Diagnostic, TextRange};
use tokens::{FileId, Frame, FrameKind, SourceFile, Token};
use value::Slot;

/// Every evaluation error stops the evaluation; boxed to keep results small.
pub(crate) type Result<T> = std::result::Result<T, Box<Diagnostic>>;

/// Limits that turn runaway scenes into located errors instead of hangs.
#[derive(Debug, Clone, PartialEq)]
pub struct Budgets {
    /// Total `#while` and `#for` iterations.
    pub loop_iterations: u64,
    /// Nested macro calls.
    pub macro_depth: usize,
    /// Nested include files.
    pub include_depth: usize,
    /// Tokens read, counting every repetition of a loop body or macro.
    pub steps: u64,
    /// Elements of one array.
    pub array_elements: usize,
    /// Bytes of one string.
    pub string_bytes: usize,
}

impl Default for Budgets {
    fn default() -> Self {
        Budgets {
            loop_iterations: 10_000_000,
            macro_depth: 1_000,
            include_depth: 64,
            steps: 200_000_000,
            array_elements: 16_000_000,
            string_bytes: 16 << 20,
        }
    }
}

/// What the scene can ask about its rendering context.
#[derive(Debug, Clone, PartialEq)]
pub struct EvalOptions {
    pub image_width: u32,
    pub image_height: u32,
    pub clock: f64,
    /// Whether a clock value was given (`clock_on`).
    pub clock_on: bool,
    pub frame_number: u32,
    pub initial_frame: u32,
    pub final_frame: u32,
    pub initial_clock: f64,
    pub final_clock: f64,
    /// The `#version` in force before the scene sets one (Version=... on the command line).
    pub version: Option<f64>,
    pub budgets: Budgets,
    /// Floats declared before the scene is read (POV-Ray's `Declare=NAME=VALUE` option).
    pub declared: Vec<(String, f64)>,
}

impl Default for EvalOptions {
    fn default() -> Self {
        EvalOptions {
            image_width: 800,
            image_height: 600,
            clock: 0.0,
            clock_on: false,
            frame_number: 0,
            initial_frame: 1,
            final_frame: 1,
            initial_clock: 0.0,
            final_clock: 1.0,
            version: None,
            budgets: Budgets::default(),
            declared: Vec::new(),
        }
    }
}

/// The message streams a scene can write to besides errors.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stream {
    Debug,
}

/// Text a scene printed with `#debug`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Message {
    pub stream: Stream,
    pub text: String,
}

/// The outcome of evaluating a scene.
#[derive(Debug, Clone)]
pub struct Evaluation {
    /// `None` when evaluation stopped at an error.
    pub scene: Option<Scene>,
    /// Warnings in the order met, then the error that stopped evaluation, if any.
    pub diagnostics: Vec<Diagnostic>,
    pub messages: Vec<Message>,
    /// Every file read, so that diagnostics can be rendered with their source lines.
    pub sources: Sources,
    /// Files the scene wrote with `#fopen`/`#write`, by name.
    pub written: std::collections::BTreeMap<String, String>,
}

impl Evaluation {
    pub fn has_errors(&self) -> bool {
        self.diagnostics.iter().any(Diagnostic::is_error)
    }

    /// All `#debug` text, concatenated as POV-Ray prints it.
    pub fn debug_text(&self) -> String {
        self.messages.iter().map(|m| m.text.as_str()).collect()
    }
}

/// Evaluates the scene `main`, reading it and its includes from `files` and then from the
/// standard includes.
pub fn evaluate(main: &str, files: &dyn FileSource, options: &EvalOptions) -> Evaluation {
    evaluate_with(main, files, options, &crate::geometry::NoGeometry)
}

/// [`evaluate`] with a renderer answering the scene's geometric queries.
pub fn evaluate_with(
    main: &str,
    files: &dyn FileSource,
    options: &EvalOptions,
    geometry: &dyn crate::geometry::Geometry,
) -> Evaluation {
    let mut evaluator = Evaluator::new(files, options, geometry);
    let outcome = evaluator.run(main);
    evaluator.finish(outcome)
}

/// The function a scene declares globally under `name`, compiled: for benchmarks and tools
/// that evaluate a scene's functions outside a render.
pub fn declared_function(
    main: &str,
    files: &dyn FileSource,
    name: &str,
) -> Option<Arc<crate::function::Function>> {
    let options = EvalOptions::default();
    let mut evaluator = Evaluator::new(files, &options, &crate::geometry::NoGeometry);
    evaluator.run(main).ok()?;
    let slot = evaluator.local_slot(0, name)?;
    let value = slot.borrow();
    match &*value {
        value::Value::Function(function) => Some(function.clone()),
        _ => None,
    }
}

/// The state of one evaluation.
pub(crate) struct Evaluator<'a> {
    source: &'a dyn FileSource,
    geometry: &'a dyn crate::geometry::Geometry,
    options: &'a EvalOptions,
    files: Vec<SourceFile>,
    file_ids: HashMap<String, FileId>,
    sources: Sources,
    frames: Vec<Frame>,
    /// Symbol tables: the global one first, then one per include file and macro call.
    scopes: Vec<Scope>,
    /// The names the tables know by number.
    interner: symbols::Interner,
    /// Emptied tables of ended scopes, for `push_scope` to reuse.
    spare_scopes: Vec<Scope>,
    /// Storage of ended scopes' definitions that nothing else held, emptied, for new
    /// definitions to reuse instead of allocating (see `Evaluator::new_slot`).
    spare_slots: Vec<Slot>,
    /// Tokens given back by the parsers, read again before the stream.
    pushed: Vec<Token>,
    /// The frame depths at which a declaration's value is being read, innermost last.
    declaring: Vec<usize>,
    /// Whether `next` hands macro calls back unexpanded (see `next_unexpanded`).
    macro_calls_held: bool,
    /// Files written with `#write`, by name.
    written: std::collections::BTreeMap<String, String>,
    /// Files being included, innermost last, to catch cycles.
    include_stack: Vec<FileId>,
    /// Images decoded so far, by the name the scene used, so each is decoded once.
    images: HashMap<String, Arc<crate::image::Image>>,
    density_grids: HashMap<String, Arc<crate::pattern::density_file::DensityGrid>>,
    steps: u64,
    loop_iterations: u64,
    macro_depth: usize,
    version: f64,
    version_set: bool,
    /// Where the last `#version` directive's keyword is, for warnings about the version.
    version_directive: Option<(FileId, TextRange)>,
    warnings: Vec<Diagnostic>,
    messages: Vec<Message>,
    rng: rng::RandomStreams,
    camera: Option<Camera>,
    lights: Vec<Light>,
    objects: Vec<Object>,
    background: Option<crate::scene::Colour>,
    fogs: Vec<crate::scene::Fog>,
    rainbows: Vec<crate::scene::Rainbow>,
    sky_sphere: Option<crate::scene::SkySphere>,
    media: Vec<Arc<crate::scene::Media>>,
    settings: GlobalSettings,
    default_texture: Texture,
    /// `#default { radiosity { importance } }`: for objects placed from now on.
    default_importance: f64,
    /// Expressions compiled for replay, by place.
    expr_cache: expr_cache::ExprCache,
    /// The renderer's prepared `trace()` and `inside()` answers for recent objects.
    object_queries: object_queries::ObjectQueries,
    /// Where skips over branches not taken ended, to jump there the next time.
    skips: stream::Skips,
}

impl<'a> Evaluator<'a> {
    fn new(
        source: &'a dyn FileSource,
        options: &'a EvalOptions,
        geometry: &'a dyn crate::geometry::Geometry,
    ) -> Self {
        let mut interner = symbols::Interner::default();
        let globals: Scope = options
            .declared
            .iter()
            .map(|(name, value)| {
                let slot = std::rc::Rc::new(std::cell::RefCell::new(value::Value::Float(*value)));
                (interner.intern(name), slot)
            })
            .collect();
        Evaluator {
            source,
            geometry,
            options,
            files: Vec::new(),
            file_ids: HashMap::new(),
            sources: Sources::default(),
            frames: Vec::new(),
            scopes: vec![globals],
            interner,
            spare_scopes: Vec::new(),
            spare_slots: Vec::new(),
            pushed: Vec::new(),
            declaring: Vec::new(),
            macro_calls_held: false,
            include_stack: Vec::new(),
            images: HashMap::new(),
            density_grids: HashMap::new(),
            written: std::collections::BTreeMap::new(),
            steps: 0,
            loop_iterations: 0,
            macro_depth: 0,
            version: options.version.unwrap_or(3.7),
            version_set: options.version.is_some(),
            version_directive: None,
            warnings: Vec::new(),
            messages: Vec::new(),
            rng: rng::RandomStreams::default(),
            camera: None,
            lights: Vec::new(),
            objects: Vec::new(),
            background: None,
            fogs: Vec::new(),
            rainbows: Vec::new(),
            sky_sphere: None,
            media: Vec::new(),
            settings: GlobalSettings::default(),
            default_texture: Texture::default(),
            default_importance: 1.0,
            expr_cache: expr_cache::ExprCache::default(),
            object_queries: object_queries::ObjectQueries::default(),
            skips: stream::Skips::default(),
        }
    }

    fn run(&mut self, main: &str) -> Result<()> {
        let Some(file) = self.load(main) else {
            return Err(Box::new(Diagnostic::error(
                main,
                TextRange::default(),
                format!("cannot read '{main}'"),
            )));
        };
        self.syntax_check(file)?;
        let end = self.files[file as usize].tokens.len();
        self.include_stack.push(file);
        self.push_frame(Frame {
            file,
            pos: 0,
            end,
            kind: FrameKind::Main,
            conds: Vec::new(),
            entered_at: None,
        });
        self.statements_until_eof()?;
        if !self.version_set {
            let range = TextRange::default();
            self.warnings.push(
                Diagnostic::warning(
                    main,
                    range,
                    "this scene has no #version directive; assuming #version 3.7",
                )
                .with_code("missing-version")
                .with_note("add `#version 3.7;` as the scene's first line"),
            );
        }
        if self.settings.assumed_gamma.is_none() {
            let warning = self.missing_assumed_gamma(main);
            self.warnings.push(warning);
        }
        Ok(())
    }

    /// POV-Ray's warning for a scene without `assumed_gamma`, which decides how its
    /// colours are read: a scene of version 3.7 or later works at gamma 1.0, an older one
    /// (or one without `#version`) without gamma handling. It points at the `#version`
    /// directive that decided, or at the scene's start.
    fn missing_assumed_gamma(&self, main: &str) -> Diagnostic {
        let version = self.version_set.then_some(self.version);
        let message = if crate::scene::default_assumed_gamma(version).is_some() {
            "assumed_gamma is not set in this POV-Ray 3.7 scene; taking assumed_gamma 1.0"
        } else {
            "assumed_gamma is not set, so colours are not gamma corrected, as in scenes older than POV-Ray 3.7"
        };
        let (file, range) = match self.version_directive {
            Some((file, range)) if self.version_set => {
                (self.files[file as usize].name.clone(), range)
            }
            _ => (main.to_owned(), TextRange::default()),
        };
        Diagnostic::warning(file, range, message)
            .with_code("missing-assumed-gamma")
            .with_note("add `assumed_gamma 1.0` to global_settings")
    }

    /// Loads a file once, by name: the caller's files first, then the standard includes.
    fn load(&mut self, name: &str) -> Option<FileId> {
        // A file the scene wrote wins, read afresh each time since it may be rewritten
        // (strings.inc's Parse_String writes a file and includes it).
        if let Some(text) = self.written.get(name) {
            let id = self.files.len() as FileId;
            let text: Arc<str> = Arc::from(text.as_str());
            self.sources.insert(name, text.clone());
            self.files.push(SourceFile::new(name.to_owned(), text));
            return Some(id);
        }
        if let Some(&id) = self.file_ids.get(name) {
            return Some(id);
        }
        let file = match self.source.read(name) {
            Some(text) => SourceFile::new(name.to_owned(), text),
            None => {
                let (name, text) = stdinc::get_named(name)?;
                SourceFile::standard(name, text)
            }
        };
        let id = self.files.len() as FileId;
        self.sources.insert(name, file.text.clone());
        self.files.push(file);
        self.file_ids.insert(name.to_owned(), id);
        Some(id)
    }

    fn finish(mut self, outcome: Result<()>) -> Evaluation {
        let mut diagnostics = std::mem::take(&mut self.warnings);
        let scene = match outcome {
            Ok(()) => Some(self.take_scene()),
            Err(mut error) => {
                self.add_context(&mut error);
                diagnostics.push(*error);
                None
            }
        };
        Evaluation {
            scene,
            diagnostics,
            messages: self.messages,
            sources: self.sources,
            written: self.written,
        }
    }

    /// Notes where the failing include file was included and the failing macro called.
    fn add_context(&self, error: &mut Diagnostic) {
        for frame in self.frames.iter().rev() {
            let Some((file, range)) = frame.entered_at else {
                continue;
            };
            let message = match &frame.kind {
                FrameKind::Macro { def } => format!("in macro '{}' called here", def.name),
                FrameKind::Include => format!(
                    "in '{}' included here",
                    self.files[frame.file as usize].name
                ),
                FrameKind::Main => continue,
            };
            let span = syntax::Span {
                file: self.files[file as usize].name.clone(),
                range,
            };
            error.related.push(syntax::Related { span, message });
        }
    }

    /// The syntax errors of a freshly loaded file stop the evaluation before any of its
    /// tokens run, so every front end reports them the same way. All of a file's syntax
    /// errors are reported at once; the first becomes the stopping error.
    fn syntax_check(&mut self, file: FileId) -> Result<()> {
        let source = &self.files[file as usize];
        // The bundled includes are parsed by their own tests, not on every use.
        if source.standard {
            return Ok(());
        }
        let mut errors = match self.source.parse(&source.name) {
            Some(parse) => syntax::syntax_diagnostics(&source.name, &parse),
            None => crate::syntax_errors(&source.name, &source.text),
        };
        if errors.is_empty() {
            return Ok(());
        }
        let first = errors.remove(0);
        self.warnings.extend(errors);
        Err(Box::new(first))
    }

    fn take_scene(&mut self) -> Scene {
        let mut objects = std::mem::take(&mut self.objects);
        let default = Arc::new(self.default_texture.clone());
        for object in &mut objects {
            object::inherit_texture(object, &default);
        }
        Scene {
            camera: self.camera.take().unwrap_or_default(),
            lights: std::mem::take(&mut self.lights),
            objects,
            background: self.background,
            fogs: std::mem::take(&mut self.fogs),
            rainbows: std::mem::take(&mut self.rainbows),
            sky_sphere: self.sky_sphere.take(),
            media: std::mem::take(&mut self.media),
            settings: self.settings.clone(),
            version: self.version_set.then_some(self.version),
        }
    }

    /// Counts one unit of work against the step budget. Every token read counts one, so
    /// the count stays inline and the error is made apart.
    #[inline]
    fn spend_step(&mut self) -> Result<()> {
        self.steps += 1;
        if self.steps > self.options.budgets.steps {
            return Err(self.step_budget_error());
        }
        Ok(())
    }

    #[cold]
    #[inline(never)]
    fn step_budget_error(&self) -> Box<Diagnostic> {
        self.budget_error(
            format!(
                "evaluation step budget of {} exceeded",
                self.options.budgets.steps
            ),
            "max-steps",
        )
    }

    fn budget_error(&self, message: String, option: &str) -> Box<Diagnostic> {
        let frame = self.frames.last().expect("budgets are spent while reading");
        let file = &self.files[frame.file as usize];
        let at = frame
            .pos
            .saturating_sub(1)
            .min(file.tokens.len().saturating_sub(1));
        let range = file.tokens.get(at).map_or(TextRange::default(), |t| {
            TextRange::new(t.start.into(), t.end.into())
        });
        Box::new(
            Diagnostic::error(file.name.clone(), range, message).with_note(format!(
                "raise the limit with the `{option}` option if the scene really needs more"
            )),
        )
    }

    /// An error at a token.
    pub(crate) fn error_at(&self, token: &Token, message: impl Into<String>) -> Box<Diagnostic> {
        self.error_in(token.file, token.range(), message)
    }

    pub(crate) fn error_in(
        &self,
        file: FileId,
        range: TextRange,
        message: impl Into<String>,
    ) -> Box<Diagnostic> {
        Box::new(Diagnostic::error(
            self.files[file as usize].name.clone(),
            range,
            message,
        ))
    }

    pub(crate) fn warn_at(&mut self, token: &Token, message: impl Into<String>) {
        let diagnostic = Diagnostic::warning(
            self.files[token.file as usize].name.clone(),
            token.range(),
            message,
        );
        self.warnings.push(diagnostic);
    }

    /// An error for a feature we do not render yet.
    pub(crate) fn unsupported(&self, token: &Token, feature: &str) -> Box<Diagnostic> {
        self.error_at(token, format!("not supported yet: {feature}"))
    }
}

#[cfg(test)]
mod tests;
