//! The statements of triangle meshes: `mesh { triangle {...} smooth_triangle {...} }` and
//! `mesh2 { vertex_vectors {...} ... face_indices {...} }`. Both produce one
//! [`MeshGeometry`], shared by every copy of the mesh. Each parser reads from after the
//! opening brace up to the object modifiers.

use super::tokens::Token;
use super::value::Value;
use super::{Evaluator, Result};
use crate::scene::mesh::{FaceTexture, Mesh, MeshFace, MeshGeometry};
use crate::scene::{Shape, Texture};
use glam::{DVec2, DVec3};
use std::collections::HashMap;
use std::rc::Rc;
use std::sync::Arc;
use syntax::SyntaxKind::*;

/// The most elements (vertices, normals, uv vectors, textures or faces) one list of a mesh
/// may declare, so that a runaway count is an error rather than an allocation that never
/// ends. Lists grow as they are read, so a large count alone reserves nothing.
const MAX_ELEMENTS: i64 = 1 << 26;

/// How many elements a list reserves before it has read them.
const RESERVE_LIMIT: usize = 1 << 16;

/// A `mesh` as it is read: each corner, normal and uv vector stored once however many
/// triangles share it, and each texture identifier once.
#[derive(Default)]
struct MeshBuilder {
    geometry: MeshGeometry,
    vertex_ids: HashMap<[u64; 3], u32>,
    normal_ids: HashMap<[u64; 3], u32>,
    uv_ids: HashMap<[u64; 2], u32>,
    /// The textures by the identifier's value they came from; the value is kept so that
    /// its address cannot be reused by another texture while the mesh is read.
    texture_ids: HashMap<*const Texture, (Rc<Texture>, u32)>,
    textures: Vec<Arc<Texture>>,
}

/// The index of `value` in `list`, appending it the first time its bits are met, so that
/// equal vertices, normals and uv coordinates are stored once.
fn intern<K: std::hash::Hash + Eq, T>(
    ids: &mut HashMap<K, u32>,
    list: &mut Vec<T>,
    key: K,
    value: T,
) -> u32 {
    *ids.entry(key).or_insert_with(|| {
        list.push(value);
        (list.len() - 1) as u32
    })
}

impl MeshBuilder {
    fn vertex(&mut self, v: DVec3) -> u32 {
        intern(
            &mut self.vertex_ids,
            &mut self.geometry.vertices,
            v.to_array().map(f64::to_bits),
            v,
        )
    }

    fn normal(&mut self, n: DVec3) -> u32 {
        intern(
            &mut self.normal_ids,
            &mut self.geometry.normals,
            n.to_array().map(f64::to_bits),
            n,
        )
    }

    fn uv(&mut self, uv: DVec2) -> u32 {
        intern(
            &mut self.uv_ids,
            &mut self.geometry.uvs,
            uv.to_array().map(f64::to_bits),
            uv,
        )
    }

    fn texture(&mut self, texture: Rc<Texture>) -> u32 {
        let key = Rc::as_ptr(&texture);
        if let Some((_, id)) = self.texture_ids.get(&key) {
            return *id;
        }
        let id = self.textures.len() as u32;
        self.textures.push(Arc::new(Texture::clone(&texture)));
        self.texture_ids.insert(key, (texture, id));
        id
    }
}

/// Whether three corners span no area: such triangles can never be hit, and POV-Ray drops
/// them.
fn degenerate(corners: [DVec3; 3]) -> bool {
    (corners[1] - corners[0])
        .cross(corners[2] - corners[0])
        .length_squared()
        == 0.0
}

