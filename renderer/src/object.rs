//! Runtime objects: a shape bound to its placement and material (a leaf), or a CSG node
//! over other objects. CSG follows POV-Ray's definition: a union keeps every crossing of its
//! children, a merge the crossings outside the other children, and an intersection those
//! inside all the others. A difference is built as the intersection of its first child with
//! the inverse of the rest, and inverting a CSG node swaps union and intersection over
//! inverted children, so subtracting a union removes no surface the union hides.

use crate::bounds::Aabb;
use crate::csg_spans::{ChildSpans, Meeting};
use crate::fast_math;
use crate::interior::Interior;
use crate::material::{Layer, Material, Surface, transmitted_through};
use crate::photons::SurfacePhotons;
use crate::ray::{Ray, RayKind};
use crate::shapes::{Root, Roots, Shape, Span};
use crate::texture_point::TexturePoint;
use analysis::pattern::Facing;
use analysis::scene::LightPhotons;
use analysis::scene::mesh::FaceTexture;
use glam::{DAffine3, DVec3};
use std::mem::MaybeUninit;
use std::sync::Arc;

/// Which kinds of rays see an object.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Visibility {
    pub no_image: bool,
    pub no_reflection: bool,
    pub no_shadow: bool,
    pub no_radiosity: bool,
}

impl Visibility {
    pub fn sees(&self, kind: RayKind) -> bool {
        match kind {
            RayKind::Primary => !self.no_image,
            RayKind::Reflected => !self.no_reflection,
            RayKind::Shadow => !self.no_shadow,
            RayKind::Radiosity => !self.no_radiosity,
            RayKind::Transmitted => true,
        }
    }

    /// The kinds of rays that see the object, as a set of [`RayKind::bit`]s.
    pub fn kinds(&self) -> u8 {
        [
            RayKind::Primary,
            RayKind::Reflected,
            RayKind::Transmitted,
            RayKind::Shadow,
            RayKind::Radiosity,
        ]
        .into_iter()
        .filter(|&kind| self.sees(kind))
        .fold(0, |set, kind| set | kind.bit())
    }
}

/// A shape placed in the world with its material.
#[derive(Debug, Clone)]
pub struct Leaf {
    pub shape: Shape,
    /// World to the canonical frame; `None` for the identity, the common case of planes.
    /// Normals go back to the world by its transposed linear part. A scene may hold a
    /// hundred thousand leaves, so nothing derived from it is stored beside it, except a
    /// plane's or a disc's normal in the world, which fits in the room the `Shape` enum
    /// has spare for those shapes.
    to_local: Option<DAffine3>,
    pub inverse: bool,
    pub material: Arc<Material>,
    /// The textures a mesh's triangles name by index; empty for other shapes.
    face_materials: Box<[Arc<Material>]>,
    /// Whether light passes somewhere, through the material or a triangle's own.
    pub transmits: bool,
    /// Whether some pattern of its materials is uv-mapped.
    uses_uv: bool,
    /// Whether some pattern of its materials looks at how the surface faces the ray.
    uses_facing: bool,
    /// The set of lights that shine on the leaf (see `World::lights_for`): 0 for the
    /// scene's lights, another for a light group's.
    pub light_set: u32,
    /// What fills the shape; shared by the leaves of one object.
    pub interior: Arc<Interior>,
    pub visibility: Visibility,
    /// Lit from behind as from the front.
    pub double_illuminate: bool,
    /// `radiosity { importance }`: the share of radiosity rays meeting it that are shaded.
    pub importance: f64,
    /// A whole object of its own, not part of a CSG: its surface alone decides whether it
    /// blocks a ray.
    pub standalone: bool,
    /// What the surface does with photons.
    pub photons: SurfacePhotons,
    /// The sides of a flat leaf's plane no other object reaches into (see
    /// [`crate::open_sides`]).
    pub open_sides: OpenSides,
    pub bounds: Aabb,
}

/// The sides of a flat leaf's plane that no other object reaches into, the side its
/// normal points to and the other, as two bits of one byte: a scene may hold a hundred
/// thousand leaves. The byte's other six bits hold the sides of the box of every object
/// that the leaf's own box reaches, across which rays from its surface may leave every
/// object behind (see [`crate::bvh::Bvh::left_behind`]), set when the hierarchy is built.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct OpenSides(u8);

impl OpenSides {
    pub const NONE: OpenSides = OpenSides(0);
    const FRONT: u8 = 1;
    const BACK: u8 = 2;
    const FLAT: u8 = Self::FRONT | Self::BACK;

    pub fn new(front: bool, back: bool) -> OpenSides {
        OpenSides((u8::from(front) * Self::FRONT) | (u8::from(back) * Self::BACK))
    }

    /// The open sides of the flat leaf's plane alone.
    pub fn flat(self) -> OpenSides {
        OpenSides(self.0 & Self::FLAT)
    }

    /// These sides with the box sides `reach` (six bits: low x, y, z, high x, y, z).
    pub fn with_reach(self, reach: u8) -> OpenSides {
        OpenSides(self.flat().0 | reach << 2)
    }

    /// The box sides the leaf reaches (six bits, as [`OpenSides::with_reach`] takes them).
    pub fn reach(self) -> u8 {
        self.0 >> 2
    }

    /// Whether the side `along` (the sign of a direction's dot product with the normal)
    /// points to is open; neither is for a direction in the plane.
    pub fn towards(self, along: f64) -> bool {
        (along > 0.0 && self.0 & Self::FRONT != 0) || (along < 0.0 && self.0 & Self::BACK != 0)
    }
}

/// A crossing of a ray with a leaf.
#[derive(Debug, Clone, Copy)]
pub struct Hit<'a> {
    pub t: f64,
    pub leaf: &'a Leaf,
    pub part: u32,
}

impl Leaf {
    pub fn new(
        shape: Shape,
        to_world: DAffine3,
        inverse: bool,
        material: Arc<Material>,
        interior: Arc<Interior>,
        visibility: Visibility,
    ) -> Leaf {
        let identity = to_world == DAffine3::IDENTITY;
        let to_local = to_world.inverse();
        let mut shape = match shape {
            Shape::Torus(torus) if !identity => Shape::Torus(torus.placed(&to_world)),
            shape => shape,
        };
        let bounds = shape.world_bounds(&to_world);
        let to_local = (!identity).then_some(to_local);
        keep_world_normal(&mut shape, to_local.as_ref());
        Leaf {
            shape,
            to_local,
            inverse,
            transmits: material.transmits,
            uses_uv: material.uses_uv,
            uses_facing: material.uses_facing,
            material,
            face_materials: Box::new([]),
            light_set: 0,
            interior,
            visibility,
            double_illuminate: false,
            importance: 1.0,
            standalone: false,
            photons: SurfacePhotons::default(),
            open_sides: OpenSides::NONE,
            bounds,
        }
    }

