//! Builds the runtime world from a scene description: shapes in their canonical frames with
//! the object's transform folded in, materials shared between objects that share a texture,
//! CSG trees with their bounds, lights, and the bounding volume hierarchy.

use crate::atmosphere::{Atmosphere, Sky};
use crate::bvh::Bvh;
use crate::colour::Sample;
use crate::interior::Interior;
use crate::light::Light;
use crate::material::{Material, Surface};
use crate::object::{Csg, CsgKind, Leaf, Object, Visibility};
use crate::photons::{PhotonMap, SurfacePhotons, Target, add_targets};
use crate::radiosity::Radiosity;
use crate::ray::RayKind;
use crate::shapes::bicubic_patch;
use crate::shapes::mesh::{Hierarchy, MeshData};
use crate::shapes::{
    Cone, Cuboid, Cylinder, Disc, Mesh, Plane, Polygon, Shape, ShapeReport, Sphere, Torus,
    Triangle, build_math_shape,
};
use crate::subsurface;
use crate::tracer::{Quality, World};
use analysis::scene::mesh::MeshGeometry;
use analysis::scene::{self, CsgOp, Origin, Scene};
use glam::{DAffine3, DMat3, DVec3};
use std::collections::HashMap;
use std::sync::Arc;
use syntax::{Diagnostic, TextRange};

/// A scene feature the renderer cannot draw, with where the scene asked for it.
#[derive(Debug, Clone, PartialEq)]
pub struct BuildError {
    pub message: String,
    pub origin: Origin,
}

impl BuildError {
    /// The error as every front end reports it: at its place in the scene, or at the start
    /// of `main` when it has none (a global setting assembled from several places).
    pub fn diagnostic(self, main: &str) -> Diagnostic {
        match self.origin {
            Some(span) => Diagnostic::error(span.file, span.range, self.message),
            None => Diagnostic::error(main, TextRange::default(), self.message),
        }
    }
}

/// What the world depends on besides the scene.
#[derive(Debug, Clone, Copy)]
pub struct BuildSettings {
    pub quality: u8,
    /// With alpha output the background is transparent.
    pub output_alpha: bool,
    /// `Max_Trace_Level` from the options, which overrides the scene's.
    pub max_trace_level: Option<u32>,
}

pub fn build_world(scene: &Scene, settings: BuildSettings) -> Result<World, BuildError> {
    let (mut world, targets) = assemble(scene, settings)?;
    let photons = scene.settings.photons.as_ref();
    if let Some(settings) = photons.filter(|_| world.quality.photons) {
        world.photons = PhotonMap::shoot(&world, settings, &targets)?;
    }
    Ok(world)
}

/// What a render of `scene` at the default quality would stop on before it traces a ray: a
/// feature not drawn yet, a camera that gives no picture. Its world is built as for a
/// render, but no photon is shot: `povrayst check`, the language server and the Typst
/// plugin report these errors with the evaluator's.
pub fn check_scene(scene: &Scene) -> Result<(), BuildError> {
    camera_of(scene)?;
    let settings = BuildSettings {
        quality: 9,
        output_alpha: false,
        max_trace_level: None,
    };
    assemble(scene, settings).map(|_| ())
}

/// The scene's camera, or why it gives no picture, located at the camera statement.
pub(crate) fn camera_of(scene: &Scene) -> Result<crate::camera::Camera, BuildError> {
    crate::camera::Camera::from_scene(&scene.camera).map_err(|message| BuildError {
        message,
        origin: scene.camera.origin.clone(),
    })
}

