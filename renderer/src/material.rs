//! Surface materials at run time: the texture an object was given (layers of pigment,
//! normal and finish, or texture maps blending textures), ready to be evaluated at a
//! point. Features not implemented yet are refused when
//! the material is built, with a message naming them, rather than drawn wrongly.

use crate::texture_point::TexturePoint;
use analysis::pattern::{self, PatternValue, bitmap};
use analysis::scene::bitmap::ImageMap;
use analysis::scene::{self, Colour, Finish};
use glam::{DAffine3, DVec3};
use std::sync::Arc;

/// One layer of a texture: its colour, bumps and finish.
#[derive(Debug, Clone)]
pub struct Layer {
    pub pigment: Pigment,
    pub normal: Option<scene::Normal>,
    pub finish: Arc<Finish>,
}

/// What a surface looks like: layers (the top one first, each showing those below through
/// its filter and transmit), or a pattern choosing among or blending between materials
/// (`texture_map` and the block patterns of textures).
#[derive(Debug, Clone)]
pub enum Surface {
    Layers(Vec<Layer>),
    Pattern {
        pattern: Box<scene::Pattern>,
        /// Map values ascending, with their surfaces.
        map: Vec<(f64, Surface)>,
    },
    /// Surfaces mixed by weights that depend on the point (a blob's component textures,
    /// by each component's share of the field).
    Blend {
        weights: Arc<dyn SurfaceWeights>,
        surfaces: Vec<Surface>,
    },
}

/// The weight of each of a blend's surfaces at a world point, not necessarily summing to
/// one (they are normalised).
pub trait SurfaceWeights: std::fmt::Debug + Send + Sync {
    fn weights(&self, p: DVec3, out: &mut Vec<f64>);
}

/// A surface with what the tracer needs to know about it at a glance.
#[derive(Debug, Clone)]
pub struct Material {
    pub surface: Surface,
    /// Whether light can pass at some point, so that shadow rays must look at the colour.
    pub transmits: bool,
    /// Whether some pattern is `uv_mapping`, so that hits must find their uv coordinates.
    pub uses_uv: bool,
    /// Whether some pattern looks at how the surface faces the ray, so that hits must
    /// find their normal before their texture.
    pub uses_facing: bool,
}

/// Where a pattern value falls in a map: the entries either side and the weight of the
/// upper one (0 when both are the same entry).
fn locate<T>(map: &[(f64, T)], value: PatternValue) -> (usize, usize, f64) {
    match value {
        PatternValue::Block(i) => {
            let i = i.min(map.len() - 1);
            (i, i, 0.0)
        }
        PatternValue::Blend(v) => {
            let upper = map.partition_point(|(at, _)| *at <= v);
            if upper == 0 {
                return (0, 0, 0.0);
            }
            if upper == map.len() {
                return (upper - 1, upper - 1, 0.0);
            }
            let (a, b) = (map[upper - 1].0, map[upper].0);
            let t = if b > a { (v - a) / (b - a) } else { 1.0 };
            (upper - 1, upper, t)
        }
    }
}

/// A pattern's value at a texture point. Inlined, as [`pattern::evaluate_on`] is.
#[inline(always)]
fn value_at(pattern: &scene::Pattern, at: &TexturePoint) -> PatternValue {
    pattern::evaluate_on(pattern, at.world, at.facing.as_ref())
}

impl Surface {
    /// The layer of a surface of one layer without bumps or reflection, whatever its
    /// pigment: where the pigment is opaque it hides everything behind the surface and
    /// sends no further rays, so that the tracer shades it as a plain surface of the
    /// pigment's colour there.
    pub fn single_unbumped_layer(&self) -> Option<&Layer> {
        match self {
            Surface::Layers(layers) => match layers.as_slice() {
                [layer] if layer.normal.is_none() && layer.finish.reflection.is_none() => {
                    Some(layer)
                }
                _ => None,
            },
            _ => None,
        }
    }

