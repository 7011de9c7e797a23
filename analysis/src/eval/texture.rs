//! Textures and their parts: `texture`, `pigment`, `normal`, `finish`, `interior`, patterns
//! with their modifiers, colour and pigment maps, and how transformations reach them.

use super::tokens::Token;
use super::value::Value;
use super::{Evaluator, Result};
use crate::scene::{
    BlendMap, Colour, Finish, Interior, Normal, NormalKind, Pattern, PatternKind, Pigment,
    Reflection, Texture, Transform, Turbulence, WaveType,
};
use crate::scene::{Fractal, FractalKind};
use glam::DVec3;
use std::sync::Arc;
use syntax::SyntaxKind::{self, *};

/// The number of entries a block pattern takes in place of a map.
pub(super) fn block_entries(kind: &PatternKind) -> Option<usize> {
    match kind {
        PatternKind::Checker => Some(2),
        PatternKind::Brick { .. } => Some(2),
        PatternKind::Hexagon => Some(3),
        PatternKind::Square => Some(4),
        PatternKind::Triangular => Some(6),
        PatternKind::Object(_) => Some(2),
        _ => None,
    }
}

impl Evaluator<'_> {
    /// `{ ... }` after `texture`.
    pub fn texture_body(&mut self) -> Result<Texture> {
        self.expect(L_BRACE, "'{'")?;
        let uv_mapping = self.eat(UV_MAPPING_KW)?;
        let mut texture = self.texture_inner(R_BRACE)?;
        self.expect(R_BRACE, "'}'")?;
        if uv_mapping {
            map_texture_uv(&mut texture);
        }
        Ok(texture)
    }

    /// The inside of a texture, up to (not including) `end`: `}` for `texture { }`, `]` for
    /// a texture map entry, which POV-Ray reads as a texture body (`[0.5 T finish {...}]`,
    /// `[0.5 pigment {...}]`).
    fn texture_inner(&mut self, end: SyntaxKind) -> Result<Texture> {
        let first = self.next()?;
        let mut texture = match first.slot.as_ref().map(|s| s.borrow().clone()) {
            Some(Value::Texture(t)) => Texture::clone(&t),
            _ => {
                self.unget(first.clone());
                self.default_texture.clone()
            }
        };
        let end_text = if end == R_BRACK { "']'" } else { "'}'" };
        loop {
            let token = self.next()?;
            match token.kind {
                kind if kind == end => {
                    self.unget(token);
                    return Ok(texture);
                }
                PIGMENT_KW | NORMAL_KW | FINISH_KW => {
                    // On a layered texture they change the top layer.
                    let Texture::Plain {
                        pigment,
                        normal,
                        finish,
                    } = top_layer(&mut texture)
                    else {
                        return Err(self.error_at(
                            &token,
                            "a patterned texture takes no pigment, normal or finish of its own",
                        ));
                    };
                    match token.kind {
                        PIGMENT_KW => *pigment = self.pigment_with(Some(pigment.clone()))?,
                        NORMAL_KW => *normal = self.normal_with(normal.clone())?,
                        _ => *finish = Arc::new(self.finish_body(Some(finish))?),
                    }
                }
                kind if Self::starts_transform(kind) => {
                    let t = self.transformation(&token)?;
                    transform_texture(&mut texture, &t);
                }
                TILES_KW => texture = self.tiles()?,
                MATERIAL_MAP_KW => texture = self.material_map_body(&token)?,
                IMAGE_MAP_KW => {
                    return Err(self.unsupported(&token, self.text(&token)));
                }
                kind if pattern_keyword(kind) => {
                    let pattern = self.pattern(&token)?;
                    let map = match block_entries(&pattern.kind) {
                        Some(n) => self.block_textures(n)?,
                        None => BlendMap {
                            entries: Vec::new(),
                        },
                    };
                    if matches!(pattern.kind, PatternKind::Object(_)) {
                        self.expect(R_BRACE, "'}'")?;
                    }
                    texture = Texture::Pattern {
                        pattern: Box::new(pattern),
                        map,
                    };
                }
                TEXTURE_MAP_KW => {
                    let Texture::Pattern { pattern, map } = &mut texture else {
                        return Err(
                            self.error_at(&token, "a texture_map needs a pattern before it")
                        );
                    };
                    *map = self.texture_map_body()?;
                    into_pattern_space(map, pattern, transform_texture);
                }
                _ if matches!(texture, Texture::Pattern { .. }) => {
                    let Texture::Pattern { pattern, .. } = &mut texture else {
                        unreachable!("just matched")
                    };
                    if !self.pattern_modifier(pattern, &token)? {
                        return Err(self.error_at(
                            &token,
                            format!(
                                "expected a pattern modifier, texture_map or {end_text}, found {}",
                                self.describe(&token)
                            ),
                        ));
                    }
                }
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected pigment, normal, finish or {end_text} in texture, found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
    }

    /// The textures listed after a block pattern (`checker texture { A } texture { B }`).
    fn block_textures(&mut self, count: usize) -> Result<BlendMap<Texture>> {
        let mut entries = Vec::new();
        while entries.len() < count && self.eat(TEXTURE_KW)? {
            entries.push((entries.len() as f64, self.texture_body()?));
            self.eat(COMMA)?;
        }
        Ok(BlendMap { entries })
    }

    /// `tiles { texture {...} tile2 texture {...} }`, the old form of a textured checker.
    fn tiles(&mut self) -> Result<Texture> {
        self.expect(L_BRACE, "'{'")?;
        let mut first = Vec::new();
        let mut second = Vec::new();
        let mut in_second = false;
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => break,
                TILE2_KW => in_second = true,
                TEXTURE_KW => {
                    let texture = self.texture_body()?;
                    if in_second {
                        second.push(texture)
                    } else {
                        first.push(texture)
                    }
                }
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected texture, tile2 or '}}' in tiles, found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
        let layered = |layers: Vec<Texture>| match layers.len() {
            0 => Texture::default(),
            1 => layers.into_iter().next().unwrap_or_default(),
            _ => Texture::Layered(layers),
        };
        let entries = vec![(0.0, layered(first)), (1.0, layered(second))];
        Ok(Texture::Pattern {
            pattern: Box::new(Pattern::new(PatternKind::Checker)),
            map: BlendMap { entries },
        })
    }

    /// `{ [value texture body] ... }` after `texture_map`, or a texture map identifier.
    fn texture_map_body(&mut self) -> Result<BlendMap<Texture>> {
        let open = self.next()?;
        if open.kind != L_BRACE {
            return match open.slot.as_ref().map(|s| s.borrow().clone()) {
                Some(Value::TextureMap(map)) => Ok(BlendMap::clone(&map)),
                _ => Err(self.error_at(
                    &open,
                    format!(
                        "expected '{{' or a texture_map identifier, found {}",
                        self.describe(&open)
                    ),
                )),
            };
        }
        let mut entries = Vec::new();
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => break,
                L_BRACK => {
                    // An average's entries may leave out their weight, which is then 1.
                    let value = if self.value_follows()? {
                        self.float()?
                    } else {
                        1.0
                    };
                    self.eat(COMMA)?;
                    let texture = self.texture_inner(R_BRACK)?;
                    entries.push((value, texture));
                    self.expect(R_BRACK, "']'")?;
                }
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected '[' or '}}' in texture_map, found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
        if entries.is_empty() {
            return Err(self.error_at(&open, "a texture_map needs at least one entry"));
        }
        Ok(BlendMap { entries })
    }

    /// `{ ... }` after `pigment`, starting from a fresh black pigment.
    pub fn pigment_body(&mut self) -> Result<Pigment> {
        self.pigment_with(None)
    }

    /// `{ ... }` after `pigment`, modifying `base` (an object's current pigment).
    pub fn pigment_with(&mut self, base: Option<Pigment>) -> Result<Pigment> {
        self.expect(L_BRACE, "'{'")?;
        let uv_mapping = self.eat(UV_MAPPING_KW)?;
        let mut pigment = self.pigment_inner(base, R_BRACE)?;
        self.expect(R_BRACE, "'}'")?;
        if uv_mapping {
            map_pigment_uv(&mut pigment);
        }
        Ok(pigment)
    }

    /// The inside of a pigment, up to (not including) `end`: `}` for `pigment { }`, `]`
    /// for a pigment map entry.
    fn pigment_inner(&mut self, base: Option<Pigment>, end: SyntaxKind) -> Result<Pigment> {
        let first = self.next()?;
        let mut pigment = match first.kind {
            IDENT => match first.slot.as_ref().map(|s| s.borrow().clone()) {
                Some(Value::Pigment(p)) => Pigment::clone(&p),
                Some(Value::Colour(_) | Value::Vector(_) | Value::Float(_)) => {
                    self.unget(first);
                    Pigment::Solid(self.scene_colour()?)
                }
                Some(other) => {
                    return Err(self.error_at(
                        &first,
                        format!("expected a pigment or color, found {}", other.type_name()),
                    ));
                }
                None => return Err(self.undeclared(&first)),
            },
            COLOR_KW | COLOUR_KW | RGB_KW | RGBF_KW | RGBT_KW | RGBFT_KW | SRGB_KW | SRGBF_KW
            | SRGBT_KW | SRGBFT_KW | RED_KW | GREEN_KW | BLUE_KW | FILTER_KW | TRANSMIT_KW | LT
            | NUMBER => {
                self.unget(first);
                Pigment::Solid(self.scene_colour()?)
            }
            IMAGE_MAP_KW => Pigment::Image(Box::new(self.image_map_body()?)),
            kind if pattern_keyword(kind) => {
                let pattern = self.pattern(&first)?;
                let map = match block_entries(&pattern.kind) {
                    Some(n) => self.block_pigments(n, &pattern.kind)?,
                    None => default_map(&pattern.kind),
                };
                if matches!(pattern.kind, PatternKind::Object(_)) {
                    self.expect(R_BRACE, "'}'")?;
                }
                Pigment::Pattern {
                    pattern: Box::new(pattern),
                    map,
                }
            }
            _ => {
                self.unget(first);
                base.unwrap_or(Pigment::Solid(Colour::BLACK))
            }
        };
        loop {
            let token = self.next()?;
            if token.kind == end {
                self.unget(token);
                return Ok(pigment);
            }
            if Self::starts_transform(token.kind) {
                let t = self.transformation(&token)?;
                transform_pigment(&mut pigment, &t);
                continue;
            }
            // `quick_color` is the colour of POV-Ray's quality levels 0 to 5, which our
            // renderer draws with the full pigment, so it is read and left out.
            if matches!(token.kind, QUICK_COLOR_KW | QUICK_COLOUR_KW) {
                self.colour()?;
                continue;
            }
            if let Pigment::Pattern { pattern, map } = &mut pigment {
                match token.kind {
                    COLOR_MAP_KW | COLOUR_MAP_KW => {
                        *map = pigment_entries(self.colour_map_body()?);
                        continue;
                    }
                    PIGMENT_MAP_KW => {
                        *map = self.pigment_map_body()?;
                        into_pattern_space(map, pattern, transform_pigment);
                        continue;
                    }
                    _ => {
                        if self.pattern_modifier(pattern, &token)? {
                            continue;
                        }
                    }
                }
            } else if let Pigment::Image(map) = &mut pigment
                && matches!(
                    token.kind,
                    TURBULENCE_KW | WARP_KW | OCTAVES_KW | OMEGA_KW | LAMBDA_KW
                )
            {
                // An image map is placed as a pattern is: its warps and turbulence go
                // through the pattern modifiers on a stand-in pattern with its placement.
                let mut placement = Pattern::new(PatternKind::Planar);
                placement.transform = map.transform;
                placement.warps = std::mem::take(&mut map.warps);
                placement.turbulence = map.turbulence.take();
                let parsed = self.pattern_modifier(&mut placement, &token);
                map.transform = placement.transform;
                map.warps = placement.warps;
                map.turbulence = placement.turbulence;
                parsed?;
                continue;
            }
            return Err(self.error_at(
                &token,
                format!(
                    "expected a pigment modifier or '}}', found {}",
                    self.describe(&token)
                ),
            ));
        }
    }

    /// The colours or pigments listed after a block pattern (`checker A, B`).
    fn block_pigments(&mut self, count: usize, kind: &PatternKind) -> Result<BlendMap<Pigment>> {
        let mut entries = default_map(kind).entries;
        for entry in entries.iter_mut().take(count) {
            let token = self.next()?;
            let pigment = match token.kind {
                PIGMENT_KW => self.pigment_body()?,
                COLOR_KW | COLOUR_KW | RGB_KW | RGBF_KW | RGBT_KW | RGBFT_KW | SRGB_KW
                | SRGBF_KW | SRGBT_KW | SRGBFT_KW | RED_KW | GREEN_KW | BLUE_KW | FILTER_KW
                | TRANSMIT_KW | LT => {
                    self.unget(token);
                    Pigment::Solid(self.scene_colour()?)
                }
                IDENT
                    if token.slot.as_ref().is_some_and(|s| {
                        matches!(
                            &*s.borrow(),
                            Value::Colour(_) | Value::Vector(_) | Value::Float(_)
                        )
                    }) =>
                {
                    self.unget(token);
                    Pigment::Solid(self.scene_colour()?)
                }
                IDENT
                    if token
                        .slot
                        .as_ref()
                        .is_some_and(|s| matches!(&*s.borrow(), Value::Pigment(_))) =>
                {
                    match token.slot.as_ref().map(|s| s.borrow().clone()) {
                        Some(Value::Pigment(p)) => Pigment::clone(&p),
                        _ => unreachable!("checked just above"),
                    }
                }
                _ => {
                    self.unget(token);
                    break;
                }
            };
            entry.1 = pigment;
            self.eat(COMMA)?;
        }
        Ok(BlendMap { entries })
    }

    /// A pattern keyword (already read) and the parameters that follow it directly.
    pub(super) fn pattern(&mut self, keyword: &Token) -> Result<Pattern> {
        let kind = match keyword.kind {
            AGATE_KW => PatternKind::Agate { turb: 1.0 },
            AVERAGE_KW => PatternKind::Average,
            BOXED_KW => PatternKind::Boxed,
            BOZO_KW | SPOTTED_KW => PatternKind::Bozo,
            BRICK_KW => PatternKind::Brick {
                size: DVec3::new(8.0, 3.0, 4.5),
                mortar: 0.5,
            },
            BUMPS_KW => PatternKind::Bumps,
            CELLS_KW => PatternKind::Cells,
            CHECKER_KW => PatternKind::Checker,
            CRACKLE_KW => PatternKind::Crackle {
                form: DVec3::new(-1.0, 1.0, 0.0),
                metric: 2.0,
                offset: 0.0,
                solid: false,
            },
            CYLINDRICAL_KW => PatternKind::Cylindrical,
            DENTS_KW => PatternKind::Dents,
            GRADIENT_KW => PatternKind::gradient(self.vector()?),
            GRANITE_KW => PatternKind::Granite,
            HEXAGON_KW => PatternKind::Hexagon,
            LEOPARD_KW => PatternKind::Leopard,
            MARBLE_KW => PatternKind::Marble,
            ONION_KW => PatternKind::Onion,
            PLANAR_KW => PatternKind::Planar,
            QUILTED_KW => PatternKind::Quilted {
                control0: 1.0,
                control1: 1.0,
            },
            RADIAL_KW => PatternKind::Radial,
            RIPPLES_KW => PatternKind::Ripples,
            SPHERICAL_KW => PatternKind::Spherical,
            SPIRAL1_KW => PatternKind::Spiral1 {
                arms: self.float()?,
            },
            SPIRAL2_KW => PatternKind::Spiral2 {
                arms: self.float()?,
            },
            SQUARE_KW => PatternKind::Square,
            TILING_KW => {
                let number = self.int()?;
                if !(1..=27).contains(&number) {
                    return Err(self.error_at(keyword, "the tiling number must be from 1 to 27"));
                }
                PatternKind::Tiling(number as u8)
            }
            TRIANGULAR_KW => PatternKind::Triangular,
            WAVES_KW => PatternKind::Waves,
            WOOD_KW => PatternKind::Wood,
            WRINKLES_KW => PatternKind::Wrinkles,
            MANDEL_KW | JULIA_KW | MAGNET_KW => {
                PatternKind::Fractal(Box::new(self.fractal(keyword)?))
            }
            FUNCTION_KW => {
                self.unget(keyword.clone());
                PatternKind::Function(Arc::new(self.function_value()?))
            }
            IMAGE_PATTERN_KW => PatternKind::Image(Box::new(self.image_pattern_body()?)),
            DENSITY_FILE_KW => PatternKind::DensityFile {
                grid: self.density_file()?,
                trilinear: false,
            },
            _ => match self.pattern_head(keyword)? {
                Some(pattern) => pattern,
                None => {
                    return Err(
                        self.unsupported(keyword, &format!("the {} pattern", self.text(keyword)))
                    );
                }
            },
        };
        let mut pattern = Pattern::new(kind);
        pattern.noise_generator = self.settings.noise_generator;
        // Marble, wood and the spirals run their maps forth and back unless told otherwise.
        if matches!(keyword.kind, MARBLE_KW | WOOD_KW | SPIRAL1_KW | SPIRAL2_KW) {
            pattern.wave = WaveType::Triangle;
        }
        Ok(pattern)
    }

    /// The parameters after `mandel`, `julia` or `magnet`.
    fn fractal(&mut self, keyword: &Token) -> Result<Fractal> {
        let kind = match keyword.kind {
            MANDEL_KW => FractalKind::Mandel,
            JULIA_KW => {
                let c = self.vector_of(2)?;
                self.eat(COMMA)?;
                FractalKind::Julia {
                    c: (c.c[0], c.c[1]),
                }
            }
            _ => {
                let variant = self.int()?.clamp(1, 2) as u8;
                let which = self.next()?;
                let julia = match which.kind {
                    MANDEL_KW => None,
                    JULIA_KW => {
                        let c = self.vector_of(2)?;
                        self.eat(COMMA)?;
                        Some((c.c[0], c.c[1]))
                    }
                    _ => {
                        return Err(self.error_at(
                            &which,
                            format!(
                                "expected mandel or julia after magnet, found {}",
                                self.describe(&which)
                            ),
                        ));
                    }
                };
                FractalKind::Magnet { variant, julia }
            }
        };
        let max_iteration = self.int()?.max(1) as u32;
        Ok(Fractal {
            kind,
            max_iteration,
            exponent: 2,
            interior: (0, 1.0),
            exterior: (1, 1.0),
        })
    }

    /// A modifier of a pattern; false when `token` is not one.
    pub(super) fn pattern_modifier(
        &mut self,
        pattern: &mut Pattern,
        token: &Token,
    ) -> Result<bool> {
        if self.pattern_parameter(pattern, token)? {
            return Ok(true);
        }
        match token.kind {
            kind if Self::starts_transform(kind) => {
                let t = self.transformation(token)?;
                pattern.transform = pattern.transform.then(&t);
            }
            TURBULENCE_KW => {
                let amount = self.vector()?;
                turbulence(pattern).amount = amount;
            }
            OCTAVES_KW => turbulence(pattern).octaves = self.int()?.clamp(1, 10) as u32,
            OMEGA_KW => turbulence(pattern).omega = self.float()?,
            LAMBDA_KW => turbulence(pattern).lambda = self.float()?,
            FREQUENCY_KW => pattern.frequency = self.float()?,
            PHASE_KW => pattern.phase = self.float()?,
            RAMP_WAVE_KW => pattern.wave = WaveType::Ramp,
            TRIANGLE_WAVE_KW => pattern.wave = WaveType::Triangle,
            SINE_WAVE_KW => pattern.wave = WaveType::Sine,
            SCALLOP_WAVE_KW => pattern.wave = WaveType::Scallop,
            CUBIC_WAVE_KW => pattern.wave = WaveType::Cubic,
            POLY_WAVE_KW => {
                let exponent = if matches!(self.peek_kind()?, NUMBER | L_PAREN) {
                    self.float()?
                } else {
                    1.0
                };
                pattern.wave = WaveType::Poly(exponent);
            }
            NOISE_GENERATOR_KW => pattern.noise_generator = self.int()?.clamp(1, 3) as u8,
            AGATE_TURB_KW => {
                let value = self.float()?;
                if let PatternKind::Agate { turb } = &mut pattern.kind {
                    *turb = value;
                }
            }
            BRICK_SIZE_KW | MORTAR_KW => {
                let PatternKind::Brick { size, mortar } = &mut pattern.kind else {
                    return Err(self.error_at(
                        token,
                        format!("'{}' applies to brick only", self.text(token)),
                    ));
                };
                if token.kind == BRICK_SIZE_KW {
                    *size = self.vector()?;
                } else {
                    *mortar = self.float()?;
                }
            }
            CONTROL0_KW | CONTROL1_KW => {
                let value = self.float()?;
                if let PatternKind::Quilted { control0, control1 } = &mut pattern.kind {
                    if token.kind == CONTROL0_KW {
                        *control0 = value
                    } else {
                        *control1 = value
                    }
                }
            }
            FORM_KW | METRIC_KW | OFFSET_KW | SOLID_KW => {
                let PatternKind::Crackle {
                    form,
                    metric,
                    offset,
                    solid,
                } = &mut pattern.kind
                else {
                    return Err(self.error_at(
                        token,
                        format!("'{}' applies to crackle only", self.text(token)),
                    ));
                };
                match token.kind {
                    FORM_KW => *form = self.vector()?,
                    METRIC_KW => *metric = self.float()?,
                    OFFSET_KW => *offset = self.float()?,
                    _ => *solid = true,
                }
            }
            WARP_KW => self.warp(pattern)?,
            EXPONENT_KW | INTERIOR_KW | EXTERIOR_KW => {
                let PatternKind::Fractal(fractal) = &mut pattern.kind else {
                    return Ok(false);
                };
                if token.kind == EXPONENT_KW {
                    fractal.exponent = self.int()?.clamp(2, 33) as u32;
                } else {
                    let most = if token.kind == INTERIOR_KW { 6 } else { 8 };
                    let kind = self.int()?.clamp(0, most) as u8;
                    self.eat(COMMA)?;
                    let factor = self.float()?;
                    if token.kind == INTERIOR_KW {
                        fractal.interior = (kind, factor);
                    } else {
                        fractal.exterior = (kind, factor);
                    }
                }
            }
            _ => return Ok(false),
        }
        Ok(true)
    }

    /// `{ [value colour] ... }` after `color_map`, or a colour map identifier.
    pub fn colour_map_body(&mut self) -> Result<BlendMap<Colour>> {
        let open = self.next()?;
        if open.kind != L_BRACE {
            return match open.slot.as_ref().map(|s| s.borrow().clone()) {
                Some(Value::ColourMap(map)) => Ok(BlendMap::clone(&map)),
                _ => Err(self.error_at(
                    &open,
                    format!(
                        "expected '{{' or a color_map identifier, found {}",
                        self.describe(&open)
                    ),
                )),
            };
        }
        let first = self.next()?;
        let mut entries: Vec<(f64, Colour)> = match first.slot.as_ref().map(|s| s.borrow().clone())
        {
            Some(Value::ColourMap(map)) => map.entries.clone(),
            _ => {
                self.unget(first);
                Vec::new()
            }
        };
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => break,
                L_BRACK => {
                    let value = self.float()?;
                    self.eat(COMMA)?;
                    if self.float_follows()? {
                        // The old two-value form: [v1, v2 color C1 color C2].
                        let end = self.float()?;
                        let c1 = self.scene_colour()?;
                        let c2 = self.scene_colour()?;
                        entries.push((value, c1));
                        entries.push((end, c2));
                    } else {
                        let colour = self.scene_colour()?;
                        entries.push((value, colour));
                    }
                    self.expect(R_BRACK, "']'")?;
                }
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected '[' or '}}' in color_map, found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
        if entries.is_empty() {
            return Err(self.error_at(&open, "a color_map needs at least one entry"));
        }
        Ok(BlendMap { entries })
    }

    /// `{ [value pigment{...}] ... }` after `pigment_map`.
    pub fn pigment_map_body(&mut self) -> Result<BlendMap<Pigment>> {
        let declared = |value: &Value| match value {
            Value::PigmentMap(map) => Some(BlendMap::clone(map)),
            _ => None,
        };
        self.blend_map_body("pigment_map", declared, |ev| {
            // An average's entries may leave out their weight, which is then 1.
            let value = if ev.value_follows()? {
                ev.float()?
            } else {
                1.0
            };
            ev.eat(COMMA)?;
            let pigment = if ev.eat(PIGMENT_KW)? {
                ev.pigment_body()?
            } else {
                ev.pigment_inner(None, R_BRACK)?
            };
            Ok((value, pigment))
        })
    }

    /// `{ [entry] ... }` after a map keyword named `what`, each entry read by `entry`
    /// between its brackets, or an identifier holding a map that `declared` accepts.
    pub(super) fn blend_map_body<T>(
        &mut self,
        what: &str,
        declared: impl Fn(&Value) -> Option<BlendMap<T>>,
        mut entry: impl FnMut(&mut Self) -> Result<(f64, T)>,
    ) -> Result<BlendMap<T>> {
        let open = self.next()?;
        if open.kind != L_BRACE {
            let map = open.slot.as_ref().and_then(|s| declared(&s.borrow()));
            return map.ok_or_else(|| {
                self.error_at(
                    &open,
                    format!(
                        "expected '{{' or a {what} identifier, found {}",
                        self.describe(&open)
                    ),
                )
            });
        }
        let mut entries = Vec::new();
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => break,
                L_BRACK => {
                    entries.push(entry(self)?);
                    self.expect(R_BRACK, "']'")?;
                }
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected '[' or '}}' in {what}, found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
        if entries.is_empty() {
            return Err(self.error_at(&open, format!("a {what} needs at least one entry")));
        }
        Ok(BlendMap { entries })
    }

    /// `{ ... }` after `normal`, starting from nothing; a declared normal needs a pattern.
    pub fn normal_body(&mut self) -> Result<Normal> {
        let at = self.next()?;
        self.unget(at.clone());
        self.normal_with(None)?
            .ok_or_else(|| self.error_at(&at, "this normal has no pattern"))
    }

    /// `{ ... }` after `normal`, modifying `base`. `None` when neither gives a pattern
    /// (`normal { bump_size 2 }` on a plain surface), which perturbs nothing.
    pub fn normal_with(&mut self, base: Option<Normal>) -> Result<Option<Normal>> {
        self.expect(L_BRACE, "'{'")?;
        let uv_mapping = self.eat(UV_MAPPING_KW)?;
        let mut normal = self.normal_inner(base, R_BRACE)?;
        self.expect(R_BRACE, "'}'")?;
        if let (true, Some(normal)) = (uv_mapping, &mut normal) {
            map_normal_uv(normal);
        }
        Ok(normal)
    }

    /// The inside of a normal, up to (not including) `end`: `}` for `normal { }`, `]` for
    /// a normal map entry.
    pub(super) fn normal_inner(
        &mut self,
        base: Option<Normal>,
        end: SyntaxKind,
    ) -> Result<Option<Normal>> {
        let first = self.next()?;
        let mut normal = match first.kind {
            IDENT => match first.slot.as_ref().map(|s| s.borrow().clone()) {
                Some(Value::Normal(n)) => Some(Normal::clone(&n)),
                Some(other) => {
                    return Err(self.error_at(
                        &first,
                        format!("expected a normal, found {}", other.type_name()),
                    ));
                }
                None => return Err(self.undeclared(&first)),
            },
            BUMP_MAP_KW => {
                let (image, bump_size) = self.bump_map_body()?;
                Some(Normal {
                    kind: NormalKind::BumpMap {
                        pattern: Box::new(Pattern::new(PatternKind::Image(Box::new(image)))),
                        bump_size,
                    },
                    accuracy: 0.02,
                    placement: None,
                })
            }
            kind if pattern_keyword(kind) => {
                let pattern = self.pattern(&first)?;
                let listed = match block_entries(&pattern.kind) {
                    Some(n) => self.block_normals(&pattern, n)?,
                    None => None,
                };
                if matches!(pattern.kind, PatternKind::Object(_)) {
                    self.expect(R_BRACE, "'}'")?;
                }
                match listed {
                    Some(map) => Some(map),
                    None => {
                        self.eat(COMMA)?;
                        let bump_size = if self.value_follows()? {
                            self.float()?
                        } else {
                            0.5
                        };
                        Some(Normal {
                            kind: NormalKind::Pattern {
                                pattern: Box::new(pattern),
                                bump_size,
                                slope_map: None,
                            },
                            accuracy: 0.02,
                            placement: None,
                        })
                    }
                }
            }
            _ => {
                self.unget(first);
                base
            }
        };
        loop {
            let token = self.next()?;
            if token.kind == end {
                self.unget(token);
                return Ok(normal);
            }
            if Self::starts_transform(token.kind) {
                let t = self.transformation(&token)?;
                if let Some(normal) = &mut normal {
                    transform_normal(normal, &t);
                }
                continue;
            }
            if matches!(token.kind, SLOPE_MAP_KW | NORMAL_MAP_KW) {
                self.normal_map_modifier(&mut normal, &token)?;
                continue;
            }
            if token.kind == BUMP_SIZE_KW || token.kind == ACCURACY_KW {
                let value = self.float()?;
                if let Some(normal) = &mut normal {
                    if token.kind == ACCURACY_KW {
                        normal.accuracy = value;
                    } else if let NormalKind::Pattern { bump_size, .. }
                    | NormalKind::BumpMap { bump_size, .. } = &mut normal.kind
                    {
                        *bump_size = value;
                    }
                }
                continue;
            }
            let pattern = match normal.as_mut().map(|n| &mut n.kind) {
                Some(
                    NormalKind::Pattern { pattern, .. }
                    | NormalKind::Map { pattern, .. }
                    | NormalKind::BumpMap { pattern, .. },
                ) => Some(pattern),
                None => None,
            };
            if let Some(pattern) = pattern
                && self.pattern_modifier(pattern, &token)?
            {
                continue;
            }
            return Err(self.error_at(
                &token,
                format!(
                    "expected a normal modifier or '}}', found {}",
                    self.describe(&token)
                ),
            ));
        }
    }

    /// Whether a number or float identifier comes next (and so no colour does).
    fn float_follows(&mut self) -> Result<bool> {
        let token = self.next()?;
        let starts = token.kind == NUMBER
            || (token.kind == IDENT
                && token
                    .slot
                    .as_ref()
                    .is_some_and(|s| matches!(&*s.borrow(), Value::Float(_))));
        self.unget(token);
        Ok(starts)
    }

    /// Whether a float expression starts at the next token.
    pub fn value_follows(&mut self) -> Result<bool> {
        let token = self.next()?;
        let starts = matches!(
            token.kind,
            NUMBER
                | L_PAREN
                | MINUS
                | PLUS
                | BANG
                | TRUE_KW
                | FALSE_KW
                | ON_KW
                | OFF_KW
                | YES_KW
                | NO_KW
                | PI_KW
                | TAU_KW
                | CLOCK_KW
        ) || (token.kind == IDENT
            && token
                .slot
                .as_ref()
                .is_some_and(|s| matches!(&*s.borrow(), Value::Float(_))));
        self.unget(token);
        Ok(starts)
    }

    /// `{ ... }` after `finish`, modifying `base`.
    pub fn finish_body(&mut self, base: Option<&Finish>) -> Result<Finish> {
        self.expect(L_BRACE, "'{'")?;
        let mut finish = base.cloned().unwrap_or_default();
        let first = self.next()?;
        match first.slot.as_ref().map(|s| s.borrow().clone()) {
            Some(Value::Finish(f)) => finish = Finish::clone(&f),
            _ => self.unget(first),
        }
        let mut albedos = Albedos::default();
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => {
                    albedos.apply_to(&mut finish);
                    return Ok(finish);
                }
                AMBIENT_KW => finish.ambient = self.scene_colour()?.rgb,
                EMISSION_KW => finish.emission = self.scene_colour()?.rgb,
                DIFFUSE_KW => {
                    albedos.diffuse = self.eat(ALBEDO_KW)?;
                    finish.diffuse = self.float()?;
                    if self.eat(COMMA)? {
                        finish.diffuse_back = self.float()?;
                    }
                }
                BRILLIANCE_KW => finish.brilliance = self.float()?,
                CRAND_KW => finish.crand = self.float()?,
                PHONG_KW => {
                    albedos.phong = self.eat(ALBEDO_KW)?;
                    finish.phong = self.float()?;
                }
                PHONG_SIZE_KW => finish.phong_size = self.float()?,
                SPECULAR_KW => {
                    albedos.specular = self.eat(ALBEDO_KW)?;
                    finish.specular = self.float()?;
                }
                ROUGHNESS_KW => finish.roughness = self.float()?,
                METALLIC_KW => {
                    finish.metallic = if self.value_follows()? {
                        self.float()?
                    } else {
                        1.0
                    }
                }
                REFLECTION_KW => finish.reflection = Some(self.reflection()?),
                REFLECTION_EXPONENT_KW => {
                    let exponent = self.float()?;
                    finish.reflection.get_or_insert_with(no_reflection).exponent = exponent;
                }
                CONSERVE_ENERGY_KW => finish.conserve_energy = self.optional_bool()?,
                IRID_KW => finish.irid = Some(self.irid()?),
                SUBSURFACE_KW => finish.translucency = Some(self.translucency()?),
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected a finish item or '}}', found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
    }

    /// `{ amount [thickness T] [turbulence T] }` after `irid`.
    fn irid(&mut self) -> Result<(f64, f64, f64)> {
        self.expect(L_BRACE, "'{'")?;
        let amount = self.float()?;
        let (mut thickness, mut turbulence) = (0.0, 0.0);
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => return Ok((amount, thickness, turbulence)),
                THICKNESS_KW => thickness = self.float()?,
                TURBULENCE_KW => turbulence = self.float()?,
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected thickness, turbulence or '}}' in irid, found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
    }

    /// `reflection C`, `reflection C1, C2`, or `reflection { ... }`.
    fn reflection(&mut self) -> Result<Reflection> {
        let mut reflection = no_reflection();
        if !self.eat(L_BRACE)? {
            let c = self.scene_colour()?;
            reflection.min = c;
            reflection.max = c;
            return Ok(reflection);
        }
        let first = self.scene_colour()?;
        reflection.min = first;
        reflection.max = first;
        // POV-Ray reads the maximum with or without the comma (`reflection { 0 1 }`).
        if self.eat(COMMA)? || self.value_follows()? {
            reflection.max = self.scene_colour()?;
        }
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => return Ok(reflection),
                FRESNEL_KW => reflection.fresnel = self.optional_bool()?,
                FALLOFF_KW => reflection.falloff = self.float()?,
                EXPONENT_KW => reflection.exponent = self.float()?,
                METALLIC_KW => {
                    reflection.metallic = if self.value_follows()? {
                        self.float()?
                    } else {
                        1.0
                    }
                }
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected a reflection item or '}}', found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
    }

    /// `{ ... }` after `interior`.
    pub fn interior_body(&mut self) -> Result<Interior> {
        self.expect(L_BRACE, "'{'")?;
        let mut interior = Interior::default();
        let first = self.next()?;
        match first.slot.as_ref().map(|s| s.borrow().clone()) {
            Some(Value::Interior(i)) => interior = Interior::clone(&i),
            _ => self.unget(first),
        }
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => return Ok(interior),
                IOR_KW => {
                    interior.ior = self.float()?;
                    interior.ior_given = true;
                }
                CAUSTICS_KW => interior.caustics = self.float()?,
                DISPERSION_KW => interior.dispersion = self.float()?,
                DISPERSION_SAMPLES_KW => {
                    let samples = self.int()?;
                    if samples > 1000 {
                        return Err(self.error_at(
                            &token,
                            "dispersion_samples traces a ray for each sample: at most 1000",
                        ));
                    }
                    interior.dispersion_samples = samples.max(2) as u32;
                }
                FADE_DISTANCE_KW => interior.fade_distance = self.float()?,
                FADE_POWER_KW => interior.fade_power = self.float()?,
                FADE_COLOR_KW | FADE_COLOUR_KW => interior.fade_colour = self.scene_colour()?,
                MEDIA_KW => self.interior_media(&mut interior)?,
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected an interior item or '}}', found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
    }

    /// `#default { texture {...} | pigment {...} | normal {...} | finish {...} }`.
    pub fn default_directive(&mut self) -> Result<()> {
        self.expect(L_BRACE, "'{'")?;
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => return Ok(()),
                TEXTURE_KW => self.default_texture = self.texture_body()?,
                RADIOSITY_KW => self.default_radiosity()?,
                PIGMENT_KW | NORMAL_KW | FINISH_KW => {
                    let Texture::Plain {
                        pigment,
                        normal,
                        finish,
                    } = &mut self.default_texture
                    else {
                        return Err(
                            self.error_at(&token, "the default texture must be a plain texture")
                        );
                    };
                    let (mut p, mut n, f) = (pigment.clone(), normal.clone(), finish.clone());
                    let mut f = Finish::clone(&f);
                    match token.kind {
                        PIGMENT_KW => p = self.pigment_with(Some(p))?,
                        NORMAL_KW => n = self.normal_with(n)?,
                        _ => f = self.finish_body(Some(&f))?,
                    }
                    self.default_texture = Texture::Plain {
                        pigment: p,
                        normal: n,
                        finish: Arc::new(f),
                    };
                }
                _ => return Err(self.error_at(
                    &token,
                    format!(
                        "expected texture, pigment, normal, finish, radiosity or '}}' in #default, found {}",
                        self.describe(&token)
                    ),
                )),
            }
        }
    }
}

