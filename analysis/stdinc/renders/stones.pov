#version 3.7;
// Every texture of stones1.inc and stones2.inc on a box, the translucent ones over a
// checkered floor.
// POV-Ray's stones1.inc needs colors.inc first; ours does not.
#include "colors.inc"
#include "stones.inc"
global_settings { assumed_gamma 1 }
camera { orthographic location <5.5, 20, -4> look_at <5.5, 0, 4.5> right 12 * 4 / 3 * x up 12 * y }
light_source { <-20, 40, -30> rgb 1 }
plane { y, -0.5 pigment { checker rgb 0.1, rgb 0.9 scale 0.25 } }
#declare Textures = array[103] {
  T_Grnt0, T_Grnt1, T_Grnt2, T_Grnt3, T_Grnt4, T_Grnt5, T_Grnt6, T_Grnt7, T_Grnt8, T_Grnt9,
  T_Grnt10, T_Grnt11, T_Grnt12, T_Grnt13, T_Grnt14, T_Grnt15, T_Grnt16, T_Grnt17, T_Grnt18, T_Grnt19,
  T_Grnt20, T_Grnt21, T_Grnt22, T_Grnt23, T_Grnt24, T_Grnt25, T_Grnt26, T_Grnt27, T_Grnt28, T_Grnt29,
  T_Grnt0a, T_Grnt1a, T_Grnt2a, T_Grnt3a, T_Grnt4a, T_Grnt5a, T_Grnt6a, T_Grnt7a, T_Grnt8a, T_Grnt9a,
  T_Grnt10a, T_Grnt11a, T_Grnt12a, T_Grnt13a, T_Grnt14a, T_Grnt15a, T_Grnt16a, T_Grnt17a, T_Grnt18a, T_Grnt19a,
  T_Grnt20a, T_Grnt21a, T_Grnt22a, T_Grnt23a, T_Grnt24a, T_Crack1, T_Crack2, T_Crack3, T_Crack4,
  T_Stone1, T_Stone2, T_Stone3, T_Stone4, T_Stone5, T_Stone6, T_Stone7, T_Stone8, T_Stone9, T_Stone10,
  T_Stone11, T_Stone12, T_Stone13, T_Stone14, T_Stone15, T_Stone16, T_Stone17, T_Stone18, T_Stone19, T_Stone20,
  T_Stone21, T_Stone22, T_Stone23, T_Stone24, T_Stone25, T_Stone26, T_Stone27, T_Stone28, T_Stone29, T_Stone30,
  T_Stone31, T_Stone32, T_Stone33, T_Stone34, T_Stone35, T_Stone36, T_Stone37, T_Stone38, T_Stone39, T_Stone40,
  T_Stone41, T_Stone42, T_Stone43, T_Stone44
}
#for (I, 0, 102)
  box { <-0.45, -0.45, -0.45>, <0.45, 0.45, 0.45> texture { Textures[I] } translate <mod(I, 12), 0, div(I, 12)> }
#end
