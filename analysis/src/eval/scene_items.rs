//! The top level of a scene: objects, lights, the camera, `global_settings`, `background`
//! and the atmospheric items (`fog`, `rainbow`, `sky_sphere` and `media`).

use super::{Evaluator, Result};
use syntax::SyntaxKind::*;

impl Evaluator<'_> {
    /// Top-level statements until the end of the main file.
    pub fn statements_until_eof(&mut self) -> Result<()> {
        loop {
            let token = self.next()?;
            match token.kind {
                ERROR_NODE => return Ok(()),
                kind if Self::starts_object(kind) => {
                    self.unget(token);
                    let object = self.object()?;
                    self.add_object(object);
                }
                LIGHT_SOURCE_KW => {
                    self.unget(token);
                    let light = self.light_source()?;
                    self.lights.push(light);
                }
                CAMERA_KW => {
                    self.unget(token);
                    let value = self.camera_value()?;
                    self.camera = Some(self.finish_camera(&value));
                }
                GLOBAL_SETTINGS_KW => self.global_settings()?,
                DEFAULT_KW => self.default_directive()?,
                // POV-Ray 3.7 still accepts these directives without their '#'.
                DECLARE_KW | LOCAL_KW | INCLUDE_KW | VERSION_KW => {
                    self.warn_at(
                        &token,
                        format!("legacy syntax: write #{}", self.text(&token)),
                    );
                    self.directive(token.clone(), token)?;
                }
                BACKGROUND_KW => {
                    self.expect(L_BRACE, "'{'")?;
                    let colour = self.scene_colour()?;
                    self.expect(R_BRACE, "'}'")?;
                    self.background = Some(colour);
                }
                FOG_KW => {
                    let fog = self.fog_body()?;
                    self.fogs.push(fog);
                }
                RAINBOW_KW => {
                    let rainbow = self.rainbow_body()?;
                    self.rainbows.push(rainbow);
                }
                // A scene has one sky sphere; a later one replaces an earlier one.
                SKY_SPHERE_KW => self.sky_sphere = Some(self.sky_sphere_body()?),
                MEDIA_KW => self.atmospheric_media()?,
                SEMICOLON => {}
                IDENT => {
                    let message = match token.slot.as_ref().map(|s| s.borrow().type_name()) {
                        Some(type_name) => format!(
                            "a {type_name} identifier cannot stand alone here; objects are placed with object {{ {} }}",
                            self.text(&token)
                        ),
                        None => return Err(self.undeclared(&token)),
                    };
                    return Err(self.error_at(&token, message));
                }
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected an object, light_source, camera or directive, found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
    }

    fn global_settings(&mut self) -> Result<()> {
        self.expect(L_BRACE, "'{'")?;
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => return Ok(()),
                ASSUMED_GAMMA_KW => {
                    let gamma = self.float()?;
                    if gamma <= 0.0 {
                        return Err(self.error_at(&token, "assumed_gamma must be positive"));
                    }
                    self.settings.assumed_gamma = Some(gamma);
                }
                MAX_TRACE_LEVEL_KW => {
                    let level = self.int()?;
                    self.settings.max_trace_level = Some(level.clamp(1, 256) as u32);
                }
                ADC_BAILOUT_KW => self.settings.adc_bailout = self.float()?,
                AMBIENT_LIGHT_KW => self.settings.ambient_light = self.scene_colour()?,
                IRID_WAVELENGTH_KW => self.settings.irid_wavelength = self.scene_colour()?.rgb,
                NUMBER_OF_WAVES_KW => self.settings.number_of_waves = self.int()?.max(1) as u32,
                NOISE_GENERATOR_KW => self.settings.noise_generator = self.int()?.clamp(1, 3) as u8,
                CHARSET_KW => {
                    self.next()?;
                }
                HF_GRAY_16_KW => {
                    self.optional_bool()?;
                }
                MAX_INTERSECTIONS_KW => {
                    self.float()?;
                }
                MM_PER_UNIT_KW => {
                    self.settings.mm_per_unit = self.positive(&token, "mm_per_unit")?
                }
                PHOTONS_KW => self.settings.photons = Some(self.global_photons(&token)?),
                RADIOSITY_KW => self.global_radiosity()?,
                SUBSURFACE_KW => self.global_subsurface()?,
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected a global setting or '}}', found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
    }
}
