#version 3.7;
#declare B = <1,2,3,4> + 1;
#debug concat("B = <", vstr(5, B, ", ", 0, 1), ">\n")
#debug concat("B.t = ", str(B.t, 0, 1), "\n")