/// The world of `scene` without its photon map, and the photon targets that map needs.
fn assemble(scene: &Scene, settings: BuildSettings) -> Result<(World, Vec<Target>), BuildError> {
    let mut builder = Builder {
        subsurface_refusal: subsurface_refusal(scene, settings.quality),
        materials: HashMap::new(),
        default_material: None,
        lights: Vec::new(),
        reports: Vec::new(),
        has_media: false,
        // POV-Ray computes media from quality 9 on.
        with_media: settings.quality >= 9,
        meshes: HashMap::new(),
        light_groups: Vec::new(),
        light_set: 0,
        outer_global_lights: None,
        light_shapes: Vec::new(),
    };
    for light in &scene.lights {
        builder.add_light(light)?;
    }
    let quality = Quality::from_level(settings.quality);
    let photons = scene.settings.photons.as_ref().filter(|_| quality.photons);
    let mut targets = Vec::new();
    let mut objects = Vec::with_capacity(scene.objects.len());
    for object in &scene.objects {
        if let Some(mut built) = builder.object(object, None, None, Visibility::default(), false)? {
            if let Object::Leaf(leaf) = &mut built {
                leaf.standalone = true;
            }
            if photons.is_some() {
                add_targets(object, &built, &mut targets)?;
            }
            objects.push(built);
        }
    }
    for mut shape in std::mem::take(&mut builder.light_shapes) {
        if let Object::Leaf(leaf) = &mut shape {
            leaf.standalone = true;
        }
        objects.push(shape);
    }
    let atmosphere =
        Atmosphere::from_scene(scene, builder.with_media).map_err(|message| BuildError {
            message,
            origin: None,
        })?;
    // Photons of a projected light would have to pass through its object first.
    if let Some(light) = scene
        .lights
        .iter()
        .find(|l| l.projected_through.is_some() && l.photons.shoots())
        && photons.is_some()
    {
        return Err(BuildError {
            message: "not supported yet: photons from a light with projected_through".into(),
            origin: light.origin.clone(),
        });
    }
    // Photons of a light group's lights would light objects outside the group.
    if let Some(group) = builder.light_groups.iter().find(|g| !g.lights.is_empty())
        && photons.is_some()
    {
        return Err(BuildError {
            message: "not supported yet: light groups in a scene with photons".into(),
            origin: group.origin.clone(),
        });
    }
    let camera_interiors = if builder.has_media || atmosphere.is_some() {
        camera_interiors(&objects, scene.camera.location)
    } else {
        Vec::new()
    };
    crate::open_sides::mark_open_sides(&mut objects);
    let bvh = Bvh::build(objects);
    // Scenes without `#version 3.7` keep POV-Ray 3.6's rules: with alpha output the
    // background is fully transparent black whatever its colour.
    let legacy = scene.version.is_none_or(|v| v < 3.7);
    // A scene without `background` has POV-Ray's default, black with transmit 1: black in
    // the picture, transparent in an alpha channel.
    let background_colour = scene.background.unwrap_or(scene::Colour {
        transmit: 1.0,
        ..scene::Colour::BLACK
    });
    let background = match (settings.output_alpha, legacy) {
        (false, _) => Sample::new(background_colour.rgb, 0.0),
        (true, true) => Sample::new(DVec3::ZERO, 1.0),
        (true, false) => {
            let c = background_colour;
            let opacity = 1.0 - c.filter - c.transmit;
            let through = c.rgb * c.filter + DVec3::splat(c.transmit);
            let grey = 0.297 * through.x + 0.589 * through.y + 0.114 * through.z;
            Sample::new(c.rgb * opacity, grey.abs().min(1.0))
        }
    };
    let scale = scene_scale(scene, &bvh);
    let sky = match &scene.sky_sphere {
        Some(s) => {
            let mut sky = Sky::from_scene(s).map_err(|message| BuildError {
                message,
                origin: None,
            })?;
            sky.reflections_only = settings.output_alpha && legacy;
            Some(sky)
        }
        None => None,
    };
    let light_sets = builder.light_sets();
    let participating = builder.has_media || atmosphere.is_some();
    let blockable = bvh.seen_by(RayKind::Shadow) || participating;
    let mut lights = builder.lights;
    for light in &mut lights {
        light.arrives_whole = light.arrives_whole_in(
            quality.shadows,
            quality.area_lights,
            blockable,
            atmosphere.is_some(),
        );
    }
    let world = World {
        bvh,
        lights,
        light_sets,
        background,
        reflected_background: background_colour.rgb,
        ambient_light: scene.settings.ambient_light.rgb,
        irid_wavelength: scene.settings.irid_wavelength,
        quality,
        max_trace_level: settings
            .max_trace_level
            .or(scene.settings.max_trace_level)
            .unwrap_or(5)
            .clamp(1, 256),
        adc_bailout: scene.settings.adc_bailout,
        legacy_opacity: legacy,
        scale,
        shape_reports: builder.reports,
        participating,
        sky,
        atmosphere,
        camera_interiors,
        radiosity: Radiosity::from_scene(scene, &quality),
        photons: None,
        subsurface: subsurface_settings(scene, settings.quality),
    };
    Ok((world, targets))
}

