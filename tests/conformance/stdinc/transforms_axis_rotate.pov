#version 3.7;
#include "transforms.inc"
#declare T = Axis_Rotate_Trans(<1, 1, 0>, 90)
#debug concat("vtransform(z, T) = <", vstr(3, vtransform(z, T), ", ", 0, 9), ">\n")
