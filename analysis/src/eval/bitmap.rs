//! The image statements' shared parts: the file at their head (`[TYPE] "name" [gamma G]
//! [premultiplied B]`), read through the evaluation's file source and decoded once per
//! evaluation, and the bitmap modifiers (`map_type`, `once`, `interpolate`). Then the
//! bodies of `image_map`, `image_pattern`, `bump_map` and `material_map` built from them.

use super::tokens::Token;
use super::{Evaluator, Result};
use crate::image::{self, FileGamma, Image, ImageFormat};
use crate::pattern::density_file::DensityGrid;
use crate::scene::bitmap::{
    Bitmap, ImageMap, ImagePattern, ImageValue, Interpolation, MapType, PaletteAmounts,
};
use crate::scene::{BlendMap, Pattern, PatternKind, Texture, Transform};
use std::sync::Arc;
use syntax::SyntaxKind::*;

/// How many available files a "cannot find" error names at most.
const LISTED_FILES: usize = 30;

/// An image file named at the head of an image statement.
pub(super) struct BitmapFile {
    pub image: Arc<Image>,
    /// `gamma G` or `gamma srgb` after the name, overriding the file's own.
    pub gamma: Option<FileGamma>,
}

impl Evaluator<'_> {
    /// `[TYPE] "name" [gamma G] [premultiplied B]`, or `function` (not supported yet).
    pub(super) fn bitmap_file(&mut self) -> Result<BitmapFile> {
        let first = self.next()?;
        let format = match first.kind {
            PNG_KW => Some(ImageFormat::Png),
            GIF_KW => Some(ImageFormat::Gif),
            TGA_KW => Some(ImageFormat::Tga),
            PPM_KW => Some(ImageFormat::Ppm),
            PGM_KW => Some(ImageFormat::Pgm),
            JPEG_KW => Some(ImageFormat::Jpeg),
            TIFF_KW => Some(ImageFormat::Tiff),
            EXR_KW => Some(ImageFormat::Exr),
            HDR_KW => Some(ImageFormat::Hdr),
            IFF_KW => Some(ImageFormat::Iff),
            SYS_KW => Some(ImageFormat::Sys),
            POT_KW => Some(ImageFormat::Pot),
            FUNCTION_KW => return Err(self.unsupported(&first, "function images")),
            _ => {
                self.unget(first.clone());
                None
            }
        };
        let at = self.next()?;
        self.unget(at.clone());
        let name = self.string()?;
        // Without a type POV-Ray 3.7 goes by the name's extension; without a known one it
        // expects its output type, PNG unless told otherwise.
        let format = format
            .or_else(|| ImageFormat::from_extension(&name))
            .unwrap_or(ImageFormat::Png);
        let image = self.load_image(format, &name, &at)?;
        let mut gamma = None;
        loop {
            let token = self.next()?;
            match token.kind {
                GAMMA_KW => {
                    if self.peek_kind()? == SRGB_KW {
                        self.next()?;
                        gamma = Some(FileGamma::Srgb);
                    } else {
                        let g = self.float()?;
                        if g <= 0.0 {
                            return Err(self.error_at(&token, "an image's gamma must be positive"));
                        }
                        gamma = Some(FileGamma::Power(g));
                    }
                }
                // Alpha is only read as straight alpha; premultiplied files need their
                // colours divided, which no scene here has asked for.
                PREMULTIPLIED_KW => {
                    if self.optional_bool()? {
                        return Err(self.unsupported(&token, "premultiplied images"));
                    }
                }
                _ => {
                    self.unget(token);
                    break;
                }
            }
        }
        Ok(BitmapFile { image, gamma })
    }

    /// The image `name`, decoded as `format`; decoded once however often it is used. A
    /// name without an extension also finds the file with the format's extension.
    fn load_image(&mut self, format: ImageFormat, name: &str, at: &Token) -> Result<Arc<Image>> {
        if let Some(image) = self.images.get(name) {
            return Ok(image.clone());
        }
        let with_extension = format!("{name}.{}", format.extension());
        let has_extension = std::path::Path::new(name).extension().is_some();
        let bytes = self.source.read_bytes(name).or_else(|| {
            (!has_extension)
                .then(|| self.source.read_bytes(&with_extension))
                .flatten()
        });
        let Some(bytes) = bytes else {
            return Err(self.missing_file(at, name, "image"));
        };
        let image = image::decode(format, &bytes).map_err(|e| match e {
            image::ImageError::Unsupported(_) => self.error_at(at, e.to_string()),
            image::ImageError::Malformed(m) => {
                self.error_at(at, format!("cannot read '{name}': {m}"))
            }
        })?;
        let image = Arc::new(image);
        self.images.insert(name.to_owned(), image.clone());
        Ok(image)
    }

    /// `df3 "name"` after `density_file`: the grid, read once however often it is used.
    pub(super) fn density_file(&mut self) -> Result<Arc<DensityGrid>> {
        self.expect(DF3_KW, "df3 after density_file")?;
        let at = self.next()?;
        self.unget(at.clone());
        let name = self.string()?;
        if let Some(grid) = self.density_grids.get(&name) {
            return Ok(grid.clone());
        }
        let Some(bytes) = self.source.read_bytes(&name) else {
            return Err(self.missing_file(&at, &name, "density"));
        };
        let grid = DensityGrid::from_df3(&bytes)
            .map_err(|m| self.error_at(&at, format!("cannot read '{name}': {m}")))?;
        let grid = Arc::new(grid);
        self.density_grids.insert(name, grid.clone());
        Ok(grid)
    }

    /// "cannot find image file 'x'", with the files the source has of the same kind: those
    /// with the missing name's extension, the first [`LISTED_FILES`] of them.
    pub(super) fn missing_file(
        &self,
        at: &Token,
        name: &str,
        what: &str,
    ) -> Box<syntax::Diagnostic> {
        let extension = |n: &str| {
            std::path::Path::new(n)
                .extension()
                .map(|e| e.to_string_lossy().to_ascii_lowercase())
        };
        let wanted = extension(name);
        let mut available = self.source.names();
        available
            .retain(|n| n != &self.files[0].name && (wanted.is_none() || extension(n) == wanted));
        let list = match available.len() {
            0 => "none".to_owned(),
            n if n > LISTED_FILES => format!(
                "{} and {} more",
                available[..LISTED_FILES].join(", "),
                n - LISTED_FILES
            ),
            _ => available.join(", "),
        };
        let mut error = self.error_at(at, format!("cannot find {what} file '{name}'"));
        error.notes.push(format!("files available: {list}"));
        error
    }

    /// A bitmap modifier (`map_type`, `once`, `interpolate`); false when `token` is not one.
    fn bitmap_modifier(&mut self, bitmap: &mut Bitmap, token: &Token) -> Result<bool> {
        match token.kind {
            MAP_TYPE_KW => {
                let at = self.next()?;
                self.unget(at.clone());
                bitmap.map_type = match self.int()? {
                    0 => MapType::Planar,
                    1 => MapType::Spherical,
                    2 => MapType::Cylindrical,
                    5 => MapType::Torus,
                    other => return Err(self.unsupported(&at, &format!("map_type {other}"))),
                };
            }
            ONCE_KW => bitmap.once = true,
            INTERPOLATE_KW => {
                let at = self.next()?;
                self.unget(at.clone());
                bitmap.interpolate = match self.int()? {
                    2 => Interpolation::Bilinear,
                    4 => Interpolation::NormalizedDistance,
                    3 => return Err(self.unsupported(&at, "bicubic interpolation (interpolate 3)")),
                    // POV-Ray ignores the other numbers.
                    _ => Interpolation::None,
                };
            }
            _ => return Ok(false),
        }
        Ok(true)
    }

    /// The image's colours in the scene's working space: decoded by the gamma given or the
    /// file's own (sRGB when it says none, as POV-Ray 3.7 reads PNG files), then encoded by
    /// `assumed_gamma`. Scenes before 3.7 use the stored values as they are.
    fn working_colours(&self, file: &BitmapFile) -> Arc<Image> {
        let gamma = file.gamma.or(file.image.gamma);
        if self.version < 3.7 && file.gamma.is_none() {
            return file.image.clone();
        }
        let working = self.settings.assumed_gamma.unwrap_or(1.0) as f32;
        let decode = move |v: f32| -> f32 {
            let linear = match gamma.unwrap_or(FileGamma::Srgb) {
                FileGamma::Srgb => {
                    if v <= 0.04045 {
                        v / 12.92
                    } else {
                        ((v + 0.055) / 1.055).powf(2.4)
                    }
                }
                FileGamma::Power(g) => v.powf(g as f32),
            };
            if working == 1.0 {
                linear
            } else {
                linear.powf(1.0 / working)
            }
        };
        Arc::new(file.image.map_colours(decode))
    }

    /// The values a bump map or image pattern reads: as stored, unless a gamma is given.
    pub(super) fn data_values(file: &BitmapFile) -> Arc<Image> {
        match file.gamma {
            None => file.image.clone(),
            Some(FileGamma::Power(g)) => Arc::new(file.image.map_colours(|v| v.powf(g as f32))),
            Some(FileGamma::Srgb) => Arc::new(file.image.map_colours(|v| {
                if v <= 0.04045 {
                    v / 12.92
                } else {
                    ((v + 0.055) / 1.055).powf(2.4)
                }
            })),
        }
    }

    /// `{ FILE [modifiers] }` after `image_map`.
    pub(super) fn image_map_body(&mut self) -> Result<ImageMap> {
        self.expect(L_BRACE, "'{'")?;
        let file = self.bitmap_file()?;
        let mut map = ImageMap {
            bitmap: new_bitmap(self.working_colours(&file)),
            filter: PaletteAmounts::default(),
            transmit: PaletteAmounts::default(),
            transform: Transform::IDENTITY,
            warps: Vec::new(),
            turbulence: None,
            uv_mapping: false,
        };
        loop {
            let token = self.next()?;
            if token.kind == R_BRACE {
                return Ok(map);
            }
            if self.bitmap_modifier(&mut map.bitmap, &token)? {
                continue;
            }
            let amounts = match token.kind {
                FILTER_KW => &mut map.filter,
                TRANSMIT_KW => &mut map.transmit,
                USE_INDEX_KW | USE_COLOR_KW | USE_COLOUR_KW => continue,
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected an image_map modifier or '}}', found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            };
            let mut amounts = std::mem::take(amounts);
            if self.peek_kind()? == ALL_KW {
                self.next()?;
                amounts.all = Some(self.float()?);
            } else {
                let index = self.int()?;
                self.eat(COMMA)?;
                let amount = self.float()?;
                if (0..=255).contains(&index) {
                    amounts.by_index.push((index as u8, amount));
                }
            }
            match token.kind {
                FILTER_KW => map.filter = amounts,
                _ => map.transmit = amounts,
            }
        }
    }

    /// `{ FILE [modifiers] texture {...}... }` after `material_map`: a texture chosen by
    /// each pixel's palette index (or red value), counting round the list. POV-Ray 3.7
    /// takes no transformation inside the map, though its manual shows one.
    pub(super) fn material_map_body(&mut self, keyword: &Token) -> Result<Texture> {
        self.expect(L_BRACE, "'{'")?;
        let file = self.bitmap_file()?;
        let mut image = ImagePattern {
            bitmap: new_bitmap(Self::data_values(&file)),
            value: ImageValue::MaterialIndex,
        };
        let mut entries = Vec::new();
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => break,
                TEXTURE_KW => entries.push((entries.len() as f64, self.texture_body()?)),
                _ if entries.is_empty() && self.bitmap_modifier(&mut image.bitmap, &token)? => {}
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected a bitmap modifier, texture or '}}' in a material_map, \
                             found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
        if entries.is_empty() {
            return Err(self.error_at(keyword, "a material_map needs at least one texture"));
        }
        let kind = PatternKind::MaterialMap {
            image: Box::new(image),
            textures: entries.len(),
        };
        Ok(Texture::Pattern {
            pattern: Box::new(Pattern::new(kind)),
            map: BlendMap { entries },
        })
    }

    /// `{ FILE [modifiers] }` after `image_pattern`.
    pub(super) fn image_pattern_body(&mut self) -> Result<ImagePattern> {
        self.expect(L_BRACE, "'{'")?;
        let file = self.bitmap_file()?;
        let mut pattern = ImagePattern {
            bitmap: new_bitmap(Self::data_values(&file)),
            value: ImageValue::Grey,
        };
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => return Ok(pattern),
                USE_ALPHA_KW => pattern.value = ImageValue::Alpha,
                // POV-Ray accepts these here but an image pattern always reads the colour
                // (measured: `use_index` on a palette image still gives grey levels).
                USE_INDEX_KW | USE_COLOR_KW | USE_COLOUR_KW => pattern.value = ImageValue::Grey,
                _ if self.bitmap_modifier(&mut pattern.bitmap, &token)? => {}
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected an image_pattern modifier or '}}', found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
    }

    /// `{ FILE [modifiers] }` after `bump_map`: the heights and the bump size.
    pub(super) fn bump_map_body(&mut self) -> Result<(ImagePattern, f64)> {
        self.expect(L_BRACE, "'{'")?;
        let file = self.bitmap_file()?;
        let mut pattern = ImagePattern {
            bitmap: new_bitmap(Self::data_values(&file)),
            value: ImageValue::Grey,
        };
        let mut bump_size = 1.0;
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => return Ok((pattern, bump_size)),
                BUMP_SIZE_KW => bump_size = self.float()?,
                USE_INDEX_KW => pattern.value = index_value(&pattern.bitmap.image),
                USE_COLOR_KW | USE_COLOUR_KW => pattern.value = ImageValue::Grey,
                _ if self.bitmap_modifier(&mut pattern.bitmap, &token)? => {}
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected a bump_map modifier or '}}', found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
    }
}

