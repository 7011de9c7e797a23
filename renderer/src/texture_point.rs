//! Where a texture is evaluated on a surface: the point in space, and the surface's own uv
//! coordinates there for the patterns that are `uv_mapping`.

use analysis::scene::Pattern;
use glam::{DVec2, DVec3};

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TexturePoint {
    /// The point in the world, where patterns in space are evaluated.
    pub world: DVec3,
    /// The surface's uv coordinates, where uv-mapped patterns are evaluated (at u, v, 0).
    pub uv: DVec2,
}

impl TexturePoint {
    /// A point of a surface without uv coordinates of its own, where POV-Ray takes the
    /// point's x and y.
    pub fn in_space(world: DVec3) -> TexturePoint {
        TexturePoint {
            world,
            uv: world.truncate(),
        }
    }

    /// Where `pattern` and the patterns of its map are evaluated: a uv-mapped pattern moves
    /// the point to (u, v, 0) for itself and everything under it.
    pub fn for_pattern(&self, pattern: &Pattern) -> TexturePoint {
        if pattern.uv_mapping {
            TexturePoint {
                world: self.uv.extend(0.0),
                uv: self.uv,
            }
        } else {
            *self
        }
    }
}
