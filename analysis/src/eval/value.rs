//! The values an SDL identifier can hold, and the arithmetic on floats, vectors and colours
//! with POV-Ray's promotion rules.

use crate::function::Function;
use crate::scene::{
    BlendMap, Camera, Colour, Finish, Fog, Interior, Light, Media, Normal, Object, Pigment,
    Rainbow, SkySphere, Texture, Transform,
};
use std::cell::RefCell;
use std::collections::BTreeMap;
use std::rc::Rc;

use super::macros::MacroDef;
use crate::spline::Spline;

/// Up to five numeric terms: a vector of 2 to 4 components, or a colour's five
/// (red, green, blue, filter, transmit).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Terms {
    pub len: u8,
    pub c: [f64; 5],
}

impl Terms {
    pub fn new(c: &[f64]) -> Terms {
        let mut terms = Terms {
            len: c.len().min(5) as u8,
            c: [0.0; 5],
        };
        terms.c[..terms.len as usize].copy_from_slice(&c[..terms.len as usize]);
        terms
    }

    /// A float promoted to `len` terms: every component takes its value.
    pub fn splat(v: f64, len: u8) -> Terms {
        Terms { len, c: [v; 5] }
    }

    /// More components, the new ones zero, as POV-Ray promotes shorter vectors.
    pub fn promoted(mut self, len: u8) -> Terms {
        for i in self.len as usize..len as usize {
            self.c[i] = 0.0;
        }
        self.len = self.len.max(len);
        self
    }

    pub fn as_slice(&self) -> &[f64] {
        &self.c[..self.len as usize]
    }

    pub fn vec3(&self) -> glam::DVec3 {
        glam::DVec3::new(self.c[0], self.c[1], self.c[2])
    }
}

/// An identifier's storage; macro parameters passed by reference share it.
pub type Slot = Rc<RefCell<Value>>;

/// An array: its dimensions and its elements in row-major order; `None` elements are
/// not yet initialised.
#[derive(Debug, Clone, PartialEq)]
pub struct Array {
    pub dims: Vec<usize>,
    pub items: Vec<Option<Value>>,
    /// `mixed` arrays may hold elements of different types.
    pub mixed: bool,
}

/// A `dictionary { }` (POV-Ray 3.8).
pub type Dictionary = BTreeMap<String, Value>;

/// A `camera { }` value, kept as the items written so that `camera { Cam ... }` can go on
/// modifying it before the final vectors are computed.
#[derive(Debug, Clone, PartialEq)]
pub struct CameraValue {
    pub camera: Camera,
    pub look_at: Option<glam::DVec3>,
    pub transforms: Vec<Transform>,
}

/// A `material { }`: a texture and an interior, either of which may be absent.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct MaterialValue {
    pub texture: Option<Texture>,
    pub interior: Option<Interior>,
}

/// One value of any SDL type.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    Float(f64),
    /// A vector of 2 to 5 components.
    Vector(Terms),
    /// A colour: always five terms.
    Colour(Terms),
    String(Rc<str>),
    Object(Rc<Object>),
    Light(Rc<Light>),
    Camera(Rc<CameraValue>),
    Texture(Rc<Texture>),
    Pigment(Rc<Pigment>),
    Normal(Rc<Normal>),
    Finish(Rc<Finish>),
    Interior(Rc<Interior>),
    Material(Rc<MaterialValue>),
    ColourMap(Rc<BlendMap<Colour>>),
    PigmentMap(Rc<BlendMap<Pigment>>),
    NormalMap(Rc<BlendMap<Normal>>),
    TextureMap(Rc<BlendMap<Texture>>),
    Media(Rc<Media>),
    /// A `density { }`, kept as the pigment whose colour is the density.
    Density(Rc<Pigment>),
    DensityMap(Rc<BlendMap<Pigment>>),
    Fog(Rc<Fog>),
    Rainbow(Rc<Rainbow>),
    SkySphere(Rc<SkySphere>),
    Transform(Rc<Transform>),
    Function(std::sync::Arc<Function>),
    Spline(Rc<Spline>),
    Array(Rc<Array>),
    Dictionary(Rc<Dictionary>),
    Macro(Rc<MacroDef>),
    /// A file handle opened by `#fopen`.
    File(Rc<RefCell<super::file_io::OpenFile>>),
    /// A `#local` whose value is still being read.
    Uninitialized,
}

impl Value {
    /// A colour value. POV-Ray keeps colours in single precision, and scenes that print
    /// colour components see it (`rgb 0.1` reads back as 0.100000001490), so we round the
    /// same way.
    pub fn colour(terms: Terms) -> Value {
        let mut c = terms.promoted(5);
        for v in &mut c.c {
            *v = f64::from(*v as f32);
        }
        Value::Colour(c)
    }

    /// The type's name as POV-Ray users know it, for messages and hover text.
    pub fn type_name(&self) -> &'static str {
        match self {
            Value::Float(_) => "float",
            Value::Vector(t) if t.len == 2 => "2d vector",
            Value::Vector(t) if t.len == 4 => "4d vector",
            Value::Vector(t) if t.len == 5 => "5d vector",
            Value::Vector(_) => "vector",
            Value::Colour(_) => "color",
            Value::String(_) => "string",
            Value::Object(_) => "object",
            Value::Light(_) => "light_source",
            Value::Camera(_) => "camera",
            Value::Texture(_) => "texture",
            Value::Pigment(_) => "pigment",
            Value::Normal(_) => "normal",
            Value::Finish(_) => "finish",
            Value::Interior(_) => "interior",
            Value::Material(_) => "material",
            Value::ColourMap(_) => "color_map",
            Value::PigmentMap(_) => "pigment_map",
            Value::NormalMap(_) => "normal_map",
            Value::TextureMap(_) => "texture_map",
            Value::Media(_) => "media",
            Value::Density(_) => "density",
            Value::DensityMap(_) => "density_map",
            Value::Fog(_) => "fog",
            Value::Rainbow(_) => "rainbow",
            Value::SkySphere(_) => "sky_sphere",
            Value::Transform(_) => "transform",
            Value::Function(_) => "function",
            Value::Spline(_) => "spline",
            Value::Array(_) => "array",
            Value::Dictionary(_) => "dictionary",
            Value::Macro(_) => "macro",
            Value::File(_) => "file handle",
            Value::Uninitialized => "identifier without a value yet",
        }
    }

    /// The numeric terms of a float, vector or colour.
    pub fn terms(&self) -> Option<Terms> {
        match self {
            Value::Float(v) => Some(Terms::splat(*v, 1)),
            Value::Vector(t) | Value::Colour(t) => Some(*t),
            _ => None,
        }
    }

    /// Whether this value is numeric: float, vector or colour.
    pub fn is_numeric(&self) -> bool {
        matches!(self, Value::Float(_) | Value::Vector(_) | Value::Colour(_))
    }
}
