#version 3.7;
// The finishes, interiors and old textures of glass.inc and glass_old.inc on spheres in
// front of a striped backdrop that shows refraction.
#include "colors.inc"
#include "glass.inc"
global_settings { assumed_gamma 1 max_trace_level 10 }
camera { location <3.5, 3, -9> look_at <3.5, 1.5, 0> angle 45 }
light_source { <-10, 20, -20> rgb 1 }
plane { z, 3 pigment { gradient x color_map { [0.5 rgb <0.9, 0.3, 0.2>] [0.5 rgb 0.95] } scale 0.5 } }
plane { y, -0.5 pigment { checker rgb 0.2, rgb 0.8 } }
#declare Finishes = array[6] { F_Glass5, F_Glass6, F_Glass7, F_Glass8, F_Glass9, F_Glass10 }
#declare Long_Fade = interior { I_Glass_Exp(3) }
#declare Interiors = array[10] { I_Glass1, I_Glass2, I_Glass3, I_Glass4, I_Glass_Fade_Sqr1,
  I_Glass_Dispersion1, I_Glass_Dispersion2, I_Glass_Caustics1, I_Glass_Caustics2, Long_Fade }
#for (I, 0, 5)
  sphere { <I * 1.2, 0, 0>, 0.5
    material { texture { pigment { Col_Glass_Bluish } finish { Finishes[I] } } interior { Interiors[I] } } }
#end
#for (I, 6, 9)
  sphere { <(I - 6) * 1.2, 1.3, 0>, 0.5
    material { texture { pigment { Col_Glass_General } finish { F_Glass6 } }
               interior { Interiors[I] fade_color Col_Amethyst_03 } } }
#end
#declare Old = array[13] { T_Glass1, T_Glass2, T_Glass3, T_Glass4, T_Old_Glass, T_Winebottle_Glass,
  T_Beerbottle_Glass, T_Ruby_Glass, T_Green_Glass, T_Dark_Green_Glass, T_Yellow_Glass, T_Orange_Glass,
  T_Vicksbottle_Glass }
#for (I, 0, 12)
  sphere { <mod(I, 7) * 1.1 - 0.2, 2.5 + div(I, 7), 0.5>, 0.45 texture { Old[I] } interior { I_Glass } }
#end
sphere { <5, 1.3, 0>, 0.5 material { texture { pigment { Col_Glass_Ruby } finish { F_Glass1 } } interior { I_Glass_Sqr(0.8) } } }
