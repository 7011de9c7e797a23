//! Image comparison for the fidelity tests: our renders against POV-Ray's reference PNGs.
//!
//! Two measures, both over the colour channels premultiplied by alpha plus the alpha
//! channel itself (so a transparent pixel of any colour equals any other):
//! - SSIM (structural similarity, Wang et al. 2004) on 8 × 8 windows stepped by 4 pixels,
//!   with the usual constants K1 = 0.01 and K2 = 0.03, averaged over windows and channels.
//!   It is 1 for identical images and drops for shifted edges, missing shadows and wrong
//!   shading; jittered antialiasing costs a few thousandths.
//! - Per-channel absolute error on the 0-255 scale: the mean, and the share of channel
//!   values that differ by more than 16 (about 6 %), which catches local defects that the
//!   mean dilutes.
//!
//! - The mean brightness of each of 4 × 4 regions, on the 0-255 scale: the largest
//!   difference between the pictures is what a viewer sees of a brighter or darker area.
//!
//! Stochastic effects (radiosity) are compared at the level a viewer sees: both pictures
//! are blurred first (each pixel the mean of the square `blur` pixels around it), so that
//! noise of a pixel or two counts for little, and the region means bound the overall light.
//!
//! A scene passes when its SSIM is at least its threshold and the error figures stay under
//! theirs; [`Thresholds::GEOMETRIC`] is the default for scenes without noise patterns.

use std::fmt;
use std::path::Path;

/// An RGBA image with channels in 0..=1, colour premultiplied by alpha.
#[derive(Debug, Clone, PartialEq)]
pub struct Picture {
    pub width: usize,
    pub height: usize,
    /// Red, green, blue (premultiplied) and alpha, row by row.
    pub pixels: Vec<[f64; 4]>,
}

impl Picture {
    /// Decodes a PNG file of any bit depth, grey or colour, with or without alpha.
    pub fn decode(bytes: &[u8]) -> Result<Picture, String> {
        let mut decoder = png::Decoder::new(std::io::Cursor::new(bytes));
        decoder.set_transformations(png::Transformations::EXPAND);
        let mut reader = decoder.read_info().map_err(|e| e.to_string())?;
        let size = reader
            .output_buffer_size()
            .ok_or("PNG too large to decode")?;
        let mut buf = vec![0; size];
        let info = reader.next_frame(&mut buf).map_err(|e| e.to_string())?;
        let channels = info.color_type.samples();
        let sixteen = info.bit_depth == png::BitDepth::Sixteen;
        let (width, height) = (info.width as usize, info.height as usize);
        let value = |i: usize| -> f64 {
            if sixteen {
                f64::from(u16::from_be_bytes([buf[2 * i], buf[2 * i + 1]])) / 65535.0
            } else {
                f64::from(buf[i]) / 255.0
            }
        };
        let mut pixels = Vec::with_capacity(width * height);
        for p in 0..width * height {
            let base = p * channels;
            let (rgb, alpha) = match channels {
                1 => ([value(base); 3], 1.0),
                2 => ([value(base); 3], value(base + 1)),
                3 => ([value(base), value(base + 1), value(base + 2)], 1.0),
                _ => (
                    [value(base), value(base + 1), value(base + 2)],
                    value(base + 3),
                ),
            };
            pixels.push([rgb[0] * alpha, rgb[1] * alpha, rgb[2] * alpha, alpha]);
        }
        Ok(Picture {
            width,
            height,
            pixels,
        })
    }

    pub fn read(path: &Path) -> Result<Picture, String> {
        let bytes = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
        Picture::decode(&bytes).map_err(|e| format!("{}: {e}", path.display()))
    }

