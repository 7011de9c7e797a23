#version 3.7;
// The six starfields of stars.inc on panels, scaled up so that the stars are several
// pixels wide at 240x180.
#include "stars.inc"
global_settings { assumed_gamma 1 }
camera { orthographic location <2.5, 1, -10> look_at <2.5, 1, 0> right 6.2 * 4 / 3 * x up 6.2 * y }
#declare Fields = array[6] { Starfield1, Starfield2, Starfield3, Starfield4, Starfield5, Starfield6 }
#for (I, 0, 5)
  box { <-0.8, -1.4, 0>, <0.8, 1.4, 1> texture { Fields[I] scale 3 } translate <I, 1, 0> }
#end
