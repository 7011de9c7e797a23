//! The files a lint looks at: the scene and every file it includes by a literal name,
//! transitively, each parsed once, with the facts the lints share about its names.

use crate::files::FileSource;
use std::collections::{BTreeMap, HashMap, HashSet};
use std::sync::{Arc, Mutex, OnceLock};
use syntax::ast::{AstNode, Include};
use syntax::green_walk::{GreenNodeRef, Step, walk};
use syntax::{SyntaxKind, SyntaxNode, TextRange};

/// Where a file came from, which decides what is reported in it: the standard includes
/// are not the user's to fix.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Origin {
    /// The scene being checked.
    Main,
    /// An include found among the user's files.
    User,
    /// One of the standard includes bundled with the evaluator.
    Standard,
}

/// What kind of name a defining occurrence introduces.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DefinitionKind {
    Declare,
    Local,
    Macro,
    MacroParameter,
    /// A function parameter, a `#for` variable, an `#fopen` handle and the like.
    Other,
}

/// One defining occurrence of a name.
#[derive(Debug, Clone)]
pub struct Definition {
    pub name: String,
    pub range: TextRange,
    pub kind: DefinitionKind,
    /// Whether it stands inside a macro's body.
    pub in_macro: bool,
}

/// The names a file defines and uses, and the rest of what the lints read in it.
#[derive(Debug, Clone)]
pub struct FileFacts {
    pub name: String,
    pub origin: Origin,
    pub text: Arc<str>,
    pub definitions: Arc<[Definition]>,
    /// Every identifier that is not a definition, by name and place.
    pub uses: Arc<[(String, TextRange)]>,
    /// Which of `uses` are read as values (not the targets of `#read`): where a misspelt
    /// keyword shows up.
    name_refs: Arc<[usize]>,
    /// The files it includes by a literal name, with the place of each `#include`.
    pub includes: Arc<[(String, TextRange)]>,
    /// The tokens of legacy syntax.
    pub legacy_tokens: Arc<[(SyntaxKind, TextRange)]>,
}

/// What [`FileFacts`] knows about a file's text, shareable between threads.
#[derive(Debug)]
struct NameFacts {
    definitions: Arc<[Definition]>,
    uses: Arc<[(String, TextRange)]>,
    name_refs: Arc<[usize]>,
    includes: Arc<[(String, TextRange)]>,
    legacy_tokens: Arc<[(SyntaxKind, TextRange)]>,
}

/// The scene and the files it includes, in the order first met.
#[derive(Debug, Clone)]
pub struct Workspace {
    pub files: Vec<FileFacts>,
}

/// Include chains deeper than this are cut off, as the evaluator's own budget would.
const MAX_FILES: usize = 512;

impl Workspace {
    pub fn load(main: &str, source: &dyn FileSource) -> Workspace {
        let mut files = Vec::new();
        let mut seen = HashSet::new();
        let mut pending = vec![(main.to_owned(), Origin::Main)];
        while let Some((name, origin)) = pending.pop() {
            if files.len() >= MAX_FILES || !seen.insert(name.clone()) {
                continue;
            }
            let (text, origin) = match source.read(&name) {
                // POV-Ray's own includes, found on a library path, are not the user's either.
                Some(text) if crate::stdinc::get(&name).is_some() => (text, Origin::Standard),
                Some(text) => (text, origin),
                None => match crate::stdinc::get(&name) {
                    Some(text) => (Arc::from(text), Origin::Standard),
                    None => continue,
                },
            };
            let parsed = source.parse(&name);
            let facts = FileFacts::new(name, origin, text, parsed);
            // Reversed, so that the first include is looked at first.
            for (include, _) in facts.includes.iter().rev() {
                let origin = if origin == Origin::Standard {
                    Origin::Standard
                } else {
                    Origin::User
                };
                pending.push((include.clone(), origin));
            }
            files.push(facts);
        }
        Workspace { files }
    }

    pub fn main(&self) -> Option<&FileFacts> {
        self.files.iter().find(|file| file.origin == Origin::Main)
    }

    /// The files the user can change: the scene and its includes that are not standard.
    pub fn user_files(&self) -> impl Iterator<Item = &FileFacts> {
        self.files
            .iter()
            .filter(|file| file.origin != Origin::Standard)
    }

    /// How many times each name is used, over all files.
    pub fn use_counts(&self) -> BTreeMap<&str, usize> {
        let mut counts = BTreeMap::new();
        for file in &self.files {
            for (name, _) in file.uses.iter() {
                *counts.entry(name.as_str()).or_default() += 1;
            }
        }
        counts
    }
}

impl FileFacts {
    /// Whether the file is named as an include (`.inc`, `.mcr`, `.mac`) rather than a scene.
    pub fn is_include_file(&self) -> bool {
        let lower = self.name.to_ascii_lowercase();
        [".inc", ".mcr", ".mac"]
            .iter()
            .any(|ext| lower.ends_with(ext))
    }

    /// The identifiers read as values, by name and place.
    pub fn name_refs(&self) -> impl Iterator<Item = &(String, TextRange)> {
        self.name_refs.iter().map(|&index| &self.uses[index])
    }