/// The shapes for which POV-Ray wraps uv-mapped textures around by surface coordinates of
/// their own (the manual's "Supported Objects"), which are not drawn yet: a uv-mapped
/// texture on them would land by the point's x and y instead, a wrong picture. Meshes and
/// bicubic patches have theirs; on the shapes the manual does not list, x and y are taken.
fn own_uv_coordinates(shape: &scene::Shape) -> Option<&'static str> {
    match shape {
        scene::Shape::Sphere { .. } => Some("sphere"),
        scene::Shape::Box { .. } => Some("box"),
        scene::Shape::Torus { .. } => Some("torus"),
        scene::Shape::Lathe(_) => Some("lathe"),
        scene::Shape::Sor(_) => Some("sor"),
        scene::Shape::Ovus { .. } => Some("ovus"),
        scene::Shape::Parametric(_) => Some("parametric"),
        _ => None,
    }
}

/// The interiors of the objects around the camera that media rays must start in: those
/// holding media and the solid ones, which keep all media and fog out.
fn camera_interiors(objects: &[Object], camera: DVec3) -> Vec<Arc<Interior>> {
    let mut found = Vec::new();
    for object in objects {
        interiors_around(object, camera, &mut found);
    }
    found.retain(|i| !i.media.is_empty() || !i.hollow);
    found
}

/// Adds the interiors of `object` that hold `point`, each once: a union's are those of
/// its parts around the point (abyss.pov's camera is in a hollow sphere of media united
/// with a solid submarine, and sees the media), any other object's the one its leaves
/// share.
fn interiors_around(object: &Object, point: DVec3, found: &mut Vec<Arc<Interior>>) {
    if !object.inside(point) {
        return;
    }
    if let Object::Csg(csg) = object
        && matches!(csg.kind, CsgKind::Union | CsgKind::Merge)
    {
        for child in &csg.children {
            interiors_around(child, point, found);
        }
        return;
    }
    if let Some(interior) = first_interior(object)
        && !found.iter().any(|f| Arc::ptr_eq(f, interior))
    {
        found.push(interior.clone());
    }
}

/// The interior an object's leaves share.
fn first_interior(object: &Object) -> Option<&Arc<Interior>> {
    match object {
        Object::Leaf(leaf) => Some(&leaf.interior),
        Object::Csg(csg) => csg.children.first().and_then(first_interior),
    }
}

/// A length typical of the scene: the camera's distance from the origin or the extent of
/// the bounded objects, whichever is larger.
fn scene_scale(scene: &Scene, bvh: &Bvh) -> f64 {
    let bounds = bvh.bounds();
    let extent = if bounds.is_finite() && !bounds.is_empty() {
        bounds.min.abs().max(bounds.max.abs()).max_element()
    } else {
        0.0
    };
    extent.max(scene.camera.location.abs().max_element())
}

/// A projection object as POV-Ray uses it: its shape alone, with its textures and
/// interiors stripped.
fn bare(object: &scene::Object) -> scene::Object {
    let mut object = object.clone();
    object.texture = None;
    object.interior = None;
    if let scene::Shape::Csg { children, .. } = &mut object.shape {
        for child in children {
            *child = bare(child);
        }
    }
    object
}

struct Builder {
    /// Why translucent finishes cannot be drawn in this scene, when subsurface light
    /// transport is on (`global_settings { subsurface { } }` at quality 9 and up) with a
    /// setting not drawn yet.
    subsurface_refusal: Option<String>,
    /// Materials by the address of the scene texture they came from, so that objects
    /// sharing a texture share one material.
    materials: HashMap<*const scene::Texture, Arc<Material>>,
    default_material: Option<Arc<Material>>,
    lights: Vec<Light>,
    reports: Vec<ShapeReport>,
    /// Whether some interior has media, so that rays must look for them.
    has_media: bool,
    with_media: bool,
    /// Mesh data by the scene geometry it came from and its hierarchy setting, so that
    /// copies of a mesh share their triangles and hierarchy.
    meshes: HashMap<(*const MeshGeometry, Hierarchy), Arc<MeshData>>,
    /// The light groups met so far: light set `i + 1` is group `i`'s.
    light_groups: Vec<LightGroupLights>,
    /// The light set of the objects being built.
    light_set: u32,
    /// Inside a light group, whether the outermost group lets the scene's lights in.
    outer_global_lights: Option<bool>,
    /// The lights' `looks_like` objects, placed in the world after the scene's objects.
    light_shapes: Vec<Object>,
}

/// The lights of one light group, and whether the scene's lights shine on its objects too.
struct LightGroupLights {
    lights: Vec<u32>,
    global_lights: bool,
    origin: Origin,
}

