use super::lint;
use crate::files::MemoryFiles;
use expect_test::{Expect, expect};

/// Lints `scene.pov` among `files` and shows the warnings as `povrayst check` prints them.
#[track_caller]
fn check(files: &[(&str, &str)], expected: Expect) {
    let mut memory = MemoryFiles::new();
    for (name, text) in files {
        memory.insert(*name, *text);
    }
    let linted = lint("scene.pov", &memory);
    let codes: Vec<&str> = linted.warnings.iter().filter_map(|w| w.code).collect();
    assert_eq!(codes.len(), linted.warnings.len(), "every lint has a code");
    expected.assert_eq(&syntax::diagnostic::render_human(
        &linted.warnings,
        &linted.sources,
    ));
}

#[test]
fn a_clean_scene_has_no_warnings() {
    check(
        &[(
            "scene.pov",
            "#version 3.7;\n#declare R = 1;\n#macro Ball(C) sphere { C, R } #end\nBall(0)\n",
        )],
        expect![""],
    );
}

#[test]
fn declarations_of_an_include_checked_on_its_own_are_not_unused() {
    let memory = MemoryFiles::new().with("shapes.inc", "#declare S = 1;");
    assert!(lint("shapes.inc", &memory).warnings.is_empty());
}

#[test]
fn unused_declarations_of_the_scene_and_uses_in_includes() {
    check(
        &[
            (
                "scene.pov",
                "#version 3.7;\n#declare Unused = 1;\n#declare Unused = 2;\n#declare ReadByInclude = 2;\n#local Alone = 3;\n#declare I = 0;\n#declare I = I + 1;\n#include \"mine.inc\"\n",
            ),
            ("mine.inc", "#declare Forgotten = ReadByInclude;\n"),
        ],
        expect![[r#"
            scene.pov:2:10: warning: 'Unused' is declared by #declare but never used
                2 | #declare Unused = 1;
                  |          ^~~~~~
            scene.pov:5:8: warning: 'Alone' is declared by #local but never used
                5 | #local Alone = 3;
                  |        ^~~~~
        "#]],
    );
}

#[test]
fn macro_parameters_and_locals_that_shadow_globals_from_includes() {
    check(
        &[
            (
                "scene.pov",
                "#version 3.7;\n#include \"colors.inc\"\n#include \"mine.inc\"\n#macro M(Red, X) #local Size = X; #local Own = Red; sphere { 0, Size + Own } #end\nM(1, 2)\n",
            ),
            ("mine.inc", "#declare Size = 1;\n"),
        ],
        expect![[r#"
            scene.pov:4:10: warning: macro parameter 'Red' shadows the global of the same name
                4 | #macro M(Red, X) #local Size = X; #local Own = Red; sphere { 0, Size + Own } #end
                  |          ^~~
            colors.inc:18:10: note: the global 'Red' is declared here
               18 | #declare Red               = rgb <1, 0, 0>;
                  |          ^~~
            scene.pov:4:25: warning: #local 'Size' shadows the global of the same name
                4 | #macro M(Red, X) #local Size = X; #local Own = Red; sphere { 0, Size + Own } #end
                  |                         ^~~~
            mine.inc:1:10: note: the global 'Size' is declared here
                1 | #declare Size = 1;
                  |          ^~~~
        "#]],
    );
}

#[test]
fn legacy_syntax_in_the_scene_and_its_own_includes() {
    check(
        &[
            (
                "scene.pov",
                "#version 3.7;\n#include \"glass_old.inc\"\n#include \"old.inc\"\nglobal_settings { hf_gray_16 }\nblob { component 1, 1, 0 }\n",
            ),
            (
                "old.inc",
                "plane { y, 0 texture { tiles { texture { T1 } tile2 texture { T2 } } } }\n",
            ),
        ],
        expect![[r#"
            old.inc:1:24: warning: 'tiles' is an obsolete patterned texture; use 'texture { checker texture { ... } texture { ... } }'
                1 | plane { y, 0 texture { tiles { texture { T1 } tile2 texture { T2 } } } }
                  |                        ^~~~~
            scene.pov:2:1: warning: glass_old.inc is deprecated since POV-Ray 3.7; the materials of glass.inc replace it
                2 | #include "glass_old.inc"
                  | ^~~~~~~~~~~~~~~~~~~~~~~~
            scene.pov:4:19: warning: 'hf_gray_16' has no effect since POV-Ray 3.7; choose a grayscale output format instead
                4 | global_settings { hf_gray_16 }
                  |                   ^~~~~~~~~~
            scene.pov:5:8: warning: 'component' is the obsolete form of a blob component; use 'sphere { center, radius, strength }' inside the blob
                5 | blob { component 1, 1, 0 }
                  |        ^~~~~~~~~
        "#]],
    );
}

#[test]
fn misspelt_keywords_even_in_branches_never_taken() {
    check(
        &[(
            "scene.pov",
            "#version 3.7;\n#declare lowercase_name = 1;\n#if (0) sphere { 0, 1 pigmnet { rgb 1 } } #end\nsphere { 0, lowercase_name finsh { phong 1 } }\n#declare Val = dictionary { .cololr: 1 };\n#fopen F \"x\" read #read (F, raed)\n",
        )],
        expect![[r#"
            scene.pov:3:23: warning: unknown keyword 'pigmnet'
                3 | #if (0) sphere { 0, 1 pigmnet { rgb 1 } } #end
                  |                       ^~~~~~~
            note: did you mean 'pigment'?
            scene.pov:4:28: warning: unknown keyword 'finsh'
                4 | sphere { 0, lowercase_name finsh { phong 1 } }
                  |                            ^~~~~
            note: did you mean 'finish'?
            scene.pov:5:10: warning: 'Val' is declared by #declare but never used
                5 | #declare Val = dictionary { .cololr: 1 };
                  |          ^~~
        "#]],
    );
}

#[test]
fn includes_named_by_an_expression_are_not_followed() {
    let memory = MemoryFiles::new()
        .with("scene.pov", "#version 3.7;\n#declare N = \"a.inc\";\n#include N\n#include concat(\"b\", \".inc\")\n")
        .with("a.inc", "#declare A = 1;");
    let workspace = super::Workspace::load("scene.pov", &memory);
    let names: Vec<&str> = workspace.files.iter().map(|f| f.name.as_str()).collect();
    assert_eq!(names, ["scene.pov"]);
}
