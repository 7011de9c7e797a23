#version 3.7;
#include "transforms.inc"
#declare T = Shear_Trans(x, <1, 1, 0>, z)
#debug concat("vtransform(<1, 2, 3>, T) = <", vstr(3, vtransform(<1, 2, 3>, T), ", ", 0, 6), ">\n")
