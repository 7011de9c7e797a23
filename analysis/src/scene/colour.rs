use glam::DVec3;

/// A POV-Ray colour: red, green, blue, filter and transmit. Components are linear values in
/// the scene's working space; the evaluator has already applied any `srgb` conversion.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Colour {
    pub rgb: DVec3,
    pub filter: f64,
    pub transmit: f64,
}

impl Colour {
    pub const BLACK: Colour = Colour {
        rgb: DVec3::ZERO,
        filter: 0.0,
        transmit: 0.0,
    };

    pub fn rgb(r: f64, g: f64, b: f64) -> Colour {
        Colour {
            rgb: DVec3::new(r, g, b),
            filter: 0.0,
            transmit: 0.0,
        }
    }

    pub fn gray(v: f64) -> Colour {
        Colour::rgb(v, v, v)
    }

    /// POV-Ray's grey value of the colour (`.gray`): 0.297 red + 0.589 green + 0.114 blue.
    pub fn grey_value(self) -> f64 {
        self.rgb.dot(DVec3::new(0.297, 0.589, 0.114))
    }

    /// The five components in POV-Ray's order: red, green, blue, filter, transmit.
    pub fn to_array(self) -> [f64; 5] {
        [
            self.rgb.x,
            self.rgb.y,
            self.rgb.z,
            self.filter,
            self.transmit,
        ]
    }

    pub fn from_array(c: [f64; 5]) -> Colour {
        Colour {
            rgb: DVec3::new(c[0], c[1], c[2]),
            filter: c[3],
            transmit: c[4],
        }
    }

    /// Linear interpolation of all five components, as colour maps blend. Inlined: the
    /// renderer's maps call it at every hit, and the call cost half of what it does.
    #[inline]
    pub fn lerp(self, other: Colour, t: f64) -> Colour {
        Colour {
            rgb: self.rgb.lerp(other.rgb, t),
            filter: self.filter + (other.filter - self.filter) * t,
            transmit: self.transmit + (other.transmit - self.transmit) * t,
        }
    }
}
