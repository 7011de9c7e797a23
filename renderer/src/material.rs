//! Surface materials at run time: the texture (pigment and finish) and interior an object
//! was given, ready to be evaluated at a point. Features not implemented yet are refused when
//! the material is built, with a message naming them, rather than drawn wrongly.

use analysis::pattern::{self, PatternValue};
use analysis::scene::{self, Colour, Finish};
use glam::DVec3;
use std::sync::Arc;

/// What a surface looks like and what is behind it.
#[derive(Debug, Clone)]
pub struct Material {
    pub pigment: Pigment,
    pub normal: Option<scene::Normal>,
    pub finish: Arc<Finish>,
    /// Whether any point of the pigment lets light through, so that shadow rays must look
    /// at the colour.
    pub transmits: bool,
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
}

impl Pigment {
    pub fn colour_at(&self, p: DVec3) -> Colour {
        match self {
            Pigment::Solid(c) => *c,
            Pigment::Pattern { pattern, map } => match pattern::evaluate(pattern, p) {
                PatternValue::Block(i) => map[i.min(map.len() - 1)].1.colour_at(p),
                PatternValue::Blend(v) => {
                    let upper = map.partition_point(|(at, _)| *at <= v);
                    if upper == 0 {
                        return map[0].1.colour_at(p);
                    }
                    if upper == map.len() {
                        return map[map.len() - 1].1.colour_at(p);
                    }
                    let (a, pa) = &map[upper - 1];
                    let (b, pb) = &map[upper];
                    let t = if b > a { (v - a) / (b - a) } else { 1.0 };
                    pa.colour_at(p).lerp(pb.colour_at(p), t)
                }
            },
        }
    }

    /// Whether any colour this pigment can take lets light through.
    pub fn may_transmit(&self) -> bool {
        match self {
            Pigment::Solid(c) => c.filter != 0.0 || c.transmit != 0.0,
            Pigment::Pattern { map, .. } => map.iter().any(|(_, p)| p.may_transmit()),
        }
    }
}

impl Material {
    /// The runtime form of a scene texture; `Err` names the first unsupported feature.
    pub fn from_scene(texture: &scene::Texture) -> Result<Material, String> {
        match texture {
            scene::Texture::Plain {
                pigment,
                normal,
                finish,
            } => {
                if let Some(n) = normal {
                    crate::normal::check(n)?;
                }
                let pigment = pigment_from_scene(pigment)?;
                Ok(Material {
                    transmits: pigment.may_transmit(),
                    pigment,
                    normal: normal.clone(),
                    finish: finish.clone(),
                })
            }
            scene::Texture::Pattern { .. } => Err("not supported yet: texture maps".into()),
            scene::Texture::Layered(_) => Err("not supported yet: layered textures".into()),
        }
    }
}

fn pigment_from_scene(pigment: &scene::Pigment) -> Result<Pigment, String> {
    match pigment {
        scene::Pigment::Solid(c) => Ok(Pigment::Solid(*c)),
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

/// Checks the finish for features the shader does not draw yet.
pub fn check_finish(finish: &Finish) -> Result<(), String> {
    if finish.crand > 0.0 {
        return Err("not supported yet: crand".into());
    }
    if finish.diffuse_back != 0.0 {
        return Err("not supported yet: backside diffuse".into());
    }
    if finish.irid.is_some() {
        return Err("not supported yet: irid".into());
    }
    Ok(())
}
