#version 3.7;
#declare C = u + z;
#debug concat("C = <", vstr(3, C, ", ", 0, 1), ">\n")
