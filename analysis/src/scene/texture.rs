use super::{Colour, Transform};
use crate::function::Function;
use glam::DVec3;
use std::sync::Arc;

/// How a pattern's value is shaped before it indexes a map.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum WaveType {
    #[default]
    Ramp,
    Triangle,
    Sine,
    Scallop,
    Cubic,
    Poly(f64),
}

/// `turbulence`, `octaves`, `omega`, `lambda`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Turbulence {
    pub amount: DVec3,
    pub octaves: u32,
    pub omega: f64,
    pub lambda: f64,
}

/// A `warp { }` block.
#[derive(Debug, Clone, PartialEq)]
pub enum Warp {
    Turbulence(Turbulence),
    Repeat {
        direction: DVec3,
        offset: DVec3,
        flip: DVec3,
    },
    BlackHole {
        center: DVec3,
        radius: f64,
        strength: f64,
        falloff: f64,
        inverse: bool,
        /// `repeat`: a black hole in every block of this size (zero: just the one).
        repeat: DVec3,
        /// `turbulence`: how far each repeated centre strays, at random, in its block.
        jitter: DVec3,
    },
    Cylindrical {
        orientation: DVec3,
        dist_exp: f64,
    },
    Spherical {
        orientation: DVec3,
        dist_exp: f64,
    },
    Toroidal {
        orientation: DVec3,
        dist_exp: f64,
        major_radius: f64,
    },
    Planar {
        orientation: DVec3,
        distance: f64,
    },
    /// A transformation written between warps: it applies in sequence with them.
    Transform(Transform),
}

/// The patterns shared by pigments, normals, textures and densities.
#[derive(Debug, Clone, PartialEq)]
pub enum PatternKind {
    /// `average`: the map's entries blended by their weights (the map values).
    Average,
    Agate {
        turb: f64,
    },
    Boxed,
    Bozo,
    Brick {
        size: DVec3,
        mortar: f64,
    },
    Bumps,
    Cells,
    Checker,
    Crackle {
        form: DVec3,
        metric: f64,
        offset: f64,
        solid: bool,
    },
    Cylindrical,
    /// `density_file df3 "name"`: a grid of voxels in the unit cube, blended trilinearly
    /// with `interpolate 1`.
    DensityFile {
        grid: Arc<crate::pattern::density_file::DensityGrid>,
        trilinear: bool,
    },
    Dents,
    Facets {
        coords: f64,
        size: f64,
        metric: f64,
    },
    Function(Arc<Function>),
    /// The direction of the ramp as a unit vector (zero for a zero vector), found once
    /// rather than at every evaluation.
    Gradient(DVec3),
    Granite,
    Hexagon,
    Leopard,
    Marble,
    Onion,
    Planar,
    Quilted {
        control0: f64,
        control1: f64,
    },
    Radial,
    Ripples,
    Spherical,
    Spiral1 {
        arms: f64,
    },
    Spiral2 {
        arms: f64,
    },
    Spotted,
    Square,
    /// `tiling N`, N from 1 to 27: one of POV-Ray's periodic tilings of the x-z plane.
    Tiling(u8),
    Triangular,
    Waves,
    Wood,
    Wrinkles,
    /// `object { O A, B }`: entry B inside the object, entry A outside.
    Object(crate::geometry::InsideTest),
    /// `pigment_pattern { PIGMENT }`: the grey value of the pigment's colour.
    PigmentPattern(Box<Pigment>),
    /// `mandel N`, `julia <c>, N`, `magnet 1|2 mandel|julia N`: escape-time fractals, with
    /// their `exponent`, `interior` and `exterior` colouring.
    Fractal(Box<Fractal>),
    /// `image_pattern { }`, and the heights of a `bump_map`.
    Image(Box<super::bitmap::ImagePattern>),
    /// `material_map { }`: the image's palette index (or red value) chooses one of
    /// `textures` textures.
    MaterialMap {
        image: Box<super::bitmap::ImagePattern>,
        textures: usize,
    },
    /// `slope { }`: which way the surface faces, optionally blended with a gradient.
    Slope(Box<Slope>),
    /// `aoi`: the angle between the ray and the surface normal.
    Aoi,
    /// `pavement`: the x-z plane paved with one polyform tile.
    Pavement(Pavement),
}

