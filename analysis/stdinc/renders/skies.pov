#version 3.7;
// The pigments, textures and objects of skies.inc, under S_Cloud5 (sky1.pov to sky4.pov
// show the other sky spheres).
#include "colors.inc"
#include "skies.inc"
global_settings { assumed_gamma 1 }
camera { orthographic location <3, 2, -10> look_at <3, 2, 0> right 7 * 4 / 3 * x up 7 * y }
light_source { <-20, 40, -30> rgb 1 }
#declare Pigments = array[4] { P_Cloud1, P_Cloud2, P_Cloud3, P_Cloud4 }
#for (I, 0, 3)
  box { <-0.7, -0.7, 0>, <0.7, 0.7, 1> pigment { Pigments[I] scale 0.3 } finish { ambient 1 diffuse 0 } translate <I * 1.6, 4, 0> }
#end
#declare Textures = array[3] { T_Cloud1, T_Cloud2, T_Cloud3 }
#for (I, 0, 2)
  box { <-0.7, -0.7, 0>, <0.7, 0.7, 1> texture { Textures[I] scale 0.3 } translate <I * 1.6, 2.4, 0> }
#end
sky_sphere { S_Cloud5 }
object { O_Cloud1 scale 0.0001 translate <5, 0.8, 5> }
object { O_Cloud2 scale 0.001 translate <0, -1, 3> }