    /// The picture seen at a coarser scale: each pixel the mean of the square of side
    /// `2 radius + 1` around it (cut at the edges), as a viewer sees sampling noise.
    pub fn blurred(&self, radius: usize) -> Picture {
        let mut pixels = Vec::with_capacity(self.pixels.len());
        for y in 0..self.height {
            for x in 0..self.width {
                let (x0, x1) = (x.saturating_sub(radius), (x + radius).min(self.width - 1));
                let (y0, y1) = (y.saturating_sub(radius), (y + radius).min(self.height - 1));
                let mut sum = [0.0; 4];
                for yy in y0..=y1 {
                    for xx in x0..=x1 {
                        let p = self.pixels[yy * self.width + xx];
                        for c in 0..4 {
                            sum[c] += p[c];
                        }
                    }
                }
                let n = ((x1 - x0 + 1) * (y1 - y0 + 1)) as f64;
                pixels.push(sum.map(|v| v / n));
            }
        }
        Picture {
            width: self.width,
            height: self.height,
            pixels,
        }
    }

    /// The mean of the colour channels over each cell of a `columns` × `rows` grid, row by
    /// row, on the 0-255 scale.
    pub fn region_means(&self, columns: usize, rows: usize) -> Vec<f64> {
        let mut sums = vec![(0.0, 0usize); columns * rows];
        for y in 0..self.height {
            for x in 0..self.width {
                let cell = (y * rows / self.height) * columns + x * columns / self.width;
                let p = self.pixels[y * self.width + x];
                sums[cell].0 += (p[0] + p[1] + p[2]) / 3.0 * 255.0;
                sums[cell].1 += 1;
            }
        }
        sums.into_iter().map(|(s, n)| s / n.max(1) as f64).collect()
    }

    fn channel(&self, x: usize, y: usize, c: usize) -> f64 {
        self.pixels[y * self.width + x][c]
    }
}

/// How two pictures differ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Difference {
    pub ssim: f64,
    /// Mean absolute channel difference on the 0-255 scale.
    pub mean_error: f64,
    /// Share (0..1) of channel values differing by more than 16 on the 0-255 scale.
    pub large_error_share: f64,
    /// The largest difference of mean brightness over a 4 × 4 grid of regions, 0-255.
    pub region_error: f64,
}

impl fmt::Display for Difference {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "SSIM {:.4}, mean error {:.3}/255, {:.3} % of channels off by more than 16, regions off by {:.2}/255 at most",
            self.ssim,
            self.mean_error,
            self.large_error_share * 100.0,
            self.region_error
        )
    }
}

/// What a scene must achieve against its reference.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Thresholds {
    /// The blur radius both pictures get before they are compared ([`Picture::blurred`]);
    /// 0 compares them as they are.
    pub blur: usize,
    pub min_ssim: f64,
    pub max_mean_error: f64,
    pub max_large_error_share: f64,
    pub max_region_error: f64,
}

impl Thresholds {
    /// For scenes of plain geometry and colour, where only antialiasing jitter differs.
    pub const GEOMETRIC: Thresholds = Thresholds {
        blur: 0,
        min_ssim: 0.98,
        max_mean_error: 1.0,
        max_large_error_share: 0.01,
        max_region_error: f64::INFINITY,
    };

    pub fn check(&self, d: &Difference) -> Result<(), String> {
        let mut failures = Vec::new();
        if d.ssim < self.min_ssim {
            failures.push(format!("SSIM {:.4} < {}", d.ssim, self.min_ssim));
        }
        if d.mean_error > self.max_mean_error {
            failures.push(format!(
                "mean error {:.3} > {}",
                d.mean_error, self.max_mean_error
            ));
        }
        if d.large_error_share > self.max_large_error_share {
            failures.push(format!(
                "{:.3} % of channels off by more than 16 > {} %",
                d.large_error_share * 100.0,
                self.max_large_error_share * 100.0
            ));
        }
        if d.region_error > self.max_region_error {
            failures.push(format!(
                "a region's mean brightness off by {:.2} > {}",
                d.region_error, self.max_region_error
            ));
        }
        if failures.is_empty() {
            Ok(())
        } else {
            Err(failures.join("; "))
        }
    }
}

/// Compares two pictures of the same size as they are.
pub fn compare(a: &Picture, b: &Picture) -> Result<Difference, String> {
    compare_blurred(a, b, 0)
}