    /// The facts of `name`, from `parsed` when the caller already holds its tree.
    pub fn new(
        name: String,
        origin: Origin,
        text: Arc<str>,
        parsed: Option<syntax::Parse>,
    ) -> FileFacts {
        let facts = if origin == Origin::Standard {
            standard_facts(&name, &text)
        } else {
            let root = parsed.unwrap_or_else(|| syntax::parse(&text)).syntax_node();
            Arc::new(NameFacts::of(&root))
        };
        FileFacts {
            name,
            origin,
            text,
            definitions: facts.definitions.clone(),
            uses: facts.uses.clone(),
            name_refs: facts.name_refs.clone(),
            includes: facts.includes.clone(),
            legacy_tokens: facts.legacy_tokens.clone(),
        }
    }
}

/// The facts of a standard include, parsed once per process: a `check` over hundreds of
/// scenes reads `colors.inc` and its friends for every one.
/// Keyed by name and a hash of the text, since the bundled `colors.inc` and the one of a
/// POV-Ray installation differ.
fn standard_facts(name: &str, text: &str) -> Arc<NameFacts> {
    type Cache = Mutex<HashMap<(String, u64), Arc<NameFacts>>>;
    static CACHE: OnceLock<Cache> = OnceLock::new();
    let key = (name.to_owned(), {
        let mut hasher = std::hash::DefaultHasher::new();
        std::hash::Hash::hash(text, &mut hasher);
        std::hash::Hasher::finish(&hasher)
    });
    let cache = CACHE.get_or_init(Mutex::default);
    if let Some(facts) = cache.lock().ok().and_then(|c| c.get(&key).cloned()) {
        return facts;
    }
    let facts = Arc::new(NameFacts::of(&syntax::parse(text).syntax_node()));
    if let Ok(mut cache) = cache.lock() {
        cache.insert(key, facts.clone());
    }
    facts
}

impl NameFacts {
    /// Everything in one walk over the tree: a scene's every token is visited on each edit.
    fn of(root: &SyntaxNode) -> NameFacts {
        let mut definitions = Vec::new();
        let mut uses = Vec::new();
        let mut name_refs = Vec::new();
        let mut includes = Vec::new();
        let mut legacy_tokens = Vec::new();
        walk(root, |step, enclosing| match step {
            Step::Node(node) if node.kind() == SyntaxKind::INCLUDE => {
                if let Some(name) = literal_include(&node) {
                    includes.push((name, node.range()));
                }
            }
            Step::Node(_) => {}
            Step::Token(token) if token.kind == SyntaxKind::IDENT => {
                let name = token.text.to_owned();
                match enclosing.last().map(GreenNodeRef::kind) {
                    Some(SyntaxKind::NAME) => definitions.push(Definition {
                        name,
                        range: token.range,
                        kind: definition_kind(enclosing),
                        in_macro: enclosing
                            .iter()
                            .any(|node| node.kind() == SyntaxKind::MACRO_BODY),
                    }),
                    parent => {
                        // `#read (F, var)` declares `var`.
                        if parent == Some(SyntaxKind::NAME_REF)
                            && !enclosing
                                .iter()
                                .any(|node| node.kind() == SyntaxKind::FILE_IO)
                        {
                            name_refs.push(uses.len());
                        }
                        uses.push((name, token.range));
                    }
                }
            }
            Step::Token(token) => {
                if super::legacy::replacement(token.kind).is_some() {
                    legacy_tokens.push((token.kind, token.range));
                }
            }
        });
        NameFacts {
            definitions: definitions.into(),
            uses: uses.into(),
            name_refs: name_refs.into(),
            includes: includes.into(),
            legacy_tokens: legacy_tokens.into(),
        }
    }
}

/// What the identifier in the `NAME` node that ends `enclosing` defines.
fn definition_kind(enclosing: &[GreenNodeRef<'_>]) -> DefinitionKind {
    // Counting back from the name: its parent, grandparent, great-grandparent.
    let up = |steps: usize| {
        enclosing
            .len()
            .checked_sub(steps + 1)
            .map(|index| enclosing[index])
    };
    let Some(parent) = up(1) else {
        return DefinitionKind::Other;
    };
    let declaration = match parent.kind() {
        SyntaxKind::DECLARE => Some(parent),
        // `#declare (A, B) = ...`
        SyntaxKind::TARGET_LIST => up(2).filter(|p| p.kind() == SyntaxKind::DECLARE),
        SyntaxKind::MACRO => return DefinitionKind::Macro,
        SyntaxKind::PARAM => {
            let in_macro = up(3).is_some_and(|owner| owner.kind() == SyntaxKind::MACRO);
            return if in_macro {
                DefinitionKind::MacroParameter
            } else {
                DefinitionKind::Other
            };
        }
        _ => None,
    };
    let Some(declaration) = declaration else {
        return DefinitionKind::Other;
    };
    let keyword = declaration
        .child_token_kinds()
        .find(|kind| matches!(kind, SyntaxKind::DECLARE_KW | SyntaxKind::LOCAL_KW));
    match keyword {
        Some(SyntaxKind::LOCAL_KW) => DefinitionKind::Local,
        Some(_) => DefinitionKind::Declare,
        None => DefinitionKind::Other,
    }
}

/// The name of an `#include "name"` directive whose name is a plain string literal; a
/// computed name is known to the evaluator alone.
fn literal_include(include: &GreenNodeRef<'_>) -> Option<String> {
    Include::cast(include.detached())?.path()
}
