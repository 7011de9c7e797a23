use super::math_shapes::{
    Blob, HeightField, Isosurface, JuliaFractal, Lathe, Lemon, Parametric, Polynomial, Prism, Sor,
    SphereSweep, Text,
};
use super::mesh::{BicubicPatch, Mesh, Polygon};
use super::{Colour, Light, LightGroup, Media, ObjectPhotons, Origin, Texture, Transform};
use glam::DVec3;
use std::sync::Arc;

/// How a CSG object combines its children.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CsgOp {
    Union,
    Merge,
    Intersection,
    Difference,
}

/// A shape in its own coordinates, as written in the scene; the object's transform places it.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    Sphere {
        center: DVec3,
        radius: f64,
    },
    Box {
        corner1: DVec3,
        corner2: DVec3,
    },
    Cylinder {
        base: DVec3,
        cap: DVec3,
        radius: f64,
        open: bool,
    },
    Cone {
        base: DVec3,
        base_radius: f64,
        cap: DVec3,
        cap_radius: f64,
        open: bool,
    },
    /// `plane { normal, distance }`: the points p with p·normal = distance·|normal|... as
    /// POV-Ray normalises the normal first and keeps the distance along it.
    Plane {
        normal: DVec3,
        distance: f64,
    },
    Disc {
        center: DVec3,
        normal: DVec3,
        radius: f64,
        hole_radius: f64,
    },
    Torus {
        major: f64,
        minor: f64,
        sturm: bool,
    },
    /// `quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }`: the surface
    /// A x² + B y² + C z² + D xy + E xz + F yz + G x + H y + I z + J = 0.
    Quadric {
        squares: DVec3,
        mixed: DVec3,
        linear: DVec3,
        constant: f64,
    },
    Triangle {
        corners: [DVec3; 3],
    },
    SmoothTriangle {
        corners: [DVec3; 3],
        normals: [DVec3; 3],
    },
    /// `mesh` and `mesh2`.
    Mesh(Box<Mesh>),
    Polygon(Box<Polygon>),
    BicubicPatch(Box<BicubicPatch>),
    /// `poly`, `cubic`, `quartic` and `polynomial`.
    Polynomial(Box<Polynomial>),
    Isosurface(Box<Isosurface>),
    Parametric(Box<Parametric>),
    JuliaFractal(Box<JuliaFractal>),
    SphereSweep(Box<SphereSweep>),
    Lathe(Box<Lathe>),
    Sor(Box<Sor>),
    Prism(Box<Prism>),
    Blob(Box<Blob>),
    /// `superellipsoid { <e, n> }`: |x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1.
    Superellipsoid {
        e: f64,
        n: f64,
    },
    /// `ovus { bottom_radius, top_radius }`: two spheres on the y axis joined smoothly.
    Ovus {
        bottom_radius: f64,
        top_radius: f64,
    },
    Lemon(Box<Lemon>),
    HeightField(Box<HeightField>),
    Text(Box<Text>),
    /// Union, merge, intersection and difference. Children carry their own transforms
    /// and textures; lights inside a CSG are kept with it.
    Csg {
        op: CsgOp,
        children: Vec<Object>,
        lights: Vec<Light>,
    },
    /// A union whose lights shine on its own objects only.
    LightGroup(Box<LightGroup>),
}

/// The yes/no modifiers of an object.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ObjectFlags {
    pub no_shadow: bool,
    pub no_image: bool,
    pub no_reflection: bool,
    pub no_radiosity: bool,
    pub double_illuminate: bool,
    pub hollow: Option<bool>,
    pub inverse: bool,
}

/// What is inside an object: refraction, attenuation and media.
#[derive(Debug, Clone, PartialEq)]
pub struct Interior {
    pub ior: f64,
    /// Whether the scene gave `ior`: POV-Ray disperses light only then.
    pub ior_given: bool,
    pub caustics: f64,
    pub dispersion: f64,
    pub dispersion_samples: u32,
    pub fade_distance: f64,
    pub fade_power: f64,
    pub fade_colour: Colour,
    /// The `media { }` blocks, which show only inside hollow objects.
    pub media: Vec<Arc<Media>>,
}

impl Default for Interior {
    fn default() -> Self {
        Interior {
            ior: 1.0,
            ior_given: false,
            caustics: 0.0,
            dispersion: 1.0,
            dispersion_samples: 7,
            fade_distance: 0.0,
            fade_power: 0.0,
            fade_colour: Colour::BLACK,
            media: Vec::new(),
        }
    }
}

/// A shape placed in the world with its surface and interior.
#[derive(Debug, Clone, PartialEq)]
pub struct Object {
    pub shape: Shape,
    /// From the shape's coordinates to the world. Transformations are applied all the way
    /// down when they are parsed, so a CSG's children carry world transforms and a CSG's own
    /// transform stays the identity.
    pub transform: Transform,
    /// `None`: the default texture, or the enclosing CSG's texture.
    pub texture: Option<Arc<Texture>>,
    /// A separate texture for the inside surface (`interior_texture`).
    pub interior_texture: Option<Arc<Texture>>,
    pub interior: Option<Arc<Interior>>,
    pub flags: ObjectFlags,
    pub photons: ObjectPhotons,
    /// `radiosity { importance }`: the share of radiosity rays that meet this object and
    /// are followed. `None` takes the enclosing CSG's, or the default's.
    pub radiosity_importance: Option<f64>,
    pub clipped_by: Vec<Object>,
    pub bounded_by: Vec<Object>,
    pub origin: Origin,
}

impl Object {
    pub fn new(shape: Shape, origin: Origin) -> Object {
        Object {
            shape,
            transform: Transform::IDENTITY,
            texture: None,
            interior_texture: None,
            interior: None,
            flags: ObjectFlags::default(),
            photons: ObjectPhotons::default(),
            radiosity_importance: None,
            clipped_by: Vec::new(),
            bounded_by: Vec::new(),
            origin,
        }
    }
}