fn new_bitmap(image: Arc<Image>) -> Bitmap {
    Bitmap {
        image,
        map_type: MapType::Planar,
        once: false,
        interpolate: Interpolation::None,
    }
}

/// `use_index` reads palette indices where the image has them, its colours elsewhere.
fn index_value(image: &Image) -> ImageValue {
    if image.indices.is_some() {
        ImageValue::Index
    } else {
        ImageValue::Grey
    }
}

#[cfg(test)]
mod tests {
    use crate::{EvalOptions, MemoryFiles, evaluate};

    fn error(scene: &str, files: MemoryFiles) -> String {
        let files = files.with("scene.pov", scene);
        let evaluation = evaluate("scene.pov", &files, &EvalOptions::default());
        let error = evaluation
            .diagnostics
            .iter()
            .find(|d| d.is_error())
            .expect("an error");
        format!("{} {:?} {:?}", error.message, error.span.range, error.notes)
    }

    /// A 1 by 1 grey PNG.
    const PIXEL: &[u8] = &[
        137, 80, 78, 71, 13, 10, 26, 10, 0, 0, 0, 13, 73, 72, 68, 82, 0, 0, 0, 1, 0, 0, 0, 1, 8, 0,
        0, 0, 0, 58, 126, 155, 85, 0, 0, 0, 10, 73, 68, 65, 84, 120, 156, 99, 104, 0, 0, 0, 130, 0,
        129, 119, 205, 114, 182, 0, 0, 0, 0, 73, 69, 78, 68, 174, 66, 96, 130,
    ];