    /// Calls `f` with each stack of layers that shows at `at`, its weight, and where the
    /// layers' patterns are evaluated: `at`, or where a texture map's pattern moved it.
    pub fn for_each_layers(
        &self,
        at: &TexturePoint,
        weight: f64,
        f: &mut impl FnMut(f64, &[Layer], &TexturePoint),
    ) {
        match self {
            Surface::Layers(layers) => f(weight, layers, at),
            Surface::Pattern { pattern, map }
                if matches!(pattern.kind, scene::PatternKind::Average) =>
            {
                let moved = at.for_pattern(pattern);
                let entries_at = moved.for_entries(pattern);
                let at: &TexturePoint = &entries_at;
                for (share, surface) in pattern::average_shares(map) {
                    surface.for_each_layers(at, weight * share, f);
                }
            }
            Surface::Pattern { pattern, map } => {
                let moved = at.for_pattern(pattern);
                let at: &TexturePoint = &moved;
                let (a, b, t) = locate(map, value_at(pattern, at));
                let entries_at;
                let at = if map[a].1.needs_point() || map[b].1.needs_point() {
                    entries_at = at.for_entries(pattern);
                    &*entries_at
                } else {
                    at
                };
                if a == b || t == 0.0 {
                    map[a].1.for_each_layers(at, weight, f);
                } else if t == 1.0 {
                    map[b].1.for_each_layers(at, weight, f);
                } else {
                    map[a].1.for_each_layers(at, weight * (1.0 - t), f);
                    map[b].1.for_each_layers(at, weight * t, f);
                }
            }
            Surface::Blend { weights, surfaces } => {
                let mut w = Vec::with_capacity(surfaces.len());
                weights.weights(at.world, &mut w);
                let total: f64 = w.iter().sum();
                if total <= 0.0 || !total.is_finite() {
                    // Outside every component's reach (a point of a CSG's other surface):
                    // the first surface, the blob's own texture.
                    surfaces[0].for_each_layers(at, weight, f);
                    return;
                }
                for (surface, w) in surfaces.iter().zip(w) {
                    if w > 0.0 {
                        surface.for_each_layers(at, weight * w / total, f);
                    }
                }
            }
        }
    }

    /// Whether the surface looks at the point at all: layers of solid colours without
    /// bumps do not, and spare their pattern the work of finding where its entries are.
    fn needs_point(&self) -> bool {
        match self {
            Surface::Layers(layers) => layers
                .iter()
                .any(|l| !matches!(l.pigment, Pigment::Solid(_)) || l.normal.is_some()),
            Surface::Pattern { .. } | Surface::Blend { .. } => true,
        }
    }

    /// Whether light can pass somewhere: every layer of some stack lets some through.
    pub fn may_transmit(&self) -> bool {
        match self {
            Surface::Layers(layers) => layers.iter().all(|l| l.pigment.may_transmit()),
            Surface::Pattern { map, .. } => map.iter().any(|(_, s)| s.may_transmit()),
            Surface::Blend { surfaces, .. } => surfaces.iter().any(Surface::may_transmit),
        }
    }

    /// Whether some pattern looks at how the surface faces the ray.
    pub fn uses_facing(&self) -> bool {
        match self {
            Surface::Layers(layers) => layers.iter().any(|l| {
                l.pigment.uses_facing() || l.normal.as_ref().is_some_and(crate::normal::uses_facing)
            }),
            Surface::Pattern { pattern, map } => {
                pattern::uses_facing(pattern) || map.iter().any(|(_, s)| s.uses_facing())
            }
            Surface::Blend { surfaces, .. } => surfaces.iter().any(Surface::uses_facing),
        }
    }

    /// Whether some pattern is uv-mapped.
    pub fn uses_uv(&self) -> bool {
        match self {
            Surface::Layers(layers) => layers.iter().any(|l| {
                l.pigment.uses_uv() || l.normal.as_ref().is_some_and(crate::normal::uses_uv)
            }),
            Surface::Pattern { pattern, map } => {
                pattern.uv_mapping || map.iter().any(|(_, s)| s.uses_uv())
            }
            Surface::Blend { surfaces, .. } => surfaces.iter().any(Surface::uses_uv),
        }
    }
}

/// The colour light keeps through a stack of layers at `at`: the product of each layer's
/// filtered and transmitted colour.
pub fn transmitted_through(layers: &[Layer], at: &TexturePoint) -> DVec3 {
    layers.iter().fold(DVec3::ONE, |acc, layer| {
        let c = layer.pigment.colour_at(at);
        acc * (c.rgb * c.filter + DVec3::splat(c.transmit))
    })
}

/// The colour of a surface point.
#[derive(Debug, Clone)]
pub enum Pigment {
    Solid(Colour),
    /// A pattern choosing among, or blending between, the pigments of its map.
    Pattern {
        pattern: Box<scene::Pattern>,
        /// Map values ascending, with their pigments.
        map: Vec<(f64, Pigment)>,
    },
    /// An image map, with the transform from the world into its pattern space.
    Image {
        map: Arc<ImageMap>,
        to_pattern: DAffine3,
    },
}

impl Pigment {
    /// The colour at `at`. A plain colour is answered inlined: most surfaces have one,
    /// and the tracer asks at every hit.
    #[inline(always)]
    pub fn colour_at(&self, at: &TexturePoint) -> Colour {
        match self {
            Pigment::Solid(c) => *c,
            _ => self.patterned_colour_at(at),
        }
    }

