//! `povrayst render` with POV-Ray's own options and `.ini` files, animations, tiles for job
//! arrays and `povrayst stitch`, and no progress bar when standard error is a pipe.

use std::path::Path;
use std::process::{Command, Output};

const SCENE: &str = "#version 3.7;\n\
    global_settings { assumed_gamma 1 }\n\
    camera { location <0, 0, -4> look_at 0 }\n\
    light_source { <2, 4, -3>, rgb 1 }\n\
    sphere { 0, 1 pigment { rgb <1, clock, 0> } }\n\
    #debug concat(\"frame \", str(frame_number, 0, 0), \" clock \", str(clock, 0, 2), \"\\n\")\n";

fn povrayst(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_povrayst"))
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap()
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

/// Width, height and the pixel bytes of a PNG file.
fn pixels(path: &Path) -> (u32, u32, Vec<u8>) {
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    let mut data = vec![0; reader.output_buffer_size().unwrap()];
    let frame = reader.next_frame(&mut data).unwrap();
    data.truncate(frame.buffer_size());
    (frame.width, frame.height, data)
}

fn scene_dir() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("scene.pov"), SCENE).unwrap();
    dir
}

#[test]
fn povray_switches_and_ini_files_set_the_picture() {
    let dir = scene_dir();
    let output = povrayst(
        dir.path(),
        &["render", "scene.pov", "+W8", "+H6", "+A0.3", "+Q9"],
    );
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert_eq!(
        stderr(&output),
        "frame 0 clock 0.00\n",
        "no progress bar in a pipe"
    );
    assert_eq!(pixels(&dir.path().join("scene.png")).0, 8);

    std::fs::write(
        dir.path().join("small.ini"),
        "; a small still\nInput_File_Name=scene.pov\nOutput_File_Name=small.png\nWidth=5\nHeight=4\n+Q4\n",
    )
    .unwrap();
    let output = povrayst(dir.path(), &["render", "small.ini", "--", "-A"]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    let (width, height, _) = pixels(&dir.path().join("small.png"));
    assert_eq!((width, height), (5, 4));

    let output = povrayst(dir.path(), &["render", "scene.pov", "+Frobnicate"]);
    assert_eq!(output.status.code(), Some(2));
    assert_eq!(
        stderr(&output),
        "povrayst: option `+Frobnicate`: unknown option\n"
    );
}

#[test]
fn animations_render_each_frame_with_its_clock_and_number() {
    let dir = scene_dir();
    let output = povrayst(
        dir.path(),
        &[
            "render",
            "scene.pov",
            "+W4",
            "+H3",
            "+KFI1",
            "+KFF3",
            "-o",
            "ball.png",
        ],
    );
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert_eq!(
        stderr(&output),
        "frame 1 clock 0.00\nframe 2 clock 0.50\nframe 3 clock 1.00\n"
    );
    for name in ["ball1.png", "ball2.png", "ball3.png"] {
        assert!(dir.path().join(name).is_file(), "{name}");
    }
    assert!(!dir.path().join("ball.png").exists());

    // One job of an array: frames 9 and 10 of 12.
    let output = povrayst(
        dir.path(),
        &[
            "render",
            "scene.pov",
            "+W4",
            "+H3",
            "Final_Frame=12",
            "--frames",
            "9-10",
        ],
    );
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert_eq!(stderr(&output), "frame 9 clock 0.73\nframe 10 clock 0.82\n");
    let mut names: Vec<String> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|n| n.starts_with("scene") && n.ends_with(".png"))
        .collect();
    names.sort();
    assert_eq!(names, ["scene09.png", "scene10.png"]);
}

#[test]
fn tiles_stitch_into_the_whole_picture() {
    let dir = scene_dir();
    // Without antialiasing, each pixel is one ray, so bands render exactly as the whole.
    let common = ["scene.pov", "+W9", "+H7", "Antialias=off", "+UA"];
    let whole = povrayst(
        dir.path(),
        &[&["render"][..], &common, &["-o", "whole.png"]].concat(),
    );
    assert_eq!(whole.status.code(), Some(0), "{}", stderr(&whole));
    let mut tiles = Vec::new();
    for tile in ["3/3", "1/3", "2/3"] {
        let output = povrayst(
            dir.path(),
            &[
                &["render"][..],
                &common,
                &["--tile", tile, "-o", "part.png"],
            ]
            .concat(),
        );
        assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    }
    for index in 1..=3 {
        let name = format!("part.tile-{index}-of-3.png");
        let (width, height, _) = pixels(&dir.path().join(&name));
        assert_eq!((width, height), (9, [2, 2, 3][index - 1]), "{name}");
        tiles.push(name);
    }
    tiles.reverse();
    let args: Vec<&str> = ["stitch"]
        .into_iter()
        .chain(tiles.iter().map(String::as_str))
        .chain(["-o", "joined.png"])
        .collect();
    let stitched = povrayst(dir.path(), &args);
    assert_eq!(stitched.status.code(), Some(0), "{}", stderr(&stitched));
    assert_eq!(
        pixels(&dir.path().join("joined.png")),
        pixels(&dir.path().join("whole.png"))
    );

    let missing = povrayst(
        dir.path(),
        &["stitch", &tiles[0], &tiles[1], "-o", "joined.png"],
    );
    assert_eq!(missing.status.code(), Some(2));
    assert_eq!(
        stderr(&missing),
        "povrayst: the tiles are not 1 to 3 of 3, once each: found [2, 3]\n"
    );
    let bad = povrayst(dir.path(), &["render", "scene.pov", "+H2", "--tile", "3/4"]);
    assert_eq!(
        stderr(&bad),
        "povrayst: tile 3/4 has no rows in a picture 2 rows high\n"
    );
}