/// Which of a finish block's `diffuse`, `phong` and `specular` amounts were given with
/// `albedo`: as total reflectance rather than as the peak the shader uses.
#[derive(Debug, Default, Clone, Copy)]
struct Albedos {
    diffuse: bool,
    phong: bool,
    specular: bool,
}

impl Albedos {
    /// Turns the amounts given as albedos into peaks, with the block's final `brilliance`,
    /// `phong_size` and `roughness`, as POV-Ray 3.7 does when the block ends (a later
    /// block that changes `brilliance` keeps the peak). The factors normalise each lobe's
    /// reflectance over the hemisphere and match POV-Ray's renders to 1/65535: diffuse (both sides) times `(brilliance + 1) / 2`, phong times
    /// `(phong_size + 1) / 2`, and the specular half-angle lobe of exponent
    /// `n = 1 / roughness` times `(n + 2) / (4 (2 - 2^(-n/2)))`.
    fn apply_to(self, finish: &mut Finish) {
        if self.diffuse {
            let factor = (finish.brilliance + 1.0) / 2.0;
            finish.diffuse *= factor;
            finish.diffuse_back *= factor;
        }
        if self.phong {
            finish.phong *= (finish.phong_size + 1.0) / 2.0;
        }
        if self.specular {
            let n = 1.0 / finish.roughness;
            finish.specular *= (n + 2.0) / (4.0 * (2.0 - (-n / 2.0).exp2()));
        }
    }
}

