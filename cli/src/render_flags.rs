//! The flags of `povrayst render` that set render options. They carry the names, defaults
//! and checks of the Typst package's keyword arguments (`typst-pkg/lib.typ`; a test keeps the
//! two tables equal), and each becomes the POV-Ray option it stands for
//! (`--aa-threshold 0.3` is `Antialias_Threshold=0.3`), which the renderer's option parser
//! applies exactly as it applies `--extra` options and the plugin's.

use clap::{Arg, ArgAction, ArgMatches, Args, FromArgMatches};

/// What a flag's value may be. `none` is always allowed and keeps POV-Ray's default.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Accepts {
    Int {
        min: u32,
        max: u32,
    },
    Number {
        min: f64,
        max: Option<f64>,
    },
    Bool,
    Choice(&'static [u32]),
    /// A positive number or `srgb`.
    Gamma,
    /// A pixel (an integer from 1) or a fraction (a number with a point, from 0.0 to 1.0).
    Extent,
}

/// One render option flag.
#[derive(Debug, Clone, Copy)]
pub struct Flag {
    /// The flag's name without `--`, and the Typst keyword argument's.
    pub name: &'static str,
    /// The default as the Typst package writes it (`true`, `0.3`, `none`).
    pub default: &'static str,
    pub accepts: Accepts,
    /// The POV-Ray `.ini` option the flag sets.
    pub option: &'static str,
    /// What `none` sends, where POV-Ray's default differs from the package default the
    /// renderer starts from.
    pub povray_default: Option<&'static str>,
    pub help: &'static str,
}

const fn flag(
    name: &'static str,
    default: &'static str,
    accepts: Accepts,
    option: &'static str,
    help: &'static str,
) -> Flag {
    Flag {
        name,
        default,
        accepts,
        option,
        povray_default: None,
        help,
    }
}

const fn int(min: u32, max: u32) -> Accepts {
    Accepts::Int { min, max }
}

/// The flags in the order their options are applied, as in `lib.typ`.
pub const FLAGS: &[Flag] = &[
    flag(
        "width",
        "800",
        int(1, 16384),
        "Width",
        "Image width in pixels",
    ),
    flag(
        "height",
        "600",
        int(1, 16384),
        "Height",
        "Image height in pixels",
    ),
    flag(
        "quality",
        "9",
        int(0, 11),
        "Quality",
        "0 ambient only, 4 shadows, 8 reflection and refraction, 9 everything",
    ),
    Flag {
        povray_default: Some("off"),
        ..flag(
            "antialias",
            "true",
            Accepts::Bool,
            "Antialias",
            "Adaptive supersampling",
        )
    },
    flag(
        "aa-threshold",
        "0.3",
        Accepts::Number {
            min: 0.0,
            max: None,
        },
        "Antialias_Threshold",
        "Colour difference that triggers more samples; lower is smoother",
    ),
    Flag {
        povray_default: Some("1"),
        ..flag(
            "aa-method",
            "2",
            Accepts::Choice(&[1, 2, 3]),
            "Sampling_Method",
            "1 fixed grid, 2 adaptive recursive, 3 stochastic",
        )
    },
    flag(
        "aa-depth",
        "3",
        int(1, 9),
        "Antialias_Depth",
        "Subdivision depth: up to depth squared samples a pixel",
    ),
    flag(
        "aa-jitter",
        "true",
        Accepts::Bool,
        "Jitter",
        "Randomise sub-pixel sample positions",
    ),
    flag(
        "aa-jitter-amount",
        "none",
        Accepts::Number {
            min: 0.0,
            max: Some(1.0),
        },
        "Jitter_Amount",
        "Jitter magnitude, 0 to 1",
    ),
    flag(
        "aa-gamma",
        "none",
        Accepts::Gamma,
        "Antialias_Gamma",
        "Gamma for comparing sub-samples",
    ),
    flag(
        "display-gamma",
        "none",
        Accepts::Gamma,
        "Display_Gamma",
        "Gamma the image is rendered for",
    ),
    flag(
        "file-gamma",
        "none",
        Accepts::Gamma,
        "File_Gamma",
        "Gamma of the output file",
    ),
    flag(
        "max-trace-level",
        "none",
        int(1, 256),
        "Max_Trace_Level",
        "Cap on reflection and refraction depth",
    ),
    flag(
        "bounding",
        "none",
        Accepts::Bool,
        "Bounding",
        "Automatic bounding boxes",
    ),
    flag(
        "bounding-threshold",
        "none",
        int(0, u32::MAX),
        "Bounding_Threshold",
        "Fewest objects worth bounding",
    ),
    flag(
        "remove-bounds",
        "none",
        Accepts::Bool,
        "Remove_Bounds",
        "Drop needless user bounds",
    ),
    flag(
        "split-unions",
        "none",
        Accepts::Bool,
        "Split_Unions",
        "Bound union members separately",
    ),
    flag(
        "start-row",
        "none",
        Accepts::Extent,
        "Start_Row",
        "First row: a pixel from 1 or a fraction 0.0 to 1.0",
    ),
    flag(
        "end-row",
        "none",
        Accepts::Extent,
        "End_Row",
        "Last row: a pixel from 1 or a fraction 0.0 to 1.0",
    ),
    flag(
        "start-column",
        "none",
        Accepts::Extent,
        "Start_Column",
        "First column: a pixel from 1 or a fraction 0.0 to 1.0",
    ),
    flag(
        "end-column",
        "none",
        Accepts::Extent,
        "End_Column",
        "Last column: a pixel from 1 or a fraction 0.0 to 1.0",
    ),
    flag(
        "output-alpha",
        "false",
        Accepts::Bool,
        "Output_Alpha",
        "Write an alpha channel (transparent background)",
    ),
    flag(
        "compression",
        "none",
        int(0, 9),
        "Compression",
        "PNG deflate level, 0 to 9; without it a fast deflate (larger files)",
    ),
];

