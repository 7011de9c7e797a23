//! `bump_map`: an image read as a relief. The normal tilts against the relief's slope,
//! measured one pixel apart along the image's two axes as they lie in pattern space for
//! the map type, and scaled by `bump_size`. Outside a `once` map the normal is left alone.

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
    let here = bitmap::value_at(image, u, v);
    let slope_u = bitmap::value_at(image, (u + du).rem_euclid(1.0), v) - here;
    // Towards the pixel below, as POV-Ray measures it: its seam between tiles falls on
    // the image's bottom row.
    let slope_v = here - bitmap::value_at(image, u, (v - dv).rem_euclid(1.0));
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
