#version 3.7;
#declare C = 0.5 + rgb <0.1, 0.2, 0.3>;
#debug concat("C = <", vstr(5, C, ", ", 0, 3), ">\n")
