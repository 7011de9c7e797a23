//! The files a lint looks at: the scene and every file it includes by a literal name,
//! transitively, each parsed once, with the facts the lints share about its names.

use crate::files::FileSource;
use std::collections::{BTreeMap, HashMap, HashSet};
use std::sync::{Arc, Mutex, OnceLock};
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

/// The names a file defines and uses.
#[derive(Debug, Clone)]
pub struct FileFacts {
    pub name: String,
    pub origin: Origin,
    pub text: Arc<str>,
    /// The syntax tree, kept for the user's files only: the lints read the standard
    /// includes' names alone, which are parsed once per process.
    pub root: Option<SyntaxNode>,
    pub definitions: Arc<[Definition]>,
    /// Every identifier that is not a definition, by name and place.
    pub uses: Arc<[(String, TextRange)]>,
    /// The names of the files it includes by a literal name.
    pub includes: Arc<[String]>,
}

/// What [`FileFacts`] knows apart from the tree, shareable between threads.
#[derive(Debug)]
struct NameFacts {
    definitions: Arc<[Definition]>,
    uses: Arc<[(String, TextRange)]>,
    includes: Arc<[String]>,
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
            for include in facts.includes.iter().rev() {
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

    /// The facts of `name`, from `parsed` when the caller already holds its tree.
    pub fn new(
        name: String,
        origin: Origin,
        text: Arc<str>,
        parsed: Option<syntax::Parse>,
    ) -> FileFacts {
        let (root, facts) = if origin == Origin::Standard {
            (None, standard_facts(&name, &text))
        } else {
            let root = parsed.unwrap_or_else(|| syntax::parse(&text)).syntax_node();
            let facts = NameFacts::of(&root);
            (Some(root), Arc::new(facts))
        };
        FileFacts {
            name,
            origin,
            text,
            root,
            definitions: facts.definitions.clone(),
            uses: facts.uses.clone(),
            includes: facts.includes.clone(),
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
    fn of(root: &SyntaxNode) -> NameFacts {
        let mut definitions = Vec::new();
        let mut uses = Vec::new();
        for token in root
            .descendants_with_tokens()
            .filter_map(|e| e.into_token())
        {
            if token.kind() != SyntaxKind::IDENT {
                continue;
            }
            let name = token.text().to_owned();
            let parent = token.parent();
            match parent.as_ref().filter(|p| p.kind() == SyntaxKind::NAME) {
                Some(name_node) => definitions.push(Definition {
                    name,
                    range: token.text_range(),
                    kind: definition_kind(name_node),
                    in_macro: name_node
                        .ancestors()
                        .any(|a| a.kind() == SyntaxKind::MACRO_BODY),
                }),
                None => uses.push((name, token.text_range())),
            }
        }
        NameFacts {
            definitions: definitions.into(),
            uses: uses.into(),
            includes: literal_includes(root).into(),
        }
    }
}

fn definition_kind(name: &SyntaxNode) -> DefinitionKind {
    let Some(parent) = name.parent() else {
        return DefinitionKind::Other;
    };
    let declaration = match parent.kind() {
        SyntaxKind::DECLARE => Some(parent),
        // `#declare (A, B) = ...`
        SyntaxKind::TARGET_LIST => parent.parent().filter(|p| p.kind() == SyntaxKind::DECLARE),
        SyntaxKind::MACRO => return DefinitionKind::Macro,
        SyntaxKind::PARAM => {
            let in_macro = parent
                .parent()
                .and_then(|list| list.parent())
                .is_some_and(|owner| owner.kind() == SyntaxKind::MACRO);
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
        .children_with_tokens()
        .filter_map(|e| e.into_token())
        .map(|t| t.kind())
        .find(|kind| matches!(kind, SyntaxKind::DECLARE_KW | SyntaxKind::LOCAL_KW));
    match keyword {
        Some(SyntaxKind::LOCAL_KW) => DefinitionKind::Local,
        Some(_) => DefinitionKind::Declare,
        None => DefinitionKind::Other,
    }
}

/// The names of `#include "name"` directives whose name is a plain string literal.
pub fn literal_includes(root: &SyntaxNode) -> Vec<String> {
    root.descendants()
        .filter(|node| node.kind() == SyntaxKind::INCLUDE)
        .filter_map(|include| {
            let tokens: Vec<_> = include
                .descendants_with_tokens()
                .filter_map(|e| e.into_token())
                .filter(|t| !t.kind().is_trivia())
                .collect();
            // Only `#include "name"`: a computed name is known to the evaluator alone.
            let [_, _, string] = tokens.as_slice() else {
                return None;
            };
            if string.kind() != SyntaxKind::STRING {
                return None;
            }
            let (name, problems) = syntax::lexer::unescape_string(string.text());
            problems.is_empty().then_some(name)
        })
        .collect()
}
