#version 3.7;
#include "math.inc"
#debug concat("VPerp_To_Vector = <", vstr(3, VPerp_To_Vector(<1, 2, 3>), ", ", 0, 9), ">\n")
#debug concat("VPerp_To_Plane(x, y) = <", vstr(3, VPerp_To_Plane(x, y), ", ", 0, 6), ">\n")
#debug concat("VProject_Axis(<1, 2, 3>, y) = <", vstr(3, VProject_Axis(<1, 2, 3>, y), ", ", 0, 6), ">\n")
#debug concat("VProject_Plane(<1, 2, 3>, y) = <", vstr(3, VProject_Plane(<1, 2, 3>, y), ", ", 0, 6), ">\n")
