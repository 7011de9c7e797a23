//! The faceted shapes as the scene writes them: triangle meshes (`mesh` and `mesh2` alike),
//! `polygon` and `bicubic_patch`. The renderer builds their runtime forms and acceleration
//! structures; nothing here knows how to trace.

use super::Texture;
use glam::{DVec2, DVec3};
use std::sync::Arc;

/// The triangles of a `mesh` or `mesh2`. Every copy of a mesh (`object { M }`) shares
/// them, so that a hundred copies of a large mesh cost little more than one, as POV-Ray
/// promises.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct MeshGeometry {
    pub vertices: Vec<DVec3>,
    /// The normals smooth triangles name, not necessarily of unit length.
    pub normals: Vec<DVec3>,
    pub uvs: Vec<DVec2>,
    pub faces: Vec<MeshFace>,
}

/// One triangle of a mesh, as indices into the mesh's lists.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshFace {
    pub vertices: [u32; 3],
    /// The corner normals of a smooth triangle; `None` for a flat one.
    pub normals: Option<[u32; 3]>,
    /// The corners' uv coordinates; `None` gives POV-Ray's default for a triangle without
    /// `uv_vectors`.
    pub uvs: Option<[u32; 3]>,
    pub texture: FaceTexture,
}

/// Which texture colours a mesh triangle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FaceTexture {
    /// The mesh object's own texture.
    Object,
    /// One texture of the mesh's list.
    One(u32),
    /// One texture per corner, blended across the triangle (`texture_list`, or three
    /// texture indices after a `mesh2` face).
    Corners([u32; 3]),
}

/// A `mesh` or `mesh2` object's shape: the shared triangles, and what belongs to this copy.
#[derive(Debug, Clone, PartialEq)]
pub struct Mesh {
    pub geometry: Arc<MeshGeometry>,
    /// The textures faces name by index. They are transformed with the mesh, so each copy
    /// keeps its own list (of shared textures while untransformed).
    pub textures: Vec<Arc<Texture>>,
    /// `inside_vector`: the direction of the ray whose crossings tell inside from outside;
    /// `None` leaves the mesh without an inside, as a union of triangles.
    pub inside_vector: Option<DVec3>,
    /// `hierarchy off` turns off the bounding hierarchy over the triangles.
    pub hierarchy: bool,
}

/// `polygon { N, points }`: flat outlines, with holes where an even number of them overlap.
#[derive(Debug, Clone, PartialEq)]
pub struct Polygon {
    /// Closed outlines (sub-polygons), each without its closing repetition of the first
    /// point. All lie in one plane.
    pub outlines: Vec<Vec<DVec3>>,
}

/// `bicubic_patch { }`: a Bézier surface over 4 × 4 control points.
#[derive(Debug, Clone, PartialEq)]
pub struct BicubicPatch {
    /// `type 0` or `type 1`; they draw the same surface (POV-Ray keeps only the control
    /// points for type 0, the subdivision for type 1).
    pub kind: u8,
    /// `flatness`: 0 always subdivides to the steps; more stops where the surface is flat.
    pub flatness: f64,
    /// `u_steps` and `v_steps`: at most 2^steps pieces across each direction.
    pub u_steps: u32,
    pub v_steps: u32,
    /// The uv coordinates of the corners points[0][0], points[0][3], points[3][3] and
    /// points[3][0].
    pub uv_corners: [DVec2; 4],
    /// Rows of control points: `points[v][u]`.
    pub points: [[DVec3; 4]; 4],
}

impl BicubicPatch {
    /// POV-Ray's default `uv_vectors <0,0>, <1,0>, <1,1>, <0,1>`.
    pub const DEFAULT_UV: [DVec2; 4] = [
        DVec2::new(0.0, 0.0),
        DVec2::new(1.0, 0.0),
        DVec2::new(1.0, 1.0),
        DVec2::new(0.0, 1.0),
    ];
}
