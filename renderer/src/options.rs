//! The one option vocabulary of the CLI flags, the Typst keyword arguments and POV-Ray's own
//! `.ini` (`Antialias_Threshold=0.1`) and command-line (`+A0.1`) options. A field left `None`
//! keeps POV-Ray's default; the non-optional fields carry the package defaults of the
//! specification (section 5), which differ from POV-Ray's (antialiasing is on, for one).

/// A gamma setting: a power-law exponent or the sRGB transfer function.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Gamma {
    Power(f64),
    Srgb,
}

/// A row or column bound of a partial render: a 1-based pixel index or a fraction of the
/// image size, as POV-Ray reads `Start_Row=12` and `Start_Row=0.25`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Extent {
    Pixel(u32),
    Fraction(f64),
}

impl Extent {
    /// The 0-based pixel index this bound names in an image `size` pixels long.
    /// `end` bounds name the last pixel included.
    pub fn resolve(self, size: u32) -> u32 {
        let last = size.saturating_sub(1);
        match self {
            Extent::Pixel(n) => n.saturating_sub(1).min(last),
            Extent::Fraction(f) => ((f * f64::from(size)) as u32).min(last),
        }
    }

    /// Reads `12` as a pixel and `0.25` (a number with a point, at most 1) as a fraction.
    pub fn parse(text: &str) -> Result<Extent, String> {
        let value = parse_number(text)?;
        if text.contains('.') && (0.0..=1.0).contains(&value) {
            Ok(Extent::Fraction(value))
        } else if value >= 1.0 && value.fract() == 0.0 && value <= f64::from(u32::MAX) {
            Ok(Extent::Pixel(value as u32))
        } else if (0.0..1.0).contains(&value) {
            Ok(Extent::Fraction(value))
        } else {
            Err(format!(
                "`{text}` is neither a pixel index (1 or more) nor a fraction between 0 and 1"
            ))
        }
    }
}

/// Everything that controls a render besides the scene itself.
#[derive(Debug, Clone, PartialEq)]
pub struct RenderOptions {
    pub width: u32,
    pub height: u32,
    /// 0 to 11, as POV-Ray's `Quality`.
    pub quality: u8,
    pub antialias: bool,
    pub aa_threshold: f64,
    /// `Sampling_Method`: 1 fixed grid, 2 adaptive recursive, 3 stochastic.
    pub aa_method: u8,
    pub aa_depth: u32,
    pub aa_jitter: bool,
    pub aa_jitter_amount: Option<f64>,
    pub aa_gamma: Option<f64>,
    /// `Antialias_Confidence` for method 3.
    pub aa_confidence: Option<f64>,
    pub display_gamma: Option<Gamma>,
    pub file_gamma: Option<Gamma>,
    pub max_trace_level: Option<u32>,
    pub bounding: Option<bool>,
    pub bounding_threshold: Option<u32>,
    pub remove_bounds: Option<bool>,
    pub split_unions: Option<bool>,
    pub start_row: Option<Extent>,
    pub end_row: Option<Extent>,
    pub start_column: Option<Extent>,
    pub end_column: Option<Extent>,
    pub output_alpha: bool,
    /// PNG deflate level 0-9.
    pub compression: Option<u8>,
    /// Bits per colour channel of the PNG: 8 or 16 (`+FN16`, `Bits_Per_Color=16`).
    pub bits_per_colour: Option<u8>,
    /// `Clock=n.n` / `+Kn.n`: the value of `clock` in the scene.
    pub clock: Option<f64>,
    /// `Declare=NAME=VALUE`: floats declared before the scene is read.
    pub declared: Vec<(String, f64)>,
    /// `+WTn` / `Work_Threads=n`: how many threads the CLI renders with. The picture does
    /// not depend on it; the Typst plugin always has one.
    pub threads: Option<usize>,
}

impl Default for RenderOptions {
    fn default() -> Self {
        RenderOptions {
            width: 800,
            height: 600,
            quality: 9,
            antialias: true,
            aa_threshold: 0.3,
            aa_method: 2,
            aa_depth: 3,
            aa_jitter: true,
            aa_jitter_amount: None,
            aa_gamma: None,
            aa_confidence: None,
            display_gamma: None,
            file_gamma: None,
            max_trace_level: None,
            bounding: None,
            bounding_threshold: None,
            remove_bounds: None,
            split_unions: None,
            start_row: None,
            end_row: None,
            start_column: None,
            end_column: None,
            output_alpha: false,
            compression: None,
            bits_per_colour: None,
            clock: None,
            declared: Vec::new(),
            threads: None,
        }
    }
}

