//! Chromatic dispersion (`interior { ior I dispersion D dispersion_samples N }`): light
//! refracted into or out of a dispersing interior splits into N bands of the spectrum, and
//! each band bends with its own index of refraction. As in POV-Ray, `D` is the ratio of
//! the violet index to the red one, the middle of the spectrum keeps `I`, the bands sit at
//! equal steps between, and there is no dispersion unless the interior gives its `ior`.
//!
//! A band's colour is the hue of the spectrum across it, from 660 nm at the red end to
//! 380 nm at the violet end: the linear sRGB colour of each wavelength, from the CIE 1931
//! colour matching functions in the multi-lobe Gaussian form of Wyman, Sloan and Shirley
//! (JCGT 2013), clipped to the gamut and brought to full brightness, averaged over the
//! band. Each channel is then scaled so that the bands add up to white and an undeflected
//! split changes nothing. Hues at full brightness keep the ends of the spectrum as strong
//! as its middle, as POV-Ray's spectrum does; the wavelength range is the one whose bands
//! come nearest to POV-Ray's colours for seven samples.

use crate::interior::Interior;
use glam::DVec3;

/// The most bands a scene may ask for: each one traces its own rays.
pub const MAX_SAMPLES: u32 = 1000;

/// One band of the spectrum.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Band {
    /// From -0.5 (red) to 0.5 (violet).
    pub position: f64,
    /// Its share of white light.
    pub colour: DVec3,
}

/// Whether light crossing a surface of `interior` splits into bands.
pub fn disperses(interior: &Interior) -> bool {
    interior.dispersion > 0.0 && (interior.dispersion - 1.0).abs() > 1e-12
}

/// The index of refraction of `interior` for the band at `position`.
pub fn ior(interior: &Interior, position: f64) -> f64 {
    if disperses(interior) {
        interior.ior * interior.dispersion.powf(position)
    } else {
        interior.ior
    }
}

/// The bands of each sample count met so far, computed once.
#[derive(Debug, Clone, Default)]
pub struct Spectra {
    known: Vec<(u32, Vec<Band>)>,
}

impl Spectra {
    /// The `samples` bands, red first.
    pub fn bands(&mut self, samples: u32) -> &[Band] {
        let samples = samples.clamp(2, MAX_SAMPLES);
        let at = match self.known.iter().position(|(n, _)| *n == samples) {
            Some(at) => at,
            None => {
                self.known.push((samples, bands(samples)));
                self.known.len() - 1
            }
        };
        &self.known[at].1
    }
}

/// `count` bands of equal width across the visible spectrum, red first.
fn bands(count: u32) -> Vec<Band> {
    const STEPS: u32 = 16;
    let (red, violet) = (660.0, 380.0);
    let width = (red - violet) / f64::from(count);
    let mut bands: Vec<Band> = (0..count)
        .map(|i| {
            let start = red - width * f64::from(i);
            let colour = (0..STEPS)
                .map(|s| spectral_rgb(start - width * (f64::from(s) + 0.5) / f64::from(STEPS)))
                .fold(DVec3::ZERO, |a, b| a + b);
            Band {
                position: (f64::from(i) + 0.5) / f64::from(count) - 0.5,
                colour,
            }
        })
        .collect();
    let total = bands.iter().fold(DVec3::ZERO, |a, b| a + b.colour);
    for band in &mut bands {
        band.colour /= total;
    }
    bands
}

/// The hue of light of one wavelength (nm) in linear sRGB, clipped to the gamut, at full
/// brightness.
fn spectral_rgb(nm: f64) -> DVec3 {
    let lobe = |mean: f64, below: f64, above: f64| {
        let t = (nm - mean) / if nm < mean { below } else { above };
        (-0.5 * t * t).exp()
    };
    let x = 1.056 * lobe(599.8, 37.9, 31.0) + 0.362 * lobe(442.0, 16.0, 26.7)
        - 0.065 * lobe(501.1, 20.4, 26.2);
    let y = 0.821 * lobe(568.8, 46.9, 40.5) + 0.286 * lobe(530.9, 16.3, 31.1);
    let z = 1.217 * lobe(437.0, 11.8, 36.0) + 0.681 * lobe(459.0, 26.0, 13.8);
    let rgb = DVec3::new(
        3.2406 * x - 1.5372 * y - 0.4986 * z,
        -0.9689 * x + 1.8758 * y + 0.0415 * z,
        0.0557 * x - 0.2040 * y + 1.0570 * z,
    )
    .max(DVec3::ZERO);
    rgb / rgb.max_element().max(1e-12)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bands_add_up_to_white_from_red_to_violet() {
        let mut spectra = Spectra::default();
        for n in [2, 3, 7, 50] {
            let bands = spectra.bands(n).to_vec();
            assert_eq!(bands.len(), n as usize);
            let sum = bands.iter().fold(DVec3::ZERO, |a, b| a + b.colour);
            assert!((sum - DVec3::ONE).abs().max_element() < 1e-12, "{n}: {sum}");
            assert!(bands[0].position < 0.0 && bands[n as usize - 1].position > 0.0);
        }
        // Seven bands: red first, green in the middle, blue towards the end.
        let seven = spectra.bands(7);
        assert!(seven[0].colour.x > 0.1 && seven[0].colour.y + seven[0].colour.z < 0.01);
        assert!(seven[3].colour.y > seven[3].colour.x && seven[3].colour.y > seven[3].colour.z);
        assert!(seven[5].colour.z > seven[5].colour.x + seven[5].colour.y);
    }

    #[test]
    fn violet_bends_more_and_only_with_an_ior() {
        let scene_glass = analysis::scene::Interior {
            ior: 1.5,
            ior_given: true,
            dispersion: 1.1,
            ..analysis::scene::Interior::default()
        };
        let glass = Interior::from_scene(&scene_glass, false, false).unwrap();
        assert!((ior(&glass, 0.5) / ior(&glass, -0.5) - 1.1).abs() < 1e-12);
        assert_eq!(ior(&glass, 0.0), 1.5);
        let scene_no_ior = analysis::scene::Interior {
            ior_given: false,
            ..scene_glass
        };
        let no_ior = Interior::from_scene(&scene_no_ior, false, false).unwrap();
        assert!(!disperses(&no_ior));
        assert_eq!(ior(&no_ior, 0.5), 1.5);
    }
}
