#version 3.7;
#include "transforms.inc"
#declare T = transform { rotate 90*z translate <1, 0, 0> }
#debug concat("vtransform(<1, 0, 0>, T) = <", vstr(3, vtransform(<1, 0, 0>, T), ", ", 0, 6), ">\n")
#debug concat("vinv_transform(<1, 1, 0>, T) = <", vstr(3, vinv_transform(<1, 1, 0>, T), ", ", 0, 6), ">\n")
