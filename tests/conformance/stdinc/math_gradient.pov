#version 3.7;
#include "math.inc"
#declare F = function { x * x + 3 * y }
#debug concat("vGradient(F, <1, 2, 3>) = <", vstr(3, vGradient(F, <1, 2, 3>), ", ", 0, 6), ">\n")
#debug concat("Gradient_Length(F, <1, 0, 0>) = ", str(Gradient_Length(F, <1, 0, 0>), 0, 6), "\n")
