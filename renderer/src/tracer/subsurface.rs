//! The diffuse light a translucent surface point gives off from under its surface: the
//! light sources' irradiance at the points of the same object around it, spread by the
//! dipole profile of `crate::subsurface`.
//!
//! The points are found as in King, Kulla, Conty and Fajardo, "BSSRDF Importance Sampling"
//! (SIGGRAPH 2013 talk): a radius drawn from the profile places a point on a disk through
//! the shaded point, and a probe ray through that point perpendicular to the disk collects
//! every crossing of the object's surface within the profile's reach. Half the probes run
//! along the normal, a quarter along each tangent, so that the sides and far faces of thin
//! parts are found as well as the surface around the point; each crossing is weighed by
//! the density with which any of the three ways finds it.
//!
//! Every number drawn follows from the shaded point and the probe's index, so that a
//! picture is the same whatever thread traces it.

use super::{Tracer, hash3};
use crate::material::Layer;
use crate::object::{Hit, Leaf, Query};
use crate::ray::{Ray, RayKind};
use crate::subsurface::Profile;
use glam::DVec3;
use std::f64::consts::TAU;

/// The most surface crossings one probe ray collects: a bound on the work a tangle of
/// surfaces may ask for.
const MAX_CROSSINGS: usize = 16;

/// The last profile built, with the pigment, translucency and index of refraction it was
/// built from: neighbouring points of one object usually share them.
#[derive(Debug, Clone, Default)]
pub(crate) struct ProfileCache {
    last: Option<(DVec3, DVec3, f64, Option<Profile>)>,
}

impl<'w> Tracer<'w> {
    /// The diffusion profile of a layer at a point of `leaf`, or `None` where the layer's
    /// light is not transported under the surface: without `global_settings { subsurface
    /// { } }`, without `translucency`, and in radiosity's gathering rays, which see
    /// translucent surfaces as plain diffuse ones (POV-Ray's `radiosity { subsurface off
    /// }`).
    pub(super) fn subsurface_profile(
        &mut self,
        layer: &Layer,
        pigment: DVec3,
        leaf: &Leaf,
    ) -> Option<Profile> {
        let settings = self.world.subsurface.as_ref()?;
        let translucency = layer.finish.translucency?;
        if self.in_radiosity_ray() {
            return None;
        }
        let ior = leaf.interior.ior;
        if let Some((p, t, i, profile)) = &self.profiles.last
            && *p == pigment
            && *t == translucency
            && *i == ior
        {
            return *profile;
        }
        let profile = Profile::new(pigment, translucency, ior, settings);
        self.profiles.last = Some((pigment, translucency, ior, profile));
        profile
    }

