//! The flags against the package's table, their defaults and their errors.
use super::*;
use clap::Parser;
use expect_test::expect;

#[derive(Parser, Debug)]
struct Probe {
    #[command(flatten)]
    flags: RenderFlags,
}

fn options(args: &[&str]) -> Result<String, String> {
    let args = std::iter::once("probe").chain(args.iter().copied());
    Probe::try_parse_from(args)
        .map(|probe| probe.flags.povray_options().join(" "))
        .map_err(|e| e.to_string().lines().next().unwrap_or_default().to_owned())
}

#[test]
fn defaults_are_the_packages() {
    expect!["Width=800 Height=600 Quality=9 Antialias=on Antialias_Threshold=0.3 Sampling_Method=2 Antialias_Depth=3 Jitter=on Output_Alpha=off"]
            .assert_eq(&options(&[]).unwrap());
}

#[test]
fn flags_become_povray_options() {
    expect!["Width=320 Height=600 Quality=9 Antialias=off Antialias_Threshold=0.1 Sampling_Method=2 Antialias_Depth=3 Display_Gamma=sRGB Start_Row=0.5 End_Row=40 Output_Alpha=on"]
            .assert_eq(
                &options(&[
                    "--width", "320", "--antialias", "none", "--aa-threshold", "0.1",
                    "--aa-jitter=none", "--display-gamma", "SRGB", "--start-row", "0.5",
                    "--end-row", "40", "--output-alpha",
                ])
                .unwrap(),
            );
}

#[test]
fn bad_values_name_the_flag() {
    let errors = [
        &["--width", "0"][..],
        &["--aa-method", "4"],
        &["--antialias", "1"],
        &["--start-row", "1.5"],
        &["--display-gamma=-1"],
    ]
    .map(|args| options(args).unwrap_err());
    expect![[r#"
        error: invalid value '0' for '--width <width>': expected an integer from 1 to 16384, or none
        error: invalid value '4' for '--aa-method <aa-method>': expected one of 1, 2, 3, or none
        error: invalid value '1' for '--antialias [<antialias>]': expected true or false, or none
        error: invalid value '1.5' for '--start-row <start-row>': expected an integer of at least 1 (a pixel) or a number from 0.0 to 1.0 (a fraction), or none
        error: invalid value '-1' for '--display-gamma <display-gamma>': expected a number above 0 or srgb, or none"#]].assert_eq(&errors.join("\n"));
}

/// The Typst package's option table, one `name: (default:, accepts:, option:, ..)` line
/// each, written back in the same form from [`FLAGS`]: the two must agree word for word.
#[test]
fn flags_match_the_typst_package() {
    let lib = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../typst-pkg/lib.typ"))
        .unwrap();
    let table = lib.split("#let _options = (\n").nth(1).unwrap();
    let typst: Vec<&str> = table
        .lines()
        .take_while(|line| *line != ")")
        .map(str::trim)
        .collect();
    let ours: Vec<String> = FLAGS
        .iter()
        .map(|flag| {
            let accepts = match flag.accepts {
                Accepts::Int { min, max: u32::MAX } => format!("_int({min}, none)"),
                Accepts::Int { min, max } => format!("_int({min}, {max})"),
                Accepts::Number { min, max } => format!(
                    "_number({min}, {})",
                    max.map_or("none".into(), |m| m.to_string())
                ),
                Accepts::Bool => "_bool".into(),
                Accepts::Choice(values) => format!(
                    "_choice({})",
                    values
                        .iter()
                        .map(u32::to_string)
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
                Accepts::Gamma => "_gamma".into(),
                Accepts::Extent => "_limit".into(),
            };
            let povray = flag
                .povray_default
                .map_or(String::new(), |v| format!(", povray-default: \"{v}\""));
            format!(
                "{}: (default: {}, accepts: {accepts}, option: \"{}\"{povray}),",
                flag.name, flag.default, flag.option
            )
        })
        .collect();
    assert_eq!(typst, ours);
}
