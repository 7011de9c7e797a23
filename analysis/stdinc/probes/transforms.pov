#version 3.7;
// The transformations of transforms.inc, seen through where they send a few points.
#include "transforms.inc"
#declare Points = array[3] { <1, 0, 0>, <0.3, -1.2, 2>, <-2, 0.5, 0.25> }
#macro Show(Label, Trans)
  #for (I, 0, 2)
    #debug concat(Label, " ", vstr(3, vtransform(Points[I], Trans), " ", 0, 5), "\n")
  #end
  #debug concat(Label, " inverse ", vstr(3, vinv_transform(Points[1], Trans), " ", 0, 5), "\n")
#end
Show("Shear_Trans", transform { Shear_Trans(<1, 0.5, 0>, <0, 2, 0>, <0.2, 0.3, 1>) })
Show("Matrix_Trans", transform { Matrix_Trans(<1, 0.5, 0>, <0, 2, 0>, <0.2, 0.3, 1>, <4, 5, 6>) })
Show("Axial_Scale_Trans", transform { Axial_Scale_Trans(<1, 1, 0>, 3) })
Show("Axis_Rotate_Trans", transform { Axis_Rotate_Trans(<1, 2, 3>, 40) })
Show("Rotate_Around_Trans", transform { Rotate_Around_Trans(<10, 20, 30>, <1, 2, 3>) })
Show("Reorient_Trans", transform { Reorient_Trans(<1, 0, 0>, <0.3, 1, -0.5>) })
Show("Reorient_Trans same", transform { Reorient_Trans(<1, 2, 0>, <2, 4, 0>) })
Show("Reorient_Trans opposite", transform { Reorient_Trans(<0, 1, 0>, <0, -3, 0>) })
Show("Reorient_Trans opposite x", transform { Reorient_Trans(<1, 0, 0>, <-1, 0, 0>) })
Show("Point_At_Trans", transform { Point_At_Trans(<1, 1, 1>) })
Show("Point_At_Trans z", transform { Point_At_Trans(<0, 0, 2>) })
Show("Point_At_Trans -z", transform { Point_At_Trans(<0, 0, -1>) })
Show("Point_At_Trans y", transform { Point_At_Trans(<0, 3, 0>) })
Show("Point_At_Trans -y", transform { Point_At_Trans(<0, -1, 0>) })
Show("Point_At_Trans x", transform { Point_At_Trans(<1, 0, 0>) })
Show("Point_At_Trans 113", transform { Point_At_Trans(<1, 1, 3>) })
Show("Point_At_Trans 123", transform { Point_At_Trans(<1, 2, 3>) })
Show("Point_At_Trans 1-2", transform { Point_At_Trans(<1, -2, 0.5>) })
#declare Thing = box { <-1, 2, 0.5>, <3, 5, 1.5> }
Show("Center_Trans x", transform { Center_Trans(Thing, x) })
Show("Center_Trans x+z", transform { Center_Trans(Thing, x + z) })
Show("Center_Trans xyz", transform { Center_Trans(Thing, <1, 1, 1>) })
Show("Align_Trans x", transform { Align_Trans(Thing, x, <10, 10, 10>) })
Show("Align_Trans -y", transform { Align_Trans(Thing, -y, <10, 10, 10>) })
Show("Align_Trans mixed", transform { Align_Trans(Thing, <-1, 1, 1>, <0, 0, 0>) })
#declare Path = spline {
  cubic_spline
  -1, <0, 0, -2>
  0, <0, 0, 0>
  1, <2, 1, 3>
  2, <5, 0, 4>
  3, <6, 2, 0>
  4, <6, 2, -3>
}
#for (T, 0.25, 2.75, 0.5)
  Show(concat("Spline_Trans ", str(T, 0, 2)), transform { Spline_Trans(Path, T, y, 0.1, 0.5) })
  Show(concat("Spline_Trans bank 0 ", str(T, 0, 2)), transform { Spline_Trans(Path, T, y, 0.2, 0) })
  Show(concat("Spline_Trans sky z ", str(T, 0, 2)), transform { Spline_Trans(Path, T, z, 0.05, 1) })
#end
