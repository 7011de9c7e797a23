#version 3.7;
// Irregular_Bricks_Ptrn from textures.inc, which is built differently from POV-Ray's and
// meant only to look alike: compare the two renders by eye (render-with-povray.sh gives
// the figures).
#include "textures.inc"
global_settings { assumed_gamma 1 }
camera { orthographic location <4, 3, -10> look_at <4, 3, 0> right 8 * 4 / 3 * x up 8 * y }
light_source { <-10, 20, -30> rgb 1 }
plane { -z, 0
  texture {
    pigment { Irregular_Bricks_Ptrn(0.1, 2, 0.5, 0.3) color_map { [0.02 rgb 0.85] [0.02 rgb <0.7, 0.3, 0.2>] } }
    normal { Irregular_Bricks_Ptrn(0.1, 2, 0.5, 0.3) 2 }
  }
}
