#version 3.7;
#declare C = rgbt <1, 0.5, 0.2, 0.7>;
#debug concat("C = <", vstr(5, C, ", ", 0, 3), ">\n")