impl Accepts {
    /// Checks a flag value and returns the text of the POV-Ray option value.
    pub fn check(self, text: &str) -> Result<String, String> {
        let fail = || Err(format!("expected {}, or none", self.describe()));
        match self {
            Accepts::Bool => match text {
                "true" | "on" | "yes" => Ok("on".into()),
                "false" | "off" | "no" => Ok("off".into()),
                _ => fail(),
            },
            Accepts::Int { min, max } => match text.parse::<u32>() {
                Ok(n) if (min..=max).contains(&n) => Ok(n.to_string()),
                _ => fail(),
            },
            Accepts::Choice(values) => match text.parse::<u32>() {
                Ok(n) if values.contains(&n) => Ok(n.to_string()),
                _ => fail(),
            },
            Accepts::Number { min, max } => match number(text) {
                Some(v) if v >= min && max.is_none_or(|max| v <= max) => Ok(text.into()),
                _ => fail(),
            },
            Accepts::Gamma => match number(text) {
                Some(v) if v > 0.0 => Ok(text.into()),
                _ if text.eq_ignore_ascii_case("srgb") => Ok("sRGB".into()),
                _ => fail(),
            },
            Accepts::Extent => {
                let pixel = text.parse::<u32>().is_ok_and(|n| n >= 1);
                let fraction =
                    text.contains('.') && number(text).is_some_and(|v| (0.0..=1.0).contains(&v));
                if pixel || fraction {
                    Ok(text.into())
                } else {
                    fail()
                }
            }
        }
    }

    fn describe(self) -> String {
        match self {
            Accepts::Bool => "true or false".into(),
            Accepts::Int { min, max: u32::MAX } => format!("an integer of at least {min}"),
            Accepts::Int { min, max } => format!("an integer from {min} to {max}"),
            Accepts::Choice(values) => {
                let values: Vec<String> = values.iter().map(u32::to_string).collect();
                format!("one of {}", values.join(", "))
            }
            Accepts::Number { min, max: None } => format!("a number of at least {min}"),
            Accepts::Number {
                min,
                max: Some(max),
            } => format!("a number from {min} to {max}"),
            Accepts::Gamma => "a number above 0 or srgb".into(),
            Accepts::Extent => {
                "an integer of at least 1 (a pixel) or a number from 0.0 to 1.0 (a fraction)".into()
            }
        }
    }
}

fn number(text: &str) -> Option<f64> {
    text.parse::<f64>().ok().filter(|v| v.is_finite())
}

/// The render option flags as given: for each flag of [`FLAGS`], the checked option value,
/// or `None` for `none`.
#[derive(Debug, Clone, PartialEq)]
pub struct RenderFlags {
    values: Vec<Option<String>>,
}

impl RenderFlags {
    /// The POV-Ray options these flags stand for, in table order (`Width=800`, ...).
    pub fn povray_options(&self) -> Vec<String> {
        FLAGS
            .iter()
            .zip(&self.values)
            .filter_map(|(flag, value)| {
                let value = value.as_deref().or(flag.povray_default)?;
                Some(format!("{}={value}", flag.option))
            })
            .collect()
    }
}

impl Args for RenderFlags {
    fn augment_args(mut command: clap::Command) -> clap::Command {
        for flag in FLAGS {
            let accepts = flag.accepts;
            let mut arg = Arg::new(flag.name)
                .long(flag.name)
                .help(format!("{} [POV-Ray: {}]", flag.help, flag.option))
                .default_value(flag.default)
                .action(ArgAction::Set)
                .value_parser(move |text: &str| -> Result<Option<String>, String> {
                    if text == "none" {
                        Ok(None)
                    } else {
                        accepts.check(text).map(Some)
                    }
                });
            if accepts == Accepts::Bool {
                // `--output-alpha` alone means `--output-alpha true`.
                arg = arg.num_args(0..=1).default_missing_value("true");
            }
            command = command.arg(arg);
        }
        command
    }

    fn augment_args_for_update(command: clap::Command) -> clap::Command {
        Self::augment_args(command)
    }
}

impl FromArgMatches for RenderFlags {
    fn from_arg_matches(matches: &ArgMatches) -> Result<Self, clap::Error> {
        let values = FLAGS
            .iter()
            .map(|flag| {
                matches
                    .get_one::<Option<String>>(flag.name)
                    .cloned()
                    .flatten()
            })
            .collect();
        Ok(RenderFlags { values })
    }

    fn update_from_arg_matches(&mut self, matches: &ArgMatches) -> Result<(), clap::Error> {
        *self = Self::from_arg_matches(matches)?;
        Ok(())
    }
}

#[cfg(test)]
mod tests;
