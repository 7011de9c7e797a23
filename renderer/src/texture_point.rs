//! Where a texture is evaluated on a surface: the point in space, the surface's own uv
//! coordinates there for the patterns that are `uv_mapping`, and how the surface faces
//! the ray for the patterns that look at it (`slope`, `aoi`).

use analysis::pattern::Facing;
use analysis::scene::Pattern;
use glam::{DVec2, DVec3};
use std::borrow::Cow;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TexturePoint {
    /// The point in the world, where patterns in space are evaluated.
    pub world: DVec3,
    /// The surface's uv coordinates, where uv-mapped patterns are evaluated (at u, v, 0).
    pub uv: DVec2,
    /// The surface's normal and the ray, found only for materials with a pattern that
    /// looks at them.
    pub facing: Option<Facing>,
}

impl TexturePoint {
    /// A point of a surface without uv coordinates of its own, where POV-Ray takes the
    /// point's x and y.
    pub fn in_space(world: DVec3) -> TexturePoint {
        TexturePoint {
            world,
            uv: world.truncate(),
            facing: None,
        }
    }

    /// Where `pattern` and the patterns of its map are evaluated: a uv-mapped pattern moves
    /// the point to (u, v, 0) for itself and everything under it. Most patterns leave the
    /// point where it is, and borrow it: a copy is fifteen words, for every pattern of
    /// every map at every hit.
    pub fn for_pattern(&self, pattern: &Pattern) -> Cow<'_, TexturePoint> {
        if pattern.uv_mapping {
            Cow::Owned(TexturePoint {
                world: self.uv.extend(0.0),
                ..*self
            })
        } else {
            Cow::Borrowed(self)
        }
    }

    /// Where the entries of `pattern`'s map are evaluated: the point the pattern's warps
    /// and turbulence moved it to (see [`analysis::pattern::entry_point`]); borrowed when
    /// they did not move it.
    pub fn for_entries(&self, pattern: &Pattern) -> Cow<'_, TexturePoint> {
        match analysis::pattern::entry_point(pattern, self.world) {
            Some(world) => Cow::Owned(TexturePoint { world, ..*self }),
            None => Cow::Borrowed(self),
        }
    }

    /// The point with the normal a layer's bumps turned the surface's to, for the
    /// patterns that look at it.
    pub fn with_normal(&self, normal: DVec3) -> TexturePoint {
        TexturePoint {
            facing: self.facing.map(|f| Facing { normal, ..f }),
            ..*self
        }
    }
}