    fn local_ray(&self, ray: &Ray) -> Ray {
        match &self.to_local {
            Some(m) => Ray::new(
                m.transform_point3(ray.origin),
                m.transform_vector3(ray.direction),
            ),
            None => *ray,
        }
    }

    /// [`Leaf::local_ray`] without copying `ray` when there is no transformation (a copy
    /// cost a dozen loads and stores in WebAssembly): `ray` itself, or the transformed ray
    /// written into `local`.
    #[inline(always)]
    fn local_ray_in<'r>(&self, ray: &'r Ray, local: &'r mut MaybeUninit<Ray>) -> &'r Ray {
        match &self.to_local {
            Some(_) => local.write(self.local_ray(ray)),
            None => ray,
        }
    }

    fn local_point(&self, p: DVec3) -> DVec3 {
        match &self.to_local {
            Some(m) => m.transform_point3(p),
            None => p,
        }
    }

    pub fn inside(&self, p: DVec3) -> bool {
        self.shape.inside(self.local_point(p)) != self.inverse
    }

    /// The plane of a flat leaf in the world, `normal · x = offset`, with the unit normal
    /// [`Leaf::normal`] gives at each of its points; `None` for a shape that is not flat
    /// (or has a normal of its own at each point, as a smooth triangle does) or a frame
    /// that flattens it.
    pub fn flat_plane(&self) -> Option<(DVec3, f64)> {
        let point = match &self.shape {
            Shape::Plane(plane) => plane.normal * plane.distance,
            Shape::Disc(_) | Shape::Polygon(_) => DVec3::ZERO,
            _ => return None,
        };
        let to_world = self.to_local.map_or(DAffine3::IDENTITY, |m| m.inverse());
        let normal = self.normal(DVec3::ZERO, 0);
        let offset = normal.dot(to_world.transform_point3(point));
        (to_world.is_finite() && offset.is_finite()).then_some((normal, offset))
    }

    /// The corners of the shape's own box carried into the world, when the leaf has a
    /// frame of its own and the box is finite: a box holding the surface that may be far
    /// tighter than its world box (a tilted ring's is a flat slab).
    pub fn frame_corners(&self) -> Option<[DVec3; 8]> {
        let to_world = self.to_local?.inverse();
        let local = self.shape.bounds();
        if local.is_empty() || !local.is_finite() || !to_world.is_finite() {
            return None;
        }
        Some(local.corners().map(|c| to_world.transform_point3(c)))
    }

    /// The corners in the world of boxes that together hold the surface more tightly than
    /// its one box: the arcs of a ring (see [`crate::shapes::Torus::arc_boxes`]). `None`
    /// for other shapes.
    pub fn piece_corners(&self) -> Option<Vec<[DVec3; 8]>> {
        let Shape::Torus(torus) = &self.shape else {
            return None;
        };
        let to_world = self.to_local.map_or(DAffine3::IDENTITY, |m| m.inverse());
        if !to_world.is_finite() {
            return None;
        }
        let pieces = torus
            .arc_boxes()
            .map(|b| b.corners().map(|c| to_world.transform_point3(c)));
        Some(pieces.to_vec())
    }

    /// Gives a mesh's triangles the materials of its texture list.
    pub fn set_face_materials(&mut self, materials: Vec<Arc<Material>>) {
        self.transmits |= materials.iter().any(|m| m.transmits);
        self.uses_uv |= materials.iter().any(|m| m.uses_uv);
        self.uses_facing |= materials.iter().any(|m| m.uses_facing);
        self.face_materials = materials.into();
    }

    /// Where the textures are evaluated at a point of the surface that `ray` reached: the
    /// shape gives its uv coordinates, and its normal turned towards the ray, when a
    /// pattern needs them.
    /// Inlined: the tracer asks at every hit it shades, and for the common shape with
    /// neither uv nor facing patterns the call cost more than the answer.
    #[inline(always)]
    pub fn texture_point(&self, p: DVec3, part: u32, ray: &Ray) -> TexturePoint {
        let mut at = TexturePoint::in_space(p);
        if self.uses_uv
            && let Shape::Mesh(mesh) = &self.shape
        {
            at.uv = mesh.uv(self.local_point(p), part);
        }
        if self.uses_facing {
            let normal = self.normal(p, part);
            let normal = if normal.dot(ray.direction) > 0.0 {
                -normal
            } else {
                normal
            };
            at.facing = Some(Facing {
                point: p,
                normal,
                ray: ray.direction.normalize_or_zero(),
            });
        }
        at
    }

    /// Calls `f` with each stack of texture layers that colours the point, and its weight:
    /// the object's texture, a mesh triangle's own, or the three textures of a triangle's
    /// corners weighted by how near the point is to each.
    pub fn for_each_layers(
        &self,
        at: &TexturePoint,
        part: u32,
        f: &mut impl FnMut(f64, &[Layer], &TexturePoint),
    ) {
        if let Shape::Mesh(mesh) = &self.shape
            && !self.face_materials.is_empty()
        {
            match mesh.texture(self.local_point(at.world), part) {
                (FaceTexture::Object, _) => {}
                (FaceTexture::One(i), _) => {
                    return self.face_materials[i as usize]
                        .surface
                        .for_each_layers(at, 1.0, f);
                }
                (FaceTexture::Corners(ids), weights) => {
                    for (id, weight) in ids.into_iter().zip(weights.to_array()) {
                        if weight != 0.0 {
                            self.face_materials[id as usize]
                                .surface
                                .for_each_layers(at, weight, f);
                        }
                    }
                    return;
                }
            }
        }
        self.material.surface.for_each_layers(at, 1.0, f);
    }

    /// The one stack of layers the whole surface shows, where it has no texture map, blend
    /// or per-face textures: what [`Leaf::for_each_layers`] calls its function with, at a
    /// weight of 1, wherever the surface is.
    pub fn single_stack(&self) -> Option<&[Layer]> {
        match &self.material.surface {
            Surface::Layers(layers) if self.face_materials.is_empty() => Some(layers),
            _ => None,
        }
    }

