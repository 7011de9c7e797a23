#version 3.7;
#include "metals.inc"
#debug concat("P_Brass1 = <", vstr(5, P_Brass1, ", ", 0, 6), ">\n")
#debug concat("P_Chrome3 = <", vstr(5, P_Chrome3, ", ", 0, 6), ">\n")
