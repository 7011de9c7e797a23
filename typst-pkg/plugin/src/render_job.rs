//! One render request from start to finish: the options, the files the scene may read, the
//! renderer's pipeline, and the answer for Typst. Everything that can go wrong with the
//! scene or its options becomes an error answer, never a panic.

use crate::request::Request;
use crate::response::{Encoding, Message, Pixels, Response};
use analysis::{MemoryFiles, Stream};
use renderer::{Image, RenderOptions};

/// The name diagnostics give the main scene; includes keep the names the scene uses.
pub const SCENE_NAME: &str = "scene.pov";

/// Renders the request's scene.
pub fn run(request: &Request) -> Response {
    let options = match options(request) {
        Ok(options) => options,
        Err(text) => return Response::error(text),
    };
    let files = files(request);
    match renderer::pipeline::render_source(SCENE_NAME, &files, &options) {
        Ok(rendered) => Response {
            outcome: Ok(pixels(&rendered.image)),
            messages: rendered
                .messages
                .iter()
                .map(|message| Message {
                    stream: match message.stream {
                        Stream::Debug => "debug",
                    },
                    text: message.text.clone(),
                })
                .collect(),
            warnings: rendered.warnings_to_human(),
        },
        Err(failure) => Response::error(failure.to_human()),
    }
}

/// The package defaults, then the options from the keyword arguments, then `extra`.
fn options(request: &Request) -> Result<RenderOptions, String> {
    let mut options = RenderOptions::default();
    for option in &request.options {
        options.apply_povray_option(option)?;
    }
    for option in &request.extra {
        options
            .apply_povray_option(option)
            .map_err(|error| format!("extra: {error}"))?;
    }
    Ok(options)
}

/// The scene, its includes and its other files (images, fonts, `#fopen` data) as the
/// evaluator reads them: files that are UTF-8 text can also be included or read as text.
fn files(request: &Request) -> MemoryFiles {
    let mut files = MemoryFiles::new();
    files.insert(SCENE_NAME, request.scene.as_str());
    for (name, text) in &request.includes {
        files.insert(name.as_str(), text.as_str());
    }
    for (name, bytes) in &request.files {
        files.insert_bytes(name.as_str(), bytes.as_slice());
    }
    files
}

/// The image as 8-bit samples, quantised as the PNG writer quantises them.
fn pixels(image: &Image) -> Pixels {
    let samples = image.samples8();
    Pixels {
        width: image.width,
        height: image.height,
        encoding: if image.has_alpha {
            Encoding::Rgba8
        } else {
            Encoding::Rgb8
        },
        samples,
    }
}
