#version 3.7;
// The pattern macros of textures.inc, sampled on a grid through a grey colour map.
// Irregular_Bricks_Ptrn is left out: ours is built differently and only looks alike.
#include "textures.inc"
#macro Sample(Label, Pattern_Pigment, Plane)
  #local Sampler = function { pigment { Pattern_Pigment } }
  #for (J, 0, 12)
    #local Row = "";
    #for (I, 0, 12)
      #local U = I * 0.23 - 1.37;
      #local V = J * 0.21 - 1.29;
      #local P = (Plane = 0 ? <U, V, 0.3> : <U, 0.3, V>);
      #local Row = concat(Row, " ", str(Sampler(P.x, P.y, P.z).red, 0, 2));
    #end
    #debug concat(Label, Row, "\n")
  #end
#end
Sample("tiles", pigment { Tiles_Ptrn() color_map { [0 rgb 0] [1 rgb 1] } }, 0)
Sample("hex", pigment { Hex_Tiles_Ptrn() color_map { [0 rgb 0] [1 rgb 1] } scale 0.7 }, 1)
Sample("star52", pigment { Star_Ptrn(1, 5, 2) color_map { [0 rgb 0] [1 rgb 1] } }, 0)
Sample("star61", pigment { Star_Ptrn(1.2, 6, 1) color_map { [0 rgb 0] [1 rgb 1] } }, 0)
Sample("star83", pigment { Star_Ptrn(1.3, 8, 3) color_map { [0 rgb 0] [1 rgb 1] } }, 0)