    /// [`Pigment::colour_at`] for a pigment that is not a plain colour.
    fn patterned_colour_at(&self, at: &TexturePoint) -> Colour {
        match self {
            Pigment::Solid(c) => *c,
            Pigment::Pattern { pattern, map }
                if matches!(pattern.kind, scene::PatternKind::Average) =>
            {
                let moved = at.for_pattern(pattern);
                let entries_at = moved.for_entries(pattern);
                let at: &TexturePoint = &entries_at;
                pattern::weighted_colour(
                    pattern::average_shares(map)
                        .map(|(share, pigment)| (share, pigment.colour_at(at))),
                )
            }
            Pigment::Pattern { pattern, map } => {
                let moved = at.for_pattern(pattern);
                let at: &TexturePoint = &moved;
                let (a, b, t) = locate(map, value_at(pattern, at));
                let (lower, upper) = (&map[a].1, &map[b].1);
                // A colour map's entries (plain colours) are read here, without a call or
                // the point where entries are evaluated.
                if let (Pigment::Solid(lower), Pigment::Solid(upper)) = (lower, upper) {
                    return if a == b || t == 0.0 {
                        *lower
                    } else {
                        lower.lerp(*upper, t)
                    };
                }
                let entries_at = at.for_entries(pattern);
                let at: &TexturePoint = &entries_at;
                if a == b || t == 0.0 {
                    lower.colour_at(at)
                } else {
                    lower.colour_at(at).lerp(upper.colour_at(at), t)
                }
            }
            Pigment::Image { map, to_pattern } => {
                let p = if map.uv_mapping {
                    at.uv.extend(0.0)
                } else {
                    at.world
                };
                bitmap::image_map_colour(map, to_pattern.transform_point3(p))
            }
        }
    }

    /// Whether some pattern looks at how the surface faces the ray.
    fn uses_facing(&self) -> bool {
        match self {
            Pigment::Solid(_) | Pigment::Image { .. } => false,
            Pigment::Pattern { pattern, map } => {
                pattern::uses_facing(pattern) || map.iter().any(|(_, p)| p.uses_facing())
            }
        }
    }

    /// Whether some pattern is uv-mapped.
    fn uses_uv(&self) -> bool {
        match self {
            Pigment::Solid(_) => false,
            Pigment::Image { map, .. } => map.uv_mapping,
            Pigment::Pattern { pattern, map } => {
                pattern.uv_mapping || map.iter().any(|(_, p)| p.uses_uv())
            }
        }
    }

    /// Whether any colour this pigment can take lets light through.
    pub fn may_transmit(&self) -> bool {
        match self {
            Pigment::Solid(c) => c.filter != 0.0 || c.transmit != 0.0,
            Pigment::Pattern { map, .. } => map.iter().any(|(_, p)| p.may_transmit()),
            Pigment::Image { map, .. } => {
                map.bitmap.image.has_alpha
                    || map.bitmap.once
                    || !map.filter.is_empty()
                    || !map.transmit.is_empty()
            }
        }
    }
}

impl Material {
    /// The runtime form of a scene texture; `Err` names the first unsupported feature.
    pub fn from_scene(texture: &scene::Texture) -> Result<Material, String> {
        let surface = surface_from_scene(texture)?;
        Ok(Material {
            transmits: surface.may_transmit(),
            uses_uv: surface.uses_uv(),
            uses_facing: surface.uses_facing(),
            surface,
        })
    }
}

fn surface_from_scene(texture: &scene::Texture) -> Result<Surface, String> {
    match texture {
        scene::Texture::Plain { .. } => Ok(Surface::Layers(vec![layer_from_scene(texture)?])),
        scene::Texture::Layered(layers) => {
            // The scene lists layers from the bottom up; the tracer starts at the top.
            let layers = layers
                .iter()
                .rev()
                .map(layer_from_scene)
                .collect::<Result<Vec<_>, String>>()?;
            Ok(Surface::Layers(layers))
        }
        scene::Texture::Pattern { pattern, map } => {
            pattern::check(pattern)?;
            let mut entries = map
                .entries
                .iter()
                .map(|(at, t)| Ok((*at, surface_from_scene(t)?)))
                .collect::<Result<Vec<_>, String>>()?;
            if entries.is_empty() {
                return Err("a texture pattern without textures".into());
            }
            entries.sort_by(|a, b| a.0.total_cmp(&b.0));
            Ok(Surface::Pattern {
                pattern: pattern.clone(),
                map: entries,
            })
        }
    }
}