impl Builder {
    /// Adds a light to the world; returns its index.
    /// Its `looks_like` object joins the world as an object of its own, lit by the lights
    /// of the objects being built (a light inside a CSG shows it beside the CSG).
    fn add_light(&mut self, light: &scene::Light) -> Result<u32, BuildError> {
        let mut built = Light::from_scene(light).map_err(|message| BuildError {
            message,
            origin: light.origin.clone(),
        })?;
        if let Some(through) = &light.projected_through {
            let shape = self.object(&bare(through), None, None, Visibility::default(), false)?;
            match shape {
                Some(shape) => built.projected_through = Some(shape),
                // Through an object without a surface, no light passes.
                None => built.colour = DVec3::ZERO,
            }
        }
        if let Some(shape) = &light.looks_like {
            let shape = self.object(shape, None, None, Visibility::default(), false)?;
            self.light_shapes.extend(shape);
        }
        self.lights.push(built);
        Ok((self.lights.len() - 1) as u32)
    }

    /// The light sets of the world: the scene's lights (every light outside light
    /// groups), then each group's.
    fn light_sets(&self) -> Vec<Vec<u32>> {
        let mut grouped = vec![false; self.lights.len()];
        for group in &self.light_groups {
            for &i in &group.lights {
                grouped[i as usize] = true;
            }
        }
        let global: Vec<u32> = (0..self.lights.len() as u32)
            .filter(|&i| !grouped[i as usize])
            .collect();
        let mut sets = vec![global.clone()];
        for group in &self.light_groups {
            let mut set = group.lights.clone();
            if group.global_lights {
                set.extend_from_slice(&global);
            }
            sets.push(set);
        }
        sets
    }

    /// The runtime object of a light group: a union of its objects, which get the
    /// group's lights. As in POV-Ray's pictures, an object in nested light groups is lit
    /// by the innermost group's lights only, and by the scene's lights when the outermost
    /// group says `global_lights`.
    fn light_group(
        &mut self,
        group: &scene::LightGroup,
        origin: &Origin,
        texture: Option<&Arc<scene::Texture>>,
        interior: Option<&Arc<Interior>>,
        visibility: Visibility,
        double: bool,
    ) -> Result<Option<Object>, BuildError> {
        let mut lights = Vec::with_capacity(group.lights.len());
        for light in &group.lights {
            lights.push(self.add_light(light)?);
        }
        let global_lights = self.outer_global_lights.unwrap_or(group.global_lights);
        self.light_groups.push(LightGroupLights {
            lights,
            global_lights,
            origin: origin.clone(),
        });
        let outer = (self.light_set, self.outer_global_lights);
        self.light_set = self.light_groups.len() as u32;
        self.outer_global_lights = Some(global_lights);
        let mut built = Vec::with_capacity(group.objects.len());
        for child in &group.objects {
            built.extend(self.object(child, texture, interior, visibility, double)?);
        }
        (self.light_set, self.outer_global_lights) = outer;
        Ok(match built.len() {
            0 => None,
            1 => built.pop(),
            _ => Some(Object::Csg(Csg::new(CsgKind::Union, built))),
        })
    }

    /// The shared runtime data of a scene mesh.
    fn mesh_data(&mut self, mesh: &scene::mesh::Mesh) -> Arc<MeshData> {
        let hierarchy = if mesh.hierarchy {
            Hierarchy::On
        } else {
            Hierarchy::Off
        };
        let key = (Arc::as_ptr(&mesh.geometry), hierarchy);
        self.meshes
            .entry(key)
            .or_insert_with(|| {
                let g = &mesh.geometry;
                Arc::new(MeshData::new(
                    g.vertices.clone(),
                    g.normals.clone(),
                    g.uvs.clone(),
                    g.faces.clone(),
                    hierarchy,
                ))
            })
            .clone()
    }

    fn material(
        &mut self,
        texture: Option<&Arc<scene::Texture>>,
        origin: &Origin,
    ) -> Result<Arc<Material>, BuildError> {
        let fail = |message| BuildError {
            message,
            origin: origin.clone(),
        };
        let Some(texture) = texture else {
            if let Some(m) = &self.default_material {
                return Ok(m.clone());
            }
            let m = Arc::new(Material::from_scene(&scene::Texture::default()).map_err(fail)?);
            self.default_material = Some(m.clone());
            return Ok(m);
        };
        let key = Arc::as_ptr(texture);
        if let Some(m) = self.materials.get(&key) {
            return Ok(m.clone());
        }
        if let Some(refusal) = self
            .subsurface_refusal
            .as_ref()
            .filter(|_| translucent(texture))
        {
            return Err(fail(refusal.clone()));
        }
        let m = Arc::new(Material::from_scene(texture).map_err(fail)?);
        self.materials.insert(key, m.clone());
        Ok(m)
    }

