//! Normal perturbation (`normal { }`): bumps that exist only in the lighting, following
//! POV-Ray's reference. Patterns built for normals push the normal by vectors of their
//! own: bumps, dents and wrinkles by solid noise, ripples and waves by their wave fronts,
//! quilted towards the centres of its cubes, facets towards random cell points. Every other
//! pattern is sampled at the four corners of a regular tetrahedron of radius `accuracy`
//! around the point (its value reshaped by the `slope_map`, if any), and each corner's
//! direction, weighted by the value there, is added to the normal, scaled by
//! `-5 bump_size` and by `0.02 / accuracy`: a gentle tilt along the pattern's slope and a
//! sharp one across its jumps. A `normal_map` (or the normals listed after a block
//! pattern) blends the perturbed normals of its entries.
//!
//! The push is added in pattern space to the unit normal there, and the sum carried back
//! to the world like a normal: scaling a pattern changes where its bumps are, not how
//! steep they look.

use crate::texture_point::TexturePoint;
use analysis::noise;
use analysis::pattern::{self, Facing, PatternValue, cells, waves};
use analysis::scene::{self, BlendMap, NormalKind, Pattern, PatternKind, Transform, Warp};
use glam::{DMat3, DVec3};

/// Whether the normal can be evaluated; `Err` names what is missing.
pub fn check(normal: &scene::Normal) -> Result<(), String> {
    match &normal.kind {
        NormalKind::Pattern { pattern, .. } => match pattern.kind {
            PatternKind::Facets { .. } => Ok(()),
            _ => pattern::check(pattern),
        },
        NormalKind::Map { pattern, map } => {
            pattern::check(pattern)?;
            map.entries.iter().try_for_each(|(_, n)| check(n))
        }
        NormalKind::BumpMap { pattern, .. } => pattern::check(pattern),
    }
}

/// Whether some pattern of the normal is uv-mapped, so that hits must find their uv
/// coordinates.
pub fn uses_uv(normal: &scene::Normal) -> bool {
    match &normal.kind {
        NormalKind::Pattern { pattern, .. } | NormalKind::BumpMap { pattern, .. } => {
            pattern.uv_mapping
        }
        NormalKind::Map { pattern, map } => {
            pattern.uv_mapping || map.entries.iter().any(|(_, n)| uses_uv(n))
        }
    }
}

/// Whether some pattern of the normal depends on how the surface faces (slope, aoi).
pub fn uses_facing(normal: &scene::Normal) -> bool {
    match &normal.kind {
        NormalKind::Pattern { pattern, .. } => pattern::uses_facing(pattern),
        NormalKind::Map { pattern, map } => {
            pattern::uses_facing(pattern) || map.entries.iter().any(|(_, n)| uses_facing(n))
        }
        NormalKind::BumpMap { .. } => false,
    }
}

/// The perturbed unit normal at texture point `at` for surface normal `n`; the point's
/// facing is the surface's, for the patterns that look at it (which see `n`).
///
/// A `uv_mapping` pattern is evaluated at (u, v, 0) and its push is added to the normal
/// as it is in pattern space, with no turn into the surface's tangents: POV-Ray's
/// pictures show uv-mapped bumps of a `gradient x` tilting every face towards the
/// world's x, whichever way the face's u runs.
pub fn perturb(normal: &scene::Normal, at: &TexturePoint, n: DVec3) -> DVec3 {
    let facing = at.facing.map(|f| Facing { normal: n, ..f });
    let facing = facing.as_ref();
    let perturbed = match &normal.kind {
        NormalKind::Pattern {
            pattern,
            bump_size,
            slope_map,
        } => {
            if *bump_size == 0.0 {
                return n;
            }
            bumped(
                pattern,
                normal.placement.as_deref(),
                *bump_size,
                slope_map.as_ref(),
                normal.accuracy,
                at.for_pattern(pattern).world,
                n,
                facing,
            )
        }
        NormalKind::Map { pattern, map } => mapped(pattern, map, &at.for_pattern(pattern), n),
        NormalKind::BumpMap { pattern, bump_size } => {
            let p = at.for_pattern(pattern).world;
            let local = pattern.transform.inverse.transform_point3(p);
            let placement = normal.placement.as_deref();
            let local_normal = into_pattern_space(pattern, placement, n).normalize_or_zero();
            let bumped = crate::bump_map::perturb(pattern, *bump_size, local, local_normal);
            out_of_pattern_space(pattern, placement, bumped).normalize_or_zero()
        }
    };
    if perturbed == DVec3::ZERO || !perturbed.is_finite() {
        n
    } else {
        perturbed
    }
}

