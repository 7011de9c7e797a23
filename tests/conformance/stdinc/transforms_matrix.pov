#version 3.7;
#include "transforms.inc"
#declare T = Matrix_Trans(<2, 0, 0>, <0, 3, 0>, <0, 0, 4>, <1, 1, 1>)
#debug concat("vtransform(<1, 1, 1>, T) = <", vstr(3, vtransform(<1, 1, 1>, T), ", ", 0, 6), ">\n")
