#version 3.7;
// The objects of shapes2.inc, seen through inside() on a fixed grid and where rays from
// all around towards the origin hit them, to 2 decimals, and the normals there, to 1
// (POV-Ray's face angles are rounded, ours exact, which shows in the third).  Their bounding boxes are left
// out: how tightly a solid of planes is bounded is each file's own choice.  So is
// Pyramid2, which the manual only calls a four-sided pyramid of planes: ours is the solid
// twin of Pyramid, POV-Ray's a lower shape.  Like POV-Ray's, shapes2.inc is included after
// shapes.inc here.
#include "shapes.inc"
#include "shapes2.inc"
// A figure to Digits decimals, with the sign of zero dropped.
#macro Figure(V, Digits) str((abs(V) < 0.5 * pow(10, -Digits) ? 0 : V), 0, Digits) #end
// A surface has no inside, so which way its normal points is arbitrary: the sign is
// chosen to make the first component that is not zero positive.
#macro Unsigned(N)
  #local Flip = (abs(N.x) > 0.05 ? N.x : (abs(N.y) > 0.05 ? N.y : N.z));
  (Flip < 0 ? -N : N)
#end
#macro Triple(V, Digits) concat(Figure(V.x, Digits), " ", Figure(V.y, Digits), " ", Figure(V.z, Digits)) #end
#macro Probe(Name, Shape, Solid)
  #local Object = object { Shape }
  #if (Solid)
    #for (I, 0, 6)
      #local Row = "";
      #for (J, 0, 6)
        #for (K, 0, 6)
          #local P = <I + 0.41, J + 0.37, K + 0.43> * 3.2 / 7 - 1.6;
          #local Row = concat(Row, str(inside(Object, P), 0, 0));
        #end
      #end
      #debug concat(Name, " inside ", Row, "\n")
    #end
  #end
  #local Dir = array[14] { x, -x, y, -y, z, -z, <1, 1, 1>, <-1, 1, 1>, <1, -1, 1>, <1, 1, -1>,
                           <-1, -1, 1>, <-1, 1, -1>, <1, -1, -1>, <-1, -1, -1> }
  #for (D, 0, 13)
    #local Start = vnormalize(Dir[D]) * 5 + <0.0123, 0.0234, 0.0345>;
    #local N = <0, 0, 0>;
    #local Hit = trace(Object, Start, -Start, N);
    #if (!Solid)
      #local N = Unsigned(N);
    #end
    #debug concat(Name, " hit ", Triple(Hit, 2), " normal ", Triple(N, 1), "\n")
  #end
#end
Probe("Tetrahedron", Tetrahedron, true)
Probe("Octahedron", Octahedron, true)
Probe("Dodecahedron", Dodecahedron, true)
Probe("Icosahedron", Icosahedron, true)
Probe("Rhomboid", Rhomboid, true)
Probe("Hexagon", Hexagon, true)
Probe("HalfCone_Y", HalfCone_Y, true)
Probe("Pyramid", Pyramid, false)
Probe("Square_X", Square_X, false)
Probe("Square_Y", Square_Y, false)
Probe("Square_Z", Square_Z, false)
