//! `bump_map`: an image read as a relief. The normal tilts against the relief's slope per
//! pixel along the image's two axes, as they lie in pattern space for the map type, scaled
//! by `bump_size`. The slope comes from three pixels as POV-Ray 3.7 takes it; its normals,
//! recovered from renders lit from three directions, agree with ours to 0.002 for planar,
//! spherical and cylindrical maps, interpolated or not. Outside a `once` map the normal is
//! left alone.

use analysis::pattern::bitmap;
use analysis::scene::bitmap::{ImagePattern, MapType};
use analysis::scene::{Pattern, PatternKind};
use glam::DVec3;

/// The perturbed normal in pattern space for the unit pattern-space normal `n` at the
/// pattern-space point `p`.
pub fn perturb(pattern: &Pattern, bump_size: f64, p: DVec3, n: DVec3) -> DVec3 {
    let PatternKind::Image(image) = &pattern.kind else {
        return n;
    };
    let Some((u, v)) = bitmap::uv(&image.bitmap, p) else {
        return n;
    };
    let (du, dv) = pixel_step(image);
    let at = |u: f64, v: f64| bitmap::value_at(image, u.rem_euclid(1.0), v.rem_euclid(1.0));
    // POV-Ray's stencil, measured from its normals: the point and the two pixels diagonally
    // below it, one to each side. Their difference is the slope along u per pixel, and
    // their mean less the point's the slope along v.
    let here = at(u, v);
    let below_left = at(u - du, v - dv);
    let below_right = at(u + du, v - dv);
    let slope_u = 0.5 * (below_right - below_left);
    let slope_v = here - 0.5 * (below_left + below_right);
    let (along_u, along_v) = axes(image.bitmap.map_type, p);
    n - (along_u * slope_u + along_v * slope_v) * bump_size
}

/// One pixel as a step in image coordinates.
fn pixel_step(image: &ImagePattern) -> (f64, f64) {
    let i = &image.bitmap.image;
    (1.0 / i.width as f64, 1.0 / i.height as f64)
}

/// The directions in pattern space in which u and v grow at `p`.
fn axes(map_type: MapType, p: DVec3) -> (DVec3, DVec3) {
    let around = DVec3::new(-p.z, 0.0, p.x).normalize_or_zero();
    match map_type {
        MapType::Planar => (DVec3::X, DVec3::Y),
        MapType::Cylindrical => (around, DVec3::Y),
        MapType::Spherical => {
            let outward = p.normalize_or_zero();
            let north = (DVec3::Y - outward * outward.y).normalize_or_zero();
            (around, north)
        }
        MapType::Torus => {
            // v grows around the tube from the outer rim over the top: in the plane of the
            // radial direction and y, a quarter turn from the offset from the tube's centre.
            let radial = DVec3::new(p.x, 0.0, p.z).normalize_or_zero();
            let from_ring = DVec3::new(p.x, 0.0, p.z).length() - 1.0;
            let over = (DVec3::Y * from_ring - radial * p.y).normalize_or_zero();
            (around, over)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use analysis::image::{ColourModel, Image};
    use analysis::scene::bitmap::{Bitmap, ImageValue, Interpolation};
    use std::sync::Arc;

    /// A planar, tiled bump map of a 4 x 4 grey image, rows from the top.
    fn four_by_four(rows: [[u8; 4]; 4]) -> Pattern {
        let pixels = rows
            .iter()
            .flatten()
            .map(|&g| {
                let g = f32::from(g) / 255.0;
                [g, g, g, 1.0]
            })
            .collect();
        let image = Image {
            width: 4,
            height: 4,
            pixels,
            indices: None,
            palette_len: 0,
            model: ColourModel::Grey,
            has_alpha: false,
            gamma: None,
        };
        let bitmap = Bitmap {
            image: Arc::new(image),
            map_type: MapType::Planar,
            once: false,
            interpolate: Interpolation::None,
        };
        let value = ImageValue::Grey;
        Pattern::new(PatternKind::Image(Box::new(ImagePattern { bitmap, value })))
    }

    #[test]
    fn normals_tilt_as_povray_tilts_them() {
        let pattern = four_by_four([
            [0, 64, 128, 255],
            [32, 200, 16, 90],
            [250, 10, 180, 60],
            [120, 240, 30, 150],
        ]);
        // POV-Ray 3.7's normals at the centres of four cells (row, column) of this map with
        // bump_size 0.5 on a face towards -z, as x and y over -z: recovered from 16-bit
        // renders lit along -z, x - z and y - z. Row 3's pixels below wrap to row 0.
        let povray = [
            ((1, 1), 0.0696, 0.0304),
            ((2, 3), -0.0882, 0.0294),
            ((3, 0), 0.1873, 0.0774),
            ((0, 2), 0.1078, 0.0314),
        ];
        for ((row, column), x, y) in povray {
            let p = DVec3::new(
                (column as f64 + 0.5) / 4.0,
                1.0 - (row as f64 + 0.5) / 4.0,
                0.0,
            );
            let n = perturb(&pattern, 0.5, p, DVec3::NEG_Z);
            let (ours_x, ours_y) = (n.x / -n.z, n.y / -n.z);
            assert!(
                (ours_x - x).abs() < 2e-3 && (ours_y - y).abs() < 2e-3,
                "cell ({row}, {column}): ours ({ours_x:.4}, {ours_y:.4}), POV-Ray ({x}, {y})"
            );
        }
    }
}
