#version 3.7;
#include "transforms.inc"
#declare T = Axial_Scale_Trans(<1, 1, 0>, 2)
#debug concat("vtransform(<1, 0, 0>, T) = <", vstr(3, vtransform(<1, 0, 0>, T), ", ", 0, 6), ">\n")
