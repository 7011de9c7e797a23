#version 3.7;
#include "transforms.inc"
#declare T = Point_At_Trans(<1, 1, 1>)
#debug concat("vtransform(y, T) = <", vstr(3, vtransform(y, T), ", ", 0, 9), ">\n")