/// A normal map: the entries either side of the pattern's value, each perturbing the
/// normal, blended by their weights; with `average`, every entry by its share.
fn mapped(pattern: &Pattern, map: &BlendMap<scene::Normal>, at: &TexturePoint, n: DVec3) -> DVec3 {
    let entries = &map.entries;
    if entries.is_empty() {
        return n;
    }
    let facing = at.facing.map(|f| Facing { normal: n, ..f });
    let facing = facing.as_ref();
    // The entries are evaluated where the pattern's warps and turbulence moved the point.
    let entries_at = &at.for_entries(pattern);
    if matches!(pattern.kind, PatternKind::Average) {
        // Each entry perturbs its own copy of the normal; the copies are weighted, added
        // and normalized.
        return pattern::average_shares(entries)
            .fold(DVec3::ZERO, |sum, (share, entry)| {
                sum + perturb(entry, entries_at, n) * share
            })
            .normalize_or_zero();
    }
    let (a, b, t) = match pattern::evaluate_on(pattern, at.world, facing) {
        PatternValue::Block(i) => {
            let i = i.min(entries.len() - 1);
            (i, i, 0.0)
        }
        PatternValue::Blend(v) => pattern::blend_position(entries.iter().map(|(at, _)| *at), v),
    };
    let lower = perturb(&entries[a].1, entries_at, n);
    if a == b || t == 0.0 {
        return lower;
    }
    let upper = perturb(&entries[b].1, entries_at, n);
    (lower * (1.0 - t) + upper * t).normalize_or_zero()
}

/// A world normal `n` carried into the pattern's warped space (see
/// [`into_pattern_space_matrix`]).
#[inline]
fn into_pattern_space(pattern: &Pattern, placement: Option<&Transform>, n: DVec3) -> DVec3 {
    let linear = &pattern.transform.matrix.matrix3;
    carry(pattern, placement, n, linear, into_pattern_space_matrix)
}

/// The way back from [`into_pattern_space`].
#[inline]
fn out_of_pattern_space(pattern: &Pattern, placement: Option<&Transform>, n: DVec3) -> DVec3 {
    let linear = &pattern.transform.inverse.matrix3;
    carry(pattern, placement, n, linear, out_of_pattern_space_matrix)
}

/// `n` times the matrix `matrix` builds. Without warps or a placement that matrix is the
/// transpose of `linear`, and its product with `n` the dot products of `linear`'s columns
/// with `n`: the same sums in the same order, without building and passing back a matrix
/// twice for each bumped normal.
#[inline(always)]
fn carry(
    pattern: &Pattern,
    placement: Option<&Transform>,
    n: DVec3,
    linear: &DMat3,
    matrix: fn(&Pattern, Option<&Transform>) -> DMat3,
) -> DVec3 {
    if placement.is_none() && pattern.warps.is_empty() {
        linear.transpose_mul_vec3(n)
    } else {
        matrix(pattern, placement) * n
    }
}

/// The matrix taking world normals into the pattern's warped space: the pattern's
/// transform and each transformation among its warps, as POV-Ray carries normals through
/// warps (the geometric warps leave normals alone). A uv-mapped normal's `placement`
/// (the object's transformations, which do not move its pattern) turns it too. Inlined,
/// as [`out_of_pattern_space_matrix`] is: a normal under warps takes both, and a call
/// costs the interpreted plugin a frame.
#[inline(always)]
fn into_pattern_space_matrix(pattern: &Pattern, placement: Option<&Transform>) -> DMat3 {
    // The linear part of the pattern's transform, then the placement's, as
    // `Transform::then` composes them, without the translations and inverses it finds too.
    let linear = pattern.transform.matrix.matrix3;
    let mut m = match placement {
        Some(p) => p.matrix.matrix3 * linear,
        None => linear,
    }
    .transpose();
    for warp in pattern.warps.iter().rev() {
        if let Warp::Transform(t) = warp {
            m = t.matrix.matrix3.transpose() * m;
        }
    }
    m
}

/// The way back from [`into_pattern_space_matrix`].
#[inline(always)]
fn out_of_pattern_space_matrix(pattern: &Pattern, placement: Option<&Transform>) -> DMat3 {
    // The inverse of the pattern's transform then the placement, as `Transform::then`
    // finds its linear part.
    let linear = pattern.transform.inverse.matrix3;
    let mut m = match placement {
        Some(p) => linear * p.inverse.matrix3,
        None => linear,
    }
    .transpose();
    for warp in pattern.warps.iter().rev() {
        if let Warp::Transform(t) = warp {
            m *= t.inverse.matrix3.transpose();
        }
    }
    m
}

