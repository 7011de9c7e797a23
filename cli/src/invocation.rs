//! The positional arguments of `povrayst render` read the way POV-Ray reads its command
//! line: the scene file, switches (`+W640 +H480 +A0.3 +Q9`), `Name=value` options and
//! `.ini` files full of them, applied left to right. The front end's own options (the
//! scene and output names, library paths, animation frames) are taken here; the picture's
//! go on to `RenderOptions::apply_povray_option`.

use crate::animation::Animation;
use std::path::{Path, PathBuf};

#[derive(Debug, Clone, Default, PartialEq)]
pub struct Invocation {
    pub scene: Option<PathBuf>,
    pub output: Option<PathBuf>,
    pub library_paths: Vec<PathBuf>,
    pub animation: Animation,
    /// Options for the renderer, in the order given.
    pub picture_options: Vec<String>,
}

/// `.ini` files may include each other (`Include_Ini=`); this deep is a cycle.
const MAX_INI_DEPTH: usize = 16;

impl Invocation {
    pub fn read(arguments: &[String]) -> Result<Invocation, String> {
        let mut invocation = Invocation::default();
        for argument in arguments {
            invocation.argument(argument, 0)?;
        }
        Ok(invocation)
    }

    fn argument(&mut self, argument: &str, depth: usize) -> Result<(), String> {
        if argument.starts_with(['+', '-']) || argument.contains('=') {
            return self
                .option(argument, depth)
                .map_err(|error| format!("option `{argument}`: {error}"));
        }
        if argument.to_ascii_lowercase().ends_with(".ini") {
            return self.ini_file(Path::new(argument), depth);
        }
        self.set_scene(argument)
    }

    fn set_scene(&mut self, name: &str) -> Result<(), String> {
        match &self.scene {
            Some(scene) if scene != Path::new(name) => {
                Err(format!("two scenes named: {} and {name}", scene.display()))
            }
            _ => {
                self.scene = Some(PathBuf::from(name));
                Ok(())
            }
        }
    }

    fn option(&mut self, option: &str, depth: usize) -> Result<(), String> {
        if let Some((key, value)) = option.split_once('=') {
            let (key, value) = (key.trim(), value.trim().trim_matches('"'));
            match key.to_ascii_lowercase().as_str() {
                "input_file_name" => return self.set_scene(value),
                "output_file_name" => self.output = Some(PathBuf::from(value)),
                "library_path" => self.library_paths.push(PathBuf::from(value)),
                "include_ini" => return self.ini_file(Path::new(value), depth + 1),
                _ if self.animation.apply_ini(key, value)? => {}
                _ => self.picture_options.push(format!("{key}={value}")),
            }
            return Ok(());
        }
        let on = option.starts_with('+');
        let switch = &option[1..];
        let upper = switch.to_ascii_uppercase();
        let value = || switch[1..].trim_matches('"').to_owned();
        match upper.as_bytes().first() {
            Some(b'I') if switch.len() > 1 => self.set_scene(&value())?,
            Some(b'O') if switch.len() > 1 => self.output = Some(PathBuf::from(value())),
            Some(b'L') if switch.len() > 1 => self.library_paths.push(PathBuf::from(value())),
            _ if self.animation.apply_switch(on, switch)? => {}
            _ => self.picture_options.push(option.to_owned()),
        }
        Ok(())
    }

    /// Reads an `.ini` file: `Name=value` lines and lines of switches, `;` comments, and
    /// `[section]` headers, which are ignored.
    fn ini_file(&mut self, path: &Path, depth: usize) -> Result<(), String> {
        if depth > MAX_INI_DEPTH {
            return Err(format!("{}: .ini files include each other", path.display()));
        }
        let text = std::fs::read_to_string(path)
            .map_err(|error| format!("cannot read {}: {error}", path.display()))?;
        for (number, line) in text.lines().enumerate() {
            let line = line.split(';').next().unwrap_or_default().trim();
            if line.is_empty() || line.starts_with('[') {
                continue;
            }
            let located = |error: String| format!("{}:{}: {error}", path.display(), number + 1);
            if line.contains('=') {
                self.argument(line, depth).map_err(located)?;
            } else {
                for word in line.split_whitespace() {
                    self.argument(word, depth + 1).map_err(located)?;
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(arguments: &[&str]) -> Result<Invocation, String> {
        let arguments: Vec<String> = arguments.iter().map(|a| a.to_string()).collect();
        Invocation::read(&arguments)
    }

    #[test]
    fn scene_switches_and_options_in_order() {
        let invocation = read(&[
            "+W640",
            "scene.pov",
            "+H480",
            "+A0.3",
            "Quality=9",
            "+Oout.png",
            "+Lincludes",
            "+KFF10",
        ])
        .unwrap();
        assert_eq!(invocation.scene, Some(PathBuf::from("scene.pov")));
        assert_eq!(invocation.output, Some(PathBuf::from("out.png")));
        assert_eq!(invocation.library_paths, [PathBuf::from("includes")]);
        assert_eq!(invocation.animation.final_frame, 10);
        assert_eq!(
            invocation.picture_options,
            ["+W640", "+H480", "+A0.3", "Quality=9"]
        );
    }

    #[test]
    fn ini_files_with_comments_sections_and_switch_lines() {
        let dir = tempfile::tempdir().unwrap();
        let ini = dir.path().join("anim.ini");
        std::fs::write(
            &ini,
            "; an animation\n[frames]\nInput_File_Name=\"ball.pov\"\nInitial_Frame = 1 ; first\nFinal_Frame=24\n+W320 +H240\nAntialias=On\n",
        )
        .unwrap();
        let invocation = read(&[ini.to_str().unwrap(), "+Q4"]).unwrap();
        assert_eq!(invocation.scene, Some(PathBuf::from("ball.pov")));
        assert_eq!(invocation.animation.final_frame, 24);
        assert_eq!(
            invocation.picture_options,
            ["+W320", "+H240", "Antialias=On", "+Q4"]
        );

        std::fs::write(&ini, "Final_Frame=many\n").unwrap();
        let error = read(&[ini.to_str().unwrap()]).unwrap_err();
        assert!(
            error.ends_with(
                "anim.ini:1: option `Final_Frame=many`: expected a frame number, found 'many'"
            ),
            "{error}"
        );
        std::fs::write(&ini, format!("Include_Ini={}\n", ini.display())).unwrap();
        let error = read(&[ini.to_str().unwrap()]).unwrap_err();
        assert!(error.contains(".ini files include each other"), "{error}");
    }

    #[test]
    fn two_scenes_are_an_error() {
        assert_eq!(
            read(&["a.pov", "b.pov"]),
            Err("two scenes named: a.pov and b.pov".to_owned())
        );
    }
}
