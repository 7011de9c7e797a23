#version 3.7;
#include "colors.inc"
#include "colors.inc"
#debug concat("Red = <", vstr(5, Red, ", ", 0, 1), ">\n")