    /// The runtime object for a scene object, or `None` when it has no surface at all
    /// (a sphere of radius 0, an empty CSG), with its `clipped_by` applied.
    fn object(
        &mut self,
        object: &scene::Object,
        inherited: Option<&Arc<scene::Texture>>,
        inherited_interior: Option<&Arc<Interior>>,
        inherited_visibility: Visibility,
        inherited_double: bool,
    ) -> Result<Option<Object>, BuildError> {
        let Some(built) = self.unclipped(
            object,
            inherited,
            inherited_interior,
            inherited_visibility,
            inherited_double,
        )?
        else {
            return Ok(None);
        };
        if object.clipped_by.is_empty() {
            return Ok(Some(built));
        }
        let mut children = vec![built];
        for clip in &object.clipped_by {
            // A clipping shape without a surface leaves nothing inside it.
            let Some(c) = self.unclipped(clip, inherited, None, Visibility::default(), false)?
            else {
                return Ok(None);
            };
            children.push(c);
        }
        Ok(Some(Object::Csg(Csg::new(CsgKind::Clip, children))))
    }

    /// The runtime object for a scene object without its `clipped_by`.
    fn unclipped(
        &mut self,
        object: &scene::Object,
        inherited: Option<&Arc<scene::Texture>>,
        inherited_interior: Option<&Arc<Interior>>,
        inherited_visibility: Visibility,
        inherited_double: bool,
    ) -> Result<Option<Object>, BuildError> {
        let fail = |message: String| BuildError {
            message,
            origin: object.origin.clone(),
        };
        let flags = object.flags;
        let visibility = Visibility {
            no_image: flags.no_image || inherited_visibility.no_image,
            no_reflection: flags.no_reflection || inherited_visibility.no_reflection,
            no_shadow: flags.no_shadow || inherited_visibility.no_shadow,
            no_radiosity: flags.no_radiosity || inherited_visibility.no_radiosity,
        };
        let texture = object.texture.as_ref().or(inherited);
        // Every object has an interior, its own or its CSG's; the leaves of one object
        // share it, so that a ray knows when it leaves what it entered.
        let hollow = flags
            .hollow
            .unwrap_or_else(|| inherited_interior.is_some_and(|i| i.hollow));
        let interior = match (&object.interior, inherited_interior) {
            (Some(own), _) => {
                let built = Interior::from_scene(own, hollow, self.with_media).map_err(fail)?;
                self.has_media |= !built.media.is_empty();
                Arc::new(built)
            }
            (None, Some(inherited)) => inherited.clone(),
            (None, None) => Arc::new(
                Interior::from_scene(&scene::Interior::default(), hollow, false).map_err(fail)?,
            ),
        };
        let (shape, frame) = match &object.shape {
            scene::Shape::LightGroup(group) => {
                let double = flags.double_illuminate || inherited_double;
                // Unlike a union, a light group passes on an interior only when it has one
                // of its own (or inherited one): POV-Ray's pictures keep its objects'
                // own `hollow`, and so the media inside them.
                let own = object.interior.is_some() || flags.hollow.is_some();
                let interior = if own {
                    Some(&interior)
                } else {
                    inherited_interior
                };
                return self.light_group(
                    group,
                    &object.origin,
                    texture,
                    interior,
                    visibility,
                    double,
                );
            }
            scene::Shape::Mesh(mesh) => (
                Shape::Mesh(Mesh {
                    data: self.mesh_data(mesh),
                    inside_vector: mesh.inside_vector,
                }),
                DAffine3::IDENTITY,
            ),
            scene::Shape::BicubicPatch(patch) => match bicubic_patch::tessellate(patch) {
                Some(data) => (
                    Shape::Mesh(Mesh {
                        data: Arc::new(data),
                        inside_vector: None,
                    }),
                    DAffine3::IDENTITY,
                ),
                None => return Ok(None),
            },
            scene::Shape::Polygon(polygon) => match Polygon::new(&polygon.outlines) {
                Some((shape, frame)) => (Shape::Polygon(shape), frame),
                None => return Ok(None),
            },
            scene::Shape::Csg {
                op,
                children,
                lights,
            } => {
                for light in lights {
                    self.add_light(light)?;
                }
                let mut built = Vec::with_capacity(children.len());
                for child in children {
                    let double = flags.double_illuminate || inherited_double;
                    if let Some(c) =
                        self.object(child, texture, Some(&interior), visibility, double)?
                    {
                        built.push(c);
                    } else if *op == CsgOp::Intersection {
                        // An empty child leaves an empty intersection.
                        return Ok(None);
                    } else if *op == CsgOp::Difference && built.is_empty() {
                        return Ok(None);
                    }
                }
                if built.is_empty() {
                    return Ok(None);
                }
                let kind = match op {
                    CsgOp::Union => CsgKind::Union,
                    CsgOp::Merge => CsgKind::Merge,
                    CsgOp::Intersection => CsgKind::Intersection,
                    CsgOp::Difference => {
                        // POV-Ray's difference: the first child within the inverse of
                        // the others.
                        let mut children = built.into_iter();
                        let first = children.next();
                        built = first
                            .into_iter()
                            .chain(children.map(Object::inverted))
                            .collect();
                        CsgKind::Intersection
                    }
                };
                let csg = Object::Csg(Csg::new(kind, built));
                return Ok(Some(if flags.inverse { csg.inverted() } else { csg }));
            }
            scene::Shape::Sphere { center, radius } => {
                let r = radius.abs();
                if r == 0.0 {
                    return Ok(None);
                }
                (
                    Shape::Sphere(Sphere),
                    DAffine3::from_scale_rotation_translation(
                        DVec3::splat(r),
                        glam::DQuat::IDENTITY,
                        *center,
                    ),
                )
            }
            scene::Shape::Box { corner1, corner2 } => (
                Shape::Cuboid(Cuboid::new(*corner1, *corner2)),
                DAffine3::IDENTITY,
            ),
            scene::Shape::Cylinder {
                base,
                cap,
                radius,
                open,
            } => {
                let frame = axis_frame(*base, *cap, radius.abs())
                    .ok_or_else(|| fail("degenerate cylinder: base and cap coincide".into()))?;
                (Shape::Cylinder(Cylinder { open: *open }), frame)
            }
            scene::Shape::Cone {
                base,
                base_radius,
                cap,
                cap_radius,
                open,
            } => {
                let frame = axis_frame(*base, *cap, 1.0)
                    .ok_or_else(|| fail("degenerate cone: base and cap coincide".into()))?;
                (
                    Shape::Cone(Cone {
                        base_radius: base_radius.abs(),
                        cap_radius: cap_radius.abs(),
                        open: *open,
                    }),
                    frame,
                )
            }
            scene::Shape::Plane { normal, distance } => {
                let n = normal.normalize_or_zero();
                if n == DVec3::ZERO {
                    return Err(fail("degenerate plane: the normal is zero".into()));
                }
                (Shape::Plane(Plane::new(n, *distance)), DAffine3::IDENTITY)
            }
            scene::Shape::Disc {
                center,
                normal,
                radius,
                hole_radius,
            } => {
                let frame = axis_frame(*center, *center + normal.normalize_or_zero(), 1.0)
                    .ok_or_else(|| fail("degenerate disc: the normal is zero".into()))?;
                (
                    Shape::Disc(Disc::new(radius.abs(), hole_radius.abs())),
                    frame,
                )
            }
            scene::Shape::Torus {
                major,
                minor,
                sturm,
            } => (
                Shape::Torus(Torus {
                    major: major.abs(),
                    minor: minor.abs(),
                    sturm: *sturm,
                    ball: None,
                }),
                DAffine3::IDENTITY,
            ),
            scene::Shape::Triangle { corners } => (
                Shape::Triangle(Triangle {
                    corners: *corners,
                    normals: None,
                }),
                DAffine3::IDENTITY,
            ),
            scene::Shape::SmoothTriangle { corners, normals } => (
                Shape::Triangle(Triangle {
                    corners: *corners,
                    normals: Some(Box::new(normals.map(|n| n.normalize_or_zero()))),
                }),
                DAffine3::IDENTITY,
            ),
            _ => match build_math_shape(object, &mut self.reports).map_err(fail)? {
                Some((shape, frame)) => (Shape::Math(Box::new(shape)), frame),
                None => return Ok(None),
            },
        };
        let mut material = self.material(texture, &object.origin)?;
        let to_world = object.transform.matrix * frame;
        if !to_world.is_finite() || to_world.matrix3.determinant() == 0.0 {
            return Err(fail("the object's transformation is singular".into()));
        }
        if let (scene::Shape::Blob(blob), Shape::Math(math)) = (&object.shape, &shape)
            && let crate::shapes::MathShape::Blob(runtime) = math.as_ref()
            && blob.components.iter().any(|c| c.texture.is_some())
        {
            // Each component shows its own texture (or the blob's) by its share of the field.
            let mut surfaces = vec![material.surface.clone()];
            for c in &blob.components {
                let m = self.material(c.texture.as_ref().or(texture), &object.origin)?;
                surfaces.push(m.surface.clone());
            }
            let surface = Surface::Blend {
                weights: runtime.texture_weights(to_world.inverse()),
                surfaces,
            };
            material = Arc::new(Material {
                transmits: surface.may_transmit(),
                uses_uv: surface.uses_uv(),
                uses_facing: surface.uses_facing(),
                surface,
            });
        }
        if material.uses_uv
            && let Some(name) = own_uv_coordinates(&object.shape)
        {
            return Err(fail(format!("not supported yet: uv_mapping on a {name}")));
        }
        let mut leaf = Leaf::new(
            shape,
            to_world,
            flags.inverse,
            material,
            interior,
            visibility,
        );
        leaf.double_illuminate = flags.double_illuminate || inherited_double;
        leaf.light_set = self.light_set;
        leaf.photons = SurfacePhotons::from_scene(&object.photons, visibility.no_shadow);
        if let scene::Shape::Mesh(mesh) = &object.shape
            && !mesh.textures.is_empty()
        {
            let materials = mesh
                .textures
                .iter()
                .map(|t| self.material(Some(t), &object.origin))
                .collect::<Result<Vec<_>, _>>()?;
            leaf.set_face_materials(materials);
        }
        leaf.importance = object.radiosity_importance.unwrap_or(1.0);
        Ok(Some(Object::Leaf(leaf)))
    }
}

