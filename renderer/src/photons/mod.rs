//! Photon mapping (POV-Ray 3.7's `photons`): caustics drawn by light that reflective and
//! refractive targets send on. Before tracing, lights shoot photons at the targets'
//! bounds (`shoot`); the photons that land on collecting surfaces after a reflection or
//! refraction go into a kd-tree (`kdtree`); while tracing, each collecting surface point
//! gathers its nearest photons (`gather`) and takes them as light arriving from the way
//! they came, through the same lighting model as a light source.
//!
//! Direct light through a refracting target is left to the photons: shadow rays towards a
//! light that shoots refraction photons stop at such targets, as in POV-Ray, so that the
//! light beyond them is the caustic and not the caustic on top of the straight light.
//!
//! With `media` in the block, photons that cross scattering media after a reflection or
//! refraction also leave photons there, which media samples gather (`in_media`).
//!
//! The pass runs only for scenes with a `photons` block in `global_settings`, at quality 6
//! and above, and only when some light shoots at some target.

mod gather;
mod grid;
mod in_media;
mod kdtree;
mod shoot;

use crate::bounds::Aabb;
use crate::build::BuildError;
use crate::fast_math;
use crate::object::Object;
use crate::tracer::World;
use analysis::scene::{
    self, LightPhotons, ObjectPhotons, PhotonDensity, Photons, photons_interact,
};
pub use gather::GatherScratch;
use gather::{Estimate, Gather};
use glam::{DVec3, Vec3};
use grid::CandidateGrid;
use in_media::Deposit;
pub use in_media::{MediaMap, collecting, media_within};
use kdtree::KdTree;
use shoot::Shooting;

/// What a surface does with photons, from its object's photons block: one bit each, so
/// that a leaf stays small in scenes of a hundred thousand objects. Refraction and
/// reflection take two bits each, for `on`, `off` and unsaid, which the light decides.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfacePhotons(u8);

const TARGET: u8 = 1;
const REFRACTION_ON: u8 = 2;
const REFLECTION_ON: u8 = 4;
const COLLECT: u8 = 8;
const PASS_THROUGH: u8 = 16;
const REFRACTION_OFF: u8 = 32;
const REFLECTION_OFF: u8 = 64;

impl Default for SurfacePhotons {
    fn default() -> Self {
        SurfacePhotons::from_scene(&ObjectPhotons::default(), false)
    }
}

impl SurfacePhotons {
    /// `no_shadow` objects let photons pass unless their block says otherwise.
    pub fn from_scene(photons: &ObjectPhotons, no_shadow: bool) -> SurfacePhotons {
        let bit = |on: bool, bit: u8| if on { bit } else { 0 };
        let said = |value: Option<bool>, on: u8, off: u8| match value {
            Some(true) => on,
            Some(false) => off,
            None => 0,
        };
        SurfacePhotons(
            bit(photons.target.is_some(), TARGET)
                | said(photons.refraction, REFRACTION_ON, REFRACTION_OFF)
                | said(photons.reflection, REFLECTION_ON, REFLECTION_OFF)
                | bit(photons.collect, COLLECT)
                | bit(photons.pass_through.unwrap_or(no_shadow), PASS_THROUGH),
        )
    }

    fn said(self, on: u8, off: u8) -> Option<bool> {
        if self.0 & on != 0 {
            Some(true)
        } else if self.0 & off != 0 {
            Some(false)
        } else {
            None
        }
    }

    /// Photons are aimed at the object.
    pub fn target(self) -> bool {
        self.0 & TARGET != 0
    }

    /// Photons from `light` go on through the surface.
    pub fn refracts(self, light: &LightPhotons) -> bool {
        photons_interact(self.said(REFRACTION_ON, REFRACTION_OFF), light.refraction)
    }

    /// Photons from `light` go on off the surface.
    pub fn reflects(self, light: &LightPhotons) -> bool {
        photons_interact(self.said(REFLECTION_ON, REFLECTION_OFF), light.reflection)
    }

    /// Photons that arrive after a reflection or refraction stay and light the surface.
    pub fn collect(self) -> bool {
        self.0 & COLLECT != 0
    }

    /// Photons on their way to a target pass through untouched.
    pub fn pass_through(self) -> bool {
        self.0 & PASS_THROUGH != 0
    }

