use super::{Colour, Photons};
use glam::DVec3;

/// `global_settings { }`, with POV-Ray's defaults. `None` means the scene did not set it.
#[derive(Debug, Clone, PartialEq)]
pub struct GlobalSettings {
    pub assumed_gamma: Option<f64>,
    pub max_trace_level: Option<u32>,
    pub adc_bailout: f64,
    pub ambient_light: Colour,
    pub irid_wavelength: DVec3,
    pub number_of_waves: u32,
    pub noise_generator: u8,
    pub photons: Option<Photons>,
    pub radiosity: Option<Radiosity>,
}

impl Default for GlobalSettings {
    fn default() -> Self {
        GlobalSettings {
            assumed_gamma: None,
            max_trace_level: None,
            adc_bailout: 1.0 / 255.0,
            ambient_light: Colour::gray(1.0),
            irid_wavelength: DVec3::new(0.25, 0.18, 0.14),
            number_of_waves: 10,
            noise_generator: 2,
            photons: None,
            radiosity: None,
        }
    }
}

/// `radiosity { }` in global_settings, with 3.7's defaults.
#[derive(Debug, Clone, PartialEq)]
pub struct Radiosity {
    pub count: u32,
    pub error_bound: f64,
    pub recursion_limit: u32,
    pub pretrace_start: f64,
    pub pretrace_end: f64,
    pub nearest_count: u32,
    pub low_error_factor: f64,
    pub gray_threshold: f64,
    pub brightness: f64,
    pub minimum_reuse: f64,
    pub maximum_reuse: f64,
    pub normal: bool,
    pub media: bool,
    pub always_sample: bool,
    pub adc_bailout: f64,
}

impl Default for Radiosity {
    fn default() -> Self {
        Radiosity {
            count: 35,
            error_bound: 1.8,
            recursion_limit: 2,
            pretrace_start: 0.08,
            pretrace_end: 0.04,
            nearest_count: 5,
            low_error_factor: 0.5,
            gray_threshold: 0.0,
            brightness: 1.0,
            minimum_reuse: 0.015,
            maximum_reuse: 0.2,
            normal: false,
            media: false,
            always_sample: false,
            adc_bailout: 0.01,
        }
    }
}
