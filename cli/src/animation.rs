//! Animation as POV-Ray's front end runs it: frames `Initial_Frame..=Final_Frame` (`+KFI`,
//! `+KFF`), the clock running from `Initial_Clock` to `Final_Clock` (`+KI`, `+KF`) over
//! them, optionally cyclic (`+KC`), and a subset of the frames to render (`+SF`, `+EF`, or
//! `--frames 5-9`) so that a job array can share one animation out. Each frame's file name
//! carries its number, zero-padded to the width of the last frame's: `scene07.png`.

use std::path::{Path, PathBuf};

#[derive(Debug, Clone, PartialEq)]
pub struct Animation {
    pub initial_frame: u32,
    pub final_frame: u32,
    pub initial_clock: f64,
    pub final_clock: f64,
    pub cyclic: bool,
    pub subset_start: Option<u32>,
    pub subset_end: Option<u32>,
}

/// One frame to render.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    pub number: u32,
    pub clock: f64,
}

impl Default for Animation {
    fn default() -> Self {
        Animation {
            initial_frame: 1,
            final_frame: 1,
            initial_clock: 0.0,
            final_clock: 1.0,
            cyclic: false,
            subset_start: None,
            subset_end: None,
        }
    }
}

impl Animation {
    /// Takes an animation option in `.ini` form; `Ok(false)` when `key` is not one.
    pub fn apply_ini(&mut self, key: &str, value: &str) -> Result<bool, String> {
        match key.to_ascii_lowercase().as_str() {
            "initial_frame" => self.initial_frame = frame_number(value)?,
            "final_frame" => self.final_frame = frame_number(value)?,
            "initial_clock" => self.initial_clock = number(value)?,
            "final_clock" => self.final_clock = number(value)?,
            "subset_start_frame" => self.subset_start = Some(frame_number(value)?),
            "subset_end_frame" => self.subset_end = Some(frame_number(value)?),
            "cyclic_animation" => self.cyclic = boolean(value)?,
            _ => return Ok(false),
        }
        Ok(true)
    }

    /// Takes an animation switch (`KFI1`, `KFF30`, `KI0`, `KF1`, `KC`, `SF5`, `EF9`, the
    /// part after `+` or `-`); `Ok(false)` when it is not one.
    pub fn apply_switch(&mut self, on: bool, switch: &str) -> Result<bool, String> {
        let upper = switch.to_ascii_uppercase();
        // Longest first: `KFI` before `KF`.
        for (name, key) in [
            ("KFI", "initial_frame"),
            ("KFF", "final_frame"),
            ("KI", "initial_clock"),
            ("KF", "final_clock"),
            ("SF", "subset_start_frame"),
            ("EF", "subset_end_frame"),
        ] {
            if let Some(value) = upper.strip_prefix(name) {
                // `+KF` followed by a letter is not `Final_Clock`.
                if value.starts_with(|c: char| c.is_ascii_alphabetic()) {
                    continue;
                }
                return self.apply_ini(key, &switch[name.len()..]);
            }
        }
        if upper == "KC" {
            self.cyclic = on;
            return Ok(true);
        }
        Ok(false)
    }

    /// Takes `--frames A-B` (or a single `N`): the frames this run renders.
    pub fn apply_frame_range(&mut self, range: &str) -> Result<(), String> {
        let (start, end) = range.split_once('-').unwrap_or((range, range));
        self.subset_start = Some(frame_number(start)?);
        self.subset_end = Some(frame_number(end)?);
        Ok(())
    }

    pub fn is_animated(&self) -> bool {
        self.final_frame > self.initial_frame
    }

    /// The frames this run renders, in order, each with its clock value.
    pub fn frames(&self) -> Result<Vec<Frame>, String> {
        if self.final_frame < self.initial_frame {
            return Err(format!(
                "the final frame {} comes before the initial frame {}",
                self.final_frame, self.initial_frame
            ));
        }
        let first = self
            .subset_start
            .unwrap_or(self.initial_frame)
            .max(self.initial_frame);
        let last = self
            .subset_end
            .unwrap_or(self.final_frame)
            .min(self.final_frame);
        if first > last {
            return Err(format!(
                "the frame range {first}-{last} has no frame of {}-{}",
                self.initial_frame, self.final_frame
            ));
        }
        // A cyclic animation's last frame is one step short of the final clock, so that the
        // first frame follows it seamlessly.
        let steps = self.final_frame - self.initial_frame + u32::from(self.cyclic);
        Ok((first..=last)
            .map(|number| {
                let clock = if steps == 0 {
                    self.initial_clock
                } else {
                    let t = f64::from(number - self.initial_frame) / f64::from(steps);
                    self.initial_clock + (self.final_clock - self.initial_clock) * t
                };
                Frame { number, clock }
            })
            .collect())
    }