/// The top layer of a layered texture, or the texture itself.
fn top_layer(texture: &mut Texture) -> &mut Texture {
    if matches!(texture, Texture::Layered(layers) if !layers.is_empty()) {
        let Texture::Layered(layers) = texture else {
            unreachable!("just matched")
        };
        let last = layers.len() - 1;
        return top_layer(&mut layers[last]);
    }
    texture
}

fn no_reflection() -> Reflection {
    Reflection {
        min: Colour::BLACK,
        max: Colour::BLACK,
        fresnel: false,
        falloff: 1.0,
        exponent: 1.0,
        metallic: 0.0,
    }
}

fn turbulence(pattern: &mut Pattern) -> &mut Turbulence {
    pattern.turbulence.get_or_insert(Turbulence {
        amount: DVec3::ZERO,
        octaves: 6,
        omega: 0.5,
        lambda: 2.0,
    })
}

/// Whether `kind` names a pattern.
pub fn pattern_keyword(kind: SyntaxKind) -> bool {
    matches!(
        kind,
        AGATE_KW
            | AOI_KW
            | DENSITY_FILE_KW
            | AVERAGE_KW
            | BOXED_KW
            | BOZO_KW
            | BRICK_KW
            | BUMPS_KW
            | CELLS_KW
            | CHECKER_KW
            | CRACKLE_KW
            | CYLINDRICAL_KW
            | DENTS_KW
            | FACETS_KW
            | FUNCTION_KW
            | GRADIENT_KW
            | GRANITE_KW
            | HEXAGON_KW
            | IMAGE_PATTERN_KW
            | JULIA_KW
            | LEOPARD_KW
            | MAGNET_KW
            | MANDEL_KW
            | MARBLE_KW
            | OBJECT_KW
            | ONION_KW
            | PAVEMENT_KW
            | PIGMENT_PATTERN_KW
            | PLANAR_KW
            | QUILTED_KW
            | RADIAL_KW
            | RIPPLES_KW
            | SLOPE_KW
            | SPHERICAL_KW
            | SPIRAL1_KW
            | SPIRAL2_KW
            | SPOTTED_KW
            | SQUARE_KW
            | TILING_KW
            | TRIANGULAR_KW
            | WAVES_KW
            | WOOD_KW
            | WRINKLES_KW
    )
}