    /// Whether this surface stops direct light from `light`: a target that refracts its
    /// photons, which bring that light instead.
    pub fn stops_light_for_photons(self, light: &LightPhotons) -> bool {
        self.target() && self.refracts(light)
    }
}

/// A bounding box photons are aimed at, with its spacing multiplier.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Target {
    pub bounds: Aabb,
    pub spacing_multiplier: f64,
}

/// Adds the targets of a top-level scene object, built as `built`: the object, or the
/// parts of a union with `split_union` on.
pub fn add_targets(
    object: &scene::Object,
    built: &Object,
    targets: &mut Vec<Target>,
) -> Result<(), BuildError> {
    let Some(multiplier) = object.photons.target else {
        return Ok(());
    };
    let split = matches!(
        (&object.shape, built),
        (scene::Shape::Csg { op: scene::CsgOp::Union, .. }, Object::Csg(csg))
            if object.photons.split_union && csg.kind == crate::object::CsgKind::Union
    );
    let parts: Vec<Aabb> = match built {
        Object::Csg(csg) if split => csg.children.iter().map(Object::bounds).collect(),
        _ => vec![built.bounds()],
    };
    for bounds in parts {
        if bounds.is_empty() {
            continue;
        }
        if !bounds.is_finite() {
            return Err(BuildError {
                message: "not supported yet: photons aimed at an unbounded object".into(),
                origin: object.origin.clone(),
            });
        }
        targets.push(Target {
            bounds,
            spacing_multiplier: multiplier,
        });
    }
    Ok(())
}

/// The most photons one render may shoot or store: enough for any caustic a picture
/// shows, and a clear error instead of exhausted memory for a spacing far too small.
const MAX_PHOTONS: u64 = 20_000_000;

/// The limit on photons, with where the scene set their density.
#[derive(Debug, Clone)]
pub struct PhotonBudget {
    max: u64,
}

impl PhotonBudget {
    fn check(&self, photons: u64) -> Result<(), String> {
        if photons > self.max {
            return Err(format!(
                "these photon settings shoot or store more than {} photons; raise the spacing or lower the count",
                self.max
            ));
        }
        Ok(())
    }
}

/// The stored photons and how to gather them.
#[derive(Debug, Clone)]
pub struct PhotonMap {
    tree: KdTree,
    /// The tree's photons listed by where they can be gathered, for most searches.
    grid: Option<CandidateGrid>,
    gather: Gather,
    /// The photons left in media, with `media` in the photons block.
    pub in_media: Option<MediaMap>,
}

impl PhotonMap {
    /// Shoots the scene's photons into `world`'s targets; `None` when no photon lands.
    pub fn shoot(
        world: &World,
        settings: &Photons,
        targets: &[Target],
    ) -> Result<Option<PhotonMap>, BuildError> {
        let fail = |message| BuildError {
            message,
            origin: settings.origin.clone(),
        };
        let shoots = world.lights.iter().any(|l| l.photons.shoots());
        if targets.is_empty() || !shoots {
            return Ok(None);
        }
        let mut shooting = Shooting {
            spacing: 1.0,
            jitter: settings.jitter,
            autostop: settings.autostop,
            max_trace_level: settings.max_trace_level.unwrap_or(world.max_trace_level),
            adc_bailout: settings.adc_bailout.unwrap_or(world.adc_bailout),
            media: None,
        };
        shooting.spacing = match settings.density {
            PhotonDensity::Spacing(spacing) => spacing,
            PhotonDensity::Count(count) => spacing_for(world, targets, &mut shooting, count),
        };
        shooting.media = settings.media.map(|m| Deposit {
            step: shooting.spacing * m.factor,
            max_steps: m.max_steps,
            jitter: settings.jitter,
        });
        let budget = PhotonBudget { max: MAX_PHOTONS };
        let (mut stored, mut in_media) = (Vec::new(), Vec::new());
        shoot::shoot_all(
            world,
            targets,
            &shooting,
            &budget,
            &mut stored,
            &mut in_media,
        )
        .map_err(fail)?;
        if stored.is_empty() && in_media.is_empty() {
            return Ok(None);
        }
        let gather = Gather::new(settings, shooting.spacing, stored.len());
        let in_media = (!in_media.is_empty()).then(|| {
            let radius = settings.media_radius.unwrap_or(f64::from(gather.radius));
            MediaMap::new(
                in_media,
                radius * settings.media_radius_multiplier,
                gather.max,
            )
        });
        let tree = KdTree::build(stored);
        Ok(Some(PhotonMap {
            grid: CandidateGrid::build(&tree, gather.max, gather.radius),
            tree,
            gather,
            in_media,
        }))
    }

