#version 3.7;
// Every texture of metals.inc and golds.inc on a sphere, over a checkered floor and under
// a sky that the metals can reflect.
#include "colors.inc"
#include "metals.inc"
global_settings { assumed_gamma 1 }
camera { orthographic location <5.5, 12, -3> look_at <5.5, 0, 5.5> right 13 * x * 4 / 3 up 13 * y }
light_source { <-20, 40, -30> rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.6, 0.7, 1>] [1 rgb <0.1, 0.2, 0.6>] } } }
plane { y, -0.5 pigment { checker rgb 0.2, rgb 0.9 scale 0.5 } }
#declare Textures = array[125] {
  T_Brass_1A, T_Brass_1B, T_Brass_1C, T_Brass_1D, T_Brass_1E, T_Brass_2A, T_Brass_2B, T_Brass_2C, T_Brass_2D, T_Brass_2E,
  T_Brass_3A, T_Brass_3B, T_Brass_3C, T_Brass_3D, T_Brass_3E, T_Brass_4A, T_Brass_4B, T_Brass_4C, T_Brass_4D, T_Brass_4E,
  T_Brass_5A, T_Brass_5B, T_Brass_5C, T_Brass_5D, T_Brass_5E,
  T_Copper_1A, T_Copper_1B, T_Copper_1C, T_Copper_1D, T_Copper_1E, T_Copper_2A, T_Copper_2B, T_Copper_2C, T_Copper_2D, T_Copper_2E,
  T_Copper_3A, T_Copper_3B, T_Copper_3C, T_Copper_3D, T_Copper_3E, T_Copper_4A, T_Copper_4B, T_Copper_4C, T_Copper_4D, T_Copper_4E,
  T_Copper_5A, T_Copper_5B, T_Copper_5C, T_Copper_5D, T_Copper_5E,
  T_Chrome_1A, T_Chrome_1B, T_Chrome_1C, T_Chrome_1D, T_Chrome_1E, T_Chrome_2A, T_Chrome_2B, T_Chrome_2C, T_Chrome_2D, T_Chrome_2E,
  T_Chrome_3A, T_Chrome_3B, T_Chrome_3C, T_Chrome_3D, T_Chrome_3E, T_Chrome_4A, T_Chrome_4B, T_Chrome_4C, T_Chrome_4D, T_Chrome_4E,
  T_Chrome_5A, T_Chrome_5B, T_Chrome_5C, T_Chrome_5D, T_Chrome_5E,
  T_Silver_1A, T_Silver_1B, T_Silver_1C, T_Silver_1D, T_Silver_1E, T_Silver_2A, T_Silver_2B, T_Silver_2C, T_Silver_2D, T_Silver_2E,
  T_Silver_3A, T_Silver_3B, T_Silver_3C, T_Silver_3D, T_Silver_3E, T_Silver_4A, T_Silver_4B, T_Silver_4C, T_Silver_4D, T_Silver_4E,
  T_Silver_5A, T_Silver_5B, T_Silver_5C, T_Silver_5D, T_Silver_5E,
  T_Gold_1A, T_Gold_1B, T_Gold_1C, T_Gold_1D, T_Gold_1E, T_Gold_2A, T_Gold_2B, T_Gold_2C, T_Gold_2D, T_Gold_2E,
  T_Gold_3A, T_Gold_3B, T_Gold_3C, T_Gold_3D, T_Gold_3E, T_Gold_4A, T_Gold_4B, T_Gold_4C, T_Gold_4D, T_Gold_4E,
  T_Gold_5A, T_Gold_5B, T_Gold_5C, T_Gold_5D, T_Gold_5E
}
#for (I, 0, 124)
  sphere { <mod(I, 12), 0, div(I, 12)>, 0.45 texture { Textures[I] } }
#end
// The finishes that metals.inc leaves under the shared names.
#for (I, 0, 4)
  #local F = array[5] { F_MetalA, F_MetalB, F_MetalC, F_MetalD, F_MetalE }
  sphere { <5 + I, 0, 10.5>, 0.45 pigment { rgb <0.8, 0.3, 0.3> } finish { F[I] } }
#end
