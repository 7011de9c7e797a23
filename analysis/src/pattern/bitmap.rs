//! Images in space: where a point falls on a bitmap (`map_type`, `once`), which pixels it
//! reads and with what weights (`interpolate`), and what it reads there: an image map's
//! colour, or the value of an image pattern or bump map.

use crate::image::Image;
use crate::scene::Colour;
use crate::scene::bitmap::{Bitmap, ImageMap, ImagePattern, ImageValue, Interpolation, MapType};
use glam::DVec3;
use std::f64::consts::{PI, TAU};

/// The image coordinates of a pattern-space point: u to the right and v up, in 0..1;
/// `None` outside a map that shows `once`.
pub fn uv(bitmap: &Bitmap, p: DVec3) -> Option<(f64, f64)> {
    let longitude = || {
        // From +x, turning towards +z: west to east in a rotation about -y.
        (p.z.atan2(p.x) / TAU).rem_euclid(1.0)
    };
    let (u, v) = match bitmap.map_type {
        MapType::Planar => (p.x, p.y),
        MapType::Spherical => {
            let length = p.length();
            if length == 0.0 {
                return Some((0.0, 0.5));
            }
            let latitude = (p.y / length).clamp(-1.0, 1.0).asin();
            return Some((longitude(), 0.5 + latitude / PI));
        }
        MapType::Cylindrical => (longitude(), p.y),
        MapType::Torus => {
            let from_ring = (p.x * p.x + p.z * p.z).sqrt() - 1.0;
            // Around the tube: the middle of the image on the outer rim, its upper half
            // over the top, its lower half underneath, the top and bottom edges meeting on
            // the inner rim (measured against POV-Ray 3.7).
            let around = (0.5 + p.y.atan2(from_ring) / TAU).rem_euclid(1.0);
            return Some((longitude(), around));
        }
    };
    let tiled =
        matches!(bitmap.map_type, MapType::Planar) || bitmap.map_type == MapType::Cylindrical;
    if bitmap.once && tiled {
        let inside = |t: f64| (0.0..1.0).contains(&t);
        let u_inside = bitmap.map_type == MapType::Cylindrical || inside(u);
        if !u_inside || !inside(v) {
            return None;
        }
    }
    Some((u.rem_euclid(1.0), v.rem_euclid(1.0)))
}

/// Up to four pixels (column, row) and their weights for the point `(u, v)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Taps {
    pub pixels: [(usize, usize, f64); 4],
    pub count: usize,
}

impl Taps {
    pub fn as_slice(&self) -> &[(usize, usize, f64)] {
        &self.pixels[..self.count]
    }
}

/// The pixels the point `(u, v)` reads: the one it falls in, or its four nearest pixel
/// centres (the image wrapping around at the edges) weighted by the interpolation.
pub fn taps(bitmap: &Bitmap, u: f64, v: f64) -> Taps {
    let (w, h) = (bitmap.image.width, bitmap.image.height);
    // Continuous pixel coordinates, rows counted from the top.
    let x = u * w as f64;
    let y = (1.0 - v) * h as f64;
    // Tiles wrap around to the neighbouring copy; a single copy stops at its edges.
    let clamp = bitmap.once;
    let index = move |t: f64, n: usize| {
        let i = t.floor() as i64;
        if clamp {
            i.clamp(0, n as i64 - 1) as usize
        } else {
            i.rem_euclid(n as i64) as usize
        }
    };
    let column = |x: f64| index(x, w);
    let row = |y: f64| index(y, h);
    if bitmap.interpolate == Interpolation::None {
        return Taps {
            pixels: [
                (column(x), row(y), 1.0),
                (0, 0, 0.0),
                (0, 0, 0.0),
                (0, 0, 0.0),
            ],
            count: 1,
        };
    }
    let (x0, y0) = ((x - 0.5).floor(), (y - 0.5).floor());
    let (fx, fy) = (x - 0.5 - x0, y - 0.5 - y0);
    let corners = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)];
    let weights: [f64; 4] = match bitmap.interpolate {
        Interpolation::Bilinear => [
            (1.0 - fx) * (1.0 - fy),
            fx * (1.0 - fy),
            (1.0 - fx) * fy,
            fx * fy,
        ],
        _ => {
            let distances =
                corners.map(|(cx, cy): (f64, f64)| ((fx - cx).powi(2) + (fy - cy).powi(2)).sqrt());
            if let Some(exact) = distances.iter().position(|&d| d < 1e-12) {
                let mut w = [0.0; 4];
                w[exact] = 1.0;
                w
            } else {
                let inverse = distances.map(|d| 1.0 / d);
                let sum: f64 = inverse.iter().sum();
                inverse.map(|i| i / sum)
            }
        }
    };
    let mut pixels = [(0, 0, 0.0); 4];
    for (i, (cx, cy)) in corners.iter().enumerate() {
        pixels[i] = (column(x0 + 0.5 + cx), row(y0 + 0.5 + cy), weights[i]);
    }
    Taps { pixels, count: 4 }
}

