#version 3.7;
// The colour identifiers of textures.inc, which the manual names but does not give.
#include "textures.inc"
#macro Show(Name, Colour)
  #local C = color Colour;
  #debug concat(Name, " ", vstr(5, <C.red, C.green, C.blue, C.filter, C.transmit>, " ", 0, 6), "\n")
#end
Show("Silver1_Colour", Silver1_Colour)
Show("Silver2_Colour", Silver2_Colour)
Show("Silver3_Colour", Silver3_Colour)