/// Subsurface light transport as the tracer runs it: on only with `global_settings {
/// subsurface { } }` and at quality 9 or more, as in POV-Ray.
fn subsurface_settings(scene: &Scene, quality: u8) -> Option<subsurface::Settings> {
    let s = scene
        .settings
        .subsurface
        .as_ref()
        .filter(|_| quality >= 9)?;
    Some(subsurface::Settings {
        samples: s.samples.0,
        mm_per_unit: scene.settings.mm_per_unit,
    })
}

/// What keeps translucent finishes from being drawn when subsurface light transport is
/// on: indirect light scattering under the surface (`subsurface { radiosity on }`, or
/// radiosity gathers seeing it with `radiosity { subsurface on }`), or more probe rays per
/// point than the budget.
fn subsurface_refusal(scene: &Scene, quality: u8) -> Option<String> {
    let settings = subsurface_settings(scene, quality)?;
    let s = scene.settings.subsurface.as_ref()?;
    let radiosity = scene.settings.radiosity.as_ref();
    if radiosity.is_some_and(|r| r.subsurface) {
        return Some("not supported yet: radiosity { subsurface on }".into());
    }
    if radiosity.is_some() && s.radiosity {
        return Some("not supported yet: subsurface { radiosity on }".into());
    }
    if settings.samples > subsurface::MAX_SAMPLES {
        return Some(format!(
            "subsurface samples {} exceed the limit of {} probe rays per point",
            settings.samples,
            subsurface::MAX_SAMPLES
        ));
    }
    None
}

