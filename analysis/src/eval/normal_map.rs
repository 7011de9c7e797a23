//! The maps of normals: `normal_map { }` (a pattern choosing between normals), the normals
//! listed after a block pattern (`checker normal { A }, normal { B }`) and `slope_map { }`
//! (a pattern's value reshaped into a height profile for its bumps).

use super::tokens::Token;
use super::{Evaluator, Result};
use crate::scene::{BlendMap, Normal, NormalKind, Pattern};
use syntax::SyntaxKind::*;

impl Evaluator<'_> {
    /// The normals after a block pattern in a normal (`checker normal { A } normal { B }`),
    /// or `None` when none follow and the pattern's values are the bumps themselves.
    pub(super) fn block_normals(
        &mut self,
        pattern: &Pattern,
        count: usize,
    ) -> Result<Option<Normal>> {
        if self.peek_kind()? != NORMAL_KW {
            return Ok(None);
        }
        let mut entries = Vec::new();
        while entries.len() < count && self.eat(NORMAL_KW)? {
            entries.push((entries.len() as f64, self.normal_body()?));
            self.eat(COMMA)?;
        }
        Ok(Some(Normal {
            kind: NormalKind::Map {
                pattern: Box::new(pattern.clone()),
                map: BlendMap { entries },
            },
            accuracy: 0.02,
            placement: None,
        }))
    }

    /// `normal_map { }` or `slope_map { }` (the keyword already read) on the normal being
    /// parsed.
    pub(super) fn normal_map_modifier(
        &mut self,
        normal: &mut Option<Normal>,
        keyword: &Token,
    ) -> Result<()> {
        let Some(current) = normal else {
            return Err(self.error_at(
                keyword,
                format!("{} needs a pattern before it", self.text(keyword)),
            ));
        };
        let pattern = match &current.kind {
            NormalKind::Pattern { pattern, .. } | NormalKind::Map { pattern, .. } => {
                pattern.clone()
            }
            NormalKind::BumpMap { .. } => {
                return Err(self.error_at(
                    keyword,
                    format!("a bump_map takes no {}", self.text(keyword)),
                ));
            }
        };
        if keyword.kind == NORMAL_MAP_KW {
            let mut map = self.normal_map_body()?;
            super::texture::into_pattern_space(
                &mut map,
                &pattern,
                super::texture::transform_normal,
            );
            current.kind = NormalKind::Map { pattern, map };
            return Ok(());
        }
        let profile = self.slope_map_body()?;
        match &mut current.kind {
            NormalKind::Pattern { slope_map, .. } => *slope_map = Some(profile),
            NormalKind::Map { .. } | NormalKind::BumpMap { .. } => {
                return Err(self.error_at(keyword, "a slope_map cannot follow a normal_map"));
            }
        }
        Ok(())
    }

    /// `{ [value normal-contents] ... }` after `normal_map`: each entry a normal written out
    /// or inside `normal { }`.
    fn normal_map_body(&mut self) -> Result<BlendMap<Normal>> {
        let open = self.expect(L_BRACE, "'{'")?;
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
                    let normal = if self.eat(NORMAL_KW)? {
                        self.normal_body()?
                    } else {
                        let at = self.next()?;
                        self.unget(at.clone());
                        self.normal_inner(None, R_BRACK)?
                            .ok_or_else(|| self.error_at(&at, "this normal has no pattern"))?
                    };
                    self.expect(R_BRACK, "']'")?;
                    entries.push((value, normal));
                }
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected '[' or '}}' in normal_map, found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
        if entries.is_empty() {
            return Err(self.error_at(&open, "a normal_map needs at least one entry"));
        }
        Ok(BlendMap { entries })
    }

    /// `{ [value, <height, slope>] ... }` after `slope_map`.
    fn slope_map_body(&mut self) -> Result<BlendMap<(f64, f64)>> {
        let open = self.expect(L_BRACE, "'{'")?;
        let mut entries = Vec::new();
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => break,
                L_BRACK => {
                    let value = self.float()?;
                    self.eat(COMMA)?;
                    let point = self.vector_of(2)?;
                    self.expect(R_BRACK, "']'")?;
                    entries.push((value, (point.c[0], point.c[1])));
                }
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected '[' or '}}' in slope_map, found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
        if entries.is_empty() {
            return Err(self.error_at(&open, "a slope_map needs at least one entry"));
        }
        Ok(BlendMap { entries })
    }
}

#[cfg(test)]
mod tests {
    use crate::eval::{EvalOptions, evaluate};
    use crate::files::MemoryFiles;
    use crate::scene::{NormalKind, Texture};

    fn normal_kind(text: &str) -> NormalKind {
        let files = MemoryFiles::new().with("scene.pov", text);
        let evaluation = evaluate("scene.pov", &files, &EvalOptions::default());
        let scene = evaluation.scene.expect("the scene evaluates");
        let texture = scene.objects[0].texture.clone().expect("a texture");
        let Texture::Plain {
            normal: Some(normal),
            ..
        } = &*texture
        else {
            panic!("no normal")
        };
        normal.kind.clone()
    }

    #[test]
    fn normal_maps_and_block_normals_hold_their_entries() {
        let NormalKind::Map { map, .. } = normal_kind(
            "sphere { 0, 1 normal { gradient x normal_map { [0 bumps 0.5 scale 0.1] \
             [1 normal { dents 0.8 }] } } }",
        ) else {
            panic!("not a map")
        };
        assert_eq!(map.entries.len(), 2);
        let NormalKind::Map { map, .. } =
            normal_kind("sphere { 0, 1 normal { checker normal { bumps }, normal { granite } } }")
        else {
            panic!("not a map")
        };
        assert_eq!(map.entries.len(), 2);
        let NormalKind::Pattern {
            slope_map: Some(profile),
            ..
        } = normal_kind(
            "sphere { 0, 1 normal { gradient y slope_map { [0 <0, 1>] [1 <1, 0>] } } }",
        )
        else {
            panic!("no slope map")
        };
        assert_eq!(profile.entries[1], (1.0, (1.0, 0.0)));
    }
}
