#version 3.7;
#include "math.inc"
#debug concat("VWith_Len(<3, 4, 0>, 10) = <", vstr(3, VWith_Len(<3, 4, 0>, 10), ", ", 0, 6), ">\n")