/// A map of solid pigments from a colour map.
fn pigment_entries(map: BlendMap<Colour>) -> BlendMap<Pigment> {
    BlendMap {
        entries: map
            .entries
            .into_iter()
            .map(|(v, c)| (v, Pigment::Solid(c)))
            .collect(),
    }
}

/// The colours a pattern shows without a colour map.
fn default_map(kind: &PatternKind) -> BlendMap<Pigment> {
    BlendMap {
        entries: crate::pattern::default_colours(kind)
            .into_iter()
            .map(|(at, colour)| (at, Pigment::Solid(colour)))
            .collect(),
    }
}

/// Moves a map's entries by the transformations its pattern has so far. POV-Ray
/// evaluates the entries in the pattern's space, so a transformation written before the
/// map moves them as much as one written after it, which moves pattern and entries alike
/// as it comes (measured: `gradient y scale 10 pigment_map { ... }` draws what
/// `gradient y pigment_map { ... } scale 10` draws). The pattern's warps reach the
/// entries when they are evaluated (`pattern::entry_point`).
pub(super) fn into_pattern_space<T>(
    map: &mut BlendMap<T>,
    pattern: &Pattern,
    transform: impl Fn(&mut T, &Transform),
) {
    let moved = crate::pattern::all_transforms(pattern);
    if !moved.is_identity() {
        for (_, entry) in &mut map.entries {
            transform(entry, &moved);
        }
    }
}

