#version 3.7;
#declare C = x + t;
#debug concat("C = <", vstr(5, C, ", ", 0, 1), ">\n")
#debug concat("C.t = ", str(C.t, 0, 1), "\n")
