//! `povrayst stitch TILE.png... -o OUT.png`: joins the bands that `render --tile i/n`
//! wrote into one picture. Files named by `render` (`scene.tile-03-of-08.png`) are put in
//! tile order and must be all there; other names are stacked in the order given. The
//! bands must agree in width, colour type, bit depth and gamma, which the result keeps.

use crate::Outcome;
use crate::tiles::Tile;
use clap::Args;
use std::path::{Path, PathBuf};

#[derive(Args, Debug)]
pub struct StitchArgs {
    /// The tiles' PNG files.
    #[arg(required = true, value_name = "TILE.png")]
    tiles: Vec<PathBuf>,
    /// The picture to write.
    #[arg(short, long, value_name = "OUT.png")]
    output: PathBuf,
}

/// One decoded band.
struct Band {
    width: u32,
    height: u32,
    color: png::ColorType,
    depth: png::BitDepth,
    srgb: Option<png::SrgbRenderingIntent>,
    gamma: Option<png::ScaledFloat>,
    data: Vec<u8>,
}

pub fn run(args: &StitchArgs) -> Outcome {
    match stitch(args) {
        Ok(()) => Outcome::Success,
        Err(error) => {
            eprintln!("povrayst: {error}");
            Outcome::UsageOrIo
        }
    }
}

fn stitch(args: &StitchArgs) -> Result<(), String> {
    let tiles = in_order(&args.tiles)?;
    let bands = tiles
        .iter()
        .map(|path| {
            decode(path).map_err(|error| format!("cannot read {}: {error}", path.display()))
        })
        .collect::<Result<Vec<Band>, String>>()?;
    let first = &bands[0];
    for (band, path) in bands.iter().zip(&tiles).skip(1) {
        if (band.width, band.color, band.depth) != (first.width, first.color, first.depth)
            || band.srgb != first.srgb
            || band.gamma != first.gamma
        {
            return Err(format!(
                "{} does not match {}: tiles of one picture share width, colour type, depth and gamma",
                path.display(),
                tiles[0].display()
            ));
        }
    }
    let height: u32 = bands.iter().map(|band| band.height).sum();
    let mut out = Vec::new();
    {
        let mut encoder = png::Encoder::new(&mut out, first.width, height);
        encoder.set_color(first.color);
        encoder.set_depth(first.depth);
        if let Some(intent) = first.srgb {
            encoder.set_source_srgb(intent);
        } else if let Some(gamma) = first.gamma {
            encoder.set_source_gamma(gamma);
        }
        let mut writer = encoder.write_header().map_err(|e| e.to_string())?;
        let data: Vec<u8> = bands
            .iter()
            .flat_map(|band| band.data.iter().copied())
            .collect();
        writer.write_image_data(&data).map_err(|e| e.to_string())?;
    }
    crate::whole_file::write(&args.output, &out)
        .map_err(|error| format!("cannot write {}: {error}", args.output.display()))
}

/// The tiles in the order to stack them.
fn in_order(paths: &[PathBuf]) -> Result<Vec<PathBuf>, String> {
    let named: Option<Vec<(Tile, &PathBuf)>> = paths
        .iter()
        .map(|path| Tile::of_file(path).map(|tile| (tile, path)))
        .collect();
    let Some(mut named) = named else {
        return Ok(paths.to_vec());
    };
    named.sort_by_key(|(tile, _)| tile.index);
    let count = named[0].0.count;
    let indices: Vec<u32> = named.iter().map(|(tile, _)| tile.index).collect();
    if named.iter().any(|(tile, _)| tile.count != count)
        || indices != (1..=count).collect::<Vec<_>>()
    {
        return Err(format!(
            "the tiles are not 1 to {count} of {count}, once each: found {indices:?}"
        ));
    }
    Ok(named.into_iter().map(|(_, path)| path.clone()).collect())
}

fn decode(path: &Path) -> Result<Band, String> {
    let file = std::fs::File::open(path).map_err(|e| e.to_string())?;
    let decoder = png::Decoder::new(std::io::BufReader::new(file));
    let mut reader = decoder.read_info().map_err(|e| e.to_string())?;
    let size = reader.output_buffer_size().ok_or("the PNG is too large")?;
    let mut data = vec![0; size];
    let frame = reader.next_frame(&mut data).map_err(|e| e.to_string())?;
    data.truncate(frame.buffer_size());
    let info = reader.info();
    Ok(Band {
        width: frame.width,
        height: frame.height,
        color: frame.color_type,
        depth: frame.bit_depth,
        srgb: info.srgb,
        gamma: info.source_gamma,
        data,
    })
}