fn layer_from_scene(texture: &scene::Texture) -> Result<Layer, String> {
    let scene::Texture::Plain {
        pigment,
        normal,
        finish,
    } = texture
    else {
        // The evaluator refuses these as POV-Ray 3.7 does.
        return Err("cannot layer a patterned texture with another".into());
    };
    if let Some(n) = normal {
        crate::normal::check(n)?;
    }
    Ok(Layer {
        pigment: pigment_from_scene(pigment)?,
        normal: normal.clone(),
        finish: finish.clone(),
    })
}

pub(crate) fn pigment_from_scene(pigment: &scene::Pigment) -> Result<Pigment, String> {
    match pigment {
        scene::Pigment::Solid(c) => Ok(Pigment::Solid(*c)),
        scene::Pigment::Image(map) => Ok(Pigment::Image {
            map: Arc::new(ImageMap::clone(map)),
            to_pattern: map.transform.inverse,
        }),
        scene::Pigment::Pattern { pattern, map } => {
            pattern::check(pattern)?;
            let mut entries = map
                .entries
                .iter()
                .map(|(at, p)| Ok((*at, pigment_from_scene(p)?)))
                .collect::<Result<Vec<_>, String>>()?;
            if entries.is_empty() {
                return Err("a pigment pattern without colours".into());
            }
            entries.sort_by(|a, b| a.0.total_cmp(&b.0));
            Ok(Pigment::Pattern {
                pattern: pattern.clone(),
                map: entries,
            })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use analysis::scene::{BlendMap, Pattern, PatternKind};

    fn plain(rgb: DVec3) -> scene::Texture {
        scene::Texture::Plain {
            pigment: scene::Pigment::Solid(Colour {
                rgb,
                filter: 0.0,
                transmit: 0.0,
            }),
            normal: None,
            finish: Arc::new(Finish::default()),
        }
    }

    fn weights(material: &Material, p: DVec3) -> Vec<(f64, DVec3)> {
        let mut seen = Vec::new();
        let at = TexturePoint::in_space(p);
        material
            .surface
            .for_each_layers(&at, 1.0, &mut |w, layers, at| {
                seen.push((w, layers[0].pigment.colour_at(at).rgb));
            });
        seen
    }

    #[test]
    fn texture_maps_blend_and_block_patterns_choose() {
        let map = BlendMap {
            entries: vec![(0.0, plain(DVec3::X)), (1.0, plain(DVec3::Y))],
        };
        let gradient = scene::Texture::Pattern {
            pattern: Box::new(Pattern::new(PatternKind::Gradient(DVec3::X))),
            map: map.clone(),
        };
        let m = Material::from_scene(&gradient).unwrap();
        let seen = weights(&m, DVec3::new(0.25, 0.0, 0.0));
        assert_eq!(seen, vec![(0.75, DVec3::X), (0.25, DVec3::Y)]);
        let checker = scene::Texture::Pattern {
            pattern: Box::new(Pattern::new(PatternKind::Checker)),
            map,
        };
        let m = Material::from_scene(&checker).unwrap();
        assert_eq!(
            weights(&m, DVec3::new(1.5, 0.5, 0.5)),
            vec![(1.0, DVec3::Y)]
        );
        assert!(!m.transmits);
    }

    #[test]
    fn an_average_shows_every_texture_by_its_weight() {
        let average = scene::Texture::Pattern {
            pattern: Box::new(Pattern::new(PatternKind::Average)),
            map: BlendMap {
                entries: vec![(1.0, plain(DVec3::X)), (3.0, plain(DVec3::Y))],
            },
        };
        let m = Material::from_scene(&average).unwrap();
        let seen = weights(&m, DVec3::new(0.25, 7.0, 0.0));
        assert_eq!(seen, vec![(0.25, DVec3::X), (0.75, DVec3::Y)]);
    }

    #[test]
    fn layers_filter_the_light_through_them() {
        let clear = scene::Texture::Plain {
            pigment: scene::Pigment::Solid(Colour {
                rgb: DVec3::new(1.0, 0.5, 0.0),
                filter: 0.5,
                transmit: 0.25,
            }),
            normal: None,
            finish: Arc::new(Finish::default()),
        };
        let layered = scene::Texture::Layered(vec![clear.clone(), clear]);
        let m = Material::from_scene(&layered).unwrap();
        assert!(m.transmits);
        // Each layer keeps filter * colour + transmit: (0.75, 0.5, 0.25), twice.
        let Surface::Layers(layers) = &m.surface else {
            panic!("layers stay layers");
        };
        let through = transmitted_through(layers, &TexturePoint::in_space(DVec3::ZERO));
        assert!((through - DVec3::new(0.5625, 0.25, 0.0625)).length() < 1e-12);
    }
}