    /// The one layer of an opaque surface without bumps or reflection (see
    /// [`crate::material::Surface::single_unbumped_layer`]), whose pigment is opaque
    /// everywhere.
    pub fn opaque_layer(&self) -> Option<&Layer> {
        if self.face_materials.is_empty() && !self.material.transmits {
            self.material.surface.single_unbumped_layer()
        } else {
            None
        }
    }

    /// The colour light keeps through the surface at the point, averaged over a texture
    /// map's or a triangle's blend.
    pub fn transmitted_at(&self, at: &TexturePoint, part: u32) -> DVec3 {
        let mut total = DVec3::ZERO;
        self.for_each_layers(at, part, &mut |w, layers, layers_at| {
            total += transmitted_through(layers, layers_at) * w;
        });
        total
    }

    /// Whether the leaf's frame keeps the axes' directions (no rotation or shear), so that
    /// its box is its shape's own box.
    fn is_upright(&self) -> bool {
        self.to_local.is_none_or(|m| {
            let m = m.matrix3;
            [
                m.x_axis.y, m.x_axis.z, m.y_axis.x, m.y_axis.z, m.z_axis.x, m.z_axis.y,
            ] == [0.0; 6]
        })
    }

    /// Whether this standalone leaf crosses the query's interval and stops the light there:
    /// opaque, or a target refracting the photons of the light whose settings are
    /// `photons_stop` (see [`crate::photons::SurfacePhotons::stops_light_for_photons`]).
    pub fn blocks(&self, q: &Query, photons_stop: Option<&LightPhotons>) -> bool {
        self.standalone
            && (!self.transmits
                || photons_stop.is_some_and(|light| self.photons.stops_light_for_photons(light)))
            && self.visibility.sees(q.kind)
            && self.first_hit(&q.ray, q.tmin, q.tmax).is_some()
    }

    /// The nearest crossing inside the query's interval that rays of the query's kind
    /// see. Inlined, as [`Leaf::first_hit`] is.
    #[inline(always)]
    pub fn nearest(&self, q: &Query) -> Option<Hit<'_>> {
        self.nearest_in(q, q.tmin, q.tmax)
    }

    /// [`Leaf::nearest`] inside `(tmin, tmax)` instead of the query's interval: the
    /// searches that narrow the interval keep its ends apart, since narrowing a copy of
    /// the query cost them a memory copy or a dozen loads and stores in WebAssembly.
    #[inline(always)]
    pub fn nearest_in(&self, q: &Query, tmin: f64, tmax: f64) -> Option<Hit<'_>> {
        if !self.visibility.sees(q.kind) {
            return None;
        }
        self.first_hit(&q.ray, tmin, tmax).map(|r| Hit {
            t: r.t,
            leaf: self,
            part: r.part,
        })
    }

    /// The nearest crossing of `ray` inside `(tmin, tmax)`. Inlined into the searches,
    /// which call it for every leaf a ray reaches: a call costs the interpreted plugin as
    /// much as a box test. So are a plane's test and a disc's, a few operations each,
    /// which the shapes' dispatch called out of line: a floor and a water surface are
    /// tested by several rays at every sample.
    #[inline(always)]
    fn first_hit(&self, ray: &Ray, tmin: f64, tmax: f64) -> Option<crate::shapes::Root> {
        // Without a transformation the shape is asked along the ray itself: a copy of
        // it, as `local_ray` gives, cost every search of such a leaf in WebAssembly a
        // dozen loads and stores.
        let Some(to_local) = &self.to_local else {
            if let Shape::Plane(plane) = &self.shape {
                return plane.first_hit(ray, tmin, tmax);
            }
            return self.shape.first_hit(ray, tmin, tmax);
        };
        match &self.shape {
            Shape::Disc(disc) => return disc.first_hit(&self.local_ray(ray), tmin, tmax),
            Shape::Torus(torus) if !torus.may_meet(to_local, ray, tmin, tmax) => return None,
            _ => {}
        }
        self.shape.first_hit(&self.local_ray(ray), tmin, tmax)
    }

    /// The unit outward normal in the world at a point of this leaf's surface. Inlined for
    /// planes, discs and polygons, whose normal their shape keeps: rays meet and leave them
    /// at every sample of a floor, a water surface or a wall, and a call costs the
    /// interpreted plugin a frame.
    #[inline]
    pub fn normal(&self, p: DVec3, part: u32) -> DVec3 {
        let kept = match &self.shape {
            Shape::Plane(plane) => plane.world_normal(),
            Shape::Disc(disc) => disc.world_normal(),
            Shape::Polygon(polygon) => polygon.world_normal(),
            _ => DVec3::ZERO,
        };
        if kept == DVec3::ZERO {
            return self.transformed_normal(p, part);
        }
        if self.inverse { -kept } else { kept }
    }

    /// [`Leaf::normal`] from the shape's normal at the point, carried into the world.
    #[inline(never)]
    fn transformed_normal(&self, p: DVec3, part: u32) -> DVec3 {
        // A box in world space: its face's normal is already a unit axis, which
        // normalizing keeps bit for bit.
        if let (Shape::Cuboid(cuboid), None) = (&self.shape, &self.to_local) {
            let n = cuboid.normal(part);
            return if self.inverse { -n } else { n };
        }
        let n = world_normal_of(
            self.to_local.as_ref(),
            self.shape.normal(self.local_point(p), part),
        );
        if n == DVec3::ZERO {
            // A degenerate spot (a cone's apex): any direction facing the ray will do
            // once the shader turns it; never NaN.
            DVec3::Y
        } else if self.inverse {
            -n
        } else {
            n
        }
    }

    /// The stretch of the ray inside the shape, inverse or not, for convex shapes (see
    /// [`Shape::convex_span`]).
    #[inline]
    pub fn span(&self, ray: &Ray) -> Option<Span> {
        if !self.shape.has_convex_span() {
            return None;
        }
        self.shape
            .convex_span(self.local_ray_in(ray, &mut MaybeUninit::uninit()))
    }

    fn roots(&self, ray: &Ray) -> Roots {
        let mut roots = Roots::new();
        self.shape.intersect(
            self.local_ray_in(ray, &mut MaybeUninit::uninit()),
            &mut roots,
        );
        roots
    }
}

/// Works out a plane's, a disc's or a polygon's normal in the world once, into the shape:
/// it is the same at each of its points, each ray that meets or leaves one asks for it,
/// and its transformation costs a dozen operations and a square root.
fn keep_world_normal(shape: &mut Shape, to_local: Option<&DAffine3>) {
    match shape {
        Shape::Plane(plane) => plane.place(world_normal_of(to_local, plane.normal)),
        Shape::Disc(disc) => disc.place(world_normal_of(to_local, DVec3::Z)),
        Shape::Polygon(polygon) => polygon.place(world_normal_of(to_local, DVec3::Z)),
        _ => {}
    }
}