    /// The photons lighting the point `p` of a surface whose normal `normal` faces the
    /// viewer, as at most two lights, one on each side of the surface: `(colour,
    /// direction towards where the photons came from)`. Each light is its photons' total
    /// power from their power-weighted mean direction, with the colour that gives a flat
    /// surface their density estimate once the lighting model's cosine has been applied:
    /// the photons' power spread over the gathered disc as it spread over the surface.
    /// That is exact for diffuse light on flat surfaces and costs one lighting evaluation
    /// instead of one per photon; the photons of a caustic arrive from nearly one
    /// direction, so highlights and bumps see little difference.
    pub fn lights_at(
        &self,
        p: DVec3,
        normal: DVec3,
        scratch: &mut GatherScratch,
        lights: &mut Vec<(DVec3, DVec3)>,
    ) {
        lights.clear();
        let Some(Estimate { area_radius2 }) =
            self.gather
                .gather(&self.tree, self.grid.as_ref(), p.as_vec3(), scratch)
        else {
            return;
        };
        let normal = normal.as_vec3();
        // Power and power-weighted direction from the front and from behind, each side's
        // sums apart rather than in an array indexed by the side, which the plugin would
        // keep in memory.
        let (mut front, mut behind) = ((Vec3::ZERO, Vec3::ZERO), (Vec3::ZERO, Vec3::ZERO));
        for &key in &scratch.photons {
            let photon = self.tree.photon(grid::index_of(key));
            let from = -photon.direction;
            let add = |(power, direction): &mut (Vec3, Vec3)| {
                *power += photon.power;
                *direction += from * photon.power.element_sum();
            };
            if from.dot(normal) < 0.0 {
                add(&mut behind);
            } else {
                add(&mut front);
            }
        }
        let area = std::f64::consts::PI * f64::from(area_radius2);
        for (power, direction) in [front, behind] {
            let Some(direction) = direction.try_normalize() else {
                continue;
            };
            // `fast_math::max`, the same value without a call into libm.
            let cos = fast_math::max(f64::from(direction.dot(normal).abs()), 0.1);
            lights.push((power.as_dvec3() / (area * cos), direction.as_dvec3()));
        }
    }
}

/// The spacing at which the spirals shoot about `count` photons, found from a trial at a
/// coarse spacing: the number shot goes as the inverse square of the spacing, autostop
/// and all.
fn spacing_for(world: &World, targets: &[Target], shooting: &mut Shooting, count: u32) -> f64 {
    // A trial of about two thousand photons per target.
    let trial = targets
        .iter()
        .map(|t| (t.bounds.max - t.bounds.min).length() * t.spacing_multiplier)
        .fold(0.0, f64::max)
        / 50.0;
    shooting.spacing = trial;
    let shot = shoot::count_shots(world, targets, shooting).max(1);
    trial * (shot as f64 / f64::from(count)).sqrt()
}

#[cfg(test)]
mod tests {
    use crate::build::{BuildError, BuildSettings, build_world};
    use crate::tracer::World;
    use analysis::{EvalOptions, MemoryFiles, evaluate};

    fn build(text: &str, quality: u8) -> Result<World, BuildError> {
        let files = MemoryFiles::new().with("scene.pov", format!("#version 3.7;\n{text}"));
        let scene = evaluate("scene.pov", &files, &EvalOptions::default())
            .scene
            .expect("the scene evaluates");
        let settings = BuildSettings {
            quality,
            output_alpha: false,
            max_trace_level: None,
        };
        build_world(&scene, settings)
    }

    /// A glass sphere over a floor, lit from above; `global` goes in `global_settings`.
    fn lens(global: &str, sphere: &str) -> String {
        format!(
            "global_settings {{ {global} }}
             light_source {{ <0, 10, 0> rgb 1 }}
             plane {{ y, -1 pigment {{ rgb 1 }} }}
             sphere {{ 0, 0.5 pigment {{ rgbf 1 }} interior {{ ior 1.5 }} {sphere} }}"
        )
    }

