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
    /// `subsurface { }`: subsurface light transport is on only with this block.
    pub subsurface: Option<Subsurface>,
    /// `mm_per_unit`: the scene's scale for subsurface scattering, in millimetres.
    pub mm_per_unit: f64,
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
            subsurface: None,
            mm_per_unit: 10.0,
        }
    }
}

/// `radiosity { }` in global_settings, with 3.7's defaults.
#[derive(Debug, Clone, PartialEq)]
pub struct Radiosity {
    /// Rays per gathered sample.
    pub count: u32,
    /// `count`'s second argument: how many directions the gathers draw from in turn.
    pub direction_pool: Option<u32>,
    pub error_bound: f64,
    pub recursion_limit: u32,
    /// The mosaic block sizes of the first and last pretrace pass, as fractions of the
    /// image size.
    pub pretrace_start: f64,
    pub pretrace_end: f64,
    pub nearest_count: u32,
    /// `nearest_count`'s second argument: the sample density at which the pretrace stops
    /// refining an area (adaptive pretrace).
    pub adaptive_nearest_count: Option<u32>,
    pub low_error_factor: f64,
    pub gray_threshold: f64,
    pub brightness: f64,
    pub minimum_reuse: f64,
    pub maximum_reuse: f64,
    pub normal: bool,
    pub media: bool,
    /// Whether subsurface light transport shows in the light radiosity gathers.
    pub subsurface: bool,
    pub always_sample: bool,
    pub adc_bailout: f64,
    /// The brightest a gathered ray may be; `None` leaves them as they are.
    pub max_sample: Option<f64>,
}

impl Default for Radiosity {
    fn default() -> Self {
        Radiosity {
            count: 35,
            direction_pool: None,
            error_bound: 1.8,
            recursion_limit: 2,
            pretrace_start: 0.08,
            pretrace_end: 0.04,
            nearest_count: 5,
            adaptive_nearest_count: None,
            low_error_factor: 0.5,
            gray_threshold: 0.0,
            brightness: 1.0,
            minimum_reuse: 0.015,
            maximum_reuse: 0.2,
            normal: false,
            media: false,
            subsurface: false,
            always_sample: false,
            adc_bailout: 0.01,
            max_sample: None,
        }
    }
}

/// `subsurface { }` in global_settings, with 3.7's defaults.
#[derive(Debug, Clone, PartialEq)]
pub struct Subsurface {
    /// Samples for the diffuse scattering and for the single-scattering approximation.
    pub samples: (u32, u32),
    /// Whether indirect light from radiosity scatters under the surface too.
    pub radiosity: bool,
}

impl Default for Subsurface {
    fn default() -> Self {
        Subsurface {
            samples: (50, 50),
            radiosity: false,
        }
    }
}
