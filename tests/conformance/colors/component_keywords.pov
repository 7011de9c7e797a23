#version 3.7;
#declare C = color red 1.0 green 0.5;
#debug concat("C = <", vstr(5, C, ", ", 0, 2), ">\n")
