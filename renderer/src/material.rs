//! Surface materials at run time: the texture (pigment and finish) and interior an object
//! was given, ready to be evaluated at a point. Features not implemented yet are refused when
//! the material is built, with a message naming them, rather than drawn wrongly.

use analysis::scene::{self, Colour, Finish};
use std::sync::Arc;

/// What a surface looks like and what is behind it.
#[derive(Debug, Clone)]
pub struct Material {
    pub pigment: Pigment,
    pub finish: Arc<Finish>,
}

/// The colour of a surface point.
#[derive(Debug, Clone)]
pub enum Pigment {
    Solid(Colour),
}

impl Pigment {
    pub fn colour_at(&self) -> Colour {
        match self {
            Pigment::Solid(c) => *c,
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
                if normal.is_some() {
                    return Err("not supported yet: normal patterns".into());
                }
                Ok(Material {
                    pigment: pigment_from_scene(pigment)?,
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
        scene::Pigment::Pattern { .. } => Err("not supported yet: pigment patterns".into()),
    }
}

/// Checks the finish for features the shader does not draw yet.
pub fn check_finish(finish: &Finish) -> Result<(), String> {
    if finish.reflection.is_some() {
        return Err("not supported yet: reflection".into());
    }
    if finish.irid.is_some() {
        return Err("not supported yet: irid".into());
    }
    Ok(())
}
