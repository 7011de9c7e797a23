#version 3.7;
#include "transforms.inc"
#declare T = Reorient_Trans(x, y)
#debug concat("vtransform(x, T) = <", vstr(3, vtransform(x, T), ", ", 0, 9), ">\n")
#debug concat("vtransform(z, T) = <", vstr(3, vtransform(z, T), ", ", 0, 9), ">\n")