/// The unit normal in the world of a shape's normal `n` in its canonical frame, which
/// `to_local` (`None` for the identity) maps the world to; zero where the frame flattens
/// it.
fn world_normal_of(to_local: Option<&DAffine3>, n: DVec3) -> DVec3 {
    let n = if let Some(m) = to_local {
        // The transposed linear part times n: each column's dot product with n.
        DVec3::new(
            m.matrix3.x_axis.dot(n),
            m.matrix3.y_axis.dot(n),
            m.matrix3.z_axis.dot(n),
        )
    } else {
        n
    };
    n.normalize_or_zero()
}

/// A node of the object tree. Leaves are kept inline although they are larger than CSG
/// nodes: most objects are leaves, and a box around each would cost a pointer chase per test.
#[derive(Debug, Clone)]
#[allow(clippy::large_enum_variant)]
pub enum Object {
    Leaf(Leaf),
    Csg(Csg),
}

#[derive(Debug, Clone)]
pub struct Csg {
    pub kind: CsgKind,
    pub children: Vec<Object>,
    /// Bounds of the surface.
    pub bounds: Aabb,
    /// Bounds of the inside: infinite once an inverted child makes it so.
    pub region: Aabb,
    /// A sphere or box among the children of an intersection (one that clips, for a clip)
    /// holding all of the node's surface: a ray that passes it by misses the node, whose
    /// other children then need no test (a `cubic` clipped by a sphere inside its box).
    hull: Option<usize>,
    /// A clip whose clipping objects are all uninverted spheres, boxes or planes, and whose
    /// clipped object is none of them (a `cubic` clipped by a sphere): its nearest crossing
    /// is the clipped object's own nearest one where the clipping stretches meet (see
    /// [`Csg::nearest_clipped`], which the hierarchy's searches call for it).
    pub convex_clip: bool,
    /// Whether a ray that crosses the hull may still pass the node's bounds by: not when
    /// the hull's own box is the bounds (a clipping sphere inside the clipped object's
    /// box), so that such a clip tests no box.
    box_culls: bool,
}

/// The CSG operations a runtime node performs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CsgKind {
    Union,
    Merge,
    Intersection,
    /// `clipped_by`: the first child's surface where it lies inside all the others, whose
    /// own surfaces never show.
    Clip,
}

impl Csg {
    pub fn new(kind: CsgKind, children: Vec<Object>) -> Csg {
        let children = if kind == CsgKind::Intersection {
            flatten_intersections(children)
        } else {
            children
        };
        let surfaces = children
            .iter()
            .fold(Aabb::EMPTY, |b, o| b.union(&o.bounds()));
        let (bounds, region) = match kind {
            CsgKind::Union | CsgKind::Merge => {
                let region = children
                    .iter()
                    .fold(Aabb::EMPTY, |b, o| b.union(&o.region()));
                (surfaces, region)
            }
            CsgKind::Intersection => {
                let region = children
                    .iter()
                    .fold(Aabb::INFINITE, |b, o| b.intersection(&o.region()));
                (surfaces.intersection(&region), region)
            }
            CsgKind::Clip => {
                let region = children
                    .iter()
                    .fold(Aabb::INFINITE, |b, o| b.intersection(&o.region()));
                (children[0].bounds().intersection(&region), region)
            }
        };
        let (bounds, region) = match kind {
            CsgKind::Intersection | CsgKind::Clip => match shared_frame_region(&children) {
                Some(shared) => (bounds.intersection(&shared), region.intersection(&shared)),
                None => (bounds, region),
            },
            CsgKind::Union | CsgKind::Merge => (bounds, region),
        };
        let first_bound = usize::from(kind == CsgKind::Clip);
        let hull = match kind {
            CsgKind::Intersection | CsgKind::Clip => children
                .iter()
                .skip(first_bound)
                .position(|o| match o {
                    Object::Leaf(l) if !l.inverse => match l.shape {
                        Shape::Sphere(_) => true,
                        // An upright box holding the node's own bounds turns away no ray
                        // that the bounds let through (csg.pov's rounded cube).
                        Shape::Cuboid(_) => !(l.is_upright() && o.bounds().contains(&bounds)),
                        _ => false,
                    },
                    _ => false,
                })
                .map(|i| i + first_bound),
            CsgKind::Union | CsgKind::Merge => None,
        };
        let convex_clip = kind == CsgKind::Clip
            && children.split_first().is_some_and(|(clipped, clips)| {
                !spans_always(clipped) && clips.iter().all(spans_always)
            });
        let box_culls = hull.is_none_or(|h| children[h].bounds() != bounds);
        Csg {
            kind,
            children,
            bounds,
            region,
            hull,
            convex_clip,
            box_culls,
        }
    }
}

/// Whether the object is an uninverted leaf whose stretch along every ray
/// [`Shape::convex_span`] gives: a sphere, a box or a plane's half-space.
fn spans_always(object: &Object) -> bool {
    matches!(object, Object::Leaf(l) if !l.inverse
        && matches!(l.shape, Shape::Sphere(_) | Shape::Cuboid(_) | Shape::Plane(_)))
}

/// The box around the inside of an intersection (or a clip) whose parts are all leaves
/// placed by one transformation, from their boxes met in that shared frame: a cylinder cut
/// by two planes is a finite piece there, while in the world, once rotated, each part's
/// box is infinite along every axis and so is their meeting. `None` for other parts.
fn shared_frame_region(children: &[Object]) -> Option<Aabb> {
    let mut frame = None;
    let mut local = Aabb::INFINITE;
    for child in children {
        let Object::Leaf(leaf) = child else {
            return None;
        };
        if *frame.get_or_insert(leaf.to_local) != leaf.to_local {
            return None;
        }
        if !leaf.inverse {
            local = local.intersection(&leaf.shape.bounds());
        }
    }
    if local.is_empty() || !local.is_finite() {
        return None;
    }
    let to_world = frame?.map_or(DAffine3::IDENTITY, |m| m.inverse());
    let world = local.transformed(&to_world);
    // The frame is the inverse of an inverse, a few ulps off the leaves' own: a hair
    // wider keeps every crossing inside.
    let pad = DVec3::splat(1e-9 * world.min.abs().max(world.max.abs()).max_element());
    Some(Aabb::new(world.min - pad, world.max + pad))
}