/// A pattern used as bumps: the push in pattern space added to the unit normal there.
#[allow(clippy::too_many_arguments)]
fn bumped(
    pattern: &Pattern,
    placement: Option<&Transform>,
    bump_size: f64,
    slope_map: Option<&BlendMap<(f64, f64)>>,
    accuracy: f64,
    p: DVec3,
    n: DVec3,
    facing: Option<&Facing>,
) -> DVec3 {
    let local = pattern::warped(pattern, pattern.transform.inverse.transform_point3(p));
    let local_normal = into_pattern_space(pattern, placement, n).normalize_or_zero();
    // The bump patterns' own pushes take the point after the classic turbulence, as the
    // patterns' values do (the pyramid below gets it through the pattern's evaluation).
    let turbulent = match &pattern.turbulence {
        Some(t) => pattern::warp::turbulent(t, local),
        None => local,
    };
    let bumped = match pattern.kind {
        PatternKind::Bumps => local_normal + noise::vector(turbulent) * bump_size,
        PatternKind::Dents => {
            // Along the vector noise, scaled by the cube of the scalar noise: POV-Ray's
            // normals, measured from renders lit from three directions, agree exactly.
            let depth = noise::noise(turbulent).powi(3);
            local_normal + noise::vector(turbulent) * (bump_size * depth)
        }
        PatternKind::Wrinkles => {
            let mut v = DVec3::ZERO;
            let mut scale = 1.0;
            for _ in 0..10 {
                v += (noise::vector(turbulent * scale) / scale).abs();
                scale *= 2.0;
            }
            local_normal + v * bump_size
        }
        PatternKind::Ripples | PatternKind::Waves => {
            let own = matches!(pattern.kind, PatternKind::Waves);
            local_normal + waves::push(turbulent, pattern.frequency, pattern.phase, own) * bump_size
        }
        PatternKind::Quilted { control0, control1 } => {
            local_normal + pattern::quilt_offset(turbulent, control0, control1) * bump_size
        }
        PatternKind::Facets {
            coords,
            size,
            metric,
        } => facets(local, local_normal, coords, size, metric),
        _ => {
            let accuracy = if accuracy > 0.0 { accuracy } else { 0.02 };
            let amount = -5.0 * bump_size * (0.02 / accuracy);
            local_normal + pyramid(pattern, slope_map, local, accuracy, facing) * amount
        }
    };
    out_of_pattern_space(pattern, placement, bumped).normalize_or_zero()
}

/// `facets`: the normal turned towards the nearest random cell point of the normal itself
/// scaled by `1/size`, or, with `coords`, tilted by solid noise at the nearest cell point
/// of the surface position, so that each cell shows one flat facet.
fn facets(p: DVec3, normal: DVec3, coords: f64, size: f64, metric: f64) -> DVec3 {
    let scale = if size < 1e-6 { 1e6 } else { 1.0 / size };
    let at = if coords != 0.0 { p } else { normal } * scale;
    let nearest = cells::nearest_nucleus(at, metric);
    if coords == 0.0 {
        return nearest;
    }
    let tilt = noise::vector(nearest);
    normal + (tilt - normal * tilt.dot(normal)) * coords
}

/// The corners of a regular tetrahedron around the origin, one straight up.
const PYRAMID: [DVec3; 4] = [
    DVec3::new(0.942_809_041, -0.333_333_333, 0.0),
    DVec3::new(-0.471_404_521, -0.333_333_333, 0.816_496_581),
    DVec3::new(-0.471_404_521, -0.333_333_333, -0.816_496_581),
    DVec3::new(0.0, 1.0, 0.0),
];

/// The sum of the tetrahedron's corner directions weighted by the pattern's value (through
/// the slope map) at each corner, around a point already through the pattern's warps.
fn pyramid(
    pattern: &Pattern,
    slope_map: Option<&BlendMap<(f64, f64)>>,
    warped: DVec3,
    h: f64,
    facing: Option<&Facing>,
) -> DVec3 {
    // Spelled out: `PYRAMID.map` was a call of its own.
    let corner = |i: usize| warped + PYRAMID[i] * h;
    let points = [corner(0), corner(1), corner(2), corner(3)];
    let values = pattern::evaluate_warped_each(pattern, points, facing);
    PYRAMID
        .iter()
        .zip(values)
        .fold(DVec3::ZERO, |sum, (corner, value)| {
            let value = match value {
                PatternValue::Blend(v) => v,
                // Through `u32`, whose conversion is one instruction where `usize`'s is a
                // dozen: a block pattern's index is small.
                PatternValue::Block(i) => f64::from(i as u32),
            };
            let height = slope_map.map_or(value, |map| slope_profile(map, value));
            sum + *corner * height
        })
}