    #[test]
    fn image_files_are_found_decoded_or_refused_with_located_errors() {
        let mut files = MemoryFiles::new();
        files.insert_bytes("map.png", PIXEL);
        files.insert_bytes("bad.png", &PIXEL[..40]);
        let scene = |body: &str| format!("plane {{ z, 0 pigment {{ image_map {{ {body} }} }} }}");
        let ok = files
            .clone()
            .with("scene.pov", scene("png \"map\" interpolate 2"));
        assert!(!evaluate("scene.pov", &ok, &EvalOptions::default()).has_errors());
        assert_eq!(
            error(&scene("png \"missing.png\""), files.clone()),
            "cannot find image file 'missing.png' 39..52 [\"files available: bad.png, map.png\"]"
        );
        assert!(
            error(&scene("png \"bad.png\""), files.clone())
                .starts_with("cannot read 'bad.png': not a valid PNG file")
        );
        assert!(
            error(&scene("jpeg \"map.png\""), files.clone())
                .starts_with("cannot read 'map.png': not a valid JPEG file")
        );
        // Without a type keyword the extension names the format, as in POV-Ray 3.7: a PNG
        // under another name is read as that format, not as PNG.
        let mut renamed = files.clone();
        renamed.insert_bytes("photo.jpg", PIXEL);
        renamed.insert_bytes("map.gif", PIXEL);
        assert!(
            error(&scene("\"photo.jpg\""), renamed.clone())
                .starts_with("cannot read 'photo.jpg': not a valid JPEG file")
        );
        renamed.insert_bytes(
            "real.jpg",
            &include_bytes!("../image/testdata/colour.jpg")[..],
        );
        let jpeg = renamed.clone().with("scene.pov", scene("\"real.jpg\""));
        assert!(!evaluate("scene.pov", &jpeg, &EvalOptions::default()).has_errors());
        assert!(error(&scene("\"map.gif\""), renamed).starts_with("cannot read 'map.gif'"));
        assert_eq!(
            error(&scene("png \"map.png\" map_type 3"), files.clone()),
            "not supported yet: map_type 3 58..59 []"
        );
        // The note names the files of the missing one's kind, the first thirty of them.
        let mut many = files;
        many.insert_bytes("notes.txt", PIXEL);
        for i in 10..45 {
            many.insert_bytes(format!("tile{i}.PNG"), PIXEL);
        }
        let listed: Vec<String> = (10..38).map(|i| format!("tile{i}.PNG")).collect();
        assert_eq!(
            error(&scene("png \"tile9.png\""), many),
            format!(
                "cannot find image file 'tile9.png' 39..50 [\"files available: bad.png, map.png, {} and 7 more\"]",
                listed.join(", ")
            )
        );
    }

