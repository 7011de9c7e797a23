//! `--tile i/n`: one of `n` horizontal bands of the picture, so that a job array (Slurm
//! arrays, GNU parallel, Kubernetes indexed Jobs) can spread one render over many machines.
//! A tile is rendered with POV-Ray's partial-render rows and written as a PNG of its band
//! alone, named `scene.tile-03-of-08.png`; `povrayst stitch` stacks the bands again.

use std::path::{Path, PathBuf};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Tile {
    /// From 1 to `count`, as job array indices usually are.
    pub index: u32,
    pub count: u32,
}

impl Tile {
    pub fn parse(text: &str) -> Result<Tile, String> {
        let bad = || format!("expected a tile as i/n with 1 <= i <= n, found '{text}'");
        let (index, count) = text.split_once('/').ok_or_else(bad)?;
        let index: u32 = index.trim().parse().map_err(|_| bad())?;
        let count: u32 = count.trim().parse().map_err(|_| bad())?;
        if index == 0 || index > count {
            return Err(bad());
        }
        Ok(Tile { index, count })
    }

    /// The first and last row (zero-based, inclusive) of the band in a picture `height`
    /// rows high; the bands of all tiles cover every row once. `None` for a band with no
    /// rows, when there are more tiles than rows.
    pub fn rows(self, height: u32) -> Option<(u32, u32)> {
        let start = |i: u32| (u64::from(height) * u64::from(i) / u64::from(self.count)) as u32;
        let (first, end) = (start(self.index - 1), start(self.index));
        (end > first).then(|| (first, end - 1))
    }

    /// The tile's file beside `base`: `scene.png` becomes `scene.tile-03-of-08.png`.
    pub fn output_for(self, base: &Path) -> PathBuf {
        let width = self.count.to_string().len();
        let stem = base.file_stem().unwrap_or_default().to_string_lossy();
        let extension = base
            .extension()
            .map_or(String::new(), |e| format!(".{}", e.to_string_lossy()));
        base.with_file_name(format!(
            "{stem}.tile-{:0width$}-of-{:0width$}{extension}",
            self.index, self.count
        ))
    }

    /// The tile a file name made by [`Tile::output_for`] stands for.
    pub fn of_file(path: &Path) -> Option<Tile> {
        let stem = path.file_stem()?.to_str()?;
        let (_, tile) = stem.rsplit_once(".tile-")?;
        let (index, count) = tile.split_once("-of-")?;
        Tile::parse(&format!("{index}/{count}")).ok()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bands_cover_every_row_once() {
        for (height, count) in [(480, 8), (7, 3), (2, 5), (1, 1)] {
            let mut next = 0;
            for index in 1..=count {
                if let Some((first, last)) = (Tile { index, count }).rows(height) {
                    assert_eq!(first, next, "{height} rows in {count}");
                    next = last + 1;
                }
            }
            assert_eq!(next, height);
        }
        assert_eq!(Tile::parse("3/8").unwrap().rows(480), Some((120, 179)));
    }

    #[test]
    fn names_carry_the_tile() {
        let tile = Tile::parse("3/12").unwrap();
        let path = tile.output_for(Path::new("out/scene.png"));
        assert_eq!(path, Path::new("out/scene.tile-03-of-12.png"));
        assert_eq!(Tile::of_file(&path), Some(tile));
        assert_eq!(Tile::of_file(Path::new("scene.png")), None);
    }

    #[test]
    fn bad_tiles_say_what_is_expected() {
        for text in ["0/4", "5/4", "1", "a/b"] {
            assert_eq!(
                Tile::parse(text),
                Err(format!(
                    "expected a tile as i/n with 1 <= i <= n, found '{text}'"
                ))
            );
        }
    }
}