/// Whether a texture has a finish with subsurface `translucency`.
fn translucent(texture: &scene::Texture) -> bool {
    match texture {
        scene::Texture::Plain { finish, .. } => finish.translucency.is_some(),
        scene::Texture::Layered(layers) => layers.iter().any(translucent),
        scene::Texture::Pattern { map, .. } => map.entries.iter().any(|(_, t)| translucent(t)),
    }
}

/// The frame taking the z axis from 0 to 1 onto `base`..`cap`, with the x and y axes of
/// length `radius` across it.
fn axis_frame(base: DVec3, cap: DVec3, radius: f64) -> Option<DAffine3> {
    let axis = cap - base;
    let length = axis.length();
    if !(length > 0.0 && length.is_finite() && radius > 0.0) {
        return None;
    }
    let w = axis / length;
    let (u, v) = w.any_orthonormal_pair();
    Some(DAffine3::from_mat3_translation(
        DMat3::from_cols(u * radius, v * radius, axis),
        base,
    ))
}

/// The world of a `#version 3.7` scene written in SDL, at quality 9, for tests.
#[cfg(test)]
pub(crate) fn world_of_source(text: &str) -> World {
    scene_and_world_of_source(text).1
}

/// [`world_of_source`] with the scene it is built from.
#[cfg(test)]
pub(crate) fn scene_and_world_of_source(text: &str) -> (Scene, World) {
    use analysis::{EvalOptions, MemoryFiles, evaluate};
    let files = MemoryFiles::new().with("scene.pov", format!("#version 3.7;\n{text}"));
    let scene = evaluate("scene.pov", &files, &EvalOptions::default())
        .scene
        .expect("the scene evaluates");
    let settings = BuildSettings {
        quality: 9,
        output_alpha: false,
        max_trace_level: None,
    };
    let world = build_world(&scene, settings).expect("the world builds");
    (scene, world)
}