/// A value through a `slope_map`: the Hermite cubic between the entries either side, each
/// entry a height and the slope there.
fn slope_profile(map: &BlendMap<(f64, f64)>, value: f64) -> f64 {
    let entries = &map.entries;
    let (a, b, t) = pattern::blend_position(entries.iter().map(|(at, _)| *at), value);
    let (h1, s1) = entries[a].1;
    if a == b {
        return h1;
    }
    let (h2, s2) = entries[b].1;
    let (t2, t3) = (t * t, t * t * t);
    t3 * (s1 + s2 + 2.0 * (h1 - h2)) - t2 * (2.0 * s1 + s2 + 3.0 * (h1 - h2)) + t * s1 + h1
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slope_maps_follow_hermite_curves() {
        let map = BlendMap {
            entries: vec![(0.0, (0.0, 1.0)), (1.0, (1.0, 1.0))],
        };
        // Heights 0 and 1 with slope 1 at both ends: the straight line.
        for v in [0.0, 0.25, 0.5, 0.9] {
            assert!((slope_profile(&map, v) - v).abs() < 1e-12);
        }
        let bump = BlendMap {
            entries: vec![(0.0, (0.0, 0.0)), (1.0, (1.0, 0.0))],
        };
        assert!((slope_profile(&bump, 0.5) - 0.5).abs() < 1e-12);
        assert!(slope_profile(&bump, 0.1) < 0.1);
    }

    #[test]
    fn an_average_adds_its_entries_perturbed_normals() {
        let bumps = |amount: f64| scene::Normal {
            kind: NormalKind::Pattern {
                pattern: Box::new(Pattern::new(PatternKind::Gradient(DVec3::X))),
                bump_size: amount,
                slope_map: None,
            },
            accuracy: 0.02,
            placement: None,
        };
        let map = BlendMap {
            entries: vec![(1.0, bumps(0.5)), (1.0, bumps(-0.5))],
        };
        // Opposite tilts of equal weight cancel, leaving the surface normal.
        let p = DVec3::new(0.3, 0.0, 0.0);
        let at = TexturePoint::in_space(p);
        let n = mapped(&Pattern::new(PatternKind::Average), &map, &at, DVec3::Y);
        assert!((n - DVec3::Y).length() < 1e-9, "{n}");
        let tilted = perturb(&bumps(0.5), &at, DVec3::Y);
        assert!((tilted - DVec3::Y).length() > 1e-3);
    }

    #[test]
    fn uv_mapped_normals_look_at_uv_and_turn_with_their_placement() {
        let ramp = |uv_mapping: bool, placement: Option<Box<Transform>>| {
            let mut pattern = Pattern::new(PatternKind::Gradient(DVec3::X));
            pattern.uv_mapping = uv_mapping;
            pattern.transform = Transform::scale(DVec3::splat(8.0)).unwrap();
            scene::Normal {
                kind: NormalKind::Pattern {
                    pattern: Box::new(pattern),
                    bump_size: 0.5,
                    slope_map: None,
                },
                accuracy: 0.02,
                placement,
            }
        };
        // A point whose uv lies on the gentle ramp (x / 8 near 0.3) while its place in
        // space sits on the ramp's jump at x = 0.
        let at = TexturePoint {
            uv: glam::DVec2::new(2.4, 0.0),
            ..TexturePoint::in_space(DVec3::new(0.0, 0.5, 0.0))
        };
        let n = -DVec3::Z;
        let in_space = perturb(&ramp(false, None), &at, n);
        let on_uv = perturb(&ramp(true, None), &at, n);
        // On the ramp the push is gentle and along x; across the jump it is steep.
        assert!(on_uv.x.abs() > 1e-3 && on_uv.y.abs() < 1e-9, "{on_uv}");
        assert!(
            in_space.x.abs() > 10.0 * on_uv.x.abs(),
            "{in_space} {on_uv}"
        );
        // A quarter turn about z after the texture turns the push to y, leaving the
        // pattern (and so the push's size) where it was.
        let quarter = Transform::rotate_degrees(DVec3::new(0.0, 0.0, 90.0));
        let turned = perturb(&ramp(true, Some(Box::new(quarter))), &at, n);
        assert!(
            (turned.y.abs() - on_uv.x.abs()).abs() < 1e-9,
            "{turned} {on_uv}"
        );
        assert!(turned.x.abs() < 1e-9, "{turned}");
    }

    #[test]
    fn facets_turn_normals_to_cell_points() {
        let n = DVec3::Y;
        let turned = facets(DVec3::ZERO, n, 0.0, 0.1, 2.0);
        // The nearest cell point to 10 * y lies within two cells of it.
        assert!((turned - DVec3::Y * 10.0).length() < 2.0);
    }
}
