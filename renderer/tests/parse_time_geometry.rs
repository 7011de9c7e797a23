//! trace(), inside() and the extents, answered by the renderer's shapes at parse time.

use analysis::{EvalOptions, MemoryFiles, evaluate_with};
use renderer::SceneGeometry;

#[test]
fn scenes_can_ask_the_renderer_about_shapes() {
    let scene = r#"#version 3.7;
#declare B = difference { box { -1, 1 } sphere { <0, 1, 0>, 0.5 } translate 2*x }
#declare P = trace(B, <2, 5, 0>, -y, N);
#debug concat(vstr(3, P, ",", 0, 2), " ", vstr(3, N, ",", 0, 2), "\n")
#debug concat(str(inside(B, <2, 0, 0>), 0, 0), str(inside(B, <2, 0.9, 0>), 0, 0), "\n")
#debug concat(vstr(3, min_extent(B), ",", 0, 1), " ", vstr(3, max_extent(B), ",", 0, 1), "\n")
#declare Miss = trace(B, <10, 10, 10>, y, M);
#debug concat(vstr(3, M, ",", 0, 0), "\n")
"#;
    let files = MemoryFiles::new().with("scene.pov", scene);
    let evaluation = evaluate_with("scene.pov", &files, &EvalOptions::default(), &SceneGeometry);
    assert!(!evaluation.has_errors(), "{:?}", evaluation.diagnostics);
    assert_eq!(
        evaluation.debug_text(),
        "2.00,0.50,0.00 -0.00,1.00,-0.00\n10\n1.0,-1.0,-1.0 3.0,1.0,1.0\n0,0,0\n"
    );
}

/// The `object` pattern asks the renderer's shapes too, so it works with every shape and
/// agrees with `inside()`: benchmark.pov colours a cylinder by the inside of a `text`.
#[test]
fn object_patterns_agree_with_inside() {
    let scene = r#"#version 3.7;
#declare Shapes = array[3] {
  text { internal 1 "X" 1, 0 },
  isosurface { function { x*x + y*y + z*z - 1 } contained_by { box { -2, 2 } } },
  blob { threshold 0.5 sphere { 0, 1, 2 } sphere { x, 1, 2 } }
}
#for (S, 0, 2)
  #declare Pattern = function { pattern { object { Shapes[S] } } }
  #declare Seen = "";
  #declare Asked = "";
  #for (X, -1, 1.5, 0.025)
    #declare P = <X, 0.3, 0.5>;
    #declare Seen = concat(Seen, str(Pattern(P.x, P.y, P.z), 0, 0));
    #declare Asked = concat(Asked, str(inside(Shapes[S], P), 0, 0));
  #end
  #debug concat(Seen, " ", Asked, "\n")
  #undef Pattern
#end
"#;
    let files = MemoryFiles::new().with("scene.pov", scene);
    let evaluation = evaluate_with("scene.pov", &files, &EvalOptions::default(), &SceneGeometry);
    assert!(!evaluation.has_errors(), "{:?}", evaluation.diagnostics);
    let text = evaluation.debug_text();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 3, "{text}");
    for line in lines {
        let (seen, asked) = line.split_once(' ').expect("two columns");
        assert_eq!(seen, asked);
        assert!(seen.contains('0') && seen.contains('1'), "{line}");
    }
}
