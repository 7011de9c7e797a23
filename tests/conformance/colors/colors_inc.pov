#version 3.7;
#include "colors.inc"
#debug concat("Red = <", vstr(5, Red, ", ", 0, 6), ">\n")
#debug concat("Green = <", vstr(5, Green, ", ", 0, 6), ">\n")
#debug concat("Blue = <", vstr(5, Blue, ", ", 0, 6), ">\n")
#debug concat("White = <", vstr(5, White, ", ", 0, 6), ">\n")
#debug concat("Gray50 = <", vstr(5, Gray50, ", ", 0, 6), ">\n")
#debug concat("Orange = <", vstr(5, Orange, ", ", 0, 6), ">\n")
#debug concat("Clear = <", vstr(5, Clear, ", ", 0, 6), ">\n")