impl RenderOptions {
    /// Applies one POV-Ray option, in the command-line form (`+W640`, `-A`, `+A0.3`,
    /// `+FN16`) or the `.ini` form (`Antialias_Threshold=0.1`). Options that only concern
    /// POV-Ray's own front end (`+D`, `+V`, output file names) are accepted and have no
    /// effect; anything else is an error naming the option.
    pub fn apply_povray_option(&mut self, option: &str) -> Result<(), String> {
        let option = option.trim();
        if let Some((key, value)) = option.split_once('=') {
            return self
                .apply_ini(key.trim(), value.trim())
                .map_err(|e| format!("option `{option}`: {e}"));
        }
        let (on, switch) = match option.as_bytes().first() {
            Some(b'+') => (true, &option[1..]),
            Some(b'-') => (false, &option[1..]),
            _ => {
                return Err(format!(
                    "option `{option}`: expected `+X`, `-X` or `Name=value` form"
                ));
            }
        };
        self.apply_switch(on, switch)
            .map_err(|e| format!("option `{option}`: {e}"))
    }

    fn apply_switch(&mut self, on: bool, switch: &str) -> Result<(), String> {
        // Longest prefixes first, so that `AM` is not read as `A` with value `M`.
        const SWITCHES: &[&str] = &[
            "AM", "AG", "AC", "SR", "SC", "ER", "EC", "MB", "UA", "SU", "UR", "WT", "FN", "A", "J",
            "R", "Q", "W", "H", "K", "D", "V", "P", "X", "O", "I",
        ];
        let upper = switch.to_ascii_uppercase();
        let Some(name) = SWITCHES.iter().find(|s| upper.starts_with(**s)) else {
            return Err("unknown option".into());
        };
        let value = &switch[name.len()..];
        let has_value = !value.is_empty();
        match *name {
            "A" => {
                self.antialias = on;
                if has_value {
                    self.aa_threshold = parse_number(value)?;
                }
            }
            "AM" => {
                self.aa_method = parse_range(value, 1, 3)? as u8;
            }
            "AG" => self.aa_gamma = Some(parse_positive(value)?),
            "AC" => self.aa_confidence = Some(parse_number(value)?),
            "J" => {
                self.aa_jitter = on;
                if has_value {
                    let amount = parse_number(value)?;
                    self.aa_jitter_amount = Some(amount);
                    if amount <= 0.0 {
                        self.aa_jitter = false;
                    }
                }
            }
            "R" => self.aa_depth = parse_range(value, 1, 9)?,
            "Q" => self.quality = parse_range(value, 0, 11)? as u8,
            "W" => self.width = parse_range(value, 1, 65535)?,
            "H" => self.height = parse_range(value, 1, 65535)?,
            "K" => self.clock = Some(parse_number(value)?),
            "SR" => self.start_row = Some(Extent::parse(value)?),
            "ER" => self.end_row = Some(Extent::parse(value)?),
            "SC" => self.start_column = Some(Extent::parse(value)?),
            "EC" => self.end_column = Some(Extent::parse(value)?),
            "MB" => {
                self.bounding = Some(on);
                if has_value {
                    self.bounding_threshold = Some(parse_range(value, 0, u32::MAX)?);
                }
            }
            "UA" => self.output_alpha = on,
            "UR" => self.remove_bounds = Some(on),
            "SU" => self.split_unions = Some(on),
            "FN" => {
                if has_value {
                    let bits = parse_range(value, 1, 16)? as u8;
                    self.bits_per_colour = Some(if bits > 8 { 16 } else { 8 });
                }
            }
            "WT" => {
                if has_value {
                    self.threads = Some(parse_range(value, 1, 512)? as usize);
                }
            }
            // Display, verbosity, pause, abort key, output and input names: the front
            // end's business, not the picture's.
            "D" | "V" | "P" | "X" | "O" | "I" => {}
            _ => return Err("unknown option".into()),
        }
        Ok(())
    }

