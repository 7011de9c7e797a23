#version 3.7;
#include "math.inc"
#debug concat("VSqr(<1, 2, 3>) = <", vstr(3, VSqr(<1, 2, 3>), ", ", 0, 3), ">\n")
#debug concat("VPow(<1, 2, 3>, 3) = <", vstr(3, VPow(<1, 2, 3>, 3), ", ", 0, 3), ">\n")
#debug concat("VEq(<1, 2, 3>, <1, 2, 3>) = ", str(VEq(<1, 2, 3>, <1, 2, 3>), 0, 0), "\n")
#debug concat("VZero(<0, 0, 0>) = ", str(VZero(<0, 0, 0>), 0, 0), "\n")