    #[test]
    fn material_maps_list_textures_after_the_image_and_its_modifiers() {
        let mut files = MemoryFiles::new();
        files.insert_bytes("map.png", PIXEL);
        let scene =
            |body: &str| format!("plane {{ z, 0 texture {{ material_map {{ {body} }} }} }}");
        for ok in [
            "png \"map.png\" texture { pigment { rgb 1 } }",
            "png \"map.png\" map_type 1 once interpolate 2 texture { pigment { rgb 1 } } texture { }",
        ] {
            let ok = files.clone().with("scene.pov", scene(ok));
            assert!(!evaluate("scene.pov", &ok, &EvalOptions::default()).has_errors());
        }
        assert_eq!(
            error(&scene("png \"map.png\" once"), files.clone()),
            "a material_map needs at least one texture 23..35 []"
        );
        // POV-Ray 3.7 takes neither a transformation nor a bitmap modifier after the
        // textures.
        assert_eq!(
            error(&scene("png \"map.png\" texture { } scale 2"), files.clone()),
            "expected a bitmap modifier, texture or '}' in a material_map, found 'scale' 64..69 []"
        );
        assert_eq!(
            error(&scene("png \"map.png\" texture { } once"), files),
            "expected a bitmap modifier, texture or '}' in a material_map, found 'once' 64..68 []"
        );
    }