    #[test]
    fn no_photon_pass_without_photons_or_targets_or_at_low_quality() {
        let target = "photons { target refraction on }";
        let world = build(&lens("", target), 9).unwrap();
        assert!(world.photons.is_none());
        let world = build(&lens("photons { spacing 0.05 }", ""), 9).unwrap();
        assert!(world.photons.is_none());
        let world = build(&lens("photons { spacing 0.05 }", target), 5).unwrap();
        assert!(world.photons.is_none());
        let world = build(&lens("photons { spacing 0.05 }", target), 9).unwrap();
        assert!(world.photons.is_some());
    }

    /// What POV-Ray 3.7's photon counts show: an `off` on the object or the light stops
    /// refraction, an `on` on either side allows it, and nothing said means none.
    #[test]
    fn object_and_light_settings_decide_together() {
        let refracts = |light: &str, object: &str| {
            let scene = lens(
                "photons { spacing 0.05 }",
                &format!("photons {{ target {object} }}"),
            )
            .replace(
                "<0, 10, 0> rgb 1",
                &format!("<0, 10, 0> rgb 1 photons {{ {light} }}"),
            );
            build(&scene, 9).unwrap().photons.is_some()
        };
        assert!(!refracts("", ""));
        assert!(refracts("", "refraction on"));
        assert!(refracts("refraction on", ""));
        assert!(!refracts("refraction off", "refraction on"));
        assert!(!refracts("refraction on", "refraction off"));
    }

    #[test]
    fn the_map_is_the_same_on_every_build() {
        let scene = lens(
            "photons { spacing 0.05 jitter 1 }",
            "photons { target refraction on }",
        );
        let a = build(&scene, 9).unwrap().photons.unwrap();
        let b = build(&scene, 9).unwrap().photons.unwrap();
        assert_eq!(format!("{:?}", a.tree), format!("{:?}", b.tree));
    }

    /// The caustic's light under the lens: the photons' colour gathered on the floor below.
    fn caustic_colour(interior: &str) -> glam::DVec3 {
        let scene = lens(
            "photons { spacing 0.02 }",
            &format!("hollow interior {{ ior 1.5 {interior} }} photons {{ target refraction on }}"),
        );
        let world = build(&scene, 9).unwrap();
        let map = world.photons.as_ref().unwrap();
        let (mut scratch, mut lights) = (super::GatherScratch::default(), Vec::new());
        map.lights_at(-glam::DVec3::Y, glam::DVec3::Y, &mut scratch, &mut lights);
        lights.iter().map(|(colour, _)| *colour).sum()
    }

    #[test]
    fn media_dim_the_photons_that_cross_them() {
        let clear = caustic_colour("");
        let tinted = caustic_colour("media { absorption <0, 1, 2> }");
        assert!(clear.min_element() > 0.0, "{clear}");
        // Through about a diameter (1) of the medium: red untouched, green and blue
        // dimmed to about e^-1 and e^-2.
        let ratio = tinted / clear;
        assert!((ratio.x - 1.0).abs() < 0.02, "{ratio}");
        assert!(ratio.y > 0.25 && ratio.y < 0.5, "{ratio}");
        assert!(ratio.z > 0.08 && ratio.z < 0.2, "{ratio}");
    }

    #[test]
    fn what_is_not_drawn_is_a_located_error() {
        let plane = "global_settings { photons { spacing 0.1 } }
            light_source { <0, 10, 0> rgb 1 }
            plane { y, 0 pigment { rgb 1 } finish { reflection 1 } photons { target } }";
        let e = build(plane, 9).unwrap_err();
        assert_eq!(
            e.message,
            "not supported yet: photons aimed at an unbounded object"
        );
        assert!(e.origin.is_some());
        let groups = "global_settings { photons { spacing 0.1 } }
            light_group { light_source { <0, 10, 0> rgb 1 } sphere { 0, 1 } }";
        let e = build(groups, 9).unwrap_err();
        assert_eq!(
            e.message,
            "not supported yet: light groups in a scene with photons"
        );
        let tiny = lens("photons { spacing 0.00001 }", "photons { target }");
        let e = build(&tiny, 9).unwrap_err();
        assert!(
            e.message.contains("more than 20000000 photons"),
            "{}",
            e.message
        );
    }
}