impl PatternKind {
    /// `gradient` along `v`, kept as the unit vector its values are measured along.
    pub fn gradient(v: DVec3) -> PatternKind {
        let len = v.length();
        PatternKind::Gradient(if len > 0.0 { v / len } else { DVec3::ZERO })
    }
}

/// The tile of a `pavement`: `number_of_sides` of its cells (3, 4 or 6),
/// `number_of_tiles` (the cells in a tile, 1 to 6) and which `pattern` of those, and the
/// looks of its corners (0 sharp, 1 cut, 2 round): `form` where the tile turns (3, for
/// squares, draws those as the others), `exterior` at its pointed ends, `interior` in its
/// notches.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Pavement {
    pub sides: u8,
    pub tiles: u8,
    pub pattern: u8,
    pub form: u8,
    pub exterior: u8,
    pub interior: u8,
}

impl Pavement {
    /// Whether every corner has POV-Ray's default, sharp, look.
    pub fn sharp(&self) -> bool {
        self.form == 0 && self.exterior == 0 && self.interior == 0
    }
}

/// The parameters of `slope { <Direction> [, Lo, Hi] [altitude <Altitude> [, Lo, Hi]] }`
/// and `slope { point_at <Point> [, Lo, Hi] }`.
#[derive(Debug, Clone, PartialEq)]
pub struct Slope {
    /// What the surface's normal is compared with.
    pub towards: SlopeTarget,
    /// The slope term's weight against the altitude's: the length of `<Direction>` (1 for
    /// `point_at`).
    pub weight: f64,
    /// The slope values that map to 0 and 1; `None` when the scene gives none or two
    /// equal ones, which POV-Ray takes as the plain slope.
    pub range: Option<(f64, f64)>,
    /// The gradient blended in by `altitude`, if its vector is not zero.
    pub altitude: Option<Altitude>,
}

/// What a slope pattern compares the surface's normal with.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SlopeTarget {
    /// A unit direction, or zero when only the altitude counts.
    Direction(DVec3),
    /// `point_at`: the direction from the surface point to this world point.
    Point(DVec3),
}

/// The gradient term of a slope pattern.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Altitude {
    /// The unit direction of the gradient, in pattern space.
    pub axis: DVec3,
    /// The length of `<Altitude>`.
    pub weight: f64,
    /// The heights along `axis` that map to 0 and 1 (0 and 1 unless the scene gives two
    /// different ones).
    pub range: (f64, f64),
}