    #[test]
    fn density_files_are_found_read_or_refused_with_located_errors() {
        let mut files = MemoryFiles::new();
        // A 2 by 1 by 1 grid of 8-bit voxels.
        files.insert_bytes("grid.df3", &[0u8, 2, 0, 1, 0, 1, 0, 255][..]);
        files.insert_bytes("short.df3", &[0u8, 2, 0, 1, 0, 1, 0][..]);
        let scene = |body: &str| format!("sphere {{ 0, 1 pigment {{ density_file {body} }} }}");
        for ok in ["df3 \"grid.df3\"", "df3 \"grid.df3\" interpolate 1 scale 2"] {
            let ok = files.clone().with("scene.pov", scene(ok));
            assert!(!evaluate("scene.pov", &ok, &EvalOptions::default()).has_errors());
        }
        assert_eq!(
            error(&scene("df3 \"missing.df3\""), files.clone()),
            "cannot find density file 'missing.df3' 41..54 [\"files available: grid.df3, short.df3\"]"
        );
        assert!(
            error(&scene("df3 \"short.df3\""), files.clone())
                .starts_with("cannot read 'short.df3': not a valid df3 file")
        );
        assert_eq!(
            error(&scene("png \"grid.df3\""), files.clone()),
            "expected df3 after density_file, found 'png' 37..40 []"
        );
        assert_eq!(
            error(&scene("df3 \"grid.df3\" interpolate 2"), files.clone()),
            "not supported yet: tricubic density_file interpolation (interpolate 2) 64..65 []"
        );
        assert_eq!(
            error(&scene("df3 \"grid.df3\" interpolate 3"), files),
            "interpolate must be 0, 1 or 2 for a density_file, not 3 64..65 []"
        );
    }

