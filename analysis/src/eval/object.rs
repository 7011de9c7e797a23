//! Object statements: the shapes, CSG, `object { }` references, and the modifiers every
//! object takes (transformations, textures, flags, clipping and bounding).

use super::math_shapes::MATH_SHAPES;
use super::texture::{map_texture_uv, place_texture};
use super::tokens::Token;
use super::value::{MaterialValue, Value};
use super::{Evaluator, Result};
use crate::scene::{CsgOp, Light, Object, Shape, Texture, Transform};
use glam::DVec3;
use std::rc::Rc;
use std::sync::Arc;
use syntax::SyntaxKind::{self, *};

impl Evaluator<'_> {
    /// Whether `kind` starts an object statement.
    pub fn starts_object(kind: SyntaxKind) -> bool {
        matches!(
            kind,
            SPHERE_KW
                | BOX_KW
                | CYLINDER_KW
                | CONE_KW
                | PLANE_KW
                | TORUS_KW
                | DISC_KW
                | TRIANGLE_KW
                | SMOOTH_TRIANGLE_KW
                | MESH_KW
                | MESH2_KW
                | POLYGON_KW
                | BICUBIC_PATCH_KW
                | LIGHT_GROUP_KW
                | QUADRIC_KW
                | UNION_KW
                | INTERSECTION_KW
                | DIFFERENCE_KW
                | MERGE_KW
                | OBJECT_KW
                | TEXT_KW
        ) || MATH_SHAPES.contains(&kind)
    }

    /// One object statement, from its keyword to its closing brace.
    pub fn object(&mut self) -> Result<Object> {
        let keyword = self.next()?;
        let open = self.expect(L_BRACE, "'{'")?;
        let origin = Some(self.span(&keyword));
        let mut object = match keyword.kind {
            SPHERE_KW => {
                let center = self.vector()?;
                self.eat(COMMA)?;
                let radius = self.float()?;
                Object::new(Shape::Sphere { center, radius }, origin)
            }
            BOX_KW => {
                let corner1 = self.vector()?;
                self.eat(COMMA)?;
                let corner2 = self.vector()?;
                Object::new(Shape::Box { corner1, corner2 }, origin)
            }
            CYLINDER_KW => {
                let base = self.vector()?;
                self.eat(COMMA)?;
                let cap = self.vector()?;
                self.eat(COMMA)?;
                let radius = self.float()?;
                if (cap - base).length() == 0.0 {
                    return Err(self.error_at(
                        &keyword,
                        "degenerate cylinder: base and cap are the same point",
                    ));
                }
                Object::new(
                    Shape::Cylinder {
                        base,
                        cap,
                        radius,
                        open: false,
                    },
                    origin,
                )
            }
            CONE_KW => {
                let base = self.vector()?;
                self.eat(COMMA)?;
                let base_radius = self.float()?;
                self.eat(COMMA)?;
                let cap = self.vector()?;
                self.eat(COMMA)?;
                let cap_radius = self.float()?;
                if (cap - base).length() == 0.0 {
                    return Err(
                        self.error_at(&keyword, "degenerate cone: base and cap are the same point")
                    );
                }
                Object::new(
                    Shape::Cone {
                        base,
                        base_radius,
                        cap,
                        cap_radius,
                        open: false,
                    },
                    origin,
                )
            }
            PLANE_KW => {
                let normal = self.vector()?;
                self.eat(COMMA)?;
                let distance = self.float()?;
                if normal.length() == 0.0 {
                    return Err(self.error_at(&keyword, "degenerate plane: the normal is zero"));
                }
                Object::new(Shape::Plane { normal, distance }, origin)
            }
            TORUS_KW => {
                let major = self.float()?;
                self.eat(COMMA)?;
                let minor = self.float()?;
                Object::new(
                    Shape::Torus {
                        major,
                        minor,
                        sturm: false,
                    },
                    origin,
                )
            }
            DISC_KW => {
                let center = self.vector()?;
                self.eat(COMMA)?;
                let normal = self.vector()?;
                self.eat(COMMA)?;
                let radius = self.float()?;
                let hole_radius = if self.eat(COMMA)? { self.float()? } else { 0.0 };
                Object::new(
                    Shape::Disc {
                        center,
                        normal,
                        radius,
                        hole_radius,
                    },
                    origin,
                )
            }
            QUADRIC_KW => {
                let squares = self.vector()?;
                self.eat(COMMA)?;
                let mixed = self.vector()?;
                self.eat(COMMA)?;
                let linear = self.vector()?;
                self.eat(COMMA)?;
                let constant = self.float()?;
                Object::new(
                    Shape::Quadric {
                        squares,
                        mixed,
                        linear,
                        constant,
                    },
                    origin,
                )
            }
            TRIANGLE_KW | SMOOTH_TRIANGLE_KW => {
                let shape = match self.triangle_corners(keyword.kind)? {
                    (corners, Some(normals)) => Shape::SmoothTriangle { corners, normals },
                    (corners, None) => Shape::Triangle { corners },
                };
                Object::new(shape, origin)
            }
            MESH_KW => match self.declared_mesh()? {
                Some(object) => object,
                None => Object::new(self.mesh(&keyword)?, origin),
            },
            MESH2_KW => Object::new(self.mesh2(&keyword)?, origin),
            POLYGON_KW => Object::new(self.polygon(&keyword)?, origin),
            BICUBIC_PATCH_KW => Object::new(self.bicubic_patch(&keyword)?, origin),
            LIGHT_GROUP_KW => self.light_group(origin)?,
            UNION_KW | MERGE_KW | INTERSECTION_KW | DIFFERENCE_KW => {
                let op = match keyword.kind {
                    UNION_KW => CsgOp::Union,
                    MERGE_KW => CsgOp::Merge,
                    INTERSECTION_KW => CsgOp::Intersection,
                    _ => CsgOp::Difference,
                };
                self.csg_children(op, origin)?
            }
            OBJECT_KW => self.object_or_identifier()?,
            kind if MATH_SHAPES.contains(&kind) => Object::new(self.math_shape(&keyword)?, origin),
            TEXT_KW => Object::new(self.text_shape(&keyword)?, origin),
            _ => {
                return Err(self.error_at(
                    &keyword,
                    format!("expected an object, found {}", self.describe(&keyword)),
                ));
            }
        };
        // A light group reads its own transformations and takes no other modifiers.
        if keyword.kind != LIGHT_GROUP_KW {
            self.object_modifiers(&mut object, &keyword)?;
        }
        let close = self.next()?;
        if close.kind != R_BRACE {
            let mut error = self.error_at(
                &close,
                format!(
                    "expected an object modifier or '}}' in {}, found {}",
                    self.text(&keyword),
                    self.describe(&close)
                ),
            );
            error.related.push(syntax::Related {
                span: self.span(&open),
                message: "the object starts here".into(),
            });
            return Err(error);
        }
        Ok(object)
    }

    /// The corners of a `triangle`, or the corners and normals of a `smooth_triangle`
    /// (whose keyword is `kind`), as they follow its opening brace.
    pub(super) fn triangle_corners(
        &mut self,
        kind: SyntaxKind,
    ) -> Result<([DVec3; 3], Option<[DVec3; 3]>)> {
        let smooth = kind == SMOOTH_TRIANGLE_KW;
        let mut corners = [DVec3::ZERO; 3];
        let mut normals = [DVec3::ZERO; 3];
        for i in 0..3 {
            if i > 0 {
                self.eat(COMMA)?;
            }
            corners[i] = self.vector()?;
            if smooth {
                self.eat(COMMA)?;
                normals[i] = self.vector()?;
            }
        }
        Ok((corners, smooth.then_some(normals)))
    }

    /// An object statement or an object identifier: what `object { }`, `looks_like { }`,
    /// `projected_through { }` and the functions of objects take.
    /// A declared mesh that a `mesh { M ... }` statement copies, as POV-Ray's mesh camera
    /// examples place theirs; `None` when the statement lists its own triangles.
    fn declared_mesh(&mut self) -> Result<Option<Object>> {
        let token = self.next()?;
        if let Some(Value::Object(object)) = token.slot.as_ref().map(|s| s.borrow().clone())
            && matches!(object.shape, Shape::Mesh(_))
        {
            return Ok(Some(Rc::unwrap_or_clone(object)));
        }
        self.unget(token);
        Ok(None)
    }

    pub(super) fn object_or_identifier(&mut self) -> Result<Object> {
        self.shared_object_or_identifier().map(Rc::unwrap_or_clone)
    }

    /// [`Self::object_or_identifier`], sharing a declared object's storage rather than
    /// copying it: the geometric queries find the renderer's preparation of an object by it.
    pub(super) fn shared_object_or_identifier(&mut self) -> Result<Rc<Object>> {
        let token = self.next()?;
        if Self::starts_object(token.kind) {
            self.unget(token);
            return self.object().map(Rc::new);
        }
        match token.slot.as_ref().map(|s| s.borrow().clone()) {
            Some(Value::Object(object)) => Ok(object),
            // POV-Ray's light source is an object too: `object { Lamp rotate y*30 }` places
            // a declared light, alone or among a CSG's children.
            Some(Value::Light(light)) => Ok(Rc::new(light_only(
                Light::clone(&light),
                Some(self.span(&token)),
            ))),
            Some(other) => Err(self.error_at(
                &token,
                format!("expected an object, found {}", other.type_name()),
            )),
            None if token.kind == IDENT => Err(self.undeclared(&token)),
            None => Err(self.error_at(
                &token,
                format!("expected an object, found {}", self.describe(&token)),
            )),
        }
    }

    fn csg_children(&mut self, op: CsgOp, origin: crate::scene::Origin) -> Result<Object> {
        let mut children = Vec::new();
        let mut lights = Vec::new();
        loop {
            let token = self.next()?;
            if Self::starts_object(token.kind) {
                self.unget(token);
                let mut child = self.object()?;
                if is_light_only(&child) {
                    collect_lights(&mut child, &mut lights);
                } else {
                    children.push(child);
                }
            } else if token.kind == LIGHT_SOURCE_KW {
                self.unget(token);
                lights.push(self.light_source()?);
            } else {
                self.unget(token);
                break;
            }
        }
        Ok(Object::new(
            Shape::Csg {
                op,
                children,
                lights,
            },
            origin,
        ))
    }

    /// The modifiers after a shape's parameters, up to (not including) the closing brace.
    pub(super) fn object_modifiers(&mut self, object: &mut Object, keyword: &Token) -> Result<()> {
        // `bounded_by { clipped_by }` and `clipped_by { bounded_by }` take the other list
        // as it stands when the object ends, whichever comes first.
        let (mut bounds_are_clips, mut clips_are_bounds) = (false, false);
        // `uv_mapping` maps the textures, pigments and normals that follow it.
        let mut uv_mapping = false;
        let mut cutaway = None;
        loop {
            let token = self.next()?;
            match token.kind {
                kind if Self::starts_transform(kind) => {
                    let t = self.transformation(&token)?;
                    transform_object(object, &t);
                }
                TEXTURE_KW => {
                    let mut texture = self.texture_body()?;
                    if uv_mapping {
                        map_texture_uv(&mut texture);
                    }
                    object.texture = Some(Arc::new(match object.texture.take() {
                        Some(below) => layer(Texture::clone(&below), texture)
                            .map_err(|reason| self.error_at(&token, reason))?,
                        None => texture,
                    }));
                }
                PIGMENT_KW | NORMAL_KW | FINISH_KW => {
                    self.texture_part(object, &token)?;
                    if let (true, Some(texture)) = (uv_mapping, &mut object.texture) {
                        map_texture_uv(Arc::make_mut(texture));
                    }
                }
                UV_MAPPING_KW => {
                    if object.texture.is_some() {
                        return Err(self.error_at(
                            &token,
                            "uv_mapping must come before the object's texture, pigment and normal",
                        ));
                    }
                    uv_mapping = true;
                }
                HIERARCHY_KW => {
                    let on = self.optional_bool()?;
                    let Shape::Mesh(mesh) = &mut object.shape else {
                        return Err(self.error_at(
                            &token,
                            format!("'hierarchy' does not apply to {}", self.text(keyword)),
                        ));
                    };
                    mesh.hierarchy = on;
                }
                INTERIOR_KW => {
                    let interior = self.interior_body()?;
                    object.interior = Some(Arc::new(interior));
                }
                INTERIOR_TEXTURE_KW => {
                    let texture = self.texture_body()?;
                    object.interior_texture = Some(Arc::new(texture));
                }
                MATERIAL_KW => self.material(object)?,
                NO_SHADOW_KW => object.flags.no_shadow = self.optional_bool()?,
                NO_IMAGE_KW => object.flags.no_image = self.optional_bool()?,
                NO_REFLECTION_KW => object.flags.no_reflection = self.optional_bool()?,
                NO_RADIOSITY_KW => object.flags.no_radiosity = self.optional_bool()?,
                DOUBLE_ILLUMINATE_KW => object.flags.double_illuminate = self.optional_bool()?,
                HOLLOW_KW => object.flags.hollow = Some(self.optional_bool()?),
                INVERSE_KW => object.flags.inverse = !object.flags.inverse,
                STURM_KW => {
                    let on = self.optional_bool()?;
                    if let Shape::Torus { sturm, .. } = &mut object.shape {
                        *sturm = on;
                    } else {
                        Self::set_sturm(&mut object.shape, on);
                    }
                }
                OPEN_KW => match &mut object.shape {
                    Shape::Cylinder { open, .. } | Shape::Cone { open, .. } => {
                        *open = self.optional_bool()?
                    }
                    shape if Self::takes_open(shape) => {
                        let on = self.optional_bool()?;
                        Self::set_open(&mut object.shape, on);
                    }
                    _ => {
                        return Err(self.error_at(
                            &token,
                            format!("'open' does not apply to {}", self.text(keyword)),
                        ));
                    }
                },
                CLIPPED_BY_KW | BOUNDED_BY_KW => {
                    let list = self.object_list(&token)?;
                    let clipping = token.kind == CLIPPED_BY_KW;
                    let (own, refers) = if clipping {
                        (&mut object.clipped_by, &mut clips_are_bounds)
                    } else {
                        (&mut object.bounded_by, &mut bounds_are_clips)
                    };
                    *refers = list.is_none();
                    *own = list.unwrap_or_default();
                }
                PHOTONS_KW => {
                    self.object_photons(&mut object.photons)?;
                    super::photons::spread_to_parts(object);
                }
                RADIOSITY_KW => self.object_radiosity(object)?,
                SPLIT_UNION_KW => object.photons.split_union = self.optional_bool()?,
                CUTAWAY_TEXTURES_KW => cutaway = Some(token.clone()),
                _ => {
                    self.unget(token);
                    if let Some(at) = &cutaway
                        && cutaway_changes_textures(object)
                    {
                        return Err(self.unsupported(at, "cutaway_textures"));
                    }
                    if bounds_are_clips {
                        object.bounded_by = object.clipped_by.clone();
                    } else if clips_are_bounds {
                        object.clipped_by = object.bounded_by.clone();
                    }
                    return Ok(());
                }
            }
        }
    }

    /// `pigment { }`, `normal { }` or `finish { }` applied to an object: they modify the
    /// object's own plain texture, which starts as a copy of the default texture.
    pub(super) fn texture_part(&mut self, object: &mut Object, keyword: &Token) -> Result<()> {
        let mut texture = match object.texture.take() {
            Some(texture) => Texture::clone(&texture),
            None => self.default_texture.clone(),
        };
        let Texture::Plain {
            pigment,
            normal,
            finish,
        } = &mut texture
        else {
            return Err(self.error_at(
                keyword,
                format!(
                    "cannot add a {} to a patterned or layered texture; put it inside the texture",
                    self.text(keyword)
                ),
            ));
        };
        match keyword.kind {
            PIGMENT_KW => *pigment = self.pigment_with(Some(pigment.clone()))?,
            NORMAL_KW => *normal = self.normal_with(normal.clone())?,
            _ => *finish = Arc::new(self.finish_body(Some(finish))?),
        }
        object.texture = Some(Arc::new(texture));
        Ok(())
    }

    fn material(&mut self, object: &mut Object) -> Result<()> {
        let material = self.material_body()?;
        if let Some(texture) = material.texture {
            object.texture = Some(Arc::new(texture));
        }
        if let Some(interior) = material.interior {
            object.interior = Some(Arc::new(interior));
        }
        Ok(())
    }

    /// `{ [MATERIAL_IDENT] texture {...} interior {...} transformations }` after `material`.
    pub fn material_body(&mut self) -> Result<MaterialValue> {
        self.expect(L_BRACE, "'{'")?;
        let first = self.next()?;
        let mut material = match first.slot.as_ref().map(|s| s.borrow().clone()) {
            Some(Value::Material(m)) => MaterialValue::clone(&m),
            _ => {
                self.unget(first);
                MaterialValue::default()
            }
        };
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => return Ok(material),
                TEXTURE_KW => {
                    let texture = self.texture_body()?;
                    material.texture = Some(match material.texture.take() {
                        Some(below) => {
                            layer(below, texture).map_err(|reason| self.error_at(&token, reason))?
                        }
                        None => texture,
                    });
                }
                INTERIOR_KW => material.interior = Some(self.interior_body()?),
                kind if Self::starts_transform(kind) => {
                    let t = self.transformation(&token)?;
                    if let Some(texture) = &mut material.texture {
                        super::texture::transform_texture(texture, &t);
                    }
                }
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected texture, interior or '}}' in material, found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
    }

    /// `{ object... }` for clipped_by and bounded_by, or `None` for `clipped_by { bounded_by }`
    /// and `bounded_by { clipped_by }`, which stand for the other list.
    fn object_list(&mut self, keyword: &Token) -> Result<Option<Vec<Object>>> {
        self.expect(L_BRACE, "'{'")?;
        let mut list = Vec::new();
        loop {
            let token = self.next()?;
            if token.kind == R_BRACE {
                break;
            }
            let other = if keyword.kind == CLIPPED_BY_KW {
                BOUNDED_BY_KW
            } else {
                CLIPPED_BY_KW
            };
            if token.kind == other && list.is_empty() {
                self.expect(R_BRACE, "'}'")?;
                return Ok(None);
            }
            self.unget(token.clone());
            if !Self::starts_object(token.kind) {
                return Err(self.error_at(
                    &token,
                    format!(
                        "expected an object in {}, found {}",
                        self.text(keyword),
                        self.describe(&token)
                    ),
                ));
            }
            list.push(self.object()?);
        }
        Ok(Some(list))
    }

    /// An optional boolean after a flag keyword: `hollow`, `hollow on`, `hollow off`.
    pub fn optional_bool(&mut self) -> Result<bool> {
        let token = self.next()?;
        let is_value_start = matches!(
            token.kind,
            NUMBER | L_PAREN | TRUE_KW | FALSE_KW | ON_KW | OFF_KW | YES_KW | NO_KW | BANG
        ) || (token.kind == IDENT
            && token
                .slot
                .as_ref()
                .is_some_and(|s| matches!(&*s.borrow(), Value::Float(_))));
        self.unget(token);
        if is_value_start {
            Ok(self.float()? != 0.0)
        } else {
            Ok(true)
        }
    }

    /// Adds a finished top-level object to the scene; lights inside CSG join the scene's.
    pub fn add_object(&mut self, mut object: Object) {
        let light_only = is_light_only(&object);
        collect_lights(&mut object, &mut self.lights);
        if !light_only {
            super::radiosity::place_with_importance(&mut object, self.default_importance);
            self.objects.push(object);
        }
    }
}

