#version 3.7;
// The surfaces of shapesq.inc cut down to a box, seen through inside() on a grid across
// the box and where rays from all around hit them.  Left out: Crossed_Trough, Piriform and
// Quartic_Paraboloid (ours follow the manual's equations, POV-Ray's are scaled or turned
// otherwise), Twin_Glob, Quartic_Cylinder, Witch_Hat and Sinsurf (the manual gives no
// equation, so ours are our own surfaces), and Helix and Helix_1 (POV-Ray's are unbounded
// and trace() misses them from every side, which says nothing about their shape).
#include "shapes.inc"
#include "shapesq.inc"
#macro Probe(Name, Shape) ProbeWith(Name, Shape, true, 4) #end
#macro ProbeSurface(Name, Shape) ProbeWith(Name, Shape, false, 4) #end
// Text is compared to 3 decimals: our letter placement computes the same positions in a
// different order, which moves some figures by 1e-4.
#macro ProbeText(Name, Shape) ProbeWith(Name, Shape, true, 3) #end
#macro ProbeWith(Name, Shape, Solid, Digits)
  #local Object = object { Shape }
  #local Low = min_extent(Object);
  #local High = max_extent(Object);
  #debug concat(Name, " extent ", vstr(3, Low, " ", 0, Digits), " / ", vstr(3, High, " ", 0, Digits), "\n")
  #local Size = High - Low;
  #local Middle = (Low + High) / 2;
  #if (Solid)
    #for (I, 0, 6)
      #local Row = "";
      #for (J, 0, 6)
        #for (K, 0, 6)
          #local P = Low + Size * <I + 0.41, J + 0.37, K + 0.43> / 7.2;
          #local Row = concat(Row, str(inside(Object, P), 0, 0));
        #end
      #end
      #debug concat(Name, " inside ", Row, "\n")
    #end
  #end
  #local Reach = vlength(Size) + 1;
  #for (D, 0, 13)
    #local Dir = array[14] { x, -x, y, -y, z, -z, <1, 1, 1>, <-1, 1, 1>, <1, -1, 1>, <1, 1, -1>,
                             <-1, -1, 1>, <-1, 1, -1>, <1, -1, -1>, <-1, -1, -1> }
    #local Start = Middle + vnormalize(Dir[D]) * Reach + <0.0123, 0.0234, 0.0345> * vlength(Size);
    #local N = <0, 0, 0>;
    #local Hit = trace(Object, Start, Middle - Start, N);
    #debug concat(Name, " hit ", vstr(3, Hit, " ", 0, Digits), " normal ", vstr(3, N, " ", 0, Digits), "\n")
  #end
#end
Probe("Bicorn", intersection { object { Bicorn } box { <-1.5, -1.5, -1.5>, <1.5, 1.5, 1.5> } })
Probe("Cubic_Cylinder", intersection { object { Cubic_Cylinder } box { <-1.5, -1.5, -1.5>, <1.5, 1.5, 1.5> } })
Probe("Cubic_Saddle_1", intersection { object { Cubic_Saddle_1 } box { <-1.5, -1.5, -1.5>, <1.5, 1.5, 1.5> } })
Probe("Devils_Curve", intersection { object { Devils_Curve } box { <-1.5, -1.5, -1.5>, <1.5, 1.5, 1.5> } })
Probe("Folium", intersection { object { Folium } box { <-1.5, -1.5, -1.5>, <1.5, 1.5, 1.5> } })
Probe("Glob_5", intersection { object { Glob_5 } box { <-1.5, -1.5, -1.5>, <1.5, 1.5, 1.5> } })
Probe("Hyperbolic_Torus_40_12", intersection { object { Hyperbolic_Torus_40_12 } box { <-12, -12, -12>, <12, 12, 12> } })
Probe("Lemniscate", intersection { object { Lemniscate } box { <-1.5, -1.5, -1.5>, <1.5, 1.5, 1.5> } })
Probe("Quartic_Loop_1", intersection { object { Quartic_Loop_1 } box { <-1.5, -1.5, -1.5>, <1.5, 1.5, 1.5> } })
Probe("Monkey_Saddle", intersection { object { Monkey_Saddle } box { <-1.5, -1.5, -1.5>, <1.5, 1.5, 1.5> } })
Probe("Parabolic_Torus_40_12", intersection { object { Parabolic_Torus_40_12 } box { <-12, -12, -12>, <12, 12, 12> } })
Probe("Steiner_Surface", intersection { object { Steiner_Surface } box { <-1.5, -1.5, -1.5>, <1.5, 1.5, 1.5> } })
Probe("Torus_40_12", intersection { object { Torus_40_12 } box { <-12, -12, -12>, <12, 12, 12> } })
