#version 3.7;
// The objects of shapes2.inc, seen through their bounding boxes, inside() on a grid
// across the box and where rays from all around hit them.  Like POV-Ray's, shapes2.inc
// needs shapes.inc first.
#include "shapes.inc"
#include "shapes2.inc"
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
Probe("Tetrahedron", Tetrahedron)
Probe("Octahedron", Octahedron)
Probe("Dodecahedron", Dodecahedron)
Probe("Icosahedron", Icosahedron)
Probe("Rhomboid", Rhomboid)
Probe("Hexagon", Hexagon)
Probe("HalfCone_Y", HalfCone_Y)
Probe("Pyramid2", Pyramid2)
ProbeSurface("Pyramid", Pyramid)
ProbeSurface("Square_X", Square_X)
ProbeSurface("Square_Y", Square_Y)
ProbeSurface("Square_Z", Square_Z)
