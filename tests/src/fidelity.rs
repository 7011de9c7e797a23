//! The fidelity manifest (`tests/reference/scenes.txt`): which scenes are compared with
//! POV-Ray's renders, at which settings, against which thresholds; and rendering one of
//! them through the same pipeline as the CLI.

use crate::image_compare::{Picture, Thresholds};
use crate::workspace_root;
use std::path::{Path, PathBuf};

/// One line of the manifest.
#[derive(Debug, Clone, PartialEq)]
pub struct FidelityScene {
    pub name: String,
    /// From the workspace root.
    pub scene: PathBuf,
    /// POV-Ray options, as `povray` and `RenderOptions::apply_povray_option` read them.
    pub options: Vec<String>,
    pub thresholds: Thresholds,
}

impl FidelityScene {
    pub fn reference_png(&self) -> PathBuf {
        reference_dir()
            .join("png")
            .join(format!("{}.png", self.name))
    }

    pub fn render_options(&self) -> renderer::RenderOptions {
        let mut options = renderer::RenderOptions::default();
        for option in &self.options {
            options
                .apply_povray_option(option)
                .unwrap_or_else(|e| panic!("{}: {e}", self.name));
        }
        options
    }

    /// Renders the scene (with its directory's files available to `#include`) and decodes
    /// the PNG we would write.
    pub fn render_with(&self, source: &str) -> Result<Picture, String> {
        let image = self.render_image(source)?;
        Picture::decode(&renderer::encode_png(&image, &self.render_options()))
    }

    /// Evaluates and renders `source` as this scene, stopping before PNG encoding.
    pub fn render_image(&self, source: &str) -> Result<renderer::Image, String> {
        self.render_files(&self.files(source))
    }

    /// The scene's text under its file name, with its directory's includes and assets: what
    /// a render of it may read.
    pub fn files(&self, source: &str) -> analysis::MemoryFiles {
        let mut files = analysis::MemoryFiles::new();
        files.insert(self.file_name(), source);
        for (include, text) in self.includes() {
            files.insert(include, text);
        }
        for (asset, bytes) in self.assets() {
            files.insert_bytes(asset, bytes);
        }
        files
    }

    /// Evaluates and renders the scene from `files` (see [`FidelityScene::files`]),
    /// stopping before PNG encoding.
    pub fn render_files(&self, files: &analysis::MemoryFiles) -> Result<renderer::Image, String> {
        let rendered =
            renderer::pipeline::render_source(self.file_name(), files, &self.render_options())
                .map_err(|f| f.to_human())?;
        Ok(rendered.image)
    }

    pub fn source(&self) -> String {
        let path = workspace_root().join(&self.scene);
        std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
    }

    /// The scene's file name, as its diagnostics name it.
    pub fn file_name(&self) -> &str {
        self.scene
            .file_name()
            .and_then(|n| n.to_str())
            .unwrap_or_else(|| panic!("{}: the scene path has no UTF-8 file name", self.name))
    }

    /// The `.inc` files beside the scene, by name: what it may `#include`.
    pub fn includes(&self) -> Vec<(String, String)> {
        let dir = self.directory();
        let Ok(entries) = std::fs::read_dir(&dir) else {
            return Vec::new();
        };
        let mut includes = Vec::new();
        for entry in entries.flatten() {
            let path = entry.path();
            if path.extension().is_some_and(|e| e == "inc")
                && let (Some(name), Ok(text)) = (
                    path.file_name().and_then(|n| n.to_str()),
                    std::fs::read_to_string(&path),
                )
            {
                includes.push((name.to_owned(), text));
            }
        }
        includes
    }

    /// The images and fonts in the `assets` folder beside the scene, by the names the
    /// scenes use for them (`assets/map.png`).
    pub fn assets(&self) -> Vec<(String, Vec<u8>)> {
        let Ok(entries) = std::fs::read_dir(self.directory().join("assets")) else {
            return Vec::new();
        };
        entries
            .flatten()
            .filter_map(|entry| {
                let name = entry.file_name().to_str().map(|n| format!("assets/{n}"))?;
                Some((name, std::fs::read(entry.path()).ok()?))
            })
            .collect()
    }

    fn directory(&self) -> PathBuf {
        let path = workspace_root().join(&self.scene);
        path.parent()
            .map_or_else(|| workspace_root().to_path_buf(), Path::to_path_buf)
    }
}

pub fn reference_dir() -> PathBuf {
    workspace_root().join("tests/reference")
}

/// Reads `tests/reference/scenes.txt`.
pub fn manifest() -> Vec<FidelityScene> {
    let path = reference_dir().join("scenes.txt");
    let text = std::fs::read_to_string(&path).expect("tests/reference/scenes.txt");
    text.lines()
        .filter(|l| !l.trim().is_empty() && !l.trim_start().starts_with('#'))
        .map(|line| parse_line(line).unwrap_or_else(|e| panic!("scenes.txt: `{line}`: {e}")))
        .collect()
}

fn parse_line(line: &str) -> Result<FidelityScene, String> {
    let (settings, limits) = line.split_once('|').ok_or("no `|` before the thresholds")?;
    let mut words = settings.split_whitespace();
    let name = words.next().ok_or("no name")?.to_string();
    let scene = PathBuf::from(words.next().ok_or("no scene file")?);
    let options = words.map(str::to_string).collect();
    let mut thresholds = Thresholds::GEOMETRIC;
    for limit in limits.split_whitespace() {
        let (key, value) = limit.split_once('=').ok_or("threshold without `=`")?;
        let value: f64 = value.parse().map_err(|_| format!("bad number `{value}`"))?;
        match key {
            "blur" => thresholds.blur = value as usize,
            "region" => thresholds.max_region_error = value,
            "ssim" => thresholds.min_ssim = value,
            "mean" => thresholds.max_mean_error = value,
            "large" => thresholds.max_large_error_share = value,
            _ => return Err(format!("unknown threshold `{key}`")),
        }
    }
    Ok(FidelityScene {
        name,
        scene,
        options,
        thresholds,
    })
}