    /// The light leaving `p` (with `normal` facing the viewer) of `leaf` after travelling
    /// under the surface from where the lights reach the object, before the finish's
    /// `diffuse` scales it. Kept out of line: inlined into the shading of every hit, its
    /// set-up would be hoisted there and paid by surfaces without subsurface light.
    #[inline(never)]
    pub(super) fn subsurface_light(
        &mut self,
        profile: &Profile,
        leaf: &'w Leaf,
        p: DVec3,
        normal: DVec3,
    ) -> DVec3 {
        let Some(settings) = self.world.subsurface else {
            return DVec3::ZERO;
        };
        let (tangent, bitangent) = tangents(normal);
        let axes = [normal, tangent, bitangent];
        let reach = profile.reach;
        let seed = hash3(p, 0x55, 0x5);
        let mut crossings: Vec<Hit<'w>> = Vec::with_capacity(MAX_CROSSINGS);
        let mut total = DVec3::ZERO;
        for k in 0..settings.samples {
            // The probes go round four classes, two along the normal and one along each
            // tangent. Within a class, the radius's first number and the angle follow a
            // rotated two-dimensional low-discrepancy sequence (Roberts' R2) and the choice
            // of channel a rotated golden-ratio sequence, so that the probes spread evenly.
            let (class, m) = (k % 4, f64::from(k / 4));
            let axis = [0, 0, 1, 2][class as usize];
            let u = (unit(seed, 3 * class) + m * R2.0).fract();
            let v = (unit(seed, 3 * class + 1) + m * R2.1).fract();
            let pick = (unit(seed, 3 * class + 2) + m * GOLDEN).fract();
            let r = profile.sample_radius(pick, u, unit(seed, 16 + k));
            if r >= reach {
                continue;
            }
            let (a1, a2) = (axes[(axis + 1) % 3], axes[(axis + 2) % 3]);
            let (sin, cos) = analysis::trig::sin_cos(TAU * v);
            let half = (reach * reach - r * r).sqrt();
            let origin = p + r * (cos * a1 + sin * a2) + axes[axis] * half;
            self.probe(
                Ray::new(origin, -axes[axis]),
                2.0 * half,
                leaf,
                &mut crossings,
            );
            for hit in &crossings {
                let x = origin - axes[axis] * hit.t;
                let offset = x - p;
                let d2 = offset.length_squared();
                if d2 > reach * reach {
                    continue;
                }
                let n = hit.leaf.normal(x, hit.part);
                let density = 0.5 * on_disk(profile, offset, axes[0], n)
                    + 0.25 * on_disk(profile, offset, axes[1], n)
                    + 0.25 * on_disk(profile, offset, axes[2], n);
                if density <= 0.0 {
                    continue;
                }
                let irradiance = self.light_falling_on(hit.leaf, x, n);
                if irradiance != DVec3::ZERO {
                    total += profile.reflectance(d2) * irradiance / density;
                }
            }
        }
        total / f64::from(settings.samples.max(1))
    }

    /// The crossings of `ray` within `length` with the surface of the object `leaf`
    /// belongs to: the surfaces sharing its interior, as the leaves of one object do.
    fn probe(&mut self, ray: Ray, length: f64, leaf: &Leaf, out: &mut Vec<Hit<'w>>) {
        out.clear();
        let mut tmin = self.tolerance(ray.origin);
        while out.len() < MAX_CROSSINGS {
            let q = Query::new(ray, RayKind::Transmitted, tmin, length);
            let Some(hit) = self.world.bvh.nearest(&q, &mut self.scratch) else {
                break;
            };
            if std::ptr::eq(&*hit.leaf.interior, &*leaf.interior) {
                out.push(hit);
            }
            tmin = hit.t + self.tolerance(ray.at(hit.t));
        }
    }

    /// The light of the light sources falling on `x` of `leaf`, whose outward normal is
    /// `n`, through its shadows.
    fn light_falling_on(&mut self, leaf: &'w Leaf, x: DVec3, n: DVec3) -> DVec3 {
        let world = self.world;
        let mut total = DVec3::ZERO;
        for light in world.lights_for(leaf) {
            let Some(incoming) = light.incoming(x) else {
                continue;
            };
            let cos = n.dot(incoming.direction);
            if cos <= 0.0 {
                continue;
            }
            total += self.arriving(light, x, &incoming, leaf) * cos;
        }
        total
    }
}

/// The steps of Roberts' R2 sequence, the inverses of the plastic number and its square.
const R2: (f64, f64) = (0.754_877_666_246_692_8, 0.569_840_290_998_053_2);

/// The step of the golden-ratio sequence, the inverse of the golden ratio.
const GOLDEN: f64 = 0.618_033_988_749_894_9;

/// The density per unit area with which probes along `axis` find a surface point at
/// `offset` from the shaded point, whose normal is `n`: the density of its projection onto
/// the disk across `axis`, times the share of the surface the projection keeps.
fn on_disk(profile: &Profile, offset: DVec3, axis: DVec3, n: DVec3) -> f64 {
    let along = offset.dot(axis);
    let r2 = (offset.length_squared() - along * along).max(0.0);
    profile.area_density(r2) * n.dot(axis).abs()
}