/// Whether `cutaway_textures` would change the picture of `object`: an untextured
/// intersection or difference whose textureless children would take their textured
/// siblings' textures instead of the default one.
fn cutaway_changes_textures(object: &Object) -> bool {
    let Shape::Csg { op, children, .. } = &object.shape else {
        return false;
    };
    matches!(op, CsgOp::Intersection | CsgOp::Difference)
        && object.texture.is_none()
        && children.iter().any(|c| c.texture.is_none())
        && children.iter().any(|c| c.texture.is_some())
}

/// The layer `top` over the texture `below`; `Err` with POV-Ray 3.7's reason when either
/// is a patterned texture (a texture map, block pattern, tiles or material map), which
/// only plain and layered textures may be layered with.
pub fn layer(below: Texture, top: Texture) -> std::result::Result<Texture, &'static str> {
    if matches!(top, Texture::Pattern { .. }) {
        return Err("cannot layer a patterned texture over another");
    }
    if matches!(below, Texture::Pattern { .. }) {
        return Err("cannot layer over a patterned texture");
    }
    let mut layers = match below {
        Texture::Layered(layers) => layers,
        other => vec![other],
    };
    match top {
        Texture::Layered(more) => layers.extend(more),
        other => layers.push(other),
    }
    Ok(Texture::Layered(layers))
}

