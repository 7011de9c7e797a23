#version 3.7;
// The objects of shapes_old.inc, seen through their bounding boxes, inside() on a grid
// and where rays hit them.
#include "shapes_old.inc"
#declare Shapes = array[25] {
  Ellipsoid, Sphere, Cylinder_X, Cylinder_Y, Cylinder_Z, QCone_X, QCone_Y, QCone_Z,
  Cone_X, Cone_Y, Cone_Z, Plane_YZ, Plane_XZ, Plane_XY, Paraboloid_X, Paraboloid_Y,
  Paraboloid_Z, Hyperboloid, Hyperboloid_Y, UnitBox, Cube, Disk_X, Disk_Y, Disk_Z, Sphere
}
#declare Names = array[25] {
  "Ellipsoid", "Sphere", "Cylinder_X", "Cylinder_Y", "Cylinder_Z", "QCone_X", "QCone_Y",
  "QCone_Z", "Cone_X", "Cone_Y", "Cone_Z", "Plane_YZ", "Plane_XZ", "Plane_XY",
  "Paraboloid_X", "Paraboloid_Y", "Paraboloid_Z", "Hyperboloid", "Hyperboloid_Y", "UnitBox",
  "Cube", "Disk_X", "Disk_Y", "Disk_Z", "Sphere"
}
#declare Origins = array[4] { <3, 0.3, 0.2>, <0.2, 3, -0.1>, <-0.15, 0.25, -3>, <2, 2, 2> }
#for (I, 0, 24)
  #local S = Shapes[I];
  #local Low = min_extent(S);
  #local High = max_extent(S);
  #debug concat(Names[I], " extent ", vstr(3, Low, " ", 0, 3), " / ", vstr(3, High, " ", 0, 3), "\n")
  #local Inside = "";
  #for (X, -1.5, 1.5, 0.75)
    #for (Y, -1.5, 1.5, 0.75)
      #for (Z, -1.5, 1.5, 0.75)
        #local Inside = concat(Inside, str(inside(S, <X + 0.01, Y + 0.02, Z + 0.03>), 0, 0));
      #end
    #end
    #debug concat(Names[I], " inside ", Inside, "\n")
    #local Inside = "";
  #end
  #for (R, 0, 3)
    #local N = <0, 0, 0>;
    #local P = trace(S, Origins[R], -Origins[R], N);
    #debug concat(Names[I], " trace ", vstr(3, P, " ", 0, 4), " normal ", vstr(3, N, " ", 0, 4), "\n")
  #end
#end