/// Two unit vectors completing `n` to an orthonormal frame (Duff et al., "Building an
/// Orthonormal Basis, Revisited", 2017).
fn tangents(n: DVec3) -> (DVec3, DVec3) {
    let sign = 1f64.copysign(n.z);
    let a = -1.0 / (sign + n.z);
    let b = n.x * n.y * a;
    (
        DVec3::new(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x),
        DVec3::new(b, sign + n.y * n.y * a, -n.y),
    )
}

/// A number in 0..1 fixed by the seed and the index.
fn unit(seed: u64, index: u32) -> f64 {
    let mut h = seed ^ u64::from(index).wrapping_mul(0x9e37_79b9_7f4a_7c15);
    h = (h ^ (h >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    h = (h ^ (h >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    h ^= h >> 31;
    (h >> 11) as f64 / (1u64 << 53) as f64
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::build::world_of_source as world;

    /// The colour at the centre of a 40 × 30 picture of `text` under an orthographic camera
    /// looking along +z at the origin.
    fn centre(text: &str) -> DVec3 {
        let text = format!(
            "camera {{ orthographic location <0, 0, -10> look_at 0 right x up 0.75 * y }}\n{text}"
        );
        crate::tracer::centre(&world(&text), &text)
    }

    /// A large block, seen face on, of pigment 0.6 with subsurface `translucency` (absent
    /// when empty), lit by `light`; the global block turns subsurface transport on.
    fn block(global: &str, translucency: &str, light: &str) -> DVec3 {
        centre(&format!(
            "global_settings {{ {global} }}
             light_source {{ {light} rgb 1 }}
             box {{ <-20, -20, 0>, <20, 20, 0.1>
                    pigment {{ rgb 0.6 }}
                    finish {{ ambient 0 diffuse 1 {translucency} }}
                    interior {{ ior 1.5 }} }}"
        ))
    }

    #[test]
    fn a_large_flat_piece_looks_as_its_pigment_says() {
        // Lit from the front, the light spreads under the surface and comes out where it
        // went in, on the whole: the pigment is the reflectance of a large flat piece.
        let plain = block("", "", "<0, 0, -100>");
        let translucent = block(
            "subsurface { samples 200, 1 }",
            "subsurface { translucency 0.05 }",
            "<0, 0, -100>",
        );
        assert!(
            (plain - DVec3::splat(0.6)).abs().max_element() < 1e-3,
            "{plain}"
        );
        assert!(
            (translucent - plain).abs().max_element() < 0.03,
            "{translucent}"
        );
    }

    #[test]
    fn a_thin_slab_lit_from_behind_glows_only_with_subsurface_transport() {
        // The slab is one millimetre thick; with two millimetres of free path, much of the
        // light falling on its back comes out of its front: 0.525 by the profile integrated
        // over the back face (and 0.43 to 0.71 in POV-Ray for pigments 0.5 to 0.8).
        let behind = "<0, 0, 100>";
        let translucency = "subsurface { translucency 2 }";
        assert_eq!(block("", translucency, behind), DVec3::ZERO);
        let glow = block("subsurface { }", translucency, behind);
        assert!(
            (glow - DVec3::splat(0.525)).abs().max_element() < 0.05,
            "{glow}"
        );
        // The same pixel again gives the same colour: the probes follow from the point.
        assert_eq!(block("subsurface { }", translucency, behind), glow);
    }

    #[test]
    fn tangents_complete_an_orthonormal_frame() {
        for n in [
            DVec3::Z,
            -DVec3::Z,
            DVec3::X,
            DVec3::new(0.3, -0.5, 0.8).normalize(),
            DVec3::new(0.0, 1e-12, -1.0).normalize(),
        ] {
            let (t, b) = tangents(n);
            for (u, v) in [(n, t), (n, b), (t, b)] {
                assert!(u.dot(v).abs() < 1e-12);
            }
            for u in [t, b] {
                assert!((u.length() - 1.0).abs() < 1e-12);
            }
        }
    }
}