    fn apply_ini(&mut self, key: &str, value: &str) -> Result<(), String> {
        let value = value.trim_matches('"');
        match key.to_ascii_lowercase().as_str() {
            "width" => self.width = parse_range(value, 1, 65535)?,
            "height" => self.height = parse_range(value, 1, 65535)?,
            "quality" => self.quality = parse_range(value, 0, 11)? as u8,
            "antialias" => self.antialias = parse_bool(value)?,
            "antialias_threshold" => self.aa_threshold = parse_number(value)?,
            "sampling_method" => self.aa_method = parse_range(value, 1, 3)? as u8,
            "antialias_depth" => self.aa_depth = parse_range(value, 1, 9)?,
            "antialias_gamma" => self.aa_gamma = Some(parse_positive(value)?),
            "antialias_confidence" => self.aa_confidence = Some(parse_number(value)?),
            "jitter" => self.aa_jitter = parse_bool(value)?,
            "jitter_amount" => {
                let amount = parse_number(value)?;
                self.aa_jitter_amount = Some(amount);
                if amount <= 0.0 {
                    self.aa_jitter = false;
                }
            }
            "display_gamma" => self.display_gamma = Some(parse_gamma(value)?),
            "file_gamma" => self.file_gamma = Some(parse_gamma(value)?),
            "max_trace_level" => self.max_trace_level = Some(parse_range(value, 1, 256)?),
            "bounding" => self.bounding = Some(parse_bool(value)?),
            "bounding_threshold" => {
                self.bounding_threshold = Some(parse_range(value, 0, u32::MAX)?)
            }
            "remove_bounds" => self.remove_bounds = Some(parse_bool(value)?),
            "split_unions" => self.split_unions = Some(parse_bool(value)?),
            "start_row" => self.start_row = Some(Extent::parse(value)?),
            "end_row" => self.end_row = Some(Extent::parse(value)?),
            "start_column" => self.start_column = Some(Extent::parse(value)?),
            "end_column" => self.end_column = Some(Extent::parse(value)?),
            "output_alpha" => self.output_alpha = parse_bool(value)?,
            "compression" => self.compression = Some(parse_range(value, 0, 9)? as u8),
            "bits_per_color" | "bits_per_colour" => {
                let bits = parse_range(value, 1, 16)? as u8;
                self.bits_per_colour = Some(if bits > 8 { 16 } else { 8 });
            }
            "clock" => self.clock = Some(parse_number(value)?),
            "declare" => self.declared.push(parse_declaration(value)?),
            "work_threads" => self.threads = Some(parse_range(value, 1, 512)? as usize),
            "display" | "verbose" | "pause_when_done" | "output_file_name" | "input_file_name"
            | "output_file_type" | "output_to_file" | "test_abort" | "test_abort_count"
            | "warning_level" => {}
            _ => return Err("unknown option".into()),
        }
        Ok(())
    }

    /// The jitter amount in force: POV-Ray's default is 1, the largest that keeps every
    /// sample inside its pixel.
    pub fn jitter_amount(&self) -> f64 {
        if self.aa_jitter {
            self.aa_jitter_amount.unwrap_or(1.0)
        } else {
            0.0
        }
    }
}

/// `NAME=VALUE` of a `Declare` option: an identifier and a number.
fn parse_declaration(text: &str) -> Result<(String, f64), String> {
    let Some((name, value)) = text.split_once('=') else {
        return Err(format!("`{text}` is not NAME=VALUE"));
    };
    let name = name.trim();
    let mut chars = name.chars();
    let identifier = chars
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_');
    if !identifier {
        return Err(format!("`{name}` is not an identifier"));
    }
    Ok((name.to_string(), parse_number(value.trim())?))
}

fn parse_number(text: &str) -> Result<f64, String> {
    text.trim()
        .parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
        .ok_or_else(|| format!("`{text}` is not a number"))
}

fn parse_positive(text: &str) -> Result<f64, String> {
    let v = parse_number(text)?;
    if v > 0.0 {
        Ok(v)
    } else {
        Err(format!("`{text}` must be greater than 0"))
    }
}

fn parse_range(text: &str, min: u32, max: u32) -> Result<u32, String> {
    let v = parse_number(text)?;
    if v.fract() != 0.0 || v < f64::from(min) || v > f64::from(max) {
        return Err(format!(
            "`{text}` must be a whole number from {min} to {max}"
        ));
    }
    Ok(v as u32)
}