/// Moves a normal's patterns by a transformation written in it.
pub(super) fn transform_normal(normal: &mut Normal, t: &Transform) {
    move_normal(normal, t, Reach::Every);
}

/// Which patterns a transformation moves.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Reach {
    /// A transformation written in a texture, pigment or normal moves all its patterns.
    Every,
    /// An object's transformation leaves uv-mapped patterns where they are on its surface.
    InSpace,
    /// The transformation turns normals' pushes only, moving no pattern: an object's, for
    /// the normals under a uv-mapped normal map.
    Placement,
}

/// Applies a transformation written in a texture to its patterns, recursively.
pub fn transform_texture(texture: &mut Texture, t: &Transform) {
    move_texture(texture, t, Reach::Every);
}

/// Applies an object's transformation to its texture's patterns, recursively, except the
/// uv-mapped ones, which stay glued to the surface.
pub fn place_texture(texture: &mut Texture, t: &Transform) {
    move_texture(texture, t, Reach::InSpace);
}

/// Applies a transformation written in a pigment (or a media's density) to its patterns.
pub(super) fn transform_pigment(pigment: &mut Pigment, t: &Transform) {
    move_pigment(pigment, t, Reach::Every);
}

fn moves(pattern: &Pattern, reach: Reach) -> bool {
    match reach {
        Reach::Every => true,
        Reach::InSpace => !pattern.uv_mapping,
        Reach::Placement => false,
    }
}

