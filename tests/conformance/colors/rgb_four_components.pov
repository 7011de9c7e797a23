#version 3.7;
#declare C = rgb <0.1, 0.2, 0.3, 0.4>;
#debug concat("C = <", vstr(5, C, ", ", 0, 2), ">\n")