/// The children of an intersection with those that are intersections themselves replaced
/// by their own children, in order: the same surface, since a crossing of any part is kept
/// where it lies inside all the others either way, but each crossing is tested once against
/// the other parts instead of once per level (a difference of an intersection and a union
/// becomes one intersection of the first's parts and the inverted union's).
fn flatten_intersections(children: Vec<Object>) -> Vec<Object> {
    let mut flat = Vec::with_capacity(children.len());
    for child in children {
        match child {
            Object::Csg(csg) if csg.kind == CsgKind::Intersection => flat.extend(csg.children),
            other => flat.push(other),
        }
    }
    flat
}

/// A ray segment: the ray, its kind, and the open interval of parameters searched.
#[derive(Debug, Clone, Copy)]
pub struct Query {
    pub ray: Ray,
    pub inv_dir: DVec3,
    pub kind: RayKind,
    pub tmin: f64,
    pub tmax: f64,
}

impl Query {
    pub fn new(ray: Ray, kind: RayKind, tmin: f64, tmax: f64) -> Query {
        Query {
            ray,
            inv_dir: ray.direction.recip(),
            kind,
            tmin,
            tmax,
        }
    }
}

impl Object {
    pub fn bounds(&self) -> Aabb {
        match self {
            Object::Leaf(l) => l.bounds,
            Object::Csg(c) => c.bounds,
        }
    }

    /// The kinds of rays that may meet the object, as a set of [`RayKind::bit`]s: those
    /// that see one of its leaves, and of a clip one of the clipped object's (what clips
    /// it never shows: a `no_shadow` object casts no shadow, clipped or not).
    pub fn kinds(&self) -> u8 {
        match self {
            Object::Leaf(l) => l.visibility.kinds(),
            Object::Csg(c) if c.kind == CsgKind::Clip => c.children[0].kinds(),
            Object::Csg(c) => c.children.iter().fold(0, |set, o| set | o.kinds()),
        }
    }

    /// Bounds of the inside.
    pub fn region(&self) -> Aabb {
        match self {
            Object::Leaf(l) if l.inverse => Aabb::INFINITE,
            Object::Leaf(l) => l.bounds,
            Object::Csg(c) => c.region,
        }
    }

    /// The same surface with inside and outside swapped, built as POV-Ray inverts: a leaf
    /// flips, a union or merge becomes the intersection of its inverted children and an
    /// intersection the union of them.
    pub fn inverted(self) -> Object {
        match self {
            Object::Leaf(mut l) => {
                l.inverse = !l.inverse;
                Object::Leaf(l)
            }
            Object::Csg(c) if c.kind == CsgKind::Clip => {
                // The clipped object turns inside out; what clips it stays.
                let mut children = c.children.into_iter();
                let first = children.next().map(Object::inverted);
                Object::Csg(Csg::new(
                    CsgKind::Clip,
                    first.into_iter().chain(children).collect(),
                ))
            }
            Object::Csg(c) => {
                let kind = match c.kind {
                    CsgKind::Union | CsgKind::Merge => CsgKind::Intersection,
                    _ => CsgKind::Union,
                };
                Object::Csg(Csg::new(
                    kind,
                    c.children.into_iter().map(Object::inverted).collect(),
                ))
            }
        }
    }

    pub fn inside(&self, p: DVec3) -> bool {
        match self {
            Object::Leaf(l) => l.inside(p),
            Object::Csg(c) => match c.kind {
                CsgKind::Union | CsgKind::Merge => c.children.iter().any(|o| o.inside(p)),
                CsgKind::Intersection | CsgKind::Clip => c.children.iter().all(|o| o.inside(p)),
            },
        }
    }

    /// The nearest crossing inside the query's interval.
    pub fn nearest<'a>(&'a self, q: &Query, scratch: &mut Vec<Hit<'a>>) -> Option<Hit<'a>> {
        // A leaf's own test costs about what its box test would; CSG nodes check their box.
        if let Object::Csg(csg) = self
            && csg.bounds.is_finite()
        {
            q_clip(csg.bounds, q)?;
        }
        match self {
            Object::Leaf(leaf) => leaf.nearest(q),
            Object::Csg(csg) if csg.kind == CsgKind::Union => {
                let mut q = *q;
                let mut best = None;
                for child in &csg.children {
                    if let Some(hit) = child.nearest(&q, scratch) {
                        q.tmax = hit.t;
                        best = Some(hit);
                    }
                }
                best
            }
            Object::Csg(csg) => {
                let mut spans = ChildSpans::new();
                let meeting = csg.meet(&mut spans, q)?;
                if let Some(hit) = meeting.and_then(|m| csg.entry_hit(&spans, &m, q)) {
                    return Some(hit);
                }
                spans.complete(&csg.children, q);
                // Each child's crossings are tested nearest first and only up to the
                // nearest kept so far: testing whether a crossing is kept (inside the
                // other children or not) costs more than finding it.
                let mut q = *q;
                let mut best = None;
                for (i, child) in csg.children.iter().enumerate() {
                    if !csg.may_keep(i) {
                        break;
                    }
                    let sole_other = meeting.filter(|m| m.sole_other == Some(i));
                    let kept = match (child, spans.span(i), sole_other) {
                        (Object::Leaf(leaf), Some(span), _) => {
                            let kept = |r: &Root| {
                                r.t > q.tmin && r.t < q.tmax && csg.keeps(&spans, i, r.t, &q.ray)
                            };
                            [span.enter, span.exit]
                                .iter()
                                .find(|r| leaf.visibility.sees(q.kind) && kept(r))
                                .map(|r| Hit {
                                    t: r.t,
                                    leaf,
                                    part: r.part,
                                })
                        }
                        (_, _, Some(m)) => {
                            // Inside every other child is inside their meeting: the
                            // child's own nearest crossing there is the one kept.
                            let mut within = q;
                            within.tmin = fast_math::max(within.tmin, m.lo);
                            within.tmax = fast_math::min(within.tmax, m.hi);
                            child.nearest(&within, scratch)
                        }
                        _ => {
                            let start = scratch.len();
                            child.all_hits(&q, scratch);
                            scratch[start..].sort_by(|a, b| a.t.total_cmp(&b.t));
                            let kept = scratch[start..]
                                .iter()
                                .find(|hit| csg.keeps(&spans, i, hit.t, &q.ray))
                                .copied();
                            scratch.truncate(start);
                            kept
                        }
                    };
                    if let Some(hit) = kept {
                        q.tmax = hit.t;
                        best = Some(hit);
                    }
                }
                best
            }
        }
    }