fn move_texture(texture: &mut Texture, t: &Transform, reach: Reach) {
    match texture {
        Texture::Plain {
            pigment, normal, ..
        } => {
            move_pigment(pigment, t, reach);
            if let Some(normal) = normal {
                move_normal(normal, t, reach);
            }
        }
        Texture::Pattern { pattern, map } => {
            if !moves(pattern, reach) {
                return;
            }
            pattern.transform = pattern.transform.then(t);
            for (_, entry) in &mut map.entries {
                move_texture(entry, t, reach);
            }
        }
        Texture::Layered(layers) => {
            for layer in layers {
                move_texture(layer, t, reach);
            }
        }
    }
}

fn move_pigment(pigment: &mut Pigment, t: &Transform, reach: Reach) {
    match pigment {
        Pigment::Pattern { pattern, map } => {
            if !moves(pattern, reach) {
                return;
            }
            pattern.transform = pattern.transform.then(t);
            for (_, entry) in &mut map.entries {
                move_pigment(entry, t, reach);
            }
        }
        Pigment::Image(map) => {
            if reach == Reach::Every || !map.uv_mapping {
                map.transform = map.transform.then(t);
            }
        }
        Pigment::Solid(_) => {}
    }
}

fn move_normal(normal: &mut Normal, t: &Transform, reach: Reach) {
    let placed = match &mut normal.kind {
        NormalKind::Pattern { pattern, .. } | NormalKind::BumpMap { pattern, .. } => {
            if moves(pattern, reach) {
                pattern.transform = pattern.transform.then(t);
            }
            !moves(pattern, reach)
        }
        NormalKind::Map { pattern, map } => {
            let moved = moves(pattern, reach);
            // The entries of a map left in uv space are evaluated there too.
            let entries_reach = if moved { reach } else { Reach::Placement };
            if moved {
                pattern.transform = pattern.transform.then(t);
            }
            for (_, entry) in &mut map.entries {
                move_normal(entry, t, entries_reach);
            }
            !moved
        }
    };
    if placed {
        normal.place(t);
    }
}

