//! Scenes with one mistake each, shared by the tests that check that every front end (the
//! CLI's `check`, a Typst compile, the language server) reports it with the same words at
//! the same place. The main file is always `scene.pov`.

/// One broken scene and the include files beside it.
#[derive(Debug, Clone, Copy)]
pub struct BrokenScene {
    pub what: &'static str,
    pub scene: &'static str,
    pub includes: &'static [(&'static str, &'static str)],
}

pub const BROKEN_SCENES: &[BrokenScene] = &[
    BrokenScene {
        what: "unclosed brace",
        scene: "sphere { 0, 1\n  pigment { rgb 1 }\n",
        includes: &[],
    },
    BrokenScene {
        what: "undeclared identifier",
        scene: "#declare Radius = 1;\nsphere { 0, Raduis }\n",
        includes: &[],
    },
    BrokenScene {
        what: "missing #end",
        scene: "#if (1)\n  sphere { 0, 1 }\n",
        includes: &[],
    },
    BrokenScene {
        what: "#error",
        scene: "#declare N = 3;\n#error concat(\"N is \", str(N, 0, 0))\n",
        includes: &[],
    },
    BrokenScene {
        what: "missing include",
        scene: "#include \"materials.inc\"\n",
        includes: &[("other.inc", "")],
    },
    BrokenScene {
        what: "error inside an include",
        scene: "#include \"materials.inc\"\nsphere { 0, 1 texture { Copper } }\n",
        // The undeclared `Tint` is at materials.inc:3:7.
        includes: &[(
            "materials.inc",
            "#declare Copper = texture {\n  pigment { color\n  rgb Tint }\n}\n",
        )],
    },
    BrokenScene {
        // Evaluates without error: the renderer refuses it when it builds the world.
        what: "a feature not drawn yet",
        scene: "#version 3.7;\nglobal_settings { photons { count 100 } }\nlight_group {\n  light_source { <0, 5, -5> rgb 1 }\n  sphere { 0, 1 }\n}\n",
        includes: &[],
    },
];