/// The parameters of the fractal patterns.
#[derive(Debug, Clone, PartialEq)]
pub struct Fractal {
    pub kind: FractalKind,
    pub max_iteration: u32,
    pub exponent: u32,
    /// `interior TYPE, FACTOR`; POV-Ray's default is type 0.
    pub interior: (u8, f64),
    /// `exterior TYPE, FACTOR`; POV-Ray's default is type 1.
    pub exterior: (u8, f64),
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FractalKind {
    Mandel,
    Julia {
        c: (f64, f64),
    },
    Magnet {
        variant: u8,
        julia: Option<(f64, f64)>,
    },
}

/// A pattern with its modifiers, in pattern space; `transform` takes pattern space to the
/// world (the evaluator composes every later object transformation into it).
#[derive(Debug, Clone, PartialEq)]
pub struct Pattern {
    pub kind: PatternKind,
    pub wave: WaveType,
    pub frequency: f64,
    pub phase: f64,
    pub turbulence: Option<Turbulence>,
    pub warps: Vec<Warp>,
    pub transform: Transform,
    pub noise_generator: u8,
    /// `uv_mapping`: the pattern is evaluated at the surface's (u, v, 0) instead of the
    /// point in space, and the object's transformations do not move it.
    pub uv_mapping: bool,
}

impl Pattern {
    pub fn new(kind: PatternKind) -> Pattern {
        Pattern {
            kind,
            wave: WaveType::Ramp,
            frequency: 1.0,
            phase: 0.0,
            turbulence: None,
            warps: Vec::new(),
            transform: Transform::IDENTITY,
            noise_generator: 2,
            uv_mapping: false,
        }
    }
}

/// Values from 0 to 1 mapped to entries, blended between neighbours. Block patterns
/// (checker, hexagon, brick, square, triangular) index the entries directly instead.
#[derive(Debug, Clone, PartialEq)]
pub struct BlendMap<T> {
    pub entries: Vec<(f64, T)>,
}

#[derive(Debug, Clone, PartialEq)]
pub enum Pigment {
    Solid(Colour),
    Pattern {
        pattern: Box<Pattern>,
        map: BlendMap<Pigment>,
    },
    /// `image_map { }`.
    Image(Box<super::bitmap::ImageMap>),
}

#[derive(Debug, Clone, PartialEq)]
pub enum NormalKind {
    /// A pattern used as a height field, scaled by `bump_size`; a `slope_map` reshapes
    /// its values into heights and slopes.
    Pattern {
        pattern: Box<Pattern>,
        bump_size: f64,
        slope_map: Option<BlendMap<(f64, f64)>>,
    },
    /// `bump_map { }`: the image's values as heights, tilting the normal along the
    /// image's axes by their slope across a pixel.
    BumpMap {
        /// Of kind [`PatternKind::Image`].
        pattern: Box<Pattern>,
        bump_size: f64,
    },
    /// A `normal_map`.
    Map {
        pattern: Box<Pattern>,
        map: BlendMap<Normal>,
    },
}

#[derive(Debug, Clone, PartialEq)]
pub struct Normal {
    pub kind: NormalKind,
    /// The sample spacing for patterns that are not bumps by nature.
    pub accuracy: f64,
    /// The object's transformations after a uv-mapped normal: they leave its pattern
    /// glued to the surface but turn its push with the surface, as in POV-Ray. `None`
    /// for none (boxed: most normals have none, and textures stay small).
    pub placement: Option<Box<Transform>>,
}

impl Normal {
    /// Adds the object's transformation `t` to the placement.
    pub fn place(&mut self, t: &Transform) {
        let placed = match &self.placement {
            Some(p) => p.then(t),
            None => *t,
        };
        self.placement = Some(Box::new(placed));
    }
}

/// The `reflection { }` block, or the plain `reflection` colour.
#[derive(Debug, Clone, PartialEq)]
pub struct Reflection {
    pub min: Colour,
    pub max: Colour,
    pub fresnel: bool,
    pub falloff: f64,
    pub exponent: f64,
    pub metallic: f64,
}

/// Surface response to light, with POV-Ray's defaults.
#[derive(Debug, Clone, PartialEq)]
pub struct Finish {
    pub ambient: DVec3,
    pub emission: DVec3,
    pub diffuse: f64,
    pub diffuse_back: f64,
    pub brilliance: f64,
    pub crand: f64,
    pub phong: f64,
    pub phong_size: f64,
    pub specular: f64,
    pub roughness: f64,
    pub metallic: f64,
    pub reflection: Option<Reflection>,
    pub irid: Option<(f64, f64, f64)>,
    pub conserve_energy: bool,
    /// `subsurface { translucency }`: how strongly light scatters under the surface.
    pub translucency: Option<DVec3>,
}

impl Default for Finish {
    fn default() -> Self {
        Finish {
            ambient: DVec3::splat(0.1),
            emission: DVec3::ZERO,
            diffuse: 0.6,
            diffuse_back: 0.0,
            brilliance: 1.0,
            crand: 0.0,
            phong: 0.0,
            phong_size: 40.0,
            specular: 0.0,
            roughness: 0.05,
            metallic: 0.0,
            reflection: None,
            irid: None,
            conserve_energy: false,
            translucency: None,
        }
    }
}

/// A texture: plain, patterned (a `texture_map` or block pattern of textures), or layered.
#[derive(Debug, Clone, PartialEq)]
pub enum Texture {
    Plain {
        pigment: Pigment,
        normal: Option<Normal>,
        finish: Arc<Finish>,
    },
    Pattern {
        pattern: Box<Pattern>,
        map: BlendMap<Texture>,
    },
    /// Layers from the bottom up; each upper layer shows through its filter/transmit.
    Layered(Vec<Texture>),
}

impl Default for Texture {
    /// POV-Ray's default texture: black pigment, default finish, no normal.
    fn default() -> Self {
        Texture::Plain {
            pigment: Pigment::Solid(Colour::BLACK),
            normal: None,
            finish: Arc::new(Finish::default()),
        }
    }
}