impl Evaluator<'_> {
    /// `triangle {...}`, `smooth_triangle {...}` and `inside_vector` inside `mesh`.
    pub fn mesh(&mut self, keyword: &Token) -> Result<Shape> {
        let mut builder = MeshBuilder::default();
        let mut inside_vector = None;
        let mut hierarchy = true;
        loop {
            let token = self.next()?;
            match token.kind {
                TRIANGLE_KW | SMOOTH_TRIANGLE_KW => self.mesh_triangle(&token, &mut builder)?,
                INSIDE_VECTOR_KW => inside_vector = self.inside_vector()?,
                HIERARCHY_KW => hierarchy = self.optional_bool()?,
                _ => {
                    self.unget(token);
                    break;
                }
            }
        }
        if builder.geometry.faces.is_empty() {
            return Err(self.error_at(keyword, "a mesh needs at least one triangle"));
        }
        Ok(Shape::Mesh(Box::new(Mesh {
            geometry: Arc::new(builder.geometry),
            textures: builder.textures,
            inside_vector,
            hierarchy,
        })))
    }

    /// One `triangle { }` or `smooth_triangle { }` of a mesh, after its keyword.
    fn mesh_triangle(&mut self, keyword: &Token, builder: &mut MeshBuilder) -> Result<()> {
        self.expect(L_BRACE, "'{'")?;
        let (corners, normals) = self.triangle_corners(keyword.kind)?;
        let mut uvs = None;
        if self.eat(UV_VECTORS_KW)? {
            let mut corner_uvs = [DVec2::ZERO; 3];
            for (i, uv) in corner_uvs.iter_mut().enumerate() {
                if i > 0 {
                    self.eat(COMMA)?;
                }
                *uv = self.uv_vector()?;
            }
            uvs = Some(corner_uvs);
        }
        let token = self.next()?;
        let texture = match token.kind {
            TEXTURE_KW => {
                self.expect(L_BRACE, "'{'")?;
                let texture = self.texture_identifier()?;
                self.expect(R_BRACE, "'}' after the texture identifier")?;
                FaceTexture::One(builder.texture(texture))
            }
            TEXTURE_LIST_KW => {
                self.expect(L_BRACE, "'{'")?;
                let mut ids = [0; 3];
                for id in &mut ids {
                    self.eat(COMMA)?;
                    *id = builder.texture(self.texture_identifier()?);
                }
                self.eat(COMMA)?;
                self.expect(R_BRACE, "'}' after three texture identifiers")?;
                FaceTexture::Corners(ids)
            }
            _ => {
                self.unget(token);
                FaceTexture::Object
            }
        };
        self.expect(R_BRACE, "'}' to close the mesh triangle")?;
        if degenerate(corners) {
            return Ok(());
        }
        let face = MeshFace {
            vertices: corners.map(|c| builder.vertex(c)),
            normals: normals.map(|normals| normals.map(|n| builder.normal(n))),
            uvs: uvs.map(|uvs| uvs.map(|uv| builder.uv(uv))),
            texture,
        };
        builder.geometry.faces.push(face);
        Ok(())
    }

    /// A texture identifier, the only texture a mesh triangle may name (POV-Ray stores
    /// each once however many triangles use it).
    fn texture_identifier(&mut self) -> Result<Rc<Texture>> {
        let token = self.next()?;
        match token.slot.as_ref().map(|s| s.borrow().clone()) {
            Some(Value::Texture(texture)) => Ok(texture),
            None if token.kind == IDENT => Err(self.undeclared(&token)),
            _ => Err(self.error_at(
                &token,
                format!(
                    "expected a texture identifier, found {}; a mesh triangle takes only \
                     declared textures",
                    self.describe(&token)
                ),
            )),
        }
    }

    /// A 2-D uv vector.
    fn uv_vector(&mut self) -> Result<DVec2> {
        let v = self.vector_of(2)?;
        Ok(DVec2::new(v.c[0], v.c[1]))
    }

    /// The direction after `inside_vector`; a zero vector leaves the mesh without an
    /// inside, since no ray can be cast along it.
    fn inside_vector(&mut self) -> Result<Option<DVec3>> {
        let v = self.vector()?;
        Ok((v != DVec3::ZERO).then_some(v))
    }

    /// The sections of `mesh2`, in the order POV-Ray requires.
    pub fn mesh2(&mut self, keyword: &Token) -> Result<Shape> {
        let vertices = match self.mesh2_section(VERTEX_VECTORS_KW)? {
            Some(section) => self.mesh2_list(&section, |e| e.vector())?,
            None => {
                let found = self.next()?;
                return Err(self.error_at(
                    &found,
                    format!(
                        "expected vertex_vectors, the first section of mesh2, found {}",
                        self.describe(&found)
                    ),
                ));
            }
        };
        let normals = match self.mesh2_section(NORMAL_VECTORS_KW)? {
            Some(section) => self.mesh2_list(&section, |e| e.vector())?,
            None => Vec::new(),
        };
        let uvs = match self.mesh2_section(UV_VECTORS_KW)? {
            Some(section) => self.mesh2_list(&section, |e| e.uv_vector())?,
            None => Vec::new(),
        };
        let textures = match self.mesh2_section(TEXTURE_LIST_KW)? {
            Some(section) => self.mesh2_list(&section, |e| {
                e.expect(TEXTURE_KW, "'texture'")?;
                Ok(Arc::new(e.texture_body()?))
            })?,
            None => Vec::new(),
        };
        let Some(faces_keyword) = self.mesh2_section(FACE_INDICES_KW)? else {
            let found = self.next()?;
            return Err(self.error_at(
                &found,
                format!(
                    "expected face_indices in mesh2, found {}",
                    self.describe(&found)
                ),
            ));
        };
        if vertices.is_empty() {
            return Err(self.error_at(keyword, "a mesh2 needs at least one vertex"));
        }
        let mut faces = self.face_indices(&faces_keyword, vertices.len(), textures.len())?;
        let normal_indices = match self.mesh2_section(NORMAL_INDICES_KW)? {
            Some(section) => Some((self.index_list(&section, normals.len(), "normal")?, section)),
            None => None,
        };
        let uv_indices = match self.mesh2_section(UV_INDICES_KW)? {
            Some(section) => Some((self.index_list(&section, uvs.len(), "uv")?, section)),
            None => None,
        };
        let face_normals = self.corner_indices(
            &faces_keyword,
            &faces,
            CornerList {
                indices: normal_indices,
                section: "normal_indices",
                vectors: "normal_vectors",
                len: normals.len(),
                vertex_count: vertices.len(),
                coverage: Coverage::LeadingFaces,
            },
        )?;
        let face_uvs = self.corner_indices(
            &faces_keyword,
            &faces,
            CornerList {
                indices: uv_indices,
                section: "uv_indices",
                vectors: "uv_vectors",
                len: uvs.len(),
                vertex_count: vertices.len(),
                coverage: Coverage::EveryFace,
            },
        )?;
        for ((face, normals), uvs) in faces.iter_mut().zip(face_normals).zip(face_uvs) {
            face.normals = normals;
            face.uvs = uvs;
        }
        let mut inside_vector = None;
        let mut hierarchy = true;
        loop {
            let token = self.next()?;
            match token.kind {
                INSIDE_VECTOR_KW => inside_vector = self.inside_vector()?,
                HIERARCHY_KW => hierarchy = self.optional_bool()?,
                VERTEX_VECTORS_KW | NORMAL_VECTORS_KW | UV_VECTORS_KW | TEXTURE_LIST_KW
                | FACE_INDICES_KW | NORMAL_INDICES_KW | UV_INDICES_KW => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "{} is out of place or repeated: mesh2's sections come in the \
                             order vertex_vectors, normal_vectors, uv_vectors, texture_list, \
                             face_indices, normal_indices, uv_indices",
                            self.text(&token)
                        ),
                    ));
                }
                _ => {
                    self.unget(token);
                    break;
                }
            }
        }
        let corners = |face: &MeshFace| face.vertices.map(|i| vertices[i as usize]);
        faces.retain(|face| !degenerate(corners(face)));
        if faces.is_empty() {
            return Err(self.error_at(keyword, "a mesh2 needs at least one triangle with an area"));
        }
        Ok(Shape::Mesh(Box::new(Mesh {
            geometry: Arc::new(MeshGeometry {
                vertices,
                normals,
                uvs,
                faces,
            }),
            textures,
            inside_vector,
            hierarchy,
        })))
    }

    /// The keyword of the next section if it is `kind`.
    fn mesh2_section(&mut self, kind: syntax::SyntaxKind) -> Result<Option<Token>> {
        let token = self.next()?;
        if token.kind == kind {
            Ok(Some(token))
        } else {
            self.unget(token);
            Ok(None)
        }
    }

    /// The element count after a section's `{`, checked against the limit.
    fn mesh2_count(&mut self, section: &Token) -> Result<usize> {
        let at = self.next()?;
        self.unget(at.clone());
        let n = self.int()?;
        if !(0..=MAX_ELEMENTS).contains(&n) {
            return Err(self.error_at(
                &at,
                format!(
                    "{} cannot hold {n} elements: the count must be from 0 to {MAX_ELEMENTS}",
                    self.text(section)
                ),
            ));
        }
        self.eat(COMMA)?;
        Ok(n as usize)
    }

    /// `{ N, e1, e2, ... }`: exactly N elements read by `element`, separated by commas.
    fn mesh2_list<T>(
        &mut self,
        section: &Token,
        mut element: impl FnMut(&mut Self) -> Result<T>,
    ) -> Result<Vec<T>> {
        self.expect(L_BRACE, "'{'")?;
        let count = self.mesh2_count(section)?;
        let mut list = Vec::with_capacity(count.min(RESERVE_LIMIT));
        for i in 0..count {
            if i > 0 {
                self.eat(COMMA)?;
            }
            self.check_more(section, count, i)?;
            list.push(element(self)?);
        }
        self.eat(COMMA)?;
        self.close_section(section, count)?;
        Ok(list)
    }

    /// An error when a section closes after `read` of its `count` elements.
    fn check_more(&mut self, section: &Token, count: usize, read: usize) -> Result<()> {
        let token = self.next()?;
        let closes = token.kind == R_BRACE;
        self.unget(token.clone());
        if closes {
            return Err(self.error_at(
                &token,
                format!(
                    "{} declares {count} elements but lists {read}",
                    self.text(section)
                ),
            ));
        }
        Ok(())
    }

    /// The `}` after a section's elements, with a message naming the count when more follow.
    fn close_section(&mut self, section: &Token, count: usize) -> Result<()> {
        let token = self.next()?;
        if token.kind == R_BRACE {
            return Ok(());
        }
        Err(self.error_at(
            &token,
            format!(
                "expected '}}' after the {count} elements {} declares, found {}",
                self.text(section),
                self.describe(&token)
            ),
        ))
    }

    /// One `<a, b, c>` of indices into a list of `len` elements, read from `value` (whose
    /// first token is `at`); `what` names the list for messages.
    fn index_triple(&self, at: &Token, value: Value, len: usize, what: &str) -> Result<[u32; 3]> {
        let (Value::Vector(terms) | Value::Colour(terms)) = value else {
            return Err(self.error_at(
                at,
                format!(
                    "expected a vector of three {what} indices, found {}",
                    value.type_name()
                ),
            ));
        };
        let mut indices = [0; 3];
        for (i, index) in indices.iter_mut().enumerate() {
            let v = terms.c[i].trunc();
            if !(v >= 0.0 && v < len as f64) {
                return Err(self.error_at(
                    at,
                    format!(
                        "{what} index {v} is out of range: the mesh has {len} {what} {}",
                        if what == "texture" {
                            "entries"
                        } else {
                            "vectors"
                        }
                    ),
                ));
            }
            *index = v as u32;
        }
        Ok(indices)
    }

    /// `{ N, <a, b, c> [, t [, t, t]], ... }` after `face_indices`.
    fn face_indices(
        &mut self,
        section: &Token,
        vertex_count: usize,
        texture_count: usize,
    ) -> Result<Vec<MeshFace>> {
        self.expect(L_BRACE, "'{'")?;
        let count = self.mesh2_count(section)?;
        let mut faces = Vec::with_capacity(count.min(RESERVE_LIMIT));
        // A value read after a face, which turned out to be the next face's indices.
        let mut pending: Option<(Value, Token)> = None;
        for i in 0..count {
            let (value, at) = match pending.take() {
                Some(read) => read,
                None => {
                    self.check_more(section, count, i)?;
                    self.next_value()?
                }
            };
            let vertices = self.index_triple(&at, value, vertex_count, "vertex")?;
            let mut texture = FaceTexture::Object;
            if self.eat(COMMA)? && self.peek_kind()? != R_BRACE {
                let (value, value_at) = self.next_value()?;
                match value {
                    Value::Float(first) => {
                        let first = self.texture_index(&value_at, first, texture_count)?;
                        texture = FaceTexture::One(first);
                        if self.eat(COMMA)? && self.peek_kind()? != R_BRACE {
                            let (value, value_at) = self.next_value()?;
                            if let Value::Float(second) = value {
                                let second =
                                    self.texture_index(&value_at, second, texture_count)?;
                                self.eat(COMMA)?;
                                let at = self.next()?;
                                self.unget(at.clone());
                                let third = self.float()?;
                                let third = self.texture_index(&at, third, texture_count)?;
                                self.eat(COMMA)?;
                                texture = FaceTexture::Corners([first, second, third]);
                            } else {
                                pending = Some((value, value_at));
                            }
                        }
                    }
                    other => pending = Some((other, value_at)),
                }
            }
            faces.push(MeshFace {
                vertices,
                normals: None,
                uvs: None,
                texture,
            });
        }
        if let Some((_, at)) = pending {
            return Err(self.error_at(
                &at,
                format!("face_indices declares {count} faces, and more follow"),
            ));
        }
        self.close_section(section, count)?;
        Ok(faces)
    }

    /// The next expression's value with its first token.
    fn next_value(&mut self) -> Result<(Value, Token)> {
        let at = self.next()?;
        self.unget(at.clone());
        Ok((self.additive()?, at))
    }

    fn texture_index(&self, at: &Token, value: f64, count: usize) -> Result<u32> {
        let v = value.trunc();
        if v >= 0.0 && v < count as f64 {
            return Ok(v as u32);
        }
        let message = if count == 0 {
            format!("texture index {v} names no texture: the mesh2 has no texture_list")
        } else {
            format!("texture index {v} is out of range: the texture_list has {count} textures")
        };
        Err(self.error_at(at, message))
    }

    /// `{ N, <a, b, c>, ... }` after `normal_indices` or `uv_indices`, each checked
    /// against a list of `len` elements.
    fn index_list(&mut self, section: &Token, len: usize, what: &str) -> Result<Vec<[u32; 3]>> {
        self.expect(L_BRACE, "'{'")?;
        let count = self.mesh2_count(section)?;
        let mut list = Vec::with_capacity(count.min(RESERVE_LIMIT));
        for i in 0..count {
            if i > 0 {
                self.eat(COMMA)?;
            }
            self.check_more(section, count, i)?;
            let (value, at) = self.next_value()?;
            list.push(self.index_triple(&at, value, len, what)?);
        }
        self.eat(COMMA)?;
        self.close_section(section, count)?;
        Ok(list)
    }

    /// The corner indices of each face into the normal or uv list: from the section's
    /// own indices when there is one, or from the face's vertex indices when the list has
    /// an entry per vertex.
    fn corner_indices(
        &self,
        faces_keyword: &Token,
        faces: &[MeshFace],
        list: CornerList<'_>,
    ) -> Result<Vec<Option<[u32; 3]>>> {
        match list.indices {
            Some((indices, section)) => {
                let fits = match list.coverage {
                    Coverage::LeadingFaces => indices.len() <= faces.len(),
                    Coverage::EveryFace => indices.len() == faces.len(),
                };
                if !fits {
                    let rule = match list.coverage {
                        Coverage::LeadingFaces => "there can be no more than faces",
                        Coverage::EveryFace => "there must be one per face",
                    };
                    return Err(self.error_at(
                        &section,
                        format!(
                            "{} {} for {} faces: {rule}",
                            indices.len(),
                            self.text(&section),
                            faces.len()
                        ),
                    ));
                }
                let mut per_face: Vec<Option<[u32; 3]>> = indices.into_iter().map(Some).collect();
                per_face.resize(faces.len(), None);
                Ok(per_face)
            }
            None if list.len == 0 => Ok(vec![None; faces.len()]),
            None if list.len == list.vertex_count => {
                Ok(faces.iter().map(|f| Some(f.vertices)).collect())
            }
            None => Err(self.error_at(
                faces_keyword,
                format!(
                    "mesh2 needs {}: its {} {} do not match its {} vertices one to one",
                    list.section, list.len, list.vectors, list.vertex_count
                ),
            )),
        }
    }
}

