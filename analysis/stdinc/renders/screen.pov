#version 3.7;
// screen.inc's camera, objects and plane: a scene seen from a moved camera with a
// label object in a corner and a translucent panel along the bottom.
#include "colors.inc"
#include "screen.inc"
global_settings { assumed_gamma 1 }
Set_Camera(<3, 4, -8>, <0, 1, 0>, 50)
light_source { <-10, 20, -20> rgb 1 }
plane { y, 0 pigment { checker rgb 0.3, rgb 0.8 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.8, 0.3, 0.2> } }
Screen_Object(sphere { 0, 1 pigment { rgb <0.2, 0.4, 0.9> } scale <2, 1, 1> }, <1, 1>, 0.05, true, 0.02)
Screen_Object(box { -1, 1 pigment { Yellow } }, <0, 1>, <0.1, 0.02>, true, 0.1)
Screen_Plane(texture { pigment { rgbt <1, 1, 1, 0.5> } finish { ambient 1 diffuse 0 } }, 0.5, <0.1, 0.05>, <0.9, 0.2>)
