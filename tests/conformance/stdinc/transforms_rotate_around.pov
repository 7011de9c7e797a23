#version 3.7;
#include "transforms.inc"
#declare T = Rotate_Around_Trans(<0, 0, 90>, <1, 1, 0>)
#debug concat("vtransform(<2, 1, 0>, T) = <", vstr(3, vtransform(<2, 1, 0>, T), ", ", 0, 6), ">\n")