fn parse_bool(text: &str) -> Result<bool, String> {
    match text.to_ascii_lowercase().as_str() {
        "on" | "true" | "yes" | "1" => Ok(true),
        "off" | "false" | "no" | "0" => Ok(false),
        _ => Err(format!("`{text}` is not on/off")),
    }
}

fn parse_gamma(text: &str) -> Result<Gamma, String> {
    if text.eq_ignore_ascii_case("srgb") {
        Ok(Gamma::Srgb)
    } else {
        parse_positive(text).map(Gamma::Power)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn apply(options: &[&str]) -> Result<RenderOptions, String> {
        let mut o = RenderOptions::default();
        for option in options {
            o.apply_povray_option(option)?;
        }
        Ok(o)
    }

    #[test]
    fn command_line_switches() {
        let o = apply(&["+W640", "+H480", "+A0.1", "-J", "+AM1", "+R4", "+Q5", "+UA"]).unwrap();
        assert_eq!((o.width, o.height), (640, 480));
        assert!(o.antialias && !o.aa_jitter && o.output_alpha);
        assert_eq!(o.aa_threshold, 0.1);
        assert_eq!((o.aa_method, o.aa_depth, o.quality), (1, 4, 5));
        let o = apply(&["-A", "+FN16", "+J0.5", "+SR0.5", "+EC100"]).unwrap();
        assert!(!o.antialias && o.aa_jitter);
        assert_eq!(o.aa_jitter_amount, Some(0.5));
        assert_eq!(o.bits_per_colour, Some(16));
        assert_eq!(o.start_row, Some(Extent::Fraction(0.5)));
        assert_eq!(o.end_column, Some(Extent::Pixel(100)));
        // The thread count is kept for the front end; a bare `+WT` leaves it alone.
        assert_eq!(apply(&["+WT3"]).unwrap().threads, Some(3));
        assert_eq!(apply(&["Work_Threads=2", "+WT"]).unwrap().threads, Some(2));
        assert_eq!(apply(&["+W10"]).unwrap().threads, None);
        assert!(apply(&["+WT0"]).is_err());
    }

    #[test]
    fn ini_settings() {
        let o = apply(&[
            "Antialias_Threshold=0.1",
            "Antialias=off",
            "File_Gamma=sRGB",
            "Display_Gamma=2.2",
            "Sampling_Method = 3",
            "Output_Alpha=on",
            "Compression=9",
        ])
        .unwrap();
        assert_eq!(o.aa_threshold, 0.1);
        assert!(!o.antialias && o.output_alpha);
        assert_eq!(o.file_gamma, Some(Gamma::Srgb));
        assert_eq!(o.display_gamma, Some(Gamma::Power(2.2)));
        assert_eq!((o.aa_method, o.compression), (3, Some(9)));
    }

    #[test]
    fn declarations_collect_in_order() {
        let o = apply(&["Declare=Photons=1", "declare = Count = 2.5"]).unwrap();
        let expected = vec![("Photons".to_string(), 1.0), ("Count".to_string(), 2.5)];
        assert_eq!(o.declared, expected);
    }

    #[test]
    fn errors_name_the_option() {
        for (option, message) in [
            ("+ZZ", "unknown option"),
            ("Frobnicate=1", "unknown option"),
            ("+R12", "`12` must be a whole number from 1 to 9"),
            ("W640", "expected `+X`, `-X` or `Name=value` form"),
            ("Declare=1x=2", "`1x` is not an identifier"),
            ("Declare=Lights", "`Lights` is not NAME=VALUE"),
        ] {
            let expected = format!("option `{option}`: {message}");
            assert_eq!(apply(&[option]).unwrap_err(), expected);
        }
        assert!(apply(&["+Wabc"]).is_err());
    }

    #[test]
    fn extents_resolve_to_pixels() {
        assert_eq!(Extent::Pixel(1).resolve(100), 0);
        assert_eq!(Extent::Pixel(500).resolve(100), 99);
        assert_eq!(Extent::Fraction(0.75).resolve(100), 75);
        assert_eq!(Extent::Fraction(1.0).resolve(100), 99);
        assert!(Extent::parse("-3").is_err());
        assert!(Extent::parse("2.5").is_err());
    }
}