    /// Appends every crossing inside the query's interval that lies on this object's
    /// surface, in no particular order.
    pub fn all_hits<'a>(&'a self, q: &Query, out: &mut Vec<Hit<'a>>) {
        if self.bounds().is_finite() && q_clip(self.bounds(), q).is_none() {
            return;
        }
        match self {
            Object::Leaf(leaf) => {
                if !leaf.visibility.sees(q.kind) {
                    return;
                }
                for r in leaf.roots(&q.ray).as_slice() {
                    if r.t > q.tmin && r.t < q.tmax {
                        out.push(Hit {
                            t: r.t,
                            leaf,
                            part: r.part,
                        });
                    }
                }
            }
            Object::Csg(csg) if csg.kind == CsgKind::Union => {
                for child in &csg.children {
                    child.all_hits(q, out);
                }
            }
            Object::Csg(csg) => {
                let mut spans = ChildSpans::new();
                if csg.meet(&mut spans, q).is_none() {
                    return;
                }
                spans.complete(&csg.children, q);
                for (i, child) in csg.children.iter().enumerate() {
                    if !csg.may_keep(i) {
                        break;
                    }
                    if let (Object::Leaf(leaf), Some(span)) = (child, spans.span(i)) {
                        if leaf.visibility.sees(q.kind) {
                            for r in [span.enter, span.exit] {
                                if r.t > q.tmin && r.t < q.tmax && csg.keeps(&spans, i, r.t, &q.ray)
                                {
                                    out.push(Hit {
                                        t: r.t,
                                        leaf,
                                        part: r.part,
                                    });
                                }
                            }
                        }
                        continue;
                    }
                    let start = out.len();
                    child.all_hits(q, out);
                    let mut kept = start;
                    for k in start..out.len() {
                        let hit = out[k];
                        if csg.keeps(&spans, i, hit.t, &q.ray) {
                            out[kept] = hit;
                            kept += 1;
                        }
                    }
                    out.truncate(kept);
                }
            }
        }
    }
}

impl Csg {
    /// [`Object::nearest`] of a clip by uninverted spheres, boxes and planes
    /// ([`Csg::convex_clip`]): the clipped object's nearest crossing strictly inside every
    /// clipping stretch, the one the general search keeps as the meeting's sole other
    /// child, without its record of each child's stretch, its entry and its loop over the
    /// children. Out of line, with a frame smaller than the general search's.
    #[inline(never)]
    pub fn nearest_clipped<'a>(&'a self, q: &Query, scratch: &mut Vec<Hit<'a>>) -> Option<Hit<'a>> {
        let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
        // The hull first, so that a ray passing it by costs no other test, then the box
        // (which a ray crossing the hull mostly crosses too) and the other clipping leaves.
        let hull = self.hull.unwrap_or(0);
        if hull > 0 {
            narrow_to_stretch(&self.children[hull], q, &mut lo, &mut hi)?;
        }
        if self.box_culls && self.bounds.is_finite() {
            q_clip(self.bounds, q)?;
        }
        for (i, clip) in self.children.iter().enumerate().skip(1) {
            if i != hull {
                narrow_to_stretch(clip, q, &mut lo, &mut hi)?;
            }
        }
        let (tmin, tmax) = (fast_math::max(q.tmin, lo), fast_math::min(q.tmax, hi));
        match &self.children[0] {
            Object::Leaf(leaf) => leaf.nearest_in(q, tmin, tmax),
            csg => csg.nearest(&Query { tmin, tmax, ..*q }, scratch),
        }
    }

    /// Whether crossings of child `from` and those after it can be on this CSG's surface:
    /// not those of the objects that clip another.
    fn may_keep(&self, from: usize) -> bool {
        self.kind != CsgKind::Clip || from == 0
    }

    /// For an intersection or a clip, the stretches of its uninverted leaves along the
    /// query's ray and where they meet; `None` when the ray meets no surface of the node
    /// within the query's interval. `Some(None)` for a merge, which has no such meeting.
    #[inline]
    fn meet(&self, spans: &mut ChildSpans, q: &Query) -> Option<Option<Meeting>> {
        match self.kind {
            CsgKind::Intersection | CsgKind::Clip => {
                spans.meet(&self.children, q, self.hull).map(Some)
            }
            CsgKind::Union | CsgKind::Merge => Some(None),
        }
    }

    /// The crossing where the ray enters the meeting of an intersection's uninverted
    /// convex children, when it is kept (it lies outside the holes and inside the other
    /// children there): the nearest crossing then, since every crossing the intersection
    /// keeps lies in the meeting. The other children are tested at that one point, so that
    /// a ray meeting a face of a drilled cube away from the drills finds none of their
    /// crossings.
    fn entry_hit<'a>(
        &'a self,
        spans: &ChildSpans,
        meeting: &Meeting,
        q: &Query,
    ) -> Option<Hit<'a>> {
        let (i, root) = meeting.entry?;
        let Object::Leaf(leaf) = &self.children[i] else {
            return None;
        };
        let seen = root.t > q.tmin
            && root.t < q.tmax
            && root.t < meeting.hi
            && self.may_keep(i)
            && leaf.visibility.sees(q.kind);
        (seen && self.keeps(spans, i, root.t, &q.ray)).then_some(Hit {
            t: root.t,
            leaf,
            part: root.part,
        })
    }

    /// Whether a crossing of child `from` at parameter `t` of the ray is on this CSG's
    /// surface.
    #[inline]
    fn keeps(&self, spans: &ChildSpans, from: usize, t: f64, ray: &Ray) -> bool {
        // Whether the crossing must lie inside the other children or outside them all.
        let inside = match self.kind {
            CsgKind::Union => return true,
            CsgKind::Merge => false,
            CsgKind::Intersection => true,
            CsgKind::Clip if from == 0 => true,
            CsgKind::Clip => return false,
        };
        (0..self.children.len())
            .all(|j| j == from || spans.inside(&self.children, j, t, ray) == inside)
    }
}