#[cfg(test)]
mod tests {
    use crate::RenderOptions;
    use crate::pipeline::{Failure, Rendered, render_source};
    use analysis::MemoryFiles;

    /// A 4 x 3 render of a 3.7 scene made of `items`.
    fn render_small(items: &str, output_alpha: bool) -> Result<Rendered, Failure> {
        let scene = format!("#version 3.7; global_settings {{ assumed_gamma 1 }}\n{items}\n");
        let files = MemoryFiles::new().with("scene.pov", scene);
        let options = RenderOptions {
            width: 4,
            height: 3,
            output_alpha,
            ..RenderOptions::default()
        };
        render_source("scene.pov", &files, &options)
    }

    /// The corner pixel of a 3.7 scene that has a camera and nothing else.
    fn corner(background: &str, output_alpha: bool) -> [f32; 4] {
        let scene = format!("camera {{ location -5*z look_at 0 }}\n{background}");
        render_small(&scene, output_alpha)
            .unwrap()
            .image
            .pixel(0, 0)
    }

    #[test]
    fn uv_mapping_on_a_shape_with_its_own_uv_coordinates_is_refused() {
        let refusal = |object: &str| {
            render_small(object, false)
                .err()
                .map(|failure| failure.diagnostics[0].message.clone())
        };
        let checker = "texture { uv_mapping pigment { checker } }";
        assert_eq!(
            refusal(&format!("sphere {{ 0, 1 {checker} }}")).as_deref(),
            Some("not supported yet: uv_mapping on a sphere")
        );
        assert_eq!(
            refusal(&format!("box {{ -1, 1 {checker} }}")).as_deref(),
            Some("not supported yet: uv_mapping on a box")
        );
        // A plane has no surface coordinates in the manual: x and y, as without uv_mapping.
        assert_eq!(refusal(&format!("plane {{ y, 0 {checker} }}")), None);
    }

    fn assert_near(found: [f32; 4], expected: [f32; 4]) {
        let close = found
            .iter()
            .zip(expected)
            .all(|(f, e)| (f - e).abs() < 1e-6);
        assert!(close, "{found:?} is not {expected:?}");
    }

    #[test]
    fn the_default_background_is_transparent_black() {
        assert_near(corner("", true), [0.0, 0.0, 0.0, 0.0]);
        assert_near(corner("", false), [0.0, 0.0, 0.0, 1.0]);
        assert_near(corner("background { rgb 1 }", true), [1.0, 1.0, 1.0, 1.0]);
    }

    /// Subsurface light transport is drawn where `global_settings { subsurface { } }` asks
    /// for it; what it cannot draw yet (indirect light scattering under the surface) and
    /// probe counts past the budget are refused, with where a finish asked for it.
    #[test]
    fn subsurface_refuses_only_what_it_cannot_draw() {
        let render = |global: &str| {
            let text = format!(
                "#version 3.7; global_settings {{ {global} }}
                 light_source {{ <2, 3, -4> rgb 1 }}
                 camera {{ location -3 * z look_at 0 }}
                 sphere {{ 0, 1 finish {{ subsurface {{ translucency 0.5 }} }} }}"
            );
            let files = MemoryFiles::new().with("scene.pov", text);
            let options = RenderOptions {
                width: 8,
                height: 6,
                ..RenderOptions::default()
            };
            render_source("scene.pov", &files, &options)
        };
        assert!(render("").is_ok());
        assert!(render("subsurface { }").is_ok());
        assert!(render("subsurface { radiosity on }").is_ok());
        for (global, message) in [
            (
                "radiosity { } subsurface { radiosity on }",
                "not supported yet: subsurface { radiosity on }",
            ),
            (
                "radiosity { subsurface on } subsurface { }",
                "not supported yet: radiosity { subsurface on }",
            ),
            (
                "subsurface { samples 5000, 1 }",
                "subsurface samples 5000 exceed the limit of 4096 probe rays per point",
            ),
        ] {
            let failure = render(global).unwrap_err();
            let errors: Vec<_> = failure
                .diagnostics
                .iter()
                .filter(|d| d.is_error())
                .collect();
            assert_eq!(errors.len(), 1, "{global}");
            assert_eq!(errors[0].message, message);
            // At the sphere that asks for it.
            assert!(!errors[0].span.range.is_empty());
        }
    }
}