/// Marks a texture's patterns `uv_mapping`, as `uv_mapping` before its items asks.
pub fn map_texture_uv(texture: &mut Texture) {
    match texture {
        Texture::Plain {
            pigment, normal, ..
        } => {
            map_pigment_uv(pigment);
            if let Some(normal) = normal {
                map_normal_uv(normal);
            }
        }
        Texture::Pattern { pattern, .. } => pattern.uv_mapping = true,
        Texture::Layered(layers) => layers.iter_mut().for_each(map_texture_uv),
    }
}

/// Marks a pigment's pattern or image `uv_mapping`; its map entries are evaluated at the
/// same uv point. A plain colour has nothing to map.
pub fn map_pigment_uv(pigment: &mut Pigment) {
    match pigment {
        Pigment::Pattern { pattern, .. } => pattern.uv_mapping = true,
        Pigment::Image(map) => map.uv_mapping = true,
        Pigment::Solid(_) => {}
    }
}

/// Marks a normal's pattern `uv_mapping`.
pub fn map_normal_uv(normal: &mut Normal) {
    match &mut normal.kind {
        NormalKind::Pattern { pattern, .. }
        | NormalKind::BumpMap { pattern, .. }
        | NormalKind::Map { pattern, .. } => pattern.uv_mapping = true,
    }
}

#[cfg(test)]
mod tests {
    use crate::eval::tests::{evaluate_err, evaluate_ok};
    use crate::scene::{Finish, Texture};

    /// The finish of the scene's only object.
    fn finish_of(finish: &str) -> Finish {
        let scene = evaluate_ok(&format!("sphere {{ 0, 1 finish {{ {finish} }} }}"));
        let Some(Texture::Plain { finish, .. }) = scene.objects[0].texture.as_deref() else {
            panic!("no plain texture");
        };
        Finish::clone(finish)
    }

    fn assert_close(ours: f64, expected: f64) {
        assert!((ours - expected).abs() < 1e-4, "{ours} is not {expected}");
    }

    /// The peaks POV-Ray 3.7 draws for amounts given as albedos, read from its 16-bit
    /// renders of a lit square with linear gamma.
    #[test]
    fn albedos_become_povrays_peaks() {
        let f = finish_of("diffuse albedo 0.1, 0.2 brilliance 3");
        assert_close(f.diffuse, 0.2);
        assert_close(f.diffuse_back, 0.4);
        assert_close(finish_of("brilliance 5 diffuse albedo 0.1").diffuse, 0.3);
        assert_close(
            finish_of("diffuse albedo 0.1 brilliance 0.5").diffuse,
            0.075,
        );
        assert_close(finish_of("diffuse albedo 0.1").diffuse, 0.1);
        assert_close(finish_of("phong albedo 0.1 phong_size 10").phong, 0.55);
        assert_close(finish_of("phong albedo 0.1 phong_size 1").phong, 0.1);
        assert_close(finish_of("specular albedo 0.1").specular, 0.27514);
        assert_close(
            finish_of("specular albedo 0.1 roughness 0.1").specular,
            0.15238,
        );
        assert_close(
            finish_of("specular albedo 0.1 roughness 0.5").specular,
            0.06667,
        );
        // Without albedo the amounts are peaks already.
        assert_close(finish_of("diffuse 0.1 brilliance 3").diffuse, 0.1);
        assert_close(finish_of("specular 0.1").specular, 0.1);
    }

