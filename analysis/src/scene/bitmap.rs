//! Images placed on surfaces and in space: `image_map` pigments, `bump_map` normals and
//! `image_pattern`, which share how a point finds its pixel (the bitmap modifiers
//! `map_type`, `once` and `interpolate`).

use super::Transform;
use crate::image::Image;
use std::sync::Arc;

/// `map_type`: how points of space are wrapped onto the image's unit square.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MapType {
    /// 0: the x-y plane, the image from (0, 0) to (1, 1), projected along z.
    Planar,
    /// 1: longitude and latitude around the y axis.
    Spherical,
    /// 2: longitude around the y axis, height along it.
    Cylindrical,
    /// 5: around a torus of major radius 1 in the x-z plane.
    Torus,
}

/// `interpolate`: how samples between pixel centres are found.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Interpolation {
    /// The pixel the point falls in.
    None,
    /// 2: bilinear between the four nearest pixels.
    Bilinear,
    /// 4: the four nearest pixels weighted by their distance.
    NormalizedDistance,
}

/// An image with the bitmap modifiers that place it.
#[derive(Debug, Clone, PartialEq)]
pub struct Bitmap {
    /// The samples, already gamma decoded where the use calls for it.
    pub image: Arc<Image>,
    pub map_type: MapType,
    /// Only one copy of the image (planar and cylindrical maps), instead of tiles.
    pub once: bool,
    pub interpolate: Interpolation,
}

/// Filter or transmit added to an image map's pixels: for the whole image, or by palette
/// index.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct PaletteAmounts {
    pub all: Option<f64>,
    pub by_index: Vec<(u8, f64)>,
}

impl PaletteAmounts {
    /// The amount for a pixel with palette index `index`, if any was given.
    pub fn get(&self, index: Option<u8>) -> Option<f64> {
        let listed = index.and_then(|i| {
            self.by_index
                .iter()
                .rev()
                .find(|(at, _)| *at == i)
                .map(|(_, amount)| *amount)
        });
        listed.or(self.all)
    }

    pub fn is_empty(&self) -> bool {
        self.all.is_none() && self.by_index.is_empty()
    }
}

/// `pigment { image_map { ... } }`.
#[derive(Debug, Clone, PartialEq)]
pub struct ImageMap {
    pub bitmap: Bitmap,
    pub filter: PaletteAmounts,
    pub transmit: PaletteAmounts,
    /// From the image's pattern space to the world.
    pub transform: Transform,
    /// `warp { }`s and classic `turbulence`, applied in pattern space as a pattern's are.
    pub warps: Vec<super::Warp>,
    pub turbulence: Option<super::Turbulence>,
    /// `uv_mapping`: the image is looked up at the surface's (u, v, 0), and the object's
    /// transformations do not move it.
    pub uv_mapping: bool,
}

/// What a bump map or image pattern reads from a pixel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ImageValue {
    /// The pixel's grey value.
    Grey,
    /// The palette index over 255 (`use_index` on palette images).
    Index,
    /// The alpha channel (`use_alpha`).
    Alpha,
    /// A material map's texture number over 255: the palette index, or in an image
    /// without a palette the 8-bit value of the red channel.
    MaterialIndex,
}

/// `image_pattern { ... }`, and the heights of a `bump_map`.
#[derive(Debug, Clone, PartialEq)]
pub struct ImagePattern {
    pub bitmap: Bitmap,
    pub value: ImageValue,
}