    /// The output file of `frame`: `base` as it is for a still, with the frame number
    /// before the extension for an animation.
    pub fn output_for(&self, base: &Path, frame: Frame) -> PathBuf {
        if !self.is_animated() {
            return base.to_path_buf();
        }
        let width = self.final_frame.to_string().len();
        let stem = base.file_stem().unwrap_or_default().to_string_lossy();
        let extension = base
            .extension()
            .map_or(String::new(), |e| format!(".{}", e.to_string_lossy()));
        base.with_file_name(format!("{stem}{:0width$}{extension}", frame.number))
    }
}

fn frame_number(value: &str) -> Result<u32, String> {
    value
        .trim()
        .parse()
        .map_err(|_| format!("expected a frame number, found '{value}'"))
}

fn number(value: &str) -> Result<f64, String> {
    value
        .trim()
        .parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
        .ok_or_else(|| format!("expected a number, found '{value}'"))
}

fn boolean(value: &str) -> Result<bool, String> {
    match value.trim().to_ascii_lowercase().as_str() {
        "on" | "true" | "yes" | "1" => Ok(true),
        "off" | "false" | "no" | "0" => Ok(false),
        _ => Err(format!("expected on or off, found '{value}'")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn animation(options: &[&str]) -> Animation {
        let mut animation = Animation::default();
        for option in options {
            let consumed = match option.split_once('=') {
                Some((key, value)) => animation.apply_ini(key, value),
                None => animation.apply_switch(option.starts_with('+'), &option[1..]),
            };
            assert_eq!(consumed, Ok(true), "{option}");
        }
        animation
    }

    #[test]
    fn the_clock_runs_from_initial_to_final_over_the_frames() {
        let frames = animation(&["+KFI1", "+KFF5"]).frames().unwrap();
        let clocks: Vec<(u32, f64)> = frames.iter().map(|f| (f.number, f.clock)).collect();
        assert_eq!(clocks, [(1, 0.0), (2, 0.25), (3, 0.5), (4, 0.75), (5, 1.0)]);
        let cyclic = animation(&[
            "Initial_Frame=0",
            "Final_Frame=3",
            "Cyclic_Animation=on",
            "+KI2",
            "+KF4",
        ]);
        let clocks: Vec<f64> = cyclic.frames().unwrap().iter().map(|f| f.clock).collect();
        assert_eq!(clocks, [2.0, 2.5, 3.0, 3.5]);
    }

    #[test]
    fn subsets_pick_frames_for_a_job_array() {
        let mut animation = animation(&["+KFF100", "+SF10", "+EF12"]);
        let numbers: Vec<u32> = animation
            .frames()
            .unwrap()
            .iter()
            .map(|f| f.number)
            .collect();
        assert_eq!(numbers, [10, 11, 12]);
        animation.apply_frame_range("99-120").unwrap();
        let numbers: Vec<u32> = animation
            .frames()
            .unwrap()
            .iter()
            .map(|f| f.number)
            .collect();
        assert_eq!(numbers, [99, 100]);
        animation.apply_frame_range("7").unwrap();
        assert_eq!(animation.frames().unwrap()[0].clock, 6.0 / 99.0);
        assert_eq!(
            animation
                .apply_frame_range("200-300")
                .and_then(|()| animation.frames().map(drop)),
            Err("the frame range 200-100 has no frame of 1-100".to_owned())
        );
    }

    #[test]
    fn frame_numbers_in_output_names_are_padded_to_the_last_frame() {
        let animation = animation(&["+KFF120"]);
        let frame = Frame {
            number: 7,
            clock: 0.0,
        };
        assert_eq!(
            animation.output_for(Path::new("out/scene.png"), frame),
            Path::new("out/scene007.png")
        );
        let still = Animation::default();
        assert_eq!(
            still.output_for(Path::new("a.png"), frame),
            Path::new("a.png")
        );
    }

    #[test]
    fn other_options_are_left_alone() {
        let mut animation = Animation::default();
        assert_eq!(animation.apply_switch(true, "K0.5"), Ok(false));
        assert_eq!(animation.apply_switch(true, "W640"), Ok(false));
        assert_eq!(animation.apply_ini("Width", "640"), Ok(false));
        assert!(animation.apply_switch(true, "KFI-2").is_err());
    }
}