/// How many faces an index section covers.
#[derive(Debug, Clone, Copy)]
enum Coverage {
    /// `normal_indices`: the first faces are smooth, the rest flat.
    LeadingFaces,
    /// `uv_indices`: one triple per face.
    EveryFace,
}

/// A list faces index by corner (normals or uv vectors) and the section of its indices.
struct CornerList<'a> {
    /// The section of indices, and its name and vectors' name for messages.
    indices: Option<(Vec<[u32; 3]>, Token)>,
    section: &'a str,
    vectors: &'a str,
    len: usize,
    vertex_count: usize,
    coverage: Coverage,
}

#[cfg(test)]
mod tests {
    use crate::eval::tests::{check_debug, evaluate_ok};
    use crate::scene::mesh::{FaceTexture, Mesh};
    use crate::scene::{NormalKind, Pigment, Scene, Shape, Texture};
    use expect_test::expect;
    use glam::{DVec2, DVec3};
    use std::sync::Arc;

    fn mesh(scene: &Scene, i: usize) -> &Mesh {
        match &scene.objects[i].shape {
            Shape::Mesh(mesh) => mesh,
            other => panic!("not a mesh: {other:?}"),
        }
    }

    #[test]
    fn a_mesh_statement_copies_a_declared_mesh() {
        let scene = evaluate_ok(
            "#declare M = mesh { triangle { 0, x, y } translate y }
             mesh { M translate x pigment { rgb 1 } }",
        );
        let copy = mesh(&scene, 0);
        assert_eq!(copy.geometry.faces.len(), 1);
        assert_eq!(
            scene.objects[0].transform.matrix.translation,
            glam::DVec3::new(1.0, 1.0, 0.0)
        );
        assert!(scene.objects[0].texture.is_some());
    }