    /// The conversion happens when the block ends: a finish built on a declared one keeps
    /// the declared peak whatever brilliance it sets, as in POV-Ray's renders.
    #[test]
    fn a_declared_albedo_stays_a_peak() {
        let scene = evaluate_ok(
            "#declare F = finish { diffuse albedo 0.1 brilliance 3 }
             sphere { 0, 1 finish { F brilliance 5 } }",
        );
        let Some(Texture::Plain { finish, .. }) = scene.objects[0].texture.as_deref() else {
            panic!("no plain texture");
        };
        assert_close(finish.diffuse, 0.2);
        assert_eq!(finish.brilliance, 5.0);
    }

    /// POV-Ray 3.7 refuses a patterned texture as a layer, above or below, in objects,
    /// materials and declared layered textures alike.
    #[test]
    fn patterned_textures_are_not_layered() {
        let checker =
            "texture { checker texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } }";
        let plain = "texture { pigment { rgbt <1, 0, 0, 0.5> } }";
        let over = "cannot layer a patterned texture over another";
        let under = "cannot layer over a patterned texture";
        for (text, expected) in [
            (format!("sphere {{ 0, 1 {plain} {checker} }}"), over),
            (format!("sphere {{ 0, 1 {checker} {plain} }}"), under),
            (
                format!("sphere {{ 0, 1 material {{ {plain} {checker} }} }}"),
                over,
            ),
            (format!("#declare T = {checker} {plain}"), under),
        ] {
            assert_eq!(evaluate_err(&text), expected, "{text}");
        }
        // Layered textures may be what a pattern's entries are.
        evaluate_ok(&format!(
            "#declare L = {plain} {plain}
             sphere {{ 0, 1 texture {{ checker texture {{ L }} texture {{ L }} }} }}"
        ));
    }

    /// POV-Ray numbers its tilings 1 to 27 and refuses any other number.
    #[test]
    fn tiling_numbers_are_checked() {
        assert_eq!(
            evaluate_err("plane { y, 0 pigment { tiling 28 } }"),
            "the tiling number must be from 1 to 27"
        );
        assert_eq!(
            evaluate_err("plane { y, 0 pigment { tiling 0 } }"),
            "the tiling number must be from 1 to 27"
        );
        evaluate_ok("plane { y, 0 pigment { tiling 25 } normal { tiling 27 } }");
        evaluate_ok("plane { y, 0 pigment { tiling 24.9 } normal { tiling 3 } }");
    }

    /// pavement's corner looks are read in any order and their ranges checked; whether
    /// they fit the cells is checked with the pattern (`pattern::pavement::check`).
    #[test]
    fn pavement_looks_are_checked() {
        assert_eq!(
            evaluate_err("plane { y, 0 pigment { pavement form 4 } }"),
            "form of pavement must be from 0 to 3"
        );
        assert_eq!(
            evaluate_err("plane { y, 0 pigment { pavement interior -1 number_of_sides 4 } }"),
            "interior of pavement must be 0, 1 or 2"
        );
        evaluate_ok(
            "plane { y, 0 pigment { pavement form 3 interior 2 exterior 1 number_of_sides 4 } }",
        );
        evaluate_ok("plane { y, 0 pigment { pavement number_of_sides 6 exterior 2 } }");
    }

    /// cutaway_textures is refused where it would change the picture, and accepted where
    /// it changes nothing (every part textured, or the CSG's own texture on the cut).
    #[test]
    fn cutaway_textures_is_refused_where_it_matters() {
        let red = "pigment { rgb x }";
        assert_eq!(
            evaluate_err(&format!(
                "difference {{ box {{ -1, 1 {red} }} sphere {{ 1, 1 }} cutaway_textures }}"
            )),
            "not supported yet: cutaway_textures"
        );
        evaluate_ok(&format!(
            "difference {{ box {{ -1, 1 {red} }} sphere {{ 1, 1 {red} }} cutaway_textures }}"
        ));
        evaluate_ok(&format!(
            "intersection {{ box {{ -1, 1 {red} }} sphere {{ 1, 1 }} cutaway_textures {red} }}"
        ));
        evaluate_ok(&format!(
            "union {{ box {{ -1, 1 {red} }} sphere {{ 1, 1 }} cutaway_textures }}"
        ));
    }

    /// The debug text a scene prints.
    fn printed(text: &str) -> String {
        let files = crate::MemoryFiles::new().with("scene.pov", text);
        let evaluation = crate::evaluate("scene.pov", &files, &crate::EvalOptions::default());
        assert!(!evaluation.has_errors(), "{:?}", evaluation.diagnostics);
        evaluation.debug_text()
    }

    /// A map's entries are evaluated where their pattern was: its transformations move
    /// them whether written before the map or after, and its warps and turbulence move
    /// their point, but for marble and wood, whose turbulence goes into their value. As
    /// POV-Ray draws them (tests/reference/scenes/patterns-map-space.pov; the turbulence
    /// cases measured on its renders: a turbulent gradient whose entries are the same
    /// gradient draws what the turbulent gradient alone draws).
    #[test]
    fn map_entries_are_evaluated_where_their_pattern_was() {
        let red_at = |pigment: &str, y: f64| -> f64 {
            printed(&format!(
                "#declare Q = pigment {{ gradient y color_map {{ [0 rgb 0] [1 rgb 1] }} }}
                 #declare F = function {{ pigment {{ {pigment} }} }}
                 #debug str(F(0.3, {y}, 0.2).red, 0, 6)"
            ))
            .parse()
            .unwrap()
        };
        for y in [0.35, 1.7, 2.45] {
            let plain = red_at("Q", y);
            let scaled = red_at("Q scale 10", y);
            assert_ne!(plain, scaled);
            for before_or_after in [
                "gradient y scale 10 pigment_map { [0 Q] [1 Q] }",
                "gradient y pigment_map { [0 Q] [1 Q] } scale 10",
            ] {
                assert_eq!(red_at(before_or_after, y), scaled, "{before_or_after}");
            }
            let turbulent = "gradient y turbulence 0.6 color_map { [0 rgb 0] [1 rgb 1] }";
            assert_eq!(
                red_at("gradient y turbulence 0.6 pigment_map { [0 Q] [1 Q] }", y),
                red_at(turbulent, y)
            );
            assert_eq!(
                red_at(
                    "gradient y warp { turbulence 0.6 } pigment_map { [0 Q] [1 Q] }",
                    y
                ),
                red_at("Q warp { turbulence 0.6 }", y)
            );
            assert_eq!(
                red_at("marble turbulence 0.6 pigment_map { [0 Q] [1 Q] }", y),
                plain
            );
        }
    }
}