/// Narrows `[lo, hi]` to the stretch of the query's ray inside `clip`, an uninverted sphere,
/// box or plane (see [`Csg::convex_clip`]); `None` once no point of the query's interval is
/// left in it, as [`ChildSpans::meet`] decides.
#[inline(always)]
fn narrow_to_stretch(clip: &Object, q: &Query, lo: &mut f64, hi: &mut f64) -> Option<()> {
    // Always a leaf with a stretch, empty when the ray passes it by.
    let Object::Leaf(leaf) = clip else {
        return Some(());
    };
    let (enter, exit) = match &leaf.shape {
        // A sphere, the usual clip, is asked here: the general stretch is a call and comes
        // back through memory. A ray passing it by meets nothing of the clip.
        Shape::Sphere(sphere) => sphere.span(&leaf.local_ray(&q.ray))?,
        _ => {
            let span = leaf.span(&q.ray)?;
            (span.enter.t, span.exit.t)
        }
    };
    if enter > *lo {
        *lo = enter;
    }
    if exit < *hi {
        *hi = exit;
    }
    (!(*lo > *hi || *lo >= q.tmax || *hi <= q.tmin)).then_some(())
}

fn q_clip(bounds: Aabb, q: &Query) -> Option<(f64, f64)> {
    bounds.clip(&q.ray, q.inv_dir, q.tmin, q.tmax)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_difference_of_an_intersection_and_a_union_is_one_intersection() {
        let world = crate::build::world_of_source(
            "difference {
               intersection { box { -1, 1 } sphere { 0, 1.3 } }
               union { cylinder { -2*x, 2*x, 0.4 } cylinder { -2*y, 2*y, 0.4 } }
             }",
        );
        let Some(Object::Csg(csg)) = world.bvh.objects().next() else {
            panic!("the difference is one CSG object");
        };
        assert_eq!(csg.kind, CsgKind::Intersection);
        assert_eq!(csg.children.len(), 4);
        assert!(csg.children.iter().all(|c| matches!(c, Object::Leaf(_))));
        // The bored cube: a ray along z meets the box's face; one along the bore through
        // the x axis passes without meeting anything.
        let nearest = |origin: DVec3, direction: DVec3| {
            let q = Query::new(
                Ray::new(origin, direction),
                RayKind::Primary,
                1e-9,
                f64::INFINITY,
            );
            world.bvh.nearest(&q, &mut Vec::new()).map(|hit| hit.t)
        };
        assert_eq!(nearest(DVec3::new(0.5, 0.6, -5.0), DVec3::Z), Some(4.0));
        let bore = nearest(DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
        assert!(bore.is_none());
    }

    /// A tilted cylinder cut by two planes is bounded although each of its parts is
    /// unbounded, and its box holds the piece: its rim's farthest points.
    #[test]
    fn a_clipped_cylinder_is_bounded() {
        let world = crate::build::world_of_source(
            "quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -0.25
               clipped_by { plane { y, 1.2 } plane { -y, 1 } }
               rotate z*30 translate <3, 0, 2> }",
        );
        assert!(!world.bvh.has_unbounded());
        let b = world.bvh.bounds();
        let tilt = DAffine3::from_translation(DVec3::new(3.0, 0.0, 2.0))
            * DAffine3::from_rotation_z(30f64.to_radians());
        for (y, x) in [(1.2, -0.5), (1.2, 0.5), (-1.0, -0.5), (-1.0, 0.5)] {
            let p = tilt.transform_point3(DVec3::new(x, y, 0.0));
            assert!(p.cmpge(b.min).all() && p.cmple(b.max).all(), "{p} {b:?}");
        }
        let end = tilt.transform_point3(DVec3::new(-0.5, 1.2, 0.0));
        assert!((b.min.x - end.x).abs() < 1e-6, "{b:?}");
    }

    /// A box clipped by a sphere inside it shows the box's faces where the sphere holds
    /// them; rays through the box's corners, which pass by the sphere, and rays whose
    /// interval ends before it meet nothing.
    #[test]
    fn a_clipping_sphere_bounds_what_it_clips() {
        let world = crate::build::world_of_source(
            "box { -1, 1 clipped_by { sphere { 0, 1.2 } } }
             intersection { sphere { <5, 0, 0>, 1 } box { <4, -0.5, -2>, <6, 0.5, 2> } }",
        );
        let nearest = |origin: DVec3, tmax: f64| {
            let q = Query::new(Ray::new(origin, DVec3::Z), RayKind::Primary, 1e-9, tmax);
            world.bvh.nearest(&q, &mut Vec::new()).map(|hit| hit.t)
        };
        assert_eq!(
            nearest(DVec3::new(0.2, 0.3, -5.0), f64::INFINITY),
            Some(4.0)
        );
        assert_eq!(nearest(DVec3::new(0.95, 0.95, -5.0), f64::INFINITY), None);
        assert_eq!(nearest(DVec3::new(0.2, 0.3, -5.0), 3.0), None);
        let intersection = nearest(DVec3::new(5.0, 0.2, -5.0), f64::INFINITY).unwrap();
        assert!((intersection - (5.0 - 0.96f64.sqrt())).abs() < 1e-12);
        assert_eq!(nearest(DVec3::new(5.0, 0.7, -5.0), f64::INFINITY), None);
    }

    #[test]
    fn a_clipped_object_is_seen_by_the_rays_it_is_seen_by() {
        let world = crate::build::world_of_source(
            "box { -1, 1 clipped_by { sphere { 0, 1.2 } } no_shadow }",
        );
        let Some(clip) = world.bvh.objects().next() else {
            panic!("one object");
        };
        assert_eq!(clip.kinds() & RayKind::Shadow.bit(), 0);
        assert_ne!(clip.kinds() & RayKind::Primary.bit(), 0);
    }

    /// A sphere among an intersection's children bounds it, and so does a box turned
    /// off the axes; an upright box holding the node's bounds adds nothing to them, so
    /// the next candidate is taken, or none.
    #[test]
    fn only_hulls_that_cull_more_than_the_bounds_are_kept() {
        let hull = |source: &str| {
            let world = crate::build::world_of_source(source);
            match world.bvh.objects().next() {
                Some(Object::Csg(csg)) => csg.hull,
                _ => panic!("not a CSG node"),
            }
        };
        assert_eq!(
            hull("intersection { box { -1, 1 } sphere { 0, 1.32 } }"),
            Some(1)
        );
        assert_eq!(
            hull("intersection { box { -1, 1 rotate 30*y } sphere { 0, 1.32 } }"),
            Some(0)
        );
        assert_eq!(
            hull("intersection { box { -1, 1 } cylinder { -y, y, 1.2 } }"),
            None
        );
    }

    /// A clip by uninverted spheres, boxes and planes of an object that is none of them
    /// takes the clip's own search, which tests no box when the clipping sphere's box is
    /// the node's.
    #[test]
    fn clips_by_convex_leaves_are_searched_by_their_stretches() {
        let clip = |source: &str| {
            let world = crate::build::world_of_source(source);
            match world.bvh.objects().next() {
                Some(Object::Csg(csg)) => (csg.convex_clip, csg.box_culls),
                _ => panic!("not a CSG node"),
            }
        };
        assert_eq!(
            clip("torus { 1, 0.5 clipped_by { sphere { x, 0.45 } } }"),
            (true, false)
        );
        assert_eq!(
            clip("torus { 1, 0.5 clipped_by { sphere { x, 0.8 } plane { y, 0 } } }"),
            (true, true)
        );
        assert!(!clip("box { -1, 1 clipped_by { sphere { 0, 1.2 } } }").0);
        assert!(!clip("torus { 1, 0.5 clipped_by { plane { y, 0 inverse } } }").0);
        assert!(!clip("torus { 1, 0.5 clipped_by { cylinder { -y, y, 1 } } }").0);
    }

    /// Every crossing of the object's surface along the ray, found the plain way: each
    /// leaf's crossings, kept where point tests put them inside (or, for a merge, outside)
    /// the other children.
    fn crossings_by_point_tests(object: &Object, ray: &Ray) -> Vec<f64> {
        match object {
            Object::Leaf(leaf) => leaf.roots(ray).as_slice().iter().map(|r| r.t).collect(),
            Object::Csg(csg) => {
                let mut kept = Vec::new();
                for (i, child) in csg.children.iter().enumerate() {
                    if csg.kind == CsgKind::Clip && i > 0 {
                        break;
                    }
                    for t in crossings_by_point_tests(child, ray) {
                        let p = ray.at(t);
                        let mut others = (0..csg.children.len())
                            .filter(|&j| j != i)
                            .map(|j| &csg.children[j]);
                        let keep = match csg.kind {
                            CsgKind::Union => true,
                            CsgKind::Merge => others.all(|o| !o.inside(p)),
                            CsgKind::Intersection | CsgKind::Clip => others.all(|o| o.inside(p)),
                        };
                        if keep {
                            kept.push(t);
                        }
                    }
                }
                kept
            }
        }
    }

    /// The nearest crossing found from the children's stretches is the one point tests
    /// keep, for differences, intersections with planes, merges, clips by convex and other
    /// shapes, and nested nodes, along rays from outside and from inside the objects.
    #[test]
    fn stretches_find_the_crossings_point_tests_keep() {
        let scenes = [
            "difference {
               intersection { box { -1, 1 } sphere { 0, 1.32 } }
               union { cylinder { -1.2*x, 1.2*x, 0.42 } cylinder { -1.2*y, 1.2*y, 0.42 }
                       cylinder { -1.2*z, 1.2*z, 0.42 } }
             }",
            "intersection { sphere { 0, 1 } plane { y, 0.2 } plane { -x, 0.3 } }",
            "merge { sphere { 0, 1 } box { <0, -0.5, -0.5>, <1.5, 0.5, 0.5> }
                     cone { -y, 0.6, 1.5*y, 0.1 } }",
            "torus { 1, 0.3 clipped_by { box { <-2, -1, -2>, <0.5, 1, 2> } } }",
            "box { -1, 1 clipped_by { sphere { 0, 1.2 } plane { z, 0.4 inverse } } }",
            "intersection { torus { 1, 0.4 } sphere { <1, 0, 0>, 0.6 } rotate 20*x }",
            "difference { sphere { 0, 1 } merge { box { -0.3, 2 } sphere { -x, 0.5 } }
                          cylinder { -2*z, 2*z, 0.2 open } }",
            "torus { 1, 0.5 clipped_by { sphere { x, 0.45 } } rotate 20*x }",
            "torus { 1, 0.4 clipped_by { sphere { <0.6, 0, 0>, 0.9 } plane { y, 0.25 }
                                         box { -2, <2, 2, 0.5> } } }",
        ];
        let mut compared = 0;
        for source in scenes {
            let world = crate::build::world_of_source(source);
            let object = world.bvh.objects().next().expect("one object");
            for k in 0..400 {
                let a = k as f64 * 0.61;
                let origin = if k % 5 == 0 {
                    DVec3::new(0.1 * a.sin(), 0.05, 0.1 * a.cos())
                } else {
                    DVec3::new(3.0 * a.cos(), 1.5 * (a * 0.7).sin(), -3.0 * a.sin())
                };
                let target =
                    DVec3::new(0.6 * (a * 1.3).sin(), 0.5 * (a * 2.1).cos(), 0.4 * a.cos());
                let ray = Ray::new(origin, target - origin);
                let mut expected: Vec<f64> = crossings_by_point_tests(object, &ray)
                    .into_iter()
                    .filter(|&t| t > 1e-6)
                    .collect();
                expected.sort_by(f64::total_cmp);
                // A crossing a hair from another surface may be kept either way.
                let all: Vec<f64> = object_roots(object, &ray);
                if expected
                    .first()
                    .is_some_and(|&t| all.iter().any(|&u| u != t && (u - t).abs() < 1e-7))
                {
                    continue;
                }
                let q = Query::new(ray, RayKind::Primary, 1e-6, f64::INFINITY);
                let found = object.nearest(&q, &mut Vec::new()).map(|hit| hit.t);
                assert_eq!(found, expected.first().copied(), "{source} ray {k}");
                if let Object::Csg(csg) = object
                    && csg.convex_clip
                {
                    let clipped = csg.nearest_clipped(&q, &mut Vec::new()).map(|hit| hit.t);
                    assert_eq!(clipped, found, "{source} ray {k}");
                }
                let mut hits = Vec::new();
                object.all_hits(&q, &mut hits);
                let mut all_hits: Vec<f64> = hits.iter().map(|hit| hit.t).collect();
                all_hits.sort_by(f64::total_cmp);
                assert_eq!(all_hits, expected, "{source} ray {k}");
                compared += usize::from(found.is_some());
            }
        }
        assert!(compared > 1000, "rays meet the objects: {compared}");
    }

    /// Every crossing of every leaf of the object along the ray.
    fn object_roots(object: &Object, ray: &Ray) -> Vec<f64> {
        match object {
            Object::Leaf(leaf) => leaf.roots(ray).as_slice().iter().map(|r| r.t).collect(),
            Object::Csg(csg) => csg
                .children
                .iter()
                .flat_map(|c| object_roots(c, ray))
                .collect(),
        }
    }

    /// Scenes hold up to a hundred thousand objects and more; an object stays a few
    /// cache lines.
    #[test]
    fn objects_stay_small() {
        assert!(
            std::mem::size_of::<Object>() <= 300,
            "{}",
            std::mem::size_of::<Object>()
        );
    }
}