/// An image map's colour at a pattern-space point, with its filter and transmit.
pub fn image_map_colour(map: &ImageMap, p: DVec3) -> Colour {
    // Warps and turbulence move the point as they move a pattern's, the last written
    // first and the classic turbulence innermost.
    let p = super::warp::through_all(&map.warps, p);
    let p = match &map.turbulence {
        Some(t) => super::warp::turbulent(t, p),
        None => p,
    };
    let Some((u, v)) = uv(&map.bitmap, p) else {
        return Colour {
            rgb: DVec3::ZERO,
            filter: 0.0,
            transmit: 1.0,
        };
    };
    let image = &map.bitmap.image;
    let mut total = Colour {
        rgb: DVec3::ZERO,
        filter: 0.0,
        transmit: 0.0,
    };
    for &(x, y, weight) in taps(&map.bitmap, u, v).as_slice() {
        let [r, g, b, a] = image.pixel(x, y);
        let index = image.index(x, y);
        let transmit = map.transmit.get(index).unwrap_or(1.0 - f64::from(a));
        let filter = map.filter.get(index).unwrap_or(0.0);
        total.rgb += DVec3::new(f64::from(r), f64::from(g), f64::from(b)) * weight;
        total.filter += filter * weight;
        total.transmit += transmit * weight;
    }
    total
}

/// An image pattern's value at a pattern-space point; 0 outside a `once` map.
pub fn image_value(pattern: &ImagePattern, p: DVec3) -> f64 {
    match uv(&pattern.bitmap, p) {
        Some((u, v)) => value_at(pattern, u, v),
        None => 0.0,
    }
}

/// The value at image coordinates `(u, v)`.
pub fn value_at(pattern: &ImagePattern, u: f64, v: f64) -> f64 {
    let image = &pattern.bitmap.image;
    taps(&pattern.bitmap, u, v)
        .as_slice()
        .iter()
        .map(|&(x, y, weight)| pixel_value(image, pattern.value, x, y) * weight)
        .sum()
}

/// What an image pattern reads from one pixel. Pixels with alpha count as if over black,
/// unless the alpha itself is read.
fn pixel_value(image: &Image, value: ImageValue, x: usize, y: usize) -> f64 {
    let [r, g, b, a] = image.pixel(x, y);
    match value {
        // POV-Ray's `use_alpha` reads transparency: 0 where the image is opaque.
        ImageValue::Alpha => 1.0 - f64::from(a),
        ImageValue::Index => f64::from(image.index(x, y).unwrap_or(0)) / 255.0,
        ImageValue::MaterialIndex => match image.index(x, y) {
            Some(index) => f64::from(index) / 255.0,
            None => (f64::from(r) * 255.0).round() / 255.0,
        },
        ImageValue::Grey => {
            let grey = 0.297 * f64::from(r) + 0.589 * f64::from(g) + 0.114 * f64::from(b);
            grey * f64::from(a)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::image::ColourModel;
    use std::sync::Arc;

    fn bitmap(map_type: MapType, interpolate: Interpolation, once: bool) -> Bitmap {
        // Two pixels: black on the left, white on the right.
        Bitmap {
            image: Arc::new(Image {
                width: 2,
                height: 1,
                pixels: vec![[0.0, 0.0, 0.0, 1.0], [1.0, 1.0, 1.0, 1.0]],
                indices: None,
                palette_len: 0,
                model: ColourModel::Grey,
                has_alpha: false,
                gamma: None,
            }),
            map_type,
            once,
            interpolate,
        }
    }

    #[test]
    fn planar_maps_tile_the_unit_square_unless_once() {
        let tiled = bitmap(MapType::Planar, Interpolation::None, false);
        assert_eq!(uv(&tiled, DVec3::new(1.25, -0.5, 3.0)), Some((0.25, 0.5)));
        let once = bitmap(MapType::Planar, Interpolation::None, true);
        assert_eq!(uv(&once, DVec3::new(1.25, 0.5, 0.0)), None);
        assert_eq!(uv(&once, DVec3::new(0.25, 0.5, 0.0)), Some((0.25, 0.5)));
    }

    #[test]
    fn spherical_maps_start_at_plus_x_and_reach_the_poles() {
        let b = bitmap(MapType::Spherical, Interpolation::None, false);
        assert_eq!(uv(&b, DVec3::X), Some((0.0, 0.5)));
        let (u, v) = uv(&b, DVec3::Z).unwrap();
        assert!((u - 0.25).abs() < 1e-12 && (v - 0.5).abs() < 1e-12);
        assert_eq!(uv(&b, DVec3::Y).map(|(_, v)| v), Some(1.0));
    }

    #[test]
    fn bilinear_interpolation_blends_neighbouring_pixels() {
        let pattern = ImagePattern {
            bitmap: bitmap(MapType::Planar, Interpolation::Bilinear, false),
            value: ImageValue::Grey,
        };
        let middle = value_at(&pattern, 0.5, 0.5);
        assert!((middle - 0.5).abs() < 1e-9, "{middle}");
        let sharp = ImagePattern {
            bitmap: bitmap(MapType::Planar, Interpolation::None, false),
            value: ImageValue::Grey,
        };
        assert_eq!(value_at(&sharp, 0.4, 0.5), 0.0);
        assert!((value_at(&sharp, 0.6, 0.5) - 1.0).abs() < 1e-12);
    }
}