/// Compares two pictures of the same size after blurring both by `blur` pixels.
pub fn compare_blurred(a: &Picture, b: &Picture, blur: usize) -> Result<Difference, String> {
    if (a.width, a.height) != (b.width, b.height) {
        return Err(format!(
            "sizes differ: {}x{} against {}x{}",
            a.width, a.height, b.width, b.height
        ));
    }
    if blur > 0 {
        return compare(&a.blurred(blur), &b.blurred(blur));
    }
    let mut total = 0.0;
    let mut large = 0usize;
    for (pa, pb) in a.pixels.iter().zip(&b.pixels) {
        for c in 0..4 {
            let d = (pa[c] - pb[c]).abs() * 255.0;
            total += d;
            if d > 16.0 {
                large += 1;
            }
        }
    }
    let values = (a.pixels.len() * 4).max(1) as f64;
    Ok(Difference {
        ssim: ssim(a, b),
        mean_error: total / values,
        large_error_share: large as f64 / values,
        region_error: region_error(a, b),
    })
}

/// The largest difference of mean brightness between the pictures over a 4 × 4 grid of
/// regions, on the 0-255 scale.
fn region_error(a: &Picture, b: &Picture) -> f64 {
    a.region_means(4, 4)
        .iter()
        .zip(b.region_means(4, 4))
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

const WINDOW: usize = 8;
const STEP: usize = 4;

/// Mean SSIM over 8 × 8 windows (stepped by 4) and the four channels.
fn ssim(a: &Picture, b: &Picture) -> f64 {
    const C1: f64 = 0.01 * 0.01;
    const C2: f64 = 0.03 * 0.03;
    if a.width < WINDOW || a.height < WINDOW {
        // Too small for windows: one window over the whole picture.
        return (0..4)
            .map(|c| window_ssim(a, b, c, (0, 0), (a.width, a.height), C1, C2))
            .sum::<f64>()
            / 4.0;
    }
    let mut sum = 0.0;
    let mut count = 0usize;
    for y in (0..=a.height - WINDOW).step_by(STEP) {
        for x in (0..=a.width - WINDOW).step_by(STEP) {
            for c in 0..4 {
                sum += window_ssim(a, b, c, (x, y), (WINDOW, WINDOW), C1, C2);
                count += 1;
            }
        }
    }
    sum / count as f64
}

fn window_ssim(
    a: &Picture,
    b: &Picture,
    c: usize,
    (x0, y0): (usize, usize),
    (w, h): (usize, usize),
    c1: f64,
    c2: f64,
) -> f64 {
    let n = (w * h) as f64;
    let (mut sa, mut sb, mut saa, mut sbb, mut sab) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for y in y0..y0 + h {
        for x in x0..x0 + w {
            let va = a.channel(x, y, c);
            let vb = b.channel(x, y, c);
            sa += va;
            sb += vb;
            saa += va * va;
            sbb += vb * vb;
            sab += va * vb;
        }
    }
    let (ma, mb) = (sa / n, sb / n);
    let var_a = (saa / n - ma * ma).max(0.0);
    let var_b = (sbb / n - mb * mb).max(0.0);
    let cov = sab / n - ma * mb;
    ((2.0 * ma * mb + c1) * (2.0 * cov + c2)) / ((ma * ma + mb * mb + c1) * (var_a + var_b + c2))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A grey disc of radius 20 on a blue background, drawn with 4 × 4 supersampling.
    fn disc(cx: f64, cy: f64, grey: f64) -> Picture {
        let (width, height) = (96, 64);
        let mut pixels = Vec::new();
        for y in 0..height {
            for x in 0..width {
                let mut cover = 0.0;
                for s in 0..16 {
                    let px = x as f64 + (s % 4) as f64 / 4.0 + 0.125;
                    let py = y as f64 + (s / 4) as f64 / 4.0 + 0.125;
                    if (px - cx).powi(2) + (py - cy).powi(2) < 400.0 {
                        cover += 1.0 / 16.0;
                    }
                }
                let bg = [0.2, 0.3, 0.8];
                let rgb: Vec<f64> = bg
                    .iter()
                    .map(|b| b * (1.0 - cover) + grey * cover)
                    .collect();
                pixels.push([rgb[0], rgb[1], rgb[2], 1.0]);
            }
        }
        Picture {
            width,
            height,
            pixels,
        }
    }

    #[test]
    fn identical_pictures_pass_with_ssim_one() {
        let a = disc(48.0, 32.0, 0.7);
        let d = compare(&a, &a).unwrap();
        assert!((d.ssim - 1.0).abs() < 1e-12 && d.mean_error == 0.0);
        Thresholds::GEOMETRIC.check(&d).unwrap();
    }

    #[test]
    fn subpixel_edge_noise_passes() {
        // A quarter-pixel displacement is what jittered antialiasing can do to an edge.
        let d = compare(&disc(48.0, 32.0, 0.7), &disc(48.25, 32.0, 0.7)).unwrap();
        Thresholds::GEOMETRIC.check(&d).unwrap();
    }

    #[test]
    fn wrong_pictures_fail() {
        let reference = disc(48.0, 32.0, 0.7);
        // Moved by three pixels: a wrong camera.
        let moved = compare(&reference, &disc(51.0, 32.0, 0.7)).unwrap();
        assert!(Thresholds::GEOMETRIC.check(&moved).is_err(), "{moved}");
        // Shaded 10 % darker: a wrong lighting formula.
        let darker = compare(&reference, &disc(48.0, 32.0, 0.63)).unwrap();
        assert!(Thresholds::GEOMETRIC.check(&darker).is_err(), "{darker}");
        // Mirrored: a camera `right` vector taken the wrong way round.
        let mut mirrored = disc(30.0, 32.0, 0.7);
        let flipped = compare(&disc(66.0, 32.0, 0.7), &mirrored).unwrap();
        assert!(Thresholds::GEOMETRIC.check(&flipped).is_err(), "{flipped}");
        // Transparent where the reference is opaque: lost alpha.
        for p in &mut mirrored.pixels {
            *p = [0.0; 4];
        }
        let clear = compare(&reference, &mirrored).unwrap();
        assert!(Thresholds::GEOMETRIC.check(&clear).is_err(), "{clear}");
    }

    /// What stochastic renders are compared with: blurred by two pixels, noise of a few
    /// percent from pixel to pixel passes, a region 10 % darker does not.
    #[test]
    fn blurring_forgives_noise_but_not_wrong_light() {
        let stochastic = Thresholds {
            blur: 2,
            min_ssim: 0.98,
            max_mean_error: 2.0,
            max_large_error_share: 0.01,
            max_region_error: 3.0,
        };
        let reference = disc(48.0, 32.0, 0.7);
        let mut noisy = reference.clone();
        for (i, p) in noisy.pixels.iter_mut().enumerate() {
            let noise = if (i * 7 + i / 96) % 3 == 0 {
                0.04
            } else {
                -0.02
            };
            for c in &mut p[..3] {
                *c += noise;
            }
        }
        let raw = compare(&reference, &noisy).unwrap();
        assert!(Thresholds::GEOMETRIC.check(&raw).is_err(), "{raw}");
        let blurred = compare_blurred(&reference, &noisy, stochastic.blur).unwrap();
        stochastic.check(&blurred).unwrap();
        let darker = compare_blurred(&reference, &disc(48.0, 32.0, 0.63), 2).unwrap();
        assert!(stochastic.check(&darker).is_err(), "{darker}");
        assert!(darker.region_error > 3.0, "{darker}");
    }

    #[test]
    fn sizes_must_match() {
        let mut small = disc(48.0, 32.0, 0.7);
        small.width = 48;
        small.pixels.truncate(48 * 64);
        assert!(compare(&disc(48.0, 32.0, 0.7), &small).is_err());
    }

    #[test]
    fn decodes_rgba_and_premultiplies() {
        let mut png_bytes = Vec::new();
        {
            let mut e = png::Encoder::new(&mut png_bytes, 1, 1);
            e.set_color(png::ColorType::Rgba);
            e.set_depth(png::BitDepth::Eight);
            let mut w = e.write_header().unwrap();
            w.write_image_data(&[255, 0, 0, 51]).unwrap();
        }
        let p = Picture::decode(&png_bytes).unwrap();
        assert_eq!(p.pixels, vec![[0.2, 0.0, 0.0, 0.2]]);
    }
}