    /// Warps and turbulence move an image map's point as they move a pattern's.
    #[test]
    fn image_maps_take_warps_and_turbulence() {
        let red_at = |modifiers: &str, x: f64, y: f64| -> f64 {
            // Two pixels: black on the left half of the unit square, white on the right.
            let mut files = MemoryFiles::new();
            files.insert_bytes("ramp.pgm", &b"P5 2 1 255\n\x00\xff"[..]);
            let files = files.with(
                    "scene.pov",
                    format!(
                        "#declare F = function {{ pigment {{ image_map {{ pgm \"ramp.pgm\" }} {modifiers} }} }}
                         #debug str(F({x}, {y}, 0).red, 0, 6)"
                    ),
                );
            let evaluation = evaluate("scene.pov", &files, &EvalOptions::default());
            assert!(!evaluation.has_errors(), "{:?}", evaluation.diagnostics);
            evaluation.debug_text().parse().unwrap()
        };
        assert_eq!(red_at("", 0.25, 0.5), 0.0);
        assert_eq!(red_at("", 0.75, 0.5), 1.0);
        // The left half repeated: x = 0.75 shows x = 0.25.
        assert_eq!(red_at("warp { repeat x * 0.5 }", 0.75, 0.5), 0.0);
        // A translation written before the warp acts after it: the repeated half, moved
        // by half the image (which tiles the plane), is the white one.
        assert_eq!(
            red_at("translate x * 0.5 warp { repeat x * 0.5 }", 0.25, 0.5),
            1.0
        );
        let points = [
            (0.3, 0.2),
            (0.45, 0.6),
            (0.55, 0.9),
            (0.7, 0.4),
            (0.52, 0.5),
        ];
        let mut moved = false;
        for (x, y) in points {
            let classic = red_at("turbulence 0.3", x, y);
            assert_eq!(classic, red_at("warp { turbulence 0.3 }", x, y));
            moved |= classic != red_at("", x, y);
        }
        assert!(moved, "turbulence moved no point");
    }
}