    #[test]
    fn mesh_triangles_share_corners_and_textures() {
        let scene = evaluate_ok(
            "#declare Red = texture { pigment { rgb x } }
             #declare Blue = texture { pigment { rgb z } }
             #declare M = mesh {
               triangle { <0,0,0>, <1,0,0>, <0,1,0> uv_vectors <0,0>, <1,0>, <0,1> texture { Red } }
               smooth_triangle { <1,0,0>, y, <1,1,0>, y, <0,1,0>, y texture_list { Red Blue Red } }
               triangle { <0,0,0>, <1,1,1>, <2,2,2> }
               inside_vector z
             }
             object { M }
             object { M translate x hierarchy off }",
        );
        let (first, second) = (mesh(&scene, 0), mesh(&scene, 1));
        assert!(Arc::ptr_eq(&first.geometry, &second.geometry));
        assert!(first.hierarchy && !second.hierarchy);
        let geometry = &first.geometry;
        // The collinear third triangle is dropped; four distinct corners remain.
        assert_eq!(geometry.faces.len(), 2);
        assert_eq!(geometry.vertices.len(), 4);
        assert_eq!(geometry.normals, vec![DVec3::Y]);
        assert_eq!(geometry.faces[0].texture, FaceTexture::One(0));
        assert_eq!(geometry.faces[1].texture, FaceTexture::Corners([0, 1, 0]));
        assert_eq!(geometry.faces[1].normals, Some([0, 0, 0]));
        assert_eq!(
            geometry.uvs[geometry.faces[0].uvs.unwrap()[1] as usize],
            DVec2::X
        );
        assert_eq!(first.textures.len(), 2);
        assert_eq!(first.inside_vector, Some(DVec3::Z));
    }

    #[test]
    fn mesh2_indices_default_to_the_faces() {
        let scene = evaluate_ok(
            "mesh2 {
               vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }
               normal_vectors { 4, -z, -z, -z, -z }
               uv_vectors { 4, <0,0>, <1,0>, <1,1>, <0,1> }
               texture_list { 2, texture { pigment { rgb 1 } }, texture { pigment { rgb 0 } } }
               face_indices { 2, <0,1,2>, 1, <0,2,3>, 0, 1, 1 }
             }",
        );
        let geometry = &mesh(&scene, 0).geometry;
        assert_eq!(geometry.faces[0].normals, Some([0, 1, 2]));
        assert_eq!(geometry.faces[1].uvs, Some([0, 2, 3]));
        assert_eq!(geometry.faces[0].texture, FaceTexture::One(1));
        assert_eq!(geometry.faces[1].texture, FaceTexture::Corners([0, 1, 1]));
    }

    #[test]
    fn mesh2_faces_take_normal_indices_first() {
        let scene = evaluate_ok(
            "mesh2 {
               vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }
               normal_vectors { 1, -z }
               uv_vectors { 1, <0.5,0.5> }
               face_indices { 2, <0,1,2>, <0,2,3> }
               normal_indices { 1, <0,0,0> }
               uv_indices { 2, <0,0,0>, <0,0,0> }
             }",
        );
        let geometry = &mesh(&scene, 0).geometry;
        assert_eq!(geometry.faces[0].normals, Some([0, 0, 0]));
        assert_eq!(geometry.faces[1].normals, None);
        assert_eq!(geometry.faces[1].uvs, Some([0, 0, 0]));
    }

    #[test]
    fn uv_mapped_textures_stay_on_the_surface() {
        let scene = evaluate_ok(
            "#declare Uv = texture { uv_mapping pigment { checker scale 0.5 } }
             mesh {
               triangle { 0, x, y uv_vectors <0,0>, <1,0>, <0,1> texture { Uv } }
               uv_mapping pigment { gradient x }
               translate 2*x
             }
             sphere { 0, 1 normal { bumps } translate 2*x }",
        );
        let Texture::Plain {
            pigment: Pigment::Pattern { pattern, .. },
            ..
        } = scene.objects[0].texture.as_deref().unwrap()
        else {
            panic!("a patterned pigment");
        };
        // The uv-mapped pigment stays put while other patterns move with their objects.
        assert!(pattern.uv_mapping);
        assert!(pattern.transform.is_identity());
        let Texture::Plain {
            normal: Some(normal),
            ..
        } = scene.objects[1].texture.as_deref().unwrap()
        else {
            panic!("a normal");
        };
        let NormalKind::Pattern { pattern: bumps, .. } = &normal.kind else {
            panic!("bumps");
        };
        assert!(!bumps.uv_mapping);
        assert_eq!(bumps.transform.point(DVec3::ZERO), DVec3::X * 2.0);
        let Texture::Plain {
            pigment: Pigment::Pattern { pattern, .. },
            ..
        } = &*mesh(&scene, 0).textures[0]
        else {
            panic!("a checker");
        };
        // Its own scale applies in uv space; the mesh's translation does not.
        assert!(pattern.uv_mapping);
        assert_eq!(pattern.transform.point(DVec3::ONE), DVec3::splat(0.5));
    }

    #[test]
    fn uv_mapped_normals_keep_the_turns_that_do_not_move_them() {
        let scene = evaluate_ok(
            "mesh { triangle { 0, x, y }
               uv_mapping normal { gradient x scale 0.5 }
               rotate 90*z translate 2*x
             }",
        );
        let Texture::Plain {
            normal: Some(normal),
            ..
        } = scene.objects[0].texture.as_deref().unwrap()
        else {
            panic!("a normal");
        };
        let NormalKind::Pattern { pattern, .. } = &normal.kind else {
            panic!("a gradient");
        };
        // The pattern keeps only its own scale; the object's turn and move are the
        // placement, which turns the normal's push.
        assert_eq!(
            pattern.transform.point(DVec3::ONE),
            DVec3::new(0.5, 0.5, 0.5)
        );
        let turned = normal.placement.as_ref().unwrap().point(DVec3::X);
        assert!(
            (turned - DVec3::new(2.0, 1.0, 0.0)).length() < 1e-12,
            "{turned}"
        );
    }

    #[test]
    fn uv_mapping_comes_before_the_texture() {
        check_debug(
            "sphere { 0, 1 pigment { checker } uv_mapping }",
            expect![[r#"
                scene.pov:2:35: error: uv_mapping must come before the object's texture, pigment and normal
                    2 | sphere { 0, 1 pigment { checker } uv_mapping }
                      |                                   ^~~~~~~~~~
            "#]],
        );
    }

    #[test]
    fn mesh_errors_are_located() {
        check_debug(
            "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,3> } }",
            expect![[r#"
                scene.pov:2:75: error: vertex index 3 is out of range: the mesh has 3 vertex vectors
                    2 | mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,3> } }
                      |                                                                           ^
            "#]],
        );
        check_debug(
            "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,2>, 0 } }",
            expect![[r#"
                scene.pov:2:84: error: texture index 0 names no texture: the mesh2 has no texture_list
                    2 | mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,2>, 0 } }
                      |                                                                                    ^
            "#]],
        );
        check_debug(
            "mesh2 { vertex_vectors { 3, 0, x, y } uv_vectors { 2, 0, 1 } face_indices { 1, <0,1,2> } }",
            expect![[r#"
                scene.pov:2:62: error: mesh2 needs uv_indices: its 2 uv_vectors do not match its 3 vertices one to one
                    2 | mesh2 { vertex_vectors { 3, 0, x, y } uv_vectors { 2, 0, 1 } face_indices { 1, <0,1,2> } }
                      |                                                              ^~~~~~~~~~~~
            "#]],
        );
        check_debug(
            "mesh2 { vertex_vectors { 4, 0, x, y } face_indices { 1, <0,1,2> } }",
            expect![[r#"
                scene.pov:2:37: error: vertex_vectors declares 4 elements but lists 3
                    2 | mesh2 { vertex_vectors { 4, 0, x, y } face_indices { 1, <0,1,2> } }
                      |                                     ^
            "#]],
        );
        check_debug(
            "mesh2 { vertex_vectors { 3, 0, x, y } face_indices { 1, <0,1,2> } vertex_vectors { 1, 0 } }",
            expect![[r#"
                scene.pov:2:67: error: vertex_vectors is out of place or repeated: mesh2's sections come in the order vertex_vectors, normal_vectors, uv_vectors, texture_list, face_indices, normal_indices, uv_indices
                    2 | mesh2 { vertex_vectors { 3, 0, x, y } face_indices { 1, <0,1,2> } vertex_vectors { 1, 0 } }
                      |                                                                   ^~~~~~~~~~~~~~
            "#]],
        );
        check_debug(
            "mesh { triangle { 0, x, y texture { pigment { rgb 1 } } } }",
            expect![[r#"
                scene.pov:2:37: error: expected a texture identifier, found 'pigment'; a mesh triangle takes only declared textures
                    2 | mesh { triangle { 0, x, y texture { pigment { rgb 1 } } } }
                      |                                     ^~~~~~~
            "#]],
        );
        check_debug(
            "mesh { triangle { 0, x, 2*x } }",
            expect![[r#"
                scene.pov:2:1: error: a mesh needs at least one triangle
                    2 | mesh { triangle { 0, x, 2*x } }
                      | ^~~~
            "#]],
        );
        check_debug(
            "sphere { 0, 1 hierarchy off }",
            expect![[r#"
                scene.pov:2:15: error: 'hierarchy' does not apply to sphere
                    2 | sphere { 0, 1 hierarchy off }
                      |               ^~~~~~~~~
            "#]],
        );
    }
}
