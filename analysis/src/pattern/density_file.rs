//! `density_file df3 "name"`: a grid of voxels read from a df3 file, filling the unit cube
//! from <0, 0, 0> to <1, 1, 1> whatever its size in voxels, and 0 outside it.
//!
//! A df3 file is three big-endian 16-bit sizes (x, y, z) and then the voxels, x fastest,
//! as big-endian unsigned integers of 8, 16 or 32 bits: the file's length says which.
//! Measured on POV-Ray 3.7's renders of small grids: without interpolation a point takes
//! the voxel `floor(p * size)`; with trilinear interpolation (`interpolate 1`) voxel `i`
//! sits at `i / size` and the grid wraps around, so that past the last voxel the value
//! runs back towards the first. Its tricubic interpolation (`interpolate 2`) fits no
//! common cubic kernel to the measured values and is refused.

use glam::DVec3;

/// The voxels of a df3 file, normalised to 0..1.
#[derive(Debug, Clone, PartialEq)]
pub struct DensityGrid {
    size: [usize; 3],
    values: Vec<f32>,
}

/// The largest grid read, in voxels: at four bytes a voxel, 256 MiB.
const MAX_VOXELS: usize = 1 << 26;

impl DensityGrid {
    /// The grid a df3 file holds, or why the bytes are not one.
    pub fn from_df3(bytes: &[u8]) -> Result<DensityGrid, String> {
        let header = bytes
            .get(..6)
            .ok_or("not a valid df3 file: it is shorter than its 6-byte header")?;
        let size = [0, 2, 4].map(|i| usize::from(u16::from_be_bytes([header[i], header[i + 1]])));
        let voxels = size[0] * size[1] * size[2];
        if voxels == 0 {
            return Err(format!(
                "not a valid df3 file: it has no voxels ({} by {} by {})",
                size[0], size[1], size[2]
            ));
        }
        if voxels > MAX_VOXELS {
            return Err(format!(
                "the df3 grid is too large ({voxels} voxels; the limit is {MAX_VOXELS})"
            ));
        }
        let data = &bytes[6..];
        let width = data.len() / voxels;
        if !matches!(width, 1 | 2 | 4) || !data.len().is_multiple_of(voxels) {
            return Err(format!(
                "not a valid df3 file: {} bytes of data do not hold {voxels} voxels of 8, 16 or 32 bits",
                data.len()
            ));
        }
        let max = ((1u64 << (8 * width)) - 1) as f64;
        let values = data
            .chunks_exact(width)
            .map(|v| {
                let n = v.iter().fold(0u64, |n, &b| n << 8 | u64::from(b));
                (n as f64 / max) as f32
            })
            .collect();
        Ok(DensityGrid { size, values })
    }

    /// The voxel at grid coordinates already within the grid.
    fn voxel(&self, i: usize, j: usize, k: usize) -> f64 {
        f64::from(self.values[i + self.size[0] * (j + self.size[1] * k)])
    }

    /// The density at `p`: the voxel it lies in, or with `trilinear` the blend of the
    /// eight voxels around it.
    pub fn value(&self, p: DVec3, trilinear: bool) -> f64 {
        let unit = 0.0..1.0;
        if !(unit.contains(&p.x) && unit.contains(&p.y) && unit.contains(&p.z)) {
            return 0.0;
        }
        let scaled = p * DVec3::new(
            self.size[0] as f64,
            self.size[1] as f64,
            self.size[2] as f64,
        );
        // Inside the unit cube the scaled point is at least 0 (or -0), where the floor is
        // the conversion to an integer: `f64::floor` is a library call on targets without
        // a rounding instruction (x86-64's baseline), three for every value.
        let cell = scaled.as_uvec3().as_dvec3();
        // Rounding can put a point just below 1 on the grid's far side: it stays in the
        // last voxel.
        let index = |axis: usize| (cell[axis] as usize).min(self.size[axis] - 1);
        let (i, j, k) = (index(0), index(1), index(2));
        if !trilinear {
            return self.voxel(i, j, k);
        }
        let t = scaled - cell;
        // The next voxel, round to the first past the last (without a division).
        let next = |n: usize, axis: usize| {
            if n + 1 == self.size[axis] { 0 } else { n + 1 }
        };
        let (i1, j1, k1) = (next(i, 0), next(j, 1), next(k, 2));
        let lerp = |a: f64, b: f64, t: f64| a + (b - a) * t;
        let plane = |k: usize| {
            lerp(
                lerp(self.voxel(i, j, k), self.voxel(i1, j, k), t.x),
                lerp(self.voxel(i, j1, k), self.voxel(i1, j1, k), t.x),
                t.y,
            )
        };
        lerp(plane(k), plane(k1), t.z)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 4 by 3 by 2 grid whose voxel (x, y, z) is 10 + 60x + 7y + 100z, capped at 255.
    fn grid_bytes(width: usize) -> Vec<u8> {
        let mut bytes = vec![0, 4, 0, 3, 0, 2];
        for z in 0..2u64 {
            for y in 0..3u64 {
                for x in 0..4u64 {
                    let v = (10 + 60 * x + 7 * y + 100 * z).min(255);
                    // The same fraction of the full scale at every width.
                    let full = (1u64 << (8 * width)) - 1;
                    let n = v * full / 255;
                    bytes.extend_from_slice(&n.to_be_bytes()[8 - width..]);
                }
            }
        }
        bytes
    }

    /// Values POV-Ray 3.7 drew for this grid on the plane z = 0.25 (16-bit greyscale
    /// output at file gamma 1, colour map from black to white), as 0..255.
    #[test]
    fn values_match_povray() {
        let grid = DensityGrid::from_df3(&grid_bytes(1)).unwrap();
        let at =
            |x: f64, y: f64, trilinear: bool| grid.value(DVec3::new(x, y, 0.25), trilinear) * 255.0;
        for (x, y, nearest, trilinear) in [
            (0.0375, 0.1625, 10.0, 72.4),
            (0.3875, 0.1625, 70.0, 156.4),
            (0.0375, 0.5125, 17.0, 79.8),
            (0.9875, 0.1625, 190.0, 71.5),
        ] {
            assert!((at(x, y, false) - nearest).abs() < 1e-4, "{x} {y}");
            assert!(
                (at(x, y, true) - trilinear).abs() < 0.1,
                "{x} {y}: {}",
                at(x, y, true)
            );
        }
        // Outside the unit cube there is nothing.
        for p in [
            DVec3::new(-0.01, 0.5, 0.5),
            DVec3::new(0.5, 1.0, 0.5),
            DVec3::new(0.5, 0.5, 2.0),
        ] {
            assert_eq!(grid.value(p, true), 0.0);
        }
    }

    #[test]
    fn the_file_length_gives_the_sample_width() {
        let eight = DensityGrid::from_df3(&grid_bytes(1)).unwrap();
        for width in [2, 4] {
            let wide = DensityGrid::from_df3(&grid_bytes(width)).unwrap();
            for (a, b) in eight.values.iter().zip(&wide.values) {
                assert!((a - b).abs() < 1e-6);
            }
        }
    }

    #[test]
    fn damaged_files_are_errors() {
        let bytes = grid_bytes(1);
        for cut in [0, 5, 7, bytes.len() - 1] {
            assert!(
                DensityGrid::from_df3(&bytes[..cut]).is_err(),
                "cut at {cut}"
            );
        }
        assert!(DensityGrid::from_df3(&[0, 0, 0, 1, 0, 1]).is_err());
        assert!(DensityGrid::from_df3(&[255, 255, 255, 255, 255, 255, 1]).is_err());
    }
}