/// `object { Light }`: a union with the light and no shapes, so that the object's
/// transformations move the light and [`collect_lights`] finds it.
fn light_only(light: Light, origin: crate::scene::Origin) -> Object {
    Object::new(
        Shape::Csg {
            op: CsgOp::Union,
            children: Vec::new(),
            lights: vec![light],
        },
        origin,
    )
}

/// Whether `object` holds lights and no shapes: it takes no part in a CSG's geometry.
fn is_light_only(object: &Object) -> bool {
    matches!(&object.shape, Shape::Csg { children, lights, .. } if children.is_empty() && !lights.is_empty())
}

/// Moves the lights of CSG objects into `lights`. A light group keeps its own.
pub(super) fn collect_lights(object: &mut Object, lights: &mut Vec<Light>) {
    if let Shape::Csg {
        children,
        lights: inner,
        ..
    } = &mut object.shape
    {
        lights.append(inner);
        for child in children {
            collect_lights(child, lights);
        }
    }
}

/// Applies a transformation to an object and everything attached to it, so that every
/// shape keeps a world transform and every texture its pattern-to-world transform.
pub fn transform_object(object: &mut Object, t: &Transform) {
    match &mut object.shape {
        Shape::Csg {
            children, lights, ..
        } => {
            for child in children {
                transform_object(child, t);
            }
            for light in lights {
                super::light::transform_light(light, t);
            }
        }
        Shape::Blob(blob) => {
            object.transform = object.transform.then(t);
            for c in &mut blob.components {
                if let Some(texture) = &mut c.texture {
                    super::texture::transform_texture(Arc::make_mut(texture), t);
                }
            }
        }
        Shape::LightGroup(group) => {
            for child in &mut group.objects {
                transform_object(child, t);
            }
            for light in &mut group.lights {
                super::light::transform_light(light, t);
            }
        }
        Shape::Mesh(mesh) => {
            object.transform = object.transform.then(t);
            for texture in &mut mesh.textures {
                place_texture(Arc::make_mut(texture), t);
            }
        }
        _ => object.transform = object.transform.then(t),
    }
    if let Some(texture) = &mut object.texture {
        place_texture(Arc::make_mut(texture), t);
    }
    if let Some(texture) = &mut object.interior_texture {
        place_texture(Arc::make_mut(texture), t);
    }
    for clip in object
        .clipped_by
        .iter_mut()
        .chain(object.bounded_by.iter_mut())
    {
        transform_object(clip, t);
    }
    if let Some(interior) = &mut object.interior {
        super::media::transform_interior(Arc::make_mut(interior), t);
    }
}

/// Gives every object without a texture the texture of its enclosing CSG, or the default.
pub fn inherit_texture(object: &mut Object, inherited: &Arc<Texture>) {
    let texture = object
        .texture
        .get_or_insert_with(|| inherited.clone())
        .clone();
    match &mut object.shape {
        Shape::Csg { children, .. } => {
            for child in children {
                inherit_texture(child, &texture);
            }
        }
        Shape::LightGroup(group) => {
            for child in &mut group.objects {
                inherit_texture(child, &texture);
            }
        }
        _ => {}
    }
}
